// Compile-time surface of UnityEngine for `make test-csharp`: declarations,
// with the signatures of Unity's scripting reference, of exactly the
// members bindings/unity/Runtime/Unity and the sample use, and nothing
// else. Every member is `extern` (no body, no behaviour): the assembly only
// lets mono's compiler type-check the Unity layer here, where Unity is not
// installed. It proves the layer compiles against these signatures, not
// that it behaves in Unity. A member the layer starts to use must be added
// here, with Unity's exact signature.
using System;

namespace UnityEngine
{
    public class Object
    {
        public extern string name { get; set; }
        public extern int GetInstanceID();
    }

    public class Component : Object
    {
        public extern Transform transform { get; }
        public extern GameObject gameObject { get; }
        public extern T GetComponent<T>();
        public extern T[] GetComponentsInChildren<T>(bool includeInactive);
    }

    public class Behaviour : Component
    {
        public extern bool enabled { get; set; }
        public extern bool isActiveAndEnabled { get; }
    }

    public class Collider : Component
    {
        public extern bool enabled { get; set; }
    }

    [Flags]
    public enum CollisionFlags
    {
        None = 0,
        Sides = 1,
        Above = 2,
        Below = 4,
    }

    public class CharacterController : Collider
    {
        public extern CollisionFlags Move(Vector3 motion);
        public extern bool isGrounded { get; }
    }

    public class Animator : Behaviour
    {
        public extern bool applyRootMotion { get; set; }
        public extern bool isHuman { get; }
        public extern Transform GetBoneTransform(HumanBodyBones humanBoneId);
        public extern void ApplyBuiltinRootMotion();
    }

    public enum HumanBodyBones
    {
        Hips = 0,
        LeftUpperLeg = 1,
        RightUpperLeg = 2,
        LeftLowerLeg = 3,
        RightLowerLeg = 4,
        LeftFoot = 5,
        RightFoot = 6,
        Spine = 7,
        Chest = 8,
        Neck = 9,
        Head = 10,
        LeftShoulder = 11,
        RightShoulder = 12,
        LeftUpperArm = 13,
        RightUpperArm = 14,
        LeftLowerArm = 15,
        RightLowerArm = 16,
        LeftHand = 17,
        RightHand = 18,
        LeftToes = 19,
        RightToes = 20,
        LeftEye = 21,
        RightEye = 22,
        Jaw = 23,
        UpperChest = 54,
        LastBone = 55,
    }

    public struct LayerMask
    {
        public static extern implicit operator int(LayerMask mask);
        public static extern implicit operator LayerMask(int intVal);
    }

    public enum QueryTriggerInteraction
    {
        UseGlobal = 0,
        Ignore = 1,
        Collide = 2,
    }

    public struct RaycastHit
    {
        public extern Vector3 point { get; set; }
        public extern Collider collider { get; }
    }

    public class Physics
    {
        public static extern Vector3 gravity { get; set; }
        public static extern int RaycastNonAlloc(Ray ray, RaycastHit[] results, float maxDistance, int layerMask,
                                                 QueryTriggerInteraction queryTriggerInteraction);
    }

    public class MonoBehaviour : Behaviour
    {
    }

    public sealed class GameObject : Object
    {
        public extern GameObject(string name);
        public extern Transform transform { get; }
        public extern T AddComponent<T>() where T : Component;
    }

    public class Transform : Component
    {
        public extern Vector3 position { get; set; }
        public extern Quaternion rotation { get; set; }
        public extern Vector3 localPosition { get; set; }
        public extern Quaternion localRotation { get; set; }
        public extern Matrix4x4 worldToLocalMatrix { get; }
        public extern Matrix4x4 localToWorldMatrix { get; }
        public extern void SetParent(Transform parent, bool worldPositionStays);
        public extern Vector3 eulerAngles { get; set; }
        public extern void SetPositionAndRotation(Vector3 position, Quaternion rotation);
        public extern Vector3 TransformPoint(Vector3 position);
        public extern Vector3 InverseTransformPoint(Vector3 position);
        public extern Transform parent { get; set; }
        public extern bool IsChildOf(Transform parent);
    }

    public class TextAsset : Object
    {
        public extern byte[] bytes { get; }
    }

    public class Renderer : Component
    {
        public extern Material sharedMaterial { get; set; }
    }

    public class SkinnedMeshRenderer : Renderer
    {
        public extern Mesh sharedMesh { get; set; }
        public extern Transform[] bones { get; set; }
        public extern Transform rootBone { get; set; }
        public extern bool updateWhenOffscreen { get; set; }
    }

    public sealed class Mesh : Object
    {
        public extern Mesh();
        public extern Vector3[] vertices { get; set; }
        public extern int[] triangles { get; set; }
        public extern BoneWeight[] boneWeights { get; set; }
        public extern Matrix4x4[] bindposes { get; set; }
        public extern void RecalculateNormals();
        public extern void RecalculateBounds();
    }

    public struct BoneWeight
    {
        public extern int boneIndex0 { get; set; }
        public extern float weight0 { get; set; }
    }

    public struct Matrix4x4
    {
        public static extern Matrix4x4 operator *(Matrix4x4 lhs, Matrix4x4 rhs);
    }

    public class Material : Object
    {
        public extern Material(Shader shader);
    }

    public sealed class Shader : Object
    {
        public static extern Shader Find(string name);
    }

    public class LineRenderer : Renderer
    {
        public extern int positionCount { get; set; }
        public extern bool useWorldSpace { get; set; }
        public extern float widthMultiplier { get; set; }
        public extern int GetPositions(Vector3[] positions);
        public extern Vector3 GetPosition(int index);
        public extern void SetPosition(int index, Vector3 position);
    }

    public class Camera : Behaviour
    {
        public static extern Camera main { get; }
        public extern Ray ScreenPointToRay(Vector3 pos);
    }

    public struct Vector2
    {
        public float x, y;
        public extern Vector2(float x, float y);
        public extern float magnitude { get; }
    }

    public struct Vector3
    {
        public float x, y, z;
        public extern Vector3(float x, float y, float z);
        public static extern Vector3 Lerp(Vector3 a, Vector3 b, float t);
        public static extern float Distance(Vector3 a, Vector3 b);
        public static extern Vector3 up { get; }
        public static extern Vector3 down { get; }
        public static extern Vector3 zero { get; }
        public static extern Vector3 right { get; }
        public extern float magnitude { get; }
        public extern Vector3 normalized { get; }
        public static extern Vector3 Cross(Vector3 lhs, Vector3 rhs);
        public static extern Vector3 operator +(Vector3 a, Vector3 b);
        public static extern Vector3 operator -(Vector3 a, Vector3 b);
        public static extern Vector3 operator *(Vector3 a, float d);
    }

    public struct Quaternion
    {
        public float x, y, z, w;
        public extern Quaternion(float x, float y, float z, float w);
        public static extern Quaternion identity { get; }
        public static extern Quaternion Inverse(Quaternion rotation);
        public static extern Quaternion Euler(float x, float y, float z);
        public static extern Quaternion Slerp(Quaternion a, Quaternion b, float t);
        public static extern Quaternion operator *(Quaternion lhs, Quaternion rhs);
    }

    public struct Color
    {
        public static extern Color cyan { get; }
        public static extern Color magenta { get; }
    }

    public struct Ray
    {
        public extern Ray(Vector3 origin, Vector3 direction);
        public extern Vector3 GetPoint(float distance);
    }

    public struct Plane
    {
        public extern Plane(Vector3 inNormal, Vector3 inPoint);
        public extern bool Raycast(Ray ray, out float enter);
    }

    public struct Mathf
    {
        public static extern float Clamp(float value, float min, float max);
        public static extern int Max(int a, int b);
        public static extern float Min(float a, float b);
        public static extern float Max(float a, float b);
        public static extern float Abs(float f);
        public static extern float Sin(float f);
        public static extern int NextPowerOfTwo(int value);
    }

    public class Time
    {
        public static extern float deltaTime { get; }
    }

    public class Application
    {
        public static extern string streamingAssetsPath { get; }
    }

    public class Debug
    {
        public static extern void Log(object message);
        public static extern void LogError(object message);
        public static extern void LogError(object message, Object context);
        public static extern void LogWarning(object message, Object context);
    }

    public enum RuntimeInitializeLoadType
    {
        AfterSceneLoad = 0,
        BeforeSceneLoad = 1,
        AfterAssembliesLoaded = 2,
        BeforeSplashScreen = 3,
        SubsystemRegistration = 4,
    }

    [AttributeUsage(AttributeTargets.Method, AllowMultiple = false)]
    public class RuntimeInitializeOnLoadMethodAttribute : Attribute
    {
        public extern RuntimeInitializeOnLoadMethodAttribute(RuntimeInitializeLoadType loadType);
    }

    public class Gizmos
    {
        public static extern Color color { get; set; }
        public static extern void DrawWireSphere(Vector3 center, float radius);
        public static extern void DrawWireCube(Vector3 center, Vector3 size);
    }

    public class Input
    {
        public static extern Vector3 mousePosition { get; }
        public static extern bool GetMouseButton(int button);
        public static extern bool GetMouseButtonDown(int button);
        public static extern bool GetKeyDown(KeyCode key);
    }

    public enum KeyCode
    {
        N = 110,
        P = 112,
        R = 114,
        W = 119,
    }

    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = true)]
    public class HeaderAttribute : Attribute
    {
        public extern HeaderAttribute(string header);
    }

    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public sealed class RangeAttribute : Attribute
    {
        public extern RangeAttribute(float min, float max);
    }

    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public class TooltipAttribute : Attribute
    {
        public extern TooltipAttribute(string tooltip);
    }

    [AttributeUsage(AttributeTargets.Class, Inherited = false, AllowMultiple = false)]
    public sealed class DisallowMultipleComponent : Attribute
    {
    }

    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true, Inherited = true)]
    public sealed class RequireComponent : Attribute
    {
        public extern RequireComponent(Type requiredComponent);
    }
}
