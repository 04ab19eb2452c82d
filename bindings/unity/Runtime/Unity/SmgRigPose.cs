// A rig posed by libsmg: which Transform is each graph joint's bone (the
// rig's Humanoid avatar first, then bone names, overrides before both:
// SmgHumanoid.MapBones), each bone's rest rotation recorded at setup, and
// the pose written each frame with per-joint weights (SmgBoneMask): weight
// 1 sets the bone to libsmg's pose, below 1 blends its local rotation
// with what the engine's animation wrote this frame (the Animator has
// evaluated, its IK included, before LateUpdate), so the joints the
// mask gives to the Animator keep their animation and IK.
//
// Retargeting is by rest-pose difference: a bone gets libsmg's world
// rotation of its joint times its own rest rotation relative to the
// character (the rig stands in the graph skeleton's rest pose, facing +Z,
// at setup).
using System;
using System.Collections.Generic;
using UnityEngine;

namespace Smg.Unity
{
    sealed class SmgRigPose
    {
        readonly Transform[] bones;
        readonly Quaternion[] restRotation;   // relative to the character
        readonly Quaternion[] restLocal;      // the bone's own local rotation at setup
        readonly Vector3 rootRestLocalPosition;
        readonly int[] parents;
        readonly float[] rotations, world;
        readonly float[] rootTranslation = new float[3];

        /// <summary>Joints mapped to a bone, and through the avatar.</summary>
        public int MappedCount { get; }
        public bool ThroughAvatar { get; }

        public SmgRigPose(SmgGraph graph, Transform character, Transform skeletonRoot, Animator avatar,
                          List<SmgBoneOverride> overrides)
        {
            int n = graph.JointCount;
            parents = new int[n];
            rotations = new float[4 * n];
            world = new float[4 * n];
            restRotation = new Quaternion[n];
            restLocal = new Quaternion[n];
            var byName = new Dictionary<string, Transform>();
            foreach (Transform t in skeletonRoot.GetComponentsInChildren<Transform>(true))
                if (!byName.ContainsKey(t.name))
                    byName.Add(t.name, t);
            var byOverride = new Dictionary<string, Transform>();
            foreach (SmgBoneOverride o in overrides)
                if (o.bone != null && !string.IsNullOrEmpty(o.joint))
                    byOverride[o.joint] = o.bone;
            ThroughAvatar = avatar != null && avatar.isHuman;
            Func<SmgHumanBone, Transform> humanoid = null;
            if (ThroughAvatar)
                humanoid = h => avatar.GetBoneTransform((HumanBodyBones)(int)h);
            bones = SmgHumanoid.MapBones(graph, j => Find(byOverride, j), humanoid, j => Find(byName, j));
            Quaternion toCharacter = Quaternion.Inverse(character.rotation);
            for (int j = 0; j < n; ++j)
            {
                parents[j] = graph.GetJoint(j).Parent;
                if (bones[j] == null)
                    continue;
                ++MappedCount;
                restRotation[j] = toCharacter * bones[j].rotation;
                restLocal[j] = bones[j].localRotation;
            }
            if (bones[0] != null)
                rootRestLocalPosition = bones[0].localPosition;
        }

        public bool HasRoot => bones[0] != null;

        /// <summary>Writes the character's pose: `weights` per joint (1:
        /// libsmg's), `engineAnimates`: the bones hold this frame's engine
        /// pose (else the rest pose is blended with), `heightOffset` added
        /// to libsmg's heights.</summary>
        public void Apply(SmgCharacter character, float[] weights, bool engineAnimates, float heightOffset)
        {
            character.GetLocalPose(rootTranslation, rotations);
            SmgMirrorX.WorldRotations(rotations, parents, world);
            for (int j = 0; j < bones.Length; ++j)
            {
                Transform bone = bones[j];
                float w = weights[j];
                if (bone == null || w <= 0.0f)
                    continue;
                int i = 4 * j;
                Quaternion target = new Quaternion(world[i], world[i + 1], world[i + 2], world[i + 3]) * restRotation[j];
                if (w >= 1.0f)
                {
                    bone.rotation = target;
                    continue;
                }
                Transform parent = bone.parent;
                Quaternion targetLocal = parent != null ? Quaternion.Inverse(parent.rotation) * target : target;
                Quaternion source = engineAnimates ? bone.localRotation : restLocal[j];
                bone.localRotation = Quaternion.Slerp(source, targetLocal, w);
            }
            Transform root = bones[0];
            if (root == null || weights[0] <= 0.0f)
                return;
            Vector3 position = new Vector3(-rootTranslation[0], heightOffset + rootTranslation[1], rootTranslation[2]);
            if (weights[0] >= 1.0f)
            {
                root.position = position;
                return;
            }
            Vector3 local = root.parent != null ? root.parent.InverseTransformPoint(position) : position;
            root.localPosition = Vector3.Lerp(engineAnimates ? root.localPosition : rootRestLocalPosition, local, weights[0]);
        }

        static Transform Find(Dictionary<string, Transform> bones, string joint)
        {
            return bones.TryGetValue(joint, out Transform t) ? t : null;
        }
    }
}
