// Per-joint weights for blending libsmg's pose with the engine's own
// animation, like an avatar mask: each joint's weight says how much of
// its rotation comes from libsmg (1) rather than the engine (0). A preset
// by body part (smg_joint_info.body_part: the root, the legs and the upper
// body), scaled by an overall weight, with exact weights for named joints
// on top.
using System;
using System.Collections.Generic;

namespace Smg
{
    /// <summary>Which body parts take libsmg's pose.</summary>
    public enum SmgBodyMask
    {
        /// <summary>Every joint.</summary>
        FullBody = 0,
        /// <summary>Root and legs (SMG_BODY_ROOT, SMG_BODY_LOWER); the
        /// upper body stays the engine's (aiming, hit reactions).</summary>
        LowerBody = 1,
        /// <summary>The upper body only (SMG_BODY_UPPER): libsmg's actions
        /// over the engine's locomotion.</summary>
        UpperBody = 2,
    }

    public static class SmgBoneMask
    {
        /// <summary>The weight of every joint of `graph`: `weight` (0..1)
        /// where `mask` takes libsmg's pose, 0 elsewhere; `jointWeights`
        /// (joint name, weight) replace the weights of the joints they
        /// name. A name the graph lacks throws ArgumentException.</summary>
        public static float[] Build(SmgGraph graph, SmgBodyMask mask, float weight,
                                    IEnumerable<KeyValuePair<string, float>> jointWeights = null)
        {
            if (graph == null)
                throw new ArgumentNullException(nameof(graph));
            CheckWeight(weight, "weight");
            var weights = new float[graph.JointCount];
            for (int j = 0; j < weights.Length; ++j)
            {
                SmgBodyPart part = graph.GetJoint(j).BodyPart;
                bool fromLibsmg = mask == SmgBodyMask.FullBody
                                  || (mask == SmgBodyMask.LowerBody && part != SmgBodyPart.Upper)
                                  || (mask == SmgBodyMask.UpperBody && part == SmgBodyPart.Upper);
                weights[j] = fromLibsmg ? weight : 0.0f;
            }
            if (jointWeights != null)
                foreach (KeyValuePair<string, float> jw in jointWeights)
                {
                    if (jw.Key == null || !graph.TryFindJoint(jw.Key, out int j))
                        throw new ArgumentException("the graph has no joint \"" + jw.Key + "\" to weigh", nameof(jointWeights));
                    CheckWeight(jw.Value, jw.Key);
                    weights[j] = jw.Value;
                }
            return weights;
        }

        static void CheckWeight(float w, string what)
        {
            if (!(w >= 0.0f && w <= 1.0f))
                throw new ArgumentOutOfRangeException(what, w, "a weight is between 0 and 1");
        }
    }
}
