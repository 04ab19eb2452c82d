// The events of a character's last step (smg_character_get_events), read
// into an array allocated once and handed to an ISmgEventHandler: reading
// and dispatching allocate nothing, so a component can do it every frame.
// libsmg's queue holds constraint_capacity + 5 events, so an array of that
// size never loses one. Positions stay in libsmg's frame (SmgMirrorX
// converts them for a left-handed engine).
using System;

namespace Smg
{
    /// <summary>What a step reports, one call per event, in the order the
    /// events happened within the step.</summary>
    public interface ISmgEventHandler
    {
        /// <summary>A transition (isSplice false: value is a style) or
        /// splice (an action) took effect, or was reached while its value
        /// was already shown. id 0: a change no constraint asked for
        /// (SetStyle / SetAction, the steering walking to a stop).</summary>
        void OnConstraintReached(uint id, uint value, bool isSplice);

        /// <summary>A constraint that will never take effect: a later one
        /// of its kind (or SetStyle / SetAction) took over first. Every
        /// constraint id gets exactly one Reached or Superseded.</summary>
        void OnConstraintSuperseded(uint id, uint value, bool isSplice);

        /// <summary>A foot landed (0 left, 1 right): the toe's world
        /// position and its downward speed as it landed (m/s).</summary>
        void OnFootstep(int foot, SmgFloat3 position, float strength);

        /// <summary>The character arrived at its path's end.</summary>
        void OnPathEndReached();
    }

    public sealed class SmgEventQueue
    {
        // smg_character_desc.constraint_capacity's default and libsmg's
        // margin for the events that are not constraints (smg.h)
        const int DefaultConstraintCapacity = 32;
        const int NonConstraintEvents = 5;

        readonly SmgEvent[] events;
        int count;

        /// <summary>A queue for characters created with this
        /// constraint capacity (0: libsmg's default).</summary>
        public SmgEventQueue(uint constraintCapacity)
        {
            int constraints = constraintCapacity == 0 ? DefaultConstraintCapacity : checked((int)constraintCapacity);
            events = new SmgEvent[constraints + NonConstraintEvents];
        }

        /// <summary>The events read by the last Read.</summary>
        public int Count => count;

        public ref readonly SmgEvent this[int index]
        {
            get
            {
                if ((uint)index >= (uint)count)
                    throw new ArgumentOutOfRangeException(nameof(index));
                return ref events[index];
            }
        }

        /// <summary>Reads the events of `character`'s last step.</summary>
        public int Read(SmgCharacter character)
        {
            if (character == null)
                throw new ArgumentNullException(nameof(character));
            count = 0;
            count = character.GetEvents(events);
            return count;
        }

        /// <summary>Hands the events read last to `handler`, in order.</summary>
        public void Dispatch(ISmgEventHandler handler)
        {
            if (handler == null)
                throw new ArgumentNullException(nameof(handler));
            for (int i = 0; i < count; ++i)
            {
                SmgEvent e = events[i];
                switch (e.Type)
                {
                    case SmgEventType.Constraint:
                        bool splice = (e.Flags & SmgEventFlags.Splice) != 0;
                        if ((e.Flags & SmgEventFlags.Superseded) != 0)
                            handler.OnConstraintSuperseded(e.Id, e.Value, splice);
                        else
                            handler.OnConstraintReached(e.Id, e.Value, splice);
                        break;
                    case SmgEventType.Footstep:
                        handler.OnFootstep((int)e.Id, e.Position, e.Strength);
                        break;
                    case SmgEventType.PathEnd:
                        handler.OnPathEndReached();
                        break;
                    // a type added by a newer libsmg is not ours to report
                }
            }
        }
    }
}
