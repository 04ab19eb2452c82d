// One animated figure following one path. A SafeHandle holding a reference
// on its graph, so the graph is destroyed only after its last character
// (whatever order Dispose or the finalizers run in). One thread at a time
// per character, as in C. Step and the pose reads allocate nothing: the
// caller owns the buffers (arrays or spans, sized from SmgGraph.JointCount).
using System;
using System.Runtime.InteropServices;

namespace Smg
{
    public sealed unsafe class SmgCharacter : SafeHandle
    {
        SmgGraph graph;
        SmgHookContext hooks;
        uint jointCount;

        SmgCharacter() : base(IntPtr.Zero, true)
        {
        }

        public override bool IsInvalid => handle == IntPtr.Zero;

        /// <summary>The graph this character animates from.</summary>
        public SmgGraph Graph => graph;

        public int JointCount => (int)jointCount;

        /// <summary>Creates a character on `graph`. desc.StructSize 0 is
        /// taken as SmgCharacterDesc.Size (any other value goes to libsmg
        /// as given); desc.Allocator is ignored: pass `allocator` instead.</summary>
        public static SmgCharacter Create(SmgGraph graph, SmgCharacterDesc desc, ISmgAllocator allocator = null)
        {
            if (graph == null)
                throw new ArgumentNullException(nameof(graph));
            var ch = new SmgCharacter();
            bool graphRef = false;
            bool ok = false;
            SmgHookContext hooks = allocator != null ? new SmgHookContext(allocator, null) : null;
            try
            {
                graph.DangerousAddRef(ref graphRef); // ObjectDisposedException when disposed
                if (desc.StructSize == 0)
                    desc.StructSize = SmgCharacterDesc.Size;
                desc.Allocator = hooks != null ? hooks.NativeAllocator : default(SmgAllocator);
                IntPtr h;
                SmgException.Check(SmgNative.smg_character_create(graph, &desc, out h), "smg_character_create");
                ch.SetHandle(h);
                ch.graph = graph;
                ch.hooks = hooks;
                ch.jointCount = (uint)graph.JointCount;
                ok = true;
                return ch;
            }
            finally
            {
                if (!ok)
                {
                    ch.SetHandleAsInvalid();
                    hooks?.Release();
                    if (graphRef)
                        graph.DangerousRelease();
                }
            }
        }

        /// <summary>The native pointer for SmgNativeRaw (jobs); the
        /// character stays alive until the lease is disposed, even if it is
        /// disposed meanwhile. One thread at a time per character still.</summary>
        public SmgCharacterPointer AcquirePointer()
        {
            bool added = false;
            DangerousAddRef(ref added); // ObjectDisposedException when disposed
            return new SmgCharacterPointer(DangerousGetHandle(), this);
        }

        protected override bool ReleaseHandle()
        {
            if (SmgNative.smg_character_destroy(handle) != SmgResult.Ok)
                return false;
            hooks?.Release();
            graph.DangerousRelease();
            return true;
        }

        // --- The path: interleaved (x, z) pairs on the ground, metres ---

        public void SetPath(ReadOnlySpan<float> xz)
        {
            uint count = PointCount(xz);
            fixed (float* p = &MemoryMarshal.GetReference(xz))
                SmgException.Check(SmgNative.smg_character_set_path(this, p, count), "smg_character_set_path");
        }

        public void AppendPath(ReadOnlySpan<float> xz)
        {
            uint count = PointCount(xz);
            fixed (float* p = &MemoryMarshal.GetReference(xz))
                SmgException.Check(SmgNative.smg_character_append_path(this, p, count), "smg_character_append_path");
        }

        public void ClearPath()
        {
            SmgException.Check(SmgNative.smg_character_clear_path(this), "smg_character_clear_path");
        }

        public float PathLength
        {
            get
            {
                float length;
                SmgException.Check(SmgNative.smg_character_get_path_length(this, out length), "smg_character_get_path_length");
                return length;
            }
        }

        static uint PointCount(ReadOnlySpan<float> xz)
        {
            if ((xz.Length & 1) != 0)
                throw new ArgumentException("a path is (x, z) pairs: an even number of floats", nameof(xz));
            return (uint)(xz.Length / 2);
        }

        // --- Constraints at arc lengths along the path; ids are > 0 ---

        public uint AddTransition(float arcLength, uint style)
        {
            uint id;
            SmgException.Check(SmgNative.smg_character_add_transition(this, arcLength, style, out id), "smg_character_add_transition");
            return id;
        }

        public uint AddSplice(float arcLength, uint action)
        {
            uint id;
            SmgException.Check(SmgNative.smg_character_add_splice(this, arcLength, action, out id), "smg_character_add_splice");
            return id;
        }

        public void MoveConstraint(uint id, float arcLength)
        {
            SmgException.Check(SmgNative.smg_character_move_constraint(this, id, arcLength), "smg_character_move_constraint");
        }

        public void RemoveConstraint(uint id)
        {
            SmgException.Check(SmgNative.smg_character_remove_constraint(this, id), "smg_character_remove_constraint");
        }

        public void ClearConstraints()
        {
            SmgException.Check(SmgNative.smg_character_clear_constraints(this), "smg_character_clear_constraints");
        }

        // --- Immediate controls ---

        public void SetStyle(uint style)
        {
            SmgException.Check(SmgNative.smg_character_set_style(this, style), "smg_character_set_style");
        }

        public void SetAction(uint action)
        {
            SmgException.Check(SmgNative.smg_character_set_action(this, action), "smg_character_set_action");
        }

        public void SetErrorThreshold(float metres)
        {
            SmgException.Check(SmgNative.smg_character_set_error_threshold(this, metres), "smg_character_set_error_threshold");
        }

        public void SetIk(bool enabled)
        {
            SmgException.Check(SmgNative.smg_character_set_ik(this, enabled ? 1u : 0u), "smg_character_set_ik");
        }

        /// <summary>Root steering on or off (on by default).</summary>
        public void SetSteering(bool enabled)
        {
            SmgException.Check(SmgNative.smg_character_set_steering(this, enabled ? 1u : 0u), "smg_character_set_steering");
        }

        /// <summary>Steering bounds: heading rad/s, translation as a fraction of the motion's speed, braking seconds (0 = default each).</summary>
        public void SetSteeringLimits(float turnRate, float slideRatio, float stopSeconds)
        {
            SmgException.Check(SmgNative.smg_character_set_steering_limits(this, turnRate, slideRatio, stopSeconds), "smg_character_set_steering_limits");
        }

        /// <summary>Swing clearance on or off, and the clearance in metres (0 = 0.04 leg lengths).</summary>
        public void SetSwingClearance(bool enabled, float clearance)
        {
            SmgException.Check(SmgNative.smg_character_set_swing_clearance(this, enabled ? 1u : 0u, clearance), "smg_character_set_swing_clearance");
        }

        // --- Per frame: no allocation ---

        /// <summary>Advances by dt seconds (0 &lt;= dt &lt;= 1).</summary>
        public void Step(float dt)
        {
            SmgException.Check(SmgNative.smg_character_step(this, dt), "smg_character_step");
        }

        public SmgCharacterState State
        {
            get
            {
                SmgCharacterState s = SmgCharacterState.Create();
                SmgException.Check(SmgNative.smg_character_get_state(this, &s), "smg_character_get_state");
                return s;
            }
        }

        /// <summary>Root translation (3 floats, world) and joint-local
        /// rotations (4 floats x, y, z, w per joint; joint 0's is its world
        /// rotation). rotations must hold exactly 4 * JointCount floats.</summary>
        public void GetLocalPose(Span<float> rootTranslation, Span<float> rotations)
        {
            if (rootTranslation.Length < 3)
                throw new ArgumentException("needs 3 floats", nameof(rootTranslation));
            if ((rotations.Length & 3) != 0)
                throw new ArgumentException("4 floats per joint", nameof(rotations));
            fixed (float* root = &MemoryMarshal.GetReference(rootTranslation))
            fixed (float* rot = &MemoryMarshal.GetReference(rotations))
                SmgException.Check(SmgNative.smg_character_get_local_pose(this, root, rot, (uint)(rotations.Length / 4)),
                                   "smg_character_get_local_pose");
        }

        /// <summary>Model-space joint matrices, 16 floats per joint,
        /// column-major; matrices must hold exactly 16 * JointCount floats.</summary>
        public void GetModelMatrices(SmgSpace space, Span<float> matrices)
        {
            if ((matrices.Length & 15) != 0)
                throw new ArgumentException("16 floats per joint", nameof(matrices));
            fixed (float* m = &MemoryMarshal.GetReference(matrices))
                SmgException.Check(SmgNative.smg_character_get_model_matrices(this, space, m, (uint)(matrices.Length / 16)),
                                   "smg_character_get_model_matrices");
        }

        // --- Ground and the engine's mover, before or after the step ---

        /// <summary>Where to measure the ground for the next step: 6 floats,
        /// (x, z) of the left foot, right foot and root probes.</summary>
        public void GetGroundProbes(Span<float> xz)
        {
            if (xz.Length != 6)
                throw new ArgumentException("3 probes of (x, z): 6 floats", nameof(xz));
            fixed (float* p = &MemoryMarshal.GetReference(xz))
                SmgException.Check(SmgNative.smg_character_get_ground_probes(this, p, 3), "smg_character_get_ground_probes");
        }

        /// <summary>The ground heights measured at the probes, for the next
        /// steps (ground.StructSize 0 is taken as SmgGround.Size).</summary>
        public void SetGround(SmgGround ground)
        {
            if (ground.StructSize == 0)
                ground.StructSize = SmgGround.Size;
            SmgException.Check(SmgNative.smg_character_set_ground(this, &ground), "smg_character_set_ground");
        }

        /// <summary>The flat floor at y = 0 again (the default).</summary>
        public void ClearGround()
        {
            SmgException.Check(SmgNative.smg_character_set_ground(this, null), "smg_character_set_ground");
        }

        /// <summary>Where the engine's mover put the character after the
        /// last step: ground position (y: the floor there) and heading. The
        /// character moves rigidly, its pose does not pop.</summary>
        public void SetGroundPosition(SmgFloat3 position, float heading)
        {
            SmgException.Check(SmgNative.smg_character_set_ground_position(this, &position.X, heading),
                               "smg_character_set_ground_position");
        }

        /// <summary>The ground position's displacement over the last step.</summary>
        public SmgRootMotion RootMotion
        {
            get
            {
                SmgRootMotion m = SmgRootMotion.Create();
                SmgException.Check(SmgNative.smg_character_get_root_motion(this, &m), "smg_character_get_root_motion");
                return m;
            }
        }

        /// <summary>The events of the last step, in order, into `events`
        /// (never more than ConstraintCapacity + 5); returns how many. Too
        /// small a span throws SmgException (BufferTooSmall).</summary>
        public int GetEvents(Span<SmgEvent> events)
        {
            uint count;
            if (events.Length == 0)
            {
                SmgException.Check(SmgNative.smg_character_get_events(this, null, 0, out count), "smg_character_get_events");
                return (int)count;
            }
            events[0].StructSize = SmgEvent.Size;
            fixed (SmgEvent* e = &MemoryMarshal.GetReference(events))
                SmgException.Check(SmgNative.smg_character_get_events(this, e, (uint)events.Length, out count),
                                   "smg_character_get_events");
            return (int)count;
        }
    }
}
