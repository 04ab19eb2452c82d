// Which humanoid bone each joint of a graph is, and the rig bone of each
// joint: through the rig's humanoid avatar when it has one (Unity:
// Animator.GetBoneTransform), else by name. The graph's joints are
// recognised from their names - a baked graph's skeleton is the target
// rig's or the clips', whose names the baker itself recognised - by the
// body-part word after dropping the side (Left/Right/L/R), digits, a
// "ns:" namespace and rig prefixes (mixamorig, Bip, VRoid's J_Bip_C_,
// Character1_, DEF-/ORG-); legs and arms must then follow their chain
// order. The spine is found from the structure: the joints between the
// hips and the neck are Spine, Chest and (the last of three or more)
// UpperChest. The rig's own bone names do not matter on the avatar path.
using System;
using System.Collections.Generic;
using System.Text;

namespace Smg
{
    public static class SmgHumanoid
    {
        struct Kind
        {
            public SmgHumanBone Left, Right; // the same for unsided bones
            public string[] Words;           // body-part words, preferred first
        }

        static readonly Kind[] Kinds =
        {
            Unsided(SmgHumanBone.Hips, "hips", "pelvis", "hip"),
            Unsided(SmgHumanBone.Neck, "neck"),
            Unsided(SmgHumanBone.Head, "head"),
            Sided(SmgHumanBone.LeftUpperLeg, SmgHumanBone.RightUpperLeg, "upleg", "upperleg", "thigh", "legupper", "femur", "hip"),
            Sided(SmgHumanBone.LeftLowerLeg, SmgHumanBone.RightLowerLeg, "leg", "lowerleg", "knee", "calf", "shin", "leglower", "lowleg", "shank"),
            Sided(SmgHumanBone.LeftFoot, SmgHumanBone.RightFoot, "foot", "ankle"),
            Sided(SmgHumanBone.LeftToes, SmgHumanBone.RightToes, "toebase", "toes", "toe", "ball"),
            Sided(SmgHumanBone.LeftShoulder, SmgHumanBone.RightShoulder, "shoulder", "clavicle", "collar"),
            Sided(SmgHumanBone.LeftUpperArm, SmgHumanBone.RightUpperArm, "arm", "upperarm", "uparm", "armupper", "humerus"),
            Sided(SmgHumanBone.LeftLowerArm, SmgHumanBone.RightLowerArm, "forearm", "lowerarm", "elbow", "armlower", "lowarm"),
            Sided(SmgHumanBone.LeftHand, SmgHumanBone.RightHand, "hand", "wrist"),
        };

        static readonly string[] RigPrefixes = { "mixamorig", "bip", "j", "c", "character", "def", "org" };

        // chains that must run from the hips outwards in this order
        static readonly SmgHumanBone[][] Chains =
        {
            new[] { SmgHumanBone.LeftUpperLeg, SmgHumanBone.LeftLowerLeg, SmgHumanBone.LeftFoot, SmgHumanBone.LeftToes },
            new[] { SmgHumanBone.RightUpperLeg, SmgHumanBone.RightLowerLeg, SmgHumanBone.RightFoot, SmgHumanBone.RightToes },
            new[] { SmgHumanBone.LeftShoulder, SmgHumanBone.LeftUpperArm, SmgHumanBone.LeftLowerArm, SmgHumanBone.LeftHand },
            new[] { SmgHumanBone.RightShoulder, SmgHumanBone.RightUpperArm, SmgHumanBone.RightLowerArm, SmgHumanBone.RightHand },
            new[] { SmgHumanBone.Neck, SmgHumanBone.Head },
        };

        /// <summary>The humanoid bone of every joint of `graph` (None for
        /// joints that are none, such as CMU's LHipJoint or fingers).</summary>
        public static SmgHumanBone[] Classify(SmgGraph graph)
        {
            if (graph == null)
                throw new ArgumentNullException(nameof(graph));
            var names = new string[graph.JointCount];
            var parents = new int[graph.JointCount];
            for (int j = 0; j < names.Length; ++j)
            {
                SmgJoint joint = graph.GetJoint(j);
                names[j] = joint.Name;
                parents[j] = joint.Parent;
            }
            return Classify(names, parents);
        }

        /// <summary>The same for a skeleton given by joint names and
        /// parents (parents before children, -1 for roots).</summary>
        public static SmgHumanBone[] Classify(IReadOnlyList<string> names, IReadOnlyList<int> parents)
        {
            if (names == null || parents == null)
                throw new ArgumentNullException(names == null ? nameof(names) : nameof(parents));
            if (names.Count != parents.Count)
                throw new ArgumentException("one parent per joint");
            int n = names.Count;
            var byBone = new Dictionary<SmgHumanBone, int>();
            var rank = new Dictionary<SmgHumanBone, int>();
            for (int j = 0; j < n; ++j)
            {
                if (parents[j] >= j)
                    throw new ArgumentException("parents must come before their children");
                int side = Words(names[j], out string core);
                foreach (Kind kind in Kinds)
                {
                    bool sided = kind.Left != kind.Right;
                    if (sided == (side == 0))
                        continue;
                    int k = Array.IndexOf(kind.Words, core);
                    if (k < 0)
                        continue;
                    SmgHumanBone bone = side > 0 ? kind.Right : kind.Left;
                    // preferred word first; among equals the joint nearest
                    // the root (joints come parents first)
                    if (!rank.TryGetValue(bone, out int r) || k < r)
                    {
                        rank[bone] = k;
                        byBone[bone] = j;
                    }
                }
            }
            foreach (SmgHumanBone[] chain in Chains)
                for (int i = 1; i < chain.Length; ++i)
                    if (byBone.TryGetValue(chain[i], out int j))
                        for (int before = i - 1; before >= 0; --before)
                            if (byBone.TryGetValue(chain[before], out int a))
                            {
                                if (!IsAbove(parents, a, j))
                                    byBone.Remove(chain[i]); // better missing than wrong
                                break;
                            }
            PlaceHipsAndSpine(parents, byBone);
            var bones = new SmgHumanBone[n];
            for (int j = 0; j < n; ++j)
                bones[j] = SmgHumanBone.None;
            foreach (var entry in byBone)
                bones[entry.Value] = entry.Key;
            return bones;
        }

        // Hips: the named joint if it is above both legs, else the lowest
        // common ancestor of the legs and the neck. Spine, Chest, UpperChest:
        // the joints strictly between the hips and the neck (or head).
        static void PlaceHipsAndSpine(IReadOnlyList<int> parents, Dictionary<SmgHumanBone, int> byBone)
        {
            int left = Get(byBone, SmgHumanBone.LeftUpperLeg), right = Get(byBone, SmgHumanBone.RightUpperLeg);
            int top = byBone.ContainsKey(SmgHumanBone.Neck) ? byBone[SmgHumanBone.Neck] : Get(byBone, SmgHumanBone.Head);
            int hips = Get(byBone, SmgHumanBone.Hips);
            if (hips >= 0 && !((left < 0 || IsAbove(parents, hips, left)) && (right < 0 || IsAbove(parents, hips, right))))
                hips = -1;
            if (hips < 0)
                hips = CommonAncestor(parents, CommonAncestor(parents, left, right), top);
            byBone.Remove(SmgHumanBone.Hips);
            if (hips < 0)
                return;
            byBone[SmgHumanBone.Hips] = hips;
            if (top < 0 || !IsAbove(parents, hips, top))
                return;
            var spine = new List<int>();
            for (int j = parents[top]; j != hips; j = parents[j])
                spine.Insert(0, j);
            if (spine.Count >= 1)
                byBone[SmgHumanBone.Spine] = spine[0];
            if (spine.Count >= 2)
                byBone[SmgHumanBone.Chest] = spine[1];
            if (spine.Count >= 3)
                byBone[SmgHumanBone.UpperChest] = spine[spine.Count - 1];
        }

        /// <summary>The rig bone of every joint of `graph`: `overrides`
        /// (by joint name) first, then the rig's humanoid bone of the
        /// joint's humanoid bone (`humanoid`, null when the rig has no
        /// avatar), then `byName` (the rig bone named like the joint). A rig
        /// bone is given to one joint only; null where none is found.</summary>
        public static T[] MapBones<T>(SmgGraph graph, Func<string, T> overrides, Func<SmgHumanBone, T> humanoid,
                                      Func<string, T> byName) where T : class
        {
            if (graph == null)
                throw new ArgumentNullException(nameof(graph));
            SmgHumanBone[] roles = humanoid != null ? Classify(graph) : null;
            var bones = new T[graph.JointCount];
            var used = new HashSet<T>();
            for (int pass = 0; pass < 3; ++pass)
                for (int j = 0; j < bones.Length; ++j)
                {
                    if (bones[j] != null)
                        continue;
                    string name = graph.GetJoint(j).Name;
                    T bone = null;
                    if (pass == 0 && overrides != null)
                        bone = overrides(name);
                    else if (pass == 1 && roles != null && roles[j] != SmgHumanBone.None)
                        bone = humanoid(roles[j]);
                    else if (pass == 2 && byName != null)
                        bone = byName(name);
                    if (bone != null && used.Add(bone))
                        bones[j] = bone;
                }
            return bones;
        }

        // --- names ---

        // Splits a name into words (at _ . - space, camelCase and digit
        // runs, after a "ns:" namespace), returns the side (-1 left, 1
        // right, 0 none: the first side word) and the other words, minus
        // digits and rig prefixes, lower case and joined ("LeftUpLeg" ->
        // left, "upleg").
        static int Words(string name, out string core)
        {
            int colon = name.LastIndexOf(':');
            string s = colon >= 0 ? name.Substring(colon + 1) : name;
            var sb = new StringBuilder();
            int side = 0, i = 0;
            while (i < s.Length)
            {
                while (i < s.Length && IsSeparator(s[i]))
                    ++i;
                if (i >= s.Length)
                    break;
                int b = i++;
                if (char.IsDigit(s[b]))
                {
                    while (i < s.Length && char.IsDigit(s[i]))
                        ++i;
                    continue; // digits say nothing of the body part
                }
                while (i < s.Length && !IsSeparator(s[i]) && !char.IsDigit(s[i]))
                {
                    // "upLeg": lower -> upper starts a word; "LHip": the last
                    // capital of a run starts one when lower case follows
                    if (char.IsUpper(s[i]) && char.IsLower(s[i - 1]))
                        break;
                    if (char.IsUpper(s[i]) && char.IsUpper(s[i - 1]) && i + 1 < s.Length && char.IsLower(s[i + 1]))
                        break;
                    ++i;
                }
                string word = s.Substring(b, i - b).ToLowerInvariant();
                int wordSide = word == "left" || word == "l" ? -1 : word == "right" || word == "r" ? 1 : 0;
                if (wordSide != 0 && side == 0)
                    side = wordSide;
                else if (Array.IndexOf(RigPrefixes, word) < 0)
                    sb.Append(word);
            }
            core = sb.ToString();
            return side;
        }

        static bool IsSeparator(char c)
        {
            return c == '_' || c == '.' || c == '-' || c == ' ' || c == '\t';
        }

        // --- structure ---

        static int Get(Dictionary<SmgHumanBone, int> byBone, SmgHumanBone bone)
        {
            return byBone.TryGetValue(bone, out int j) ? j : -1;
        }

        // a strictly above j
        static bool IsAbove(IReadOnlyList<int> parents, int a, int j)
        {
            if (a < 0 || j < 0)
                return false;
            for (j = parents[j]; j >= 0; j = parents[j])
                if (j == a)
                    return true;
            return false;
        }

        static int CommonAncestor(IReadOnlyList<int> parents, int a, int b)
        {
            if (a < 0 || b < 0)
                return -1;
            for (; a >= 0; a = parents[a])
                if (a == b || IsAbove(parents, a, b))
                    return a;
            return -1;
        }

        static Kind Unsided(SmgHumanBone bone, params string[] words)
        {
            return new Kind { Left = bone, Right = bone, Words = words };
        }

        static Kind Sided(SmgHumanBone left, SmgHumanBone right, params string[] words)
        {
            return new Kind { Left = left, Right = right, Words = words };
        }
    }
}
