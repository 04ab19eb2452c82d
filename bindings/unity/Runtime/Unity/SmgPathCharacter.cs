// A character that follows a path with libsmg: loads a graph (a TextAsset
// or a file in StreamingAssets, shared through SmgGraphCache), steps one
// SmgCharacter per frame, moves the GameObject by the character's root
// motion and poses a Transform hierarchy found by bone name.
//
// Frames: libsmg is right-handed (Y up, heading 0 faces +Z), Unity is
// left-handed; everything crossing between them is mirrored in X (points
// (x, y, z) <-> (-x, y, z), rotations through SmgMirrorX, headings
// negated), so a left foot stays a left foot.
//
// Retargeting: each mapped bone gets libsmg's world rotation for its joint
// times the bone's own rotation in the rig's rest pose, recorded when the
// component starts. The rig must therefore stand in the blob skeleton's
// rest pose (all joint rotations identity: for BVH data the zero pose,
// usually a T-pose) and face its GameObject's +Z at Start. Bones of any
// local axes work; unmapped joints still pass their rotation to children.
// Sizes are libsmg's (metres): bake the blob from a skeleton of the rig's
// proportions.
using System;
using System.Collections.Generic;
using UnityEngine;

namespace Smg.Unity
{
    /// <summary>A transition (style) or splice (action) point.</summary>
    [Serializable]
    public struct SmgPathMarker
    {
        [Tooltip("Metres along the path from its first point.")]
        public float arcLength;

        [Tooltip("Style name for a transition, action name for a splice (\"none\" ends an action).")]
        public string name;
    }

    /// <summary>Maps a libsmg joint to a bone whose name differs.</summary>
    [Serializable]
    public struct SmgBoneOverride
    {
        public string joint;
        public Transform bone;
    }

    [DisallowMultipleComponent]
    public sealed class SmgPathCharacter : MonoBehaviour
    {
        [Header("Graph (set one)")]
        [Tooltip("A graph blob imported as NAME.smg.bytes.")]
        public TextAsset graphAsset;

        [Tooltip("A graph blob path relative to StreamingAssets (desktop and editor).")]
        public string streamingAssetsFile;

        [Header("Skeleton")]
        [Tooltip("Searched for bones named like the graph's joints.")]
        public Transform skeletonRoot;

        [Tooltip("Joints whose bone has another name.")]
        public List<SmgBoneOverride> boneOverrides = new List<SmgBoneOverride>();

        [Tooltip("Move and turn this GameObject with the character; off: only the bones move.")]
        public bool applyRootMotion = true;

        [Header("Path (world space)")]
        [Tooltip("Path taken from this line; used instead of Path Points when set.")]
        public LineRenderer pathLine;

        [Tooltip("Follow the line while it is drawn (points added are appended, a shorter line replaces the path).")]
        public bool followLineChanges = true;

        public List<Vector3> pathPoints = new List<Vector3>();

        [Header("Style and action")]
        [Tooltip("Locomotion style at the start (empty: the graph's first).")]
        public string style;

        [Tooltip("Upper-body action at the start (empty: none).")]
        public string action;

        [Tooltip("From each point on, the legs use the named style.")]
        public List<SmgPathMarker> transitions = new List<SmgPathMarker>();

        [Tooltip("From each point on, the upper body does the named action.")]
        public List<SmgPathMarker> splices = new List<SmgPathMarker>();

        [Header("Character")]
        public int seed;
        public bool footIk = true;

        [Tooltip("Maximum path points; 0 = 512.")]
        public int pathCapacity;

        [Tooltip("Planning look-ahead in seconds; 0 = 2.")]
        public float horizon;

        [Tooltip("Search distance-error threshold in metres; 0 = 0.25.")]
        public float errorThreshold;

        /// <summary>The shared graph and this component's character
        /// (null before Start and after destruction).</summary>
        public SmgGraph Graph { get; private set; }
        public SmgCharacter Character { get; private set; }

        /// <summary>The character's state after this frame's step.</summary>
        public SmgCharacterState State { get; private set; }

        Transform[] bones;
        Quaternion[] restRotation;
        float[] world;
        int[] parents;
        readonly float[] rootTranslation = new float[3];
        float[] rotations;
        float[] pathXz = new float[0];
        Vector3[] lineBuffer = new Vector3[0];
        int linePointsSent;
        float groundY;
        readonly List<SmgPathMarker> pendingTransitions = new List<SmgPathMarker>();
        readonly List<SmgPathMarker> pendingSplices = new List<SmgPathMarker>();
        SmgFailOnce frameGuard;
        Action stepFrame;

        void Start()
        {
            frameGuard = new SmgFailOnce(e => Debug.LogError(name + ": SmgPathCharacter stopped: " + e, this));
            stepFrame = StepFrame;
            Graph = LoadGraph();
            MapBones();
            Character = SmgCharacter.Create(Graph, Desc());
            groundY = transform.position.y;
            pendingTransitions.AddRange(transitions);
            pendingSplices.AddRange(splices);
            if (pathLine != null)
                SyncLine();
            else if (pathPoints.Count > 0)
                SetPath(pathPoints);
        }

        void OnDestroy()
        {
            if (Character != null)
                Character.Dispose();
            if (Graph != null)
                SmgGraphCache.Release(Graph);
            Character = null;
            Graph = null;
        }

        // A failure (a bad marker name, a path libsmg refuses, ...) is
        // logged once and disables the component, instead of throwing again
        // every frame.
        void Update()
        {
            if (Character == null)
                return;
            if (!frameGuard.Run(stepFrame))
                enabled = false;
        }

        void StepFrame()
        {
            if (pathLine != null && followLineChanges)
                SyncLine();
            AddReachedMarkers();
            Character.Step(Mathf.Clamp(Time.deltaTime, 0.0f, 1.0f));
            State = Character.State;
            if (applyRootMotion)
            {
                SmgFloat3 p = State.Position;
                transform.SetPositionAndRotation(new Vector3(-p.X, groundY, p.Z),
                                                 Quaternion.Euler(0.0f, SmgMirrorX.HeadingToYawDegrees(State.Heading), 0.0f));
            }
        }

        // After Update (and after an Animator on the same rig), so the
        // libsmg pose is the one rendered.
        void LateUpdate()
        {
            if (Character == null)
                return;
            Character.GetLocalPose(rootTranslation, rotations);
            SmgMirrorX.WorldRotations(rotations, parents, world);
            for (int j = 0; j < bones.Length; ++j)
            {
                int i = 4 * j;
                if (bones[j] != null)
                    bones[j].rotation = new Quaternion(world[i], world[i + 1], world[i + 2], world[i + 3]) * restRotation[j];
            }
            if (bones[0] != null)
                bones[0].position = new Vector3(-rootTranslation[0], groundY + rootTranslation[1], rootTranslation[2]);
        }

        // --- Path, styles and actions from gameplay code ---

        /// <summary>Replaces the path (world-space points; y is ignored).</summary>
        public void SetPath(IReadOnlyList<Vector3> points)
        {
            Character.SetPath(ToXz(points, 0, points.Count));
        }

        /// <summary>Adds points to the end of the path.</summary>
        public void AppendPath(IReadOnlyList<Vector3> points)
        {
            Character.AppendPath(ToXz(points, 0, points.Count));
        }

        /// <summary>From arcLength on, the legs use `styleName`.</summary>
        public uint AddTransition(float arcLength, string styleName)
        {
            return Character.AddTransition(arcLength, Graph.FindStyle(styleName));
        }

        /// <summary>From arcLength on, the upper body does `actionName`.</summary>
        public uint AddSplice(float arcLength, string actionName)
        {
            return Character.AddSplice(arcLength, Graph.FindAction(actionName));
        }

        public void SetStyle(string styleName)
        {
            Character.SetStyle(Graph.FindStyle(styleName));
        }

        public void SetAction(string actionName)
        {
            Character.SetAction(Graph.FindAction(actionName));
        }

        // --- Setup ---

        SmgGraph LoadGraph()
        {
            if (graphAsset != null)
                return SmgGraphCache.Acquire(graphAsset);
            if (!string.IsNullOrEmpty(streamingAssetsFile))
                return SmgGraphCache.AcquireStreamingAsset(streamingAssetsFile);
            throw new InvalidOperationException(name + ": SmgPathCharacter needs a Graph Asset or a Streaming Assets File");
        }

        void MapBones()
        {
            int n = Graph.JointCount;
            bones = new Transform[n];
            restRotation = new Quaternion[n];
            world = new float[4 * n];
            parents = new int[n];
            rotations = new float[4 * n];
            var byName = new Dictionary<string, Transform>();
            Transform root = skeletonRoot != null ? skeletonRoot : transform;
            foreach (Transform t in root.GetComponentsInChildren<Transform>(true))
                if (!byName.ContainsKey(t.name))
                    byName.Add(t.name, t);
            foreach (SmgBoneOverride o in boneOverrides)
                if (o.bone != null && !string.IsNullOrEmpty(o.joint))
                    byName[o.joint] = o.bone;
            Quaternion toCharacter = Quaternion.Inverse(transform.rotation);
            for (int j = 0; j < n; ++j)
            {
                SmgJoint joint = Graph.GetJoint(j);
                parents[j] = joint.Parent;
                Transform bone;
                if (byName.TryGetValue(joint.Name, out bone))
                {
                    bones[j] = bone;
                    restRotation[j] = toCharacter * bone.rotation;
                }
            }
            if (bones[0] == null)
                Debug.LogWarning(name + ": no bone for the root joint \"" + Graph.GetJoint(0).Name
                                 + "\" under " + root.name + ": add a bone override", this);
        }

        SmgCharacterDesc Desc()
        {
            SmgCharacterDesc d = SmgCharacterDesc.Create();
            d.Flags = footIk ? SmgCharacterFlags.None : SmgCharacterFlags.NoIk;
            d.Seed = (uint)seed;
            d.PathCapacity = (uint)Mathf.Max(0, pathCapacity);
            d.Horizon = horizon;
            d.ErrorThreshold = errorThreshold;
            Vector3 p = transform.position;
            d.Position = new SmgFloat3(-p.x, 0.0f, p.z);
            d.Heading = SmgMirrorX.YawDegreesToHeading(transform.eulerAngles.y);
            if (!string.IsNullOrEmpty(style))
                d.InitialStyle = Graph.FindStyle(style);
            if (!string.IsNullOrEmpty(action))
                d.InitialAction = Graph.FindAction(action);
            return d;
        }

        // --- Path plumbing ---

        // Mirrored (x, z) pairs in a reused buffer (grows, never shrinks).
        ReadOnlySpan<float> ToXz(IReadOnlyList<Vector3> points, int first, int count)
        {
            if (pathXz.Length < 2 * count)
                pathXz = new float[Mathf.NextPowerOfTwo(2 * count)];
            for (int i = 0; i < count; ++i)
            {
                Vector3 p = points[first + i];
                pathXz[2 * i] = -p.x;
                pathXz[2 * i + 1] = p.z;
            }
            return new ReadOnlySpan<float>(pathXz, 0, 2 * count);
        }

        void SyncLine()
        {
            int n = pathLine.positionCount;
            if (n == linePointsSent)
                return;
            if (lineBuffer.Length < n)
                lineBuffer = new Vector3[Mathf.NextPowerOfTwo(n)];
            pathLine.GetPositions(lineBuffer);
            if (!pathLine.useWorldSpace)
                for (int i = 0; i < n; ++i)
                    lineBuffer[i] = pathLine.transform.TransformPoint(lineBuffer[i]);
            if (n > linePointsSent && linePointsSent > 0)
                Character.AppendPath(ToXz(lineBuffer, linePointsSent, n - linePointsSent));
            else
                Character.SetPath(ToXz(lineBuffer, 0, n));
            linePointsSent = n;
        }

        // libsmg takes points only within the current path: markers wait
        // until a path being drawn has grown past them.
        void AddReachedMarkers()
        {
            if (pendingTransitions.Count == 0 && pendingSplices.Count == 0)
                return;
            float length = Character.PathLength;
            for (int i = pendingTransitions.Count - 1; i >= 0; --i)
            {
                if (pendingTransitions[i].arcLength > length)
                    continue;
                AddTransition(pendingTransitions[i].arcLength, pendingTransitions[i].name);
                pendingTransitions.RemoveAt(i);
            }
            for (int i = pendingSplices.Count - 1; i >= 0; --i)
            {
                if (pendingSplices[i].arcLength > length)
                    continue;
                AddSplice(pendingSplices[i].arcLength, pendingSplices[i].name);
                pendingSplices.RemoveAt(i);
            }
        }

        // The markers on the path, in the scene view.
        void OnDrawGizmosSelected()
        {
            List<Vector3> points = GizmoPath();
            if (points.Count < 2)
                return;
            Gizmos.color = Color.cyan;
            foreach (SmgPathMarker m in transitions)
                Gizmos.DrawWireSphere(PointAt(points, m.arcLength), 0.25f);
            Gizmos.color = Color.magenta;
            foreach (SmgPathMarker m in splices)
                Gizmos.DrawWireCube(PointAt(points, m.arcLength), new Vector3(0.4f, 0.4f, 0.4f));
        }

        List<Vector3> GizmoPath()
        {
            if (pathLine == null)
                return pathPoints;
            var points = new List<Vector3>(pathLine.positionCount);
            for (int i = 0; i < pathLine.positionCount; ++i)
            {
                Vector3 p = pathLine.GetPosition(i);
                points.Add(pathLine.useWorldSpace ? p : pathLine.transform.TransformPoint(p));
            }
            return points;
        }

        // The point at `arc` metres along a polyline, measured on the ground
        // like libsmg does.
        static Vector3 PointAt(List<Vector3> points, float arc)
        {
            for (int i = 1; i < points.Count; ++i)
            {
                Vector3 a = points[i - 1], b = points[i];
                float len = new Vector2(b.x - a.x, b.z - a.z).magnitude;
                if (arc <= len && len > 0.0f)
                    return Vector3.Lerp(a, b, arc / len);
                arc -= len;
            }
            return points[points.Count - 1];
        }
    }
}
