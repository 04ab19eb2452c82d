// The events of each step, read through SmgEventQueue and dispatched to a
// handler: every constraint once (reached at the step whose state first
// shows its style or action, or superseded), footsteps at the toe that
// landed, the path end once; reading and dispatching allocate nothing.
using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Smg.Tests
{
    [TestFixture]
    public class SmgEventQueueTests
    {
        sealed class Recorder : ISmgEventHandler
        {
            public readonly List<string> Log = new List<string>();
            public readonly Dictionary<uint, int> Reached = new Dictionary<uint, int>();
            public readonly Dictionary<uint, int> Superseded = new Dictionary<uint, int>();
            public readonly List<KeyValuePair<int, SmgFloat3>> Steps = new List<KeyValuePair<int, SmgFloat3>>();
            public int PathEnds;
            public SmgCharacterState State; // after the step being dispatched
            public SmgCharacter Character;
            public float[] Matrices;
            public int[] Toe;

            public void OnConstraintReached(uint id, uint value, bool isSplice)
            {
                Reached[id] = Reached.TryGetValue(id, out int n) ? n + 1 : 1;
                if (id != 0)
                    Assert.AreEqual(value, isSplice ? State.Action : State.Style,
                                    "constraint " + id + " reached: the state shows its " + (isSplice ? "action" : "style"));
            }

            public void OnConstraintSuperseded(uint id, uint value, bool isSplice)
            {
                Superseded[id] = Superseded.TryGetValue(id, out int n) ? n + 1 : 1;
            }

            public void OnFootstep(int foot, SmgFloat3 position, float strength)
            {
                Assert.That(foot == 0 || foot == 1, "foot " + foot);
                Assert.That(strength >= 0.0f && strength < 10.0f, "strength " + strength + " m/s");
                // the toe that landed is where the event says, on the floor
                int m = 16 * Toe[foot] + 12;
                float dx = Matrices[m] - position.X, dy = Matrices[m + 1] - position.Y, dz = Matrices[m + 2] - position.Z;
                Assert.Less(Math.Sqrt(dx * dx + dy * dy + dz * dz), 1e-3, "footstep " + foot + " at its toe");
                Assert.Less(Math.Abs(position.Y), 0.05, "footstep on the flat floor");
                Steps.Add(new KeyValuePair<int, SmgFloat3>(foot, position));
            }

            public void OnPathEndReached()
            {
                ++PathEnds;
                Assert.IsTrue((State.Flags & SmgStateFlags.PathEndReached) != 0, "path end with the state's flag");
            }
        }

        sealed class Counter : ISmgEventHandler
        {
            public int Events;
            public void OnConstraintReached(uint id, uint value, bool isSplice) { ++Events; }
            public void OnConstraintSuperseded(uint id, uint value, bool isSplice) { ++Events; }
            public void OnFootstep(int foot, SmgFloat3 position, float strength) { ++Events; }
            public void OnPathEndReached() { ++Events; }
        }

        [Test]
        public void EveryConstraintOnceFootstepsAtTheToesPathEndOnce()
        {
            using (SmgGraph graph = TestGraph.Load())
            using (SmgCharacter ch = SmgCharacter.Create(graph, SmgCharacterDesc.Create()))
            {
                if (graph.Info.StyleCount < 2 || graph.Info.ActionCount < 3)
                    Assert.Ignore("needs a graph with two styles and two actions besides none");
                ch.SetPath(new float[] { 0, 0, 0, 12, 6, 24 });
                var ids = new List<uint>
                {
                    ch.AddTransition(5.0f, 1),
                    ch.AddTransition(15.0f, 0),
                    ch.AddSplice(3.0f, 1),
                    ch.AddSplice(9.0f, 0),
                    ch.AddSplice(9.5f, 2), // may overtake the previous one: superseded then
                };
                // a splice overtaken by the next one 1 cm on, before any
                // splice candidate could show it
                uint overtaken = ch.AddSplice(17.0f, 1);
                ids.Add(overtaken);
                ids.Add(ch.AddSplice(17.01f, 2));
                var queue = new SmgEventQueue(0);
                var rec = new Recorder
                {
                    Character = ch,
                    Matrices = new float[16 * graph.JointCount],
                    Toe = new[] { Joint(graph, "LeftToeBase"), Joint(graph, "RightToeBase") },
                };
                bool ended = false;
                int afterEnd = 0, total = 0;
                for (int f = 0; f < 60 * 60 && afterEnd < 60; ++f)
                {
                    ch.Step(1.0f / 60.0f);
                    rec.State = ch.State;
                    ch.GetModelMatrices(SmgSpace.World, rec.Matrices);
                    int n = queue.Read(ch);
                    Assert.AreEqual(ch.GetEvents(Span<SmgEvent>.Empty), n, "the queue holds every event of the step");
                    total += n;
                    queue.Dispatch(rec);
                    bool nowEnded = (rec.State.Flags & SmgStateFlags.PathEndReached) != 0;
                    if (nowEnded && !ended)
                        Assert.AreEqual(1, rec.PathEnds, "path end reported at the step it was reached");
                    ended = nowEnded;
                    if (ended)
                        ++afterEnd;
                }
                Console.WriteLine("events: reached " + string.Join(",", rec.Reached.Keys) + "; superseded "
                                  + string.Join(",", rec.Superseded.Keys) + "; footsteps " + rec.Steps.Count);
                Assert.IsTrue(ended, "arrived");
                Assert.AreEqual(1, rec.PathEnds, "one path end");
                foreach (uint id in ids)
                {
                    int r = rec.Reached.TryGetValue(id, out int a) ? a : 0, s = rec.Superseded.TryGetValue(id, out int b) ? b : 0;
                    Assert.AreEqual(1, r + s, "constraint " + id + ": one event (reached " + r + ", superseded " + s + ")");
                }
                Assert.IsTrue(rec.Superseded.ContainsKey(overtaken), "the overtaken splice is reported superseded");
                Assert.AreEqual(2, rec.Reached.ContainsKey(ids[0]) && rec.Reached.ContainsKey(ids[1]) ? 2 : 0,
                                "both transitions took effect");
                int left = 0, right = 0;
                foreach (var step in rec.Steps)
                    if (step.Key == 0) ++left; else ++right;
                // about 40 m walked: a footstep per stride of each foot
                Assert.Greater(left, 10, "left footsteps");
                Assert.Greater(right, 10, "right footsteps");
                Assert.Less(Math.Abs(left - right), 3, "the feet take turns");
                Assert.Greater(total, 0);
            }
        }

        [Test]
        public void ReadingAndDispatchingAllocateNothing()
        {
            using (SmgGraph graph = TestGraph.Load())
            using (SmgCharacter ch = SmgCharacter.Create(graph, SmgCharacterDesc.Create()))
            {
                ch.SetPath(new float[] { 0, 0, 0, 40 });
                ch.AddTransition(4.0f, graph.Info.StyleCount - 1);
                var queue = new SmgEventQueue(0);
                var counter = new Counter();
                Frames(ch, queue, counter, 10); // JIT and first-call work
                long before = GC.GetAllocatedBytesForCurrentThread();
                Frames(ch, queue, counter, 1000);
                long after = GC.GetAllocatedBytesForCurrentThread();
                Assert.AreEqual(0L, after - before, "managed bytes allocated by 1000 frames of step, read and dispatch");
                Assert.Greater(counter.Events, 20, "events were read and dispatched");
            }
        }

        [Test]
        public void QueueIsSizedForTheCharactersConstraints()
        {
            using (SmgGraph graph = TestGraph.Load())
            {
                SmgCharacterDesc desc = SmgCharacterDesc.Create();
                desc.ConstraintCapacity = 4;
                using (SmgCharacter ch = SmgCharacter.Create(graph, desc))
                {
                    ch.SetPath(new float[] { 0, 0, 0, 2 });
                    for (int i = 0; i < 4; ++i)
                        ch.AddTransition(0.1f * i, (uint)(i % 2));
                    var queue = new SmgEventQueue(desc.ConstraintCapacity);
                    int most = 0;
                    for (int f = 0; f < 300; ++f)
                    {
                        ch.Step(1.0f / 30.0f);
                        most = Math.Max(most, queue.Read(ch));
                    }
                    Assert.Greater(most, 1, "a step with several events");
                    Assert.Throws<ArgumentOutOfRangeException>(() => queue[queue.Count].Type.ToString());
                }
            }
        }

        static void Frames(SmgCharacter ch, SmgEventQueue queue, ISmgEventHandler handler, int n)
        {
            for (int f = 0; f < n; ++f)
            {
                ch.Step(1.0f / 60.0f);
                queue.Read(ch);
                queue.Dispatch(handler);
            }
        }

        static int Joint(SmgGraph graph, string name)
        {
            if (!graph.TryFindJoint(name, out int index))
                Assert.Ignore("the graph has no joint " + name);
            return index;
        }
    }
}
