// A character that follows a path with libsmg: loads a graph (a TextAsset
// or a file in StreamingAssets, shared through SmgGraphCache), steps one
// SmgCharacter per frame and poses a rig (SmgRigPose: bones through the
// Humanoid avatar or by name, blended with the engine's animation by a
// per-joint mask). Who moves the GameObject is the Root Motion mode: the
// library (its ground position each frame), the engine's mover (libsmg's
// root motion goes to a CharacterController, or through OnAnimatorMove
// when an Animator applies root motion, and where the mover ended up is
// told back), or nobody (only the bones move). Uneven ground is measured by
// ray casts before each step (SmgGroundSensor). What happened in a step
// (constraints reached, footsteps, the path's end) is raised as C# events
// after it, on the main thread.
//
// Frames: libsmg is right-handed (Y up, heading 0 faces +Z), Unity is
// left-handed; everything crossing between them is mirrored in X (points
// (x, y, z) <-> (-x, y, z), rotations through SmgMirrorX, headings
// negated), so a left foot stays a left foot.
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

    /// <summary>A joint's weight in the blend with the engine's animation.</summary>
    [Serializable]
    public struct SmgJointWeight
    {
        public string joint;

        [Range(0.0f, 1.0f)]
        public float weight;
    }

    /// <summary>Who moves the GameObject.</summary>
    public enum SmgRootMotionMode
    {
        /// <summary>libsmg: the GameObject is placed at the character's
        /// ground position and heading each frame.</summary>
        Library = 0,
        /// <summary>The engine's mover: each step's root motion goes to a
        /// CharacterController (or the Transform), through OnAnimatorMove
        /// when an Animator applies root motion; the resulting position and
        /// heading are told back to libsmg.</summary>
        EngineMover = 1,
        /// <summary>Nobody: only the bones move.</summary>
        Off = 2,
    }

    [DisallowMultipleComponent]
    public sealed class SmgPathCharacter : MonoBehaviour, ISmgEventHandler
    {
        [Header("Graph (set one)")]
        [Tooltip("A graph blob imported as NAME.smg.bytes.")]
        public TextAsset graphAsset;

        [Tooltip("A graph blob path relative to StreamingAssets (desktop and editor).")]
        public string streamingAssetsFile;

        [Header("Skeleton")]
        [Tooltip("Searched for bones named like the graph's joints.")]
        public Transform skeletonRoot;

        [Tooltip("Joints whose bone has another name (these win over the avatar and names).")]
        public List<SmgBoneOverride> boneOverrides = new List<SmgBoneOverride>();

        [Tooltip("Map bones through the Animator's Humanoid avatar when it has one (names for the rest).")]
        public bool useHumanoidAvatar = true;

        [Header("Movement")]
        [Tooltip("Library: libsmg moves this GameObject. Engine Mover: a CharacterController (or the Transform) is moved by libsmg's root motion and collides; libsmg continues from where it ends up. Off: only the bones move.")]
        public SmgRootMotionMode rootMotion = SmgRootMotionMode.Library;

        [Tooltip("Engine Mover: the CharacterController to move (empty: the one on this GameObject, else the Transform).")]
        public CharacterController characterController;

        [Tooltip("Engine Mover with a CharacterController: fall with Physics.gravity when not grounded.")]
        public bool moverGravity = true;

        [Header("Uneven ground")]
        [Tooltip("Ray cast the ground under the feet and the root before each step; off: a flat floor at the start height.")]
        public bool unevenGround;

        [Tooltip("Layers the ground rays hit (the character's own colliders are skipped).")]
        public LayerMask groundLayers = ~0;

        [Tooltip("Rays start this far above the character's ground height (metres).")]
        public float groundRayAbove = 1.0f;

        [Tooltip("... and reach this far below it (metres).")]
        public float groundRayBelow = 2.0f;

        [Header("Blending with the engine's animation")]
        [Tooltip("Which body parts take libsmg's pose; the others keep the Animator's (its IK included).")]
        public SmgBodyMask bodyMask = SmgBodyMask.FullBody;

        [Tooltip("How much of libsmg's pose the masked joints take.")]
        [Range(0.0f, 1.0f)]
        public float weight = 1.0f;

        [Tooltip("Exact weights for named joints, over the mask.")]
        public List<SmgJointWeight> jointWeights = new List<SmgJointWeight>();

        [Tooltip("The Animator whose pose is blended with (empty: the one on this GameObject).")]
        public Animator animator;

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

        // --- Events, raised after each step on the main thread ---

        /// <summary>A transition (isSplice false: value is a style) or a
        /// splice (an action) took effect: (id from AddTransition /
        /// AddSplice, value, isSplice). id 0: a change no constraint asked
        /// for (SetStyle / SetAction, the steering walking to a stop).</summary>
        public event Action<uint, uint, bool> ConstraintReached;

        /// <summary>A constraint that will never take effect (a later one
        /// of its kind, or SetStyle / SetAction, took over first). Every
        /// constraint gets ConstraintReached or this, once.</summary>
        public event Action<uint, uint, bool> ConstraintSuperseded;

        /// <summary>A foot landed: (0 left, 1 right; the toe's world
        /// position; its downward speed as it landed, m/s).</summary>
        public event Action<int, Vector3, float> Footstep;

        /// <summary>The character arrived at its path's end.</summary>
        public event Action PathEndReached;

        /// <summary>After the pose is written in LateUpdate: run IK that
        /// must act on libsmg's pose (look-at, hand IK) here.</summary>
        public event Action PoseApplied;

        SmgRigPose rig;
        float[] weights;
        SmgEventQueue events;
        SmgGroundSensor ground;
        Vector3 pendingMove;
        float pendingTurn;
        float fallSpeed;
        float[] pathXz = new float[0];
        Vector3[] lineBuffer = new Vector3[0];
        int linePointsSent;
        float groundY;
        readonly List<SmgPathMarker> pendingTransitions = new List<SmgPathMarker>();
        readonly List<SmgPathMarker> pendingSplices = new List<SmgPathMarker>();
        SmgFailOnce frameGuard;
        Action stepFrame, moveFrame;

        void Start()
        {
            frameGuard = new SmgFailOnce(e => Debug.LogError(name + ": SmgPathCharacter stopped: " + e, this));
            stepFrame = StepFrame;
            moveFrame = ApplyMove;
            if (animator == null)
                animator = GetComponent<Animator>();
            if (characterController == null)
                characterController = GetComponent<CharacterController>();
            Graph = LoadGraph();
            MapBones();
            var kv = new List<KeyValuePair<string, float>>();
            foreach (SmgJointWeight jw in jointWeights)
                kv.Add(new KeyValuePair<string, float>(jw.joint, jw.weight));
            weights = SmgBoneMask.Build(Graph, bodyMask, weight, kv);
            SmgCharacterDesc desc = Desc();
            Character = SmgCharacter.Create(Graph, desc);
            events = new SmgEventQueue(desc.ConstraintCapacity);
            groundY = transform.position.y;
            if (WorldHeights)
            {
                // libsmg's heights are then world heights; its start
                // height is not in the descriptor (y is ignored there)
                Vector3 p = transform.position;
                SmgMirrorX.SetGroundPosition(Character, new SmgFloat3(p.x, p.y, p.z), transform.eulerAngles.y);
            }
            if (unevenGround)
                ground = new SmgGroundSensor(groundY);
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
        // every frame. The step's events are raised after it, outside that
        // guard: an exception in a handler is the handler's (Unity logs it),
        // not a reason to stop the character.
        void Update()
        {
            if (Character == null)
                return;
            if (!frameGuard.Run(stepFrame))
            {
                enabled = false;
                return;
            }
            events.Dispatch(this);
        }

        void StepFrame()
        {
            if (pathLine != null && followLineChanges)
                SyncLine();
            AddReachedMarkers();
            if (ground != null)
                ground.Measure(Character, transform, groundLayers, groundRayAbove, groundRayBelow);
            float dt = Mathf.Clamp(Time.deltaTime, 0.0f, 1.0f);
            Character.Step(dt);
            State = Character.State;
            if (rootMotion == SmgRootMotionMode.Library)
            {
                SmgFloat3 p = State.Position;
                transform.SetPositionAndRotation(new Vector3(-p.X, HeightOffset + p.Y, p.Z),
                                                 Quaternion.Euler(0.0f, SmgMirrorX.HeadingToYawDegrees(State.Heading), 0.0f));
            }
            else if (rootMotion == SmgRootMotionMode.EngineMover)
            {
                SmgMirrorX.RootMotion(Character.RootMotion, out SmgFloat3 d, out float turn);
                pendingMove += new Vector3(d.X, d.Y, d.Z);
                pendingTurn += turn;
                if (!AnimatorMoves)
                    ApplyMove();
            }
            events.Read(Character);
        }

        // The Animator calls this after evaluating, before LateUpdate, when
        // it applies root motion: the engine's mover takes libsmg's root
        // motion here; in the other modes the Animator's own root motion is
        // applied only when libsmg does not move the GameObject.
        void OnAnimatorMove()
        {
            if (Character == null || animator == null)
                return;
            if (rootMotion == SmgRootMotionMode.EngineMover)
            {
                if (AnimatorMoves && !frameGuard.Run(moveFrame))
                    enabled = false;
            }
            else if (rootMotion == SmgRootMotionMode.Off)
                animator.ApplyBuiltinRootMotion();
        }

        // The engine's mover: the root motion of the steps since the last
        // move (a CharacterController collides), then where it ended up is
        // libsmg's ground position and heading, so planning and steering go
        // on from there.
        void ApplyMove()
        {
            Vector3 move = pendingMove;
            float turn = pendingTurn;
            pendingMove = Vector3.zero;
            pendingTurn = 0.0f;
            if (characterController != null && characterController.enabled)
            {
                if (moverGravity)
                {
                    float dt = Time.deltaTime;
                    // grounded: a step's worth of gravity keeps it in contact
                    fallSpeed = characterController.isGrounded ? Physics.gravity.y * dt : fallSpeed + Physics.gravity.y * dt;
                    move.y += fallSpeed * dt;
                }
                characterController.Move(move);
            }
            else
                transform.position += move;
            transform.rotation = Quaternion.Euler(0.0f, transform.eulerAngles.y + turn, 0.0f);
            Vector3 p = transform.position;
            SmgMirrorX.SetGroundPosition(Character, new SmgFloat3(p.x, p.y, p.z), transform.eulerAngles.y);
            State = Character.State;
        }

        // After Update and after the Animator (its IK included), so the
        // libsmg pose is the one rendered where the mask gives it weight.
        void LateUpdate()
        {
            if (Character == null)
                return;
            rig.Apply(Character, weights, animator != null && animator.isActiveAndEnabled, HeightOffset);
            PoseApplied?.Invoke();
        }

        // libsmg's heights are world heights when it is told them (ground
        // rays, the mover's position); else its floor is at the start height
        bool WorldHeights => unevenGround || rootMotion == SmgRootMotionMode.EngineMover;

        float HeightOffset => WorldHeights ? 0.0f : groundY;

        // Unity calls OnAnimatorMove only on the Animator's own GameObject
        bool AnimatorMoves => animator != null && animator.gameObject == gameObject && animator.isActiveAndEnabled
                              && animator.applyRootMotion;

        // --- ISmgEventHandler: libsmg's events as this component's ---

        void ISmgEventHandler.OnConstraintReached(uint id, uint value, bool isSplice)
        {
            ConstraintReached?.Invoke(id, value, isSplice);
        }

        void ISmgEventHandler.OnConstraintSuperseded(uint id, uint value, bool isSplice)
        {
            ConstraintSuperseded?.Invoke(id, value, isSplice);
        }

        void ISmgEventHandler.OnFootstep(int foot, SmgFloat3 position, float strength)
        {
            Footstep?.Invoke(foot, new Vector3(-position.X, HeightOffset + position.Y, position.Z), strength);
        }

        void ISmgEventHandler.OnPathEndReached()
        {
            PathEndReached?.Invoke();
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
            Transform root = skeletonRoot != null ? skeletonRoot : transform;
            rig = new SmgRigPose(Graph, transform, root, useHumanoidAvatar ? animator : null, boneOverrides);
            if (!rig.HasRoot)
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
