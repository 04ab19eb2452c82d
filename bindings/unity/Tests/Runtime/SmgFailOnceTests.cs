// SmgPathCharacter steps through SmgFailOnce: a failing step is reported
// once, and the work is not run again (the component then disables
// itself instead of throwing every frame).
using System;
using NUnit.Framework;

namespace Smg.Tests
{
    [TestFixture]
    public class SmgFailOnceTests
    {
        [Test]
        public void FailingStepIsReportedOnceAndNotRetried()
        {
            using (SmgGraph graph = TestGraph.Load())
            using (SmgCharacter ch = TestGraph.Walker(graph))
            {
                int reports = 0, runs = 0;
                Exception reported = null;
                float dt = 1.0f / 60.0f;
                var guard = new SmgFailOnce(x => { ++reports; reported = x; });
                Action frame = () => { ++runs; ch.Step(dt); };

                Assert.IsTrue(guard.Run(frame), "a good step");
                Assert.IsNull(guard.Failure);
                dt = 2.0f; // outside 0..1: libsmg refuses the step
                for (int f = 0; f < 5; ++f)
                    Assert.IsFalse(guard.Run(frame), "frame " + f + " after the failure");
                Assert.AreEqual(1, reports, "reported once");
                Assert.AreEqual(2, runs, "not run again after the failure");
                SmgException e = reported as SmgException;
                Assert.IsNotNull(e, "libsmg's exception is the one reported");
                Assert.AreEqual(SmgResult.ErrorInvalidArgument, e.Result);
                Assert.AreSame(reported, guard.Failure);
                dt = 1.0f / 60.0f;
                Assert.IsFalse(guard.Run(frame), "stays stopped once stopped");
                Assert.AreEqual(2, runs);
            }
        }
    }
}
