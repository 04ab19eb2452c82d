// Humanoid mapping (SmgHumanoid): the graph's joints recognised as
// humanoid bones, and a rig whose bone names follow no known convention
// mapped onto them only through its humanoid table (what
// Animator.GetBoneTransform(HumanBodyBones) gives in Unity).
using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Smg.Tests
{
    [TestFixture]
    public class SmgHumanoidTests
    {
        // the graph's joint -> the humanoid bone it is (CMU's names, which
        // the default graph has); joints not listed are none
        static readonly Dictionary<string, SmgHumanBone> CmuBones = new Dictionary<string, SmgHumanBone>
        {
            { "Hips", SmgHumanBone.Hips },
            { "LeftUpLeg", SmgHumanBone.LeftUpperLeg }, { "LeftLeg", SmgHumanBone.LeftLowerLeg },
            { "LeftFoot", SmgHumanBone.LeftFoot }, { "LeftToeBase", SmgHumanBone.LeftToes },
            { "RightUpLeg", SmgHumanBone.RightUpperLeg }, { "RightLeg", SmgHumanBone.RightLowerLeg },
            { "RightFoot", SmgHumanBone.RightFoot }, { "RightToeBase", SmgHumanBone.RightToes },
            { "LowerBack", SmgHumanBone.Spine }, { "Spine", SmgHumanBone.Chest }, { "Spine1", SmgHumanBone.UpperChest },
            { "Neck", SmgHumanBone.Neck }, { "Head", SmgHumanBone.Head },
            { "LeftShoulder", SmgHumanBone.LeftShoulder }, { "LeftArm", SmgHumanBone.LeftUpperArm },
            { "LeftForeArm", SmgHumanBone.LeftLowerArm }, { "LeftHand", SmgHumanBone.LeftHand },
            { "RightShoulder", SmgHumanBone.RightShoulder }, { "RightArm", SmgHumanBone.RightUpperArm },
            { "RightForeArm", SmgHumanBone.RightLowerArm }, { "RightHand", SmgHumanBone.RightHand },
        };

        static SmgGraph LoadCmuNamedGraph()
        {
            SmgGraph graph = TestGraph.Load();
            if (!graph.TryFindJoint("LeftUpLeg", out int unused) || !graph.TryFindJoint("LowerBack", out unused))
            {
                graph.Dispose();
                Assert.Ignore("the test graph does not have CMU's joint names");
            }
            return graph;
        }

        [Test]
        public void GraphJointsAreRecognised()
        {
            using (SmgGraph graph = LoadCmuNamedGraph())
            {
                SmgHumanBone[] bones = SmgHumanoid.Classify(graph);
                for (int j = 0; j < graph.JointCount; ++j)
                {
                    string name = graph.GetJoint(j).Name;
                    SmgHumanBone expected = CmuBones.TryGetValue(name, out SmgHumanBone b) ? b : SmgHumanBone.None;
                    Assert.AreEqual(expected, bones[j], "joint " + name);
                }
            }
        }

        [Test]
        public void OtherNamingConventionsAreRecognised()
        {
            // Mixamo: namespace, Spine/Spine1/Spine2, Left/Right words
            string[] mixamo =
            {
                "mixamorig:Hips", "mixamorig:Spine", "mixamorig:Spine1", "mixamorig:Spine2", "mixamorig:Neck",
                "mixamorig:Head", "mixamorig:LeftShoulder", "mixamorig:LeftArm", "mixamorig:LeftForeArm",
                "mixamorig:LeftHand", "mixamorig:LeftUpLeg", "mixamorig:LeftLeg", "mixamorig:LeftFoot", "mixamorig:LeftToeBase",
            };
            int[] mixamoParents = { -1, 0, 1, 2, 3, 4, 3, 6, 7, 8, 0, 10, 11, 12 };
            SmgHumanBone[] expected =
            {
                SmgHumanBone.Hips, SmgHumanBone.Spine, SmgHumanBone.Chest, SmgHumanBone.UpperChest, SmgHumanBone.Neck,
                SmgHumanBone.Head, SmgHumanBone.LeftShoulder, SmgHumanBone.LeftUpperArm, SmgHumanBone.LeftLowerArm,
                SmgHumanBone.LeftHand, SmgHumanBone.LeftUpperLeg, SmgHumanBone.LeftLowerLeg, SmgHumanBone.LeftFoot, SmgHumanBone.LeftToes,
            };
            CollectionAssert.AreEqual(expected, SmgHumanoid.Classify(mixamo, mixamoParents), "Mixamo");

            // side after the part, a pelvis word, one spine joint, a left
            // foot without the rest of its leg
            string[] suffixed = { "pelvis", "thigh_r", "calf_r", "foot_r", "spine_01", "neck_01", "head", "foot_l" };
            int[] suffixedParents = { -1, 0, 1, 2, 0, 4, 5, 0 };
            SmgHumanBone[] expectedSuffixed =
            {
                SmgHumanBone.Hips, SmgHumanBone.RightUpperLeg, SmgHumanBone.RightLowerLeg, SmgHumanBone.RightFoot,
                SmgHumanBone.Spine, SmgHumanBone.Neck, SmgHumanBone.Head, SmgHumanBone.LeftFoot,
            };
            CollectionAssert.AreEqual(expectedSuffixed, SmgHumanoid.Classify(suffixed, suffixedParents), "suffixed sides");
            string[] wrongOrder = { "Hips", "LeftFoot", "LeftLowerLeg" };
            // a foot above its knee: better missing than wrong
            CollectionAssert.AreEqual(new[] { SmgHumanBone.Hips, SmgHumanBone.None, SmgHumanBone.LeftLowerLeg },
                                      SmgHumanoid.Classify(wrongOrder, new[] { -1, 0, 1 }), "a foot above its knee is dropped");
        }

        [Test]
        public void RigWithoutANamingConventionIsMappedThroughItsHumanoidTable()
        {
            using (SmgGraph graph = LoadCmuNamedGraph())
            {
                // The rig: bones named after nothing, known only through the
                // avatar's HumanBodyBones table; plus an extra bone named
                // like one of the graph's joints that is no humanoid bone.
                var avatar = new Dictionary<SmgHumanBone, string>();
                foreach (SmgHumanBone bone in Enum.GetValues(typeof(SmgHumanBone)))
                    if (bone != SmgHumanBone.None)
                        avatar[bone] = "qx" + ((int)bone * 7919 % 1000) + "_bn";
                var rig = new HashSet<string>(avatar.Values) { "Neck1" };
                Func<string, string> byName = n => rig.Contains(n) ? n : null;

                // names alone find nothing of the humanoid rig
                string[] named = SmgHumanoid.MapBones<string>(graph, null, null, byName);
                for (int j = 0; j < named.Length; ++j)
                    Assert.That(named[j] == null || named[j] == "Neck1", "by name: joint " + graph.GetJoint(j).Name + " -> " + named[j]);

                string[] mapped = SmgHumanoid.MapBones<string>(graph, null, h => avatar.TryGetValue(h, out string s) ? s : null, byName);
                for (int j = 0; j < graph.JointCount; ++j)
                {
                    string name = graph.GetJoint(j).Name;
                    string expected = CmuBones.TryGetValue(name, out SmgHumanBone b) ? avatar[b] : name == "Neck1" ? "Neck1" : null;
                    Assert.AreEqual(expected, mapped[j], "joint " + name + " (humanoid " + b + ")");
                }

                // an override wins over the avatar, and a rig bone serves one joint
                mapped = SmgHumanoid.MapBones<string>(graph, n => n == "LeftHand" ? avatar[SmgHumanBone.RightHand] : null,
                                                      h => avatar.TryGetValue(h, out string s) ? s : null, byName);
                Assert.AreEqual(avatar[SmgHumanBone.RightHand], mapped[Index(graph, "LeftHand")]);
                Assert.IsNull(mapped[Index(graph, "RightHand")], "the overridden bone is not given twice");
            }
        }

        static int Index(SmgGraph graph, string name)
        {
            Assert.IsTrue(graph.TryFindJoint(name, out int j), name);
            return j;
        }
    }
}
