// Looking a style, action or joint up by name allocates no managed memory
// after that name's first lookup (gameplay code may do it every frame).
using System;
using NUnit.Framework;

namespace Smg.Tests
{
    [TestFixture]
    public class SmgNameLookupTests
    {
        [Test]
        public void LookupsAllocateNothingAfterTheFirst()
        {
            using (SmgGraph graph = TestGraph.Load())
            using (SmgCharacter ch = TestGraph.Walker(graph))
            {
                string style = graph.GetStyleName(graph.Info.StyleCount - 1);
                string action = graph.GetActionName(graph.Info.ActionCount - 1);
                string joint = graph.GetJoint(graph.JointCount - 1).Name;
                const string missing = "no such joint";
                int index;
                uint expectedStyle = graph.FindStyle(style);
                uint expectedAction = graph.FindAction(action);
                Assert.IsTrue(graph.TryFindJoint(joint, out index));
                Assert.IsFalse(graph.TryFindJoint(missing, out index));
                Lookups(graph, ch, style, action, joint, missing, 10); // JIT and first-call work

                long before = GC.GetAllocatedBytesForCurrentThread();
                Lookups(graph, ch, style, action, joint, missing, 1000);
                long after = GC.GetAllocatedBytesForCurrentThread();
                Assert.AreEqual(0L, after - before, "managed bytes allocated by 1000 rounds of lookups");

                Assert.AreEqual(expectedStyle, graph.FindStyle(style));
                Assert.AreEqual(expectedAction, graph.FindAction(action));
                Assert.IsTrue(graph.TryFindJoint(joint, out index));
                Assert.AreEqual(graph.JointCount - 1, index);
            }
        }

        [Test]
        public void RememberedNamesStillFailAndThrowLikeLibsmg()
        {
            SmgGraph graph = TestGraph.Load();
            string style = graph.GetStyleName(0);
            graph.FindStyle(style);
            SmgException e = Assert.Throws<SmgException>(() => graph.FindStyle("no such style"));
            Assert.AreEqual(SmgResult.ErrorUnknownStyle, e.Result);
            e = Assert.Throws<SmgException>(() => graph.FindStyle("no such style"));
            Assert.AreEqual(SmgResult.ErrorUnknownStyle, e.Result, "an unknown name fails every time");
            graph.Dispose();
            Assert.Throws<ObjectDisposedException>(() => graph.FindStyle(style), "a remembered name on a disposed graph");
        }

        static void Lookups(SmgGraph graph, SmgCharacter ch, string style, string action, string joint,
                            string missing, int rounds)
        {
            int index;
            for (int i = 0; i < rounds; ++i)
            {
                graph.FindStyle(style);
                graph.FindAction(action);
                graph.TryFindJoint(joint, out index);
                graph.TryFindJoint(missing, out index);
                ch.SetStyle(graph.FindStyle(style));
            }
        }
    }
}
