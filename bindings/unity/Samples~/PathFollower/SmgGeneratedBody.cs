// The sample's skinned character, generated from the graph's skeleton so
// the sample needs no model file and works with any graph: at Awake (before
// SmgPathCharacter maps bones by name at Start) one Transform per joint,
// named like it, at its rest offset with an identity rotation (the blob's
// rest pose), and a skinned mesh of one box per bone segment, each box
// weighted to the bone it hangs from. X is mirrored like everything that
// crosses from libsmg to Unity (SmgPathCharacter's header says why).
using Smg.Unity;
using UnityEngine;

namespace Smg.Samples
{
    [RequireComponent(typeof(SmgPathCharacter))]
    public sealed class SmgGeneratedBody : MonoBehaviour
    {
        [Tooltip("Box thickness as a fraction of the segment's length (at least 3 cm).")]
        public float thickness = 0.25f;

        [Tooltip("Body material; empty: a lit material of the active render pipeline.")]
        public Material material;

        SmgGraph graph;

        void Awake()
        {
            SmgPathCharacter character = GetComponent<SmgPathCharacter>();
            if (character.graphAsset == null)
            {
                Debug.LogError(name + ": SmgGeneratedBody needs the character's Graph Asset", this);
                return;
            }
            graph = SmgGraphCache.Acquire(character.graphAsset); // shared with the character
            Build();
        }

        void OnDestroy()
        {
            if (graph != null)
                SmgGraphCache.Release(graph);
            graph = null;
        }

        void Build()
        {
            int n = graph.JointCount;
            var bones = new Transform[n];
            var rest = new Vector3[n]; // joint positions in this object's space
            for (int j = 0; j < n; ++j)
            {
                SmgJoint joint = graph.GetJoint(j);
                var offset = new Vector3(-joint.RestOffset.X, joint.RestOffset.Y, joint.RestOffset.Z);
                Transform bone = new GameObject(joint.Name).transform;
                bone.SetParent(joint.Parent < 0 ? transform : bones[joint.Parent], false);
                bone.localPosition = offset;
                bone.localRotation = Quaternion.identity;
                bones[j] = bone;
                rest[j] = joint.Parent < 0 ? offset : rest[joint.Parent] + offset;
            }

            var vertices = new Vector3[8 * n];
            var weights = new BoneWeight[8 * n];
            var triangles = new int[36 * n];
            int v = 0, t = 0;
            for (int j = 1; j < n; ++j)
            {
                int parent = graph.GetJoint(j).Parent;
                if (parent < 0)
                    continue;
                AddBox(rest[parent], rest[j], parent, vertices, weights, triangles, ref v, ref t);
            }

            var bindposes = new Matrix4x4[n];
            for (int j = 0; j < n; ++j)
                bindposes[j] = bones[j].worldToLocalMatrix * transform.localToWorldMatrix;
            var mesh = new Mesh { name = "libsmg body" };
            System.Array.Resize(ref vertices, v);
            System.Array.Resize(ref weights, v);
            System.Array.Resize(ref triangles, t);
            mesh.vertices = vertices;
            mesh.boneWeights = weights;
            mesh.triangles = triangles;
            mesh.bindposes = bindposes;
            mesh.RecalculateNormals();
            mesh.RecalculateBounds();

            var skin = gameObject.AddComponent<SkinnedMeshRenderer>();
            skin.sharedMesh = mesh;
            skin.bones = bones;
            skin.rootBone = bones[0];
            skin.updateWhenOffscreen = true; // the root moves far from the bind pose
            skin.sharedMaterial = material != null ? material : DefaultMaterial();
        }

        // A box around the segment a -> b, all eight corners on one bone.
        void AddBox(Vector3 a, Vector3 b, int bone, Vector3[] vertices, BoneWeight[] weights, int[] triangles,
                    ref int v, ref int t)
        {
            Vector3 axis = b - a;
            float length = axis.magnitude;
            if (length < 1e-4f)
                return;
            Vector3 dir = axis * (1.0f / length);
            Vector3 side = Vector3.Cross(dir, Mathf.Abs(dir.y) < 0.9f ? Vector3.up : Vector3.right).normalized;
            Vector3 front = Vector3.Cross(side, dir);
            float h = 0.5f * Mathf.Max(0.03f, thickness * length);
            int first = v;
            for (int end = 0; end < 2; ++end)
                for (int corner = 0; corner < 4; ++corner)
                {
                    float s = corner == 0 || corner == 3 ? -h : h;
                    float f = corner < 2 ? -h : h;
                    vertices[v] = (end == 0 ? a : b) + side * s + front * f;
                    weights[v] = new BoneWeight { boneIndex0 = bone, weight0 = 1.0f };
                    ++v;
                }
            int[] faces =
            {
                0, 2, 1, 0, 3, 2, // end a
                4, 5, 6, 4, 6, 7, // end b
                0, 1, 5, 0, 5, 4,
                1, 2, 6, 1, 6, 5,
                2, 3, 7, 2, 7, 6,
                3, 0, 4, 3, 4, 7,
            };
            // listed counter-clockwise seen from outside: Unity's front
            // faces are clockwise, so each triangle goes in reversed
            for (int k = 0; k < faces.Length; k += 3)
            {
                triangles[t++] = first + faces[k];
                triangles[t++] = first + faces[k + 2];
                triangles[t++] = first + faces[k + 1];
            }
        }

        static Material DefaultMaterial()
        {
            Shader shader = Shader.Find("Universal Render Pipeline/Lit");
            if (shader == null)
                shader = Shader.Find("HDRP/Lit");
            if (shader == null)
                shader = Shader.Find("Standard");
            return shader != null ? new Material(shader) : null;
        }
    }
}
