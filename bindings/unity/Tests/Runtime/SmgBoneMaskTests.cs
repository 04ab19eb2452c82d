// Per-joint blend weights (SmgBoneMask): presets by body part, an overall
// weight, named joints on top; bad names and weights are refused.
using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Smg.Tests
{
    [TestFixture]
    public class SmgBoneMaskTests
    {
        [Test]
        public void PresetsFollowTheBodyParts()
        {
            using (SmgGraph graph = TestGraph.Load())
            {
                float[] full = SmgBoneMask.Build(graph, SmgBodyMask.FullBody, 0.75f);
                float[] lower = SmgBoneMask.Build(graph, SmgBodyMask.LowerBody, 1.0f);
                float[] upper = SmgBoneMask.Build(graph, SmgBodyMask.UpperBody, 1.0f);
                int counted = 0;
                for (int j = 0; j < graph.JointCount; ++j)
                {
                    SmgJoint joint = graph.GetJoint(j);
                    bool isUpper = joint.BodyPart == SmgBodyPart.Upper;
                    Assert.AreEqual(0.75f, full[j], joint.Name);
                    Assert.AreEqual(isUpper ? 0.0f : 1.0f, lower[j], joint.Name + " in the lower-body mask");
                    Assert.AreEqual(isUpper ? 1.0f : 0.0f, upper[j], joint.Name + " in the upper-body mask");
                    counted += isUpper ? 1 : 0;
                }
                Assert.That(counted > 0 && counted < graph.JointCount, "the graph has both halves");
                Assert.AreEqual(1.0f, lower[0], "the root goes with the legs");
            }
        }

        [Test]
        public void NamedJointsOverrideThePreset()
        {
            using (SmgGraph graph = TestGraph.Load())
            {
                string upperJoint = null;
                for (int j = 0; j < graph.JointCount && upperJoint == null; ++j)
                    if (graph.GetJoint(j).BodyPart == SmgBodyPart.Upper)
                        upperJoint = graph.GetJoint(j).Name;
                var named = new[] { new KeyValuePair<string, float>(upperJoint, 0.5f) };
                float[] w = SmgBoneMask.Build(graph, SmgBodyMask.LowerBody, 1.0f, named);
                Assert.IsTrue(graph.TryFindJoint(upperJoint, out int index));
                Assert.AreEqual(0.5f, w[index]);
                Assert.Throws<ArgumentException>(() => SmgBoneMask.Build(graph, SmgBodyMask.FullBody, 1.0f,
                    new[] { new KeyValuePair<string, float>("no such joint", 1.0f) }));
                Assert.Throws<ArgumentOutOfRangeException>(() => SmgBoneMask.Build(graph, SmgBodyMask.FullBody, 1.5f));
                Assert.Throws<ArgumentOutOfRangeException>(() => SmgBoneMask.Build(graph, SmgBodyMask.FullBody, float.NaN));
                Assert.Throws<ArgumentOutOfRangeException>(() => SmgBoneMask.Build(graph, SmgBodyMask.FullBody, 1.0f,
                    new[] { new KeyValuePair<string, float>(upperJoint, -0.1f) }));
            }
        }
    }
}
