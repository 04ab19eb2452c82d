// The raw C ABI: one [DllImport] per function of include/smg.h, named
// exactly like the C function, plus the header's constants. Handles are the
// SafeHandle classes SmgGraph and SmgCharacter, so a disposed handle throws
// ObjectDisposedException before reaching native code and the GC cannot
// release a handle during a call; only the destroy functions take IntPtr
// (they are called from ReleaseHandle). Structs and buffers are passed as
// pointers: nothing is marshalled or copied, nothing allocates. Strings are
// UTF-8 (see SmgUtf8). The C# test fails when libsmg exports a function
// that has no declaration here.
using System;
using System.Runtime.InteropServices;

namespace Smg
{
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
    public delegate IntPtr SmgAllocFunc(UIntPtr size, UIntPtr align, IntPtr user);

    [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
    public delegate void SmgFreeFunc(IntPtr ptr, IntPtr user);

    [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
    public delegate void SmgLogFunc(uint level, IntPtr message, IntPtr user);

    public static unsafe class SmgNative
    {
        // iOS and WebGL link native plugins statically into the player.
#if (UNITY_IOS || UNITY_WEBGL) && !UNITY_EDITOR
        public const string Library = "__Internal";
#else
        public const string Library = "smg";
#endif

        // The header version this binding mirrors (SMG_VERSION_*).
        public const uint VersionMajor = 0;
        public const uint VersionMinor = 1;
        public const uint VersionPatch = 0;
        public const uint Version = (VersionMajor << 16) | (VersionMinor << 8) | VersionPatch;
        public const uint BlobVersionMin = 2;
        public const uint BlobVersionMax = 2;
        public const int NoParent = -1;

        const CallingConvention Cdecl = CallingConvention.Cdecl;

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern uint smg_version();

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern IntPtr smg_result_string(SmgResult result);

        // --- Graph ---

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_graph_load_file(byte* path, SmgGraphDesc* desc, out IntPtr outGraph);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_graph_load_memory(void* data, UIntPtr size, SmgGraphDesc* desc, out IntPtr outGraph);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_graph_destroy(IntPtr graph);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_graph_get_info(SmgGraph graph, SmgGraphInfo* outInfo);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_graph_get_joint(SmgGraph graph, uint index, SmgJointInfo* outJoint);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_graph_find_joint(SmgGraph graph, byte* name, out uint outIndex);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_graph_get_style_name(SmgGraph graph, uint style, out IntPtr outName);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_graph_find_style(SmgGraph graph, byte* name, out uint outStyle);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_graph_get_action_name(SmgGraph graph, uint action, out IntPtr outName);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_graph_find_action(SmgGraph graph, byte* name, out uint outAction);

        // --- Character ---

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_create(SmgGraph graph, SmgCharacterDesc* desc, out IntPtr outCharacter);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_destroy(IntPtr character);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_memory_size(SmgGraph graph, SmgCharacterDesc* desc, out UIntPtr outBytes);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_set_path(SmgCharacter character, float* xz, uint count);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_append_path(SmgCharacter character, float* xz, uint count);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_clear_path(SmgCharacter character);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_get_path_length(SmgCharacter character, out float outLength);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_add_transition(SmgCharacter character, float arcLength, uint style, out uint outId);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_add_splice(SmgCharacter character, float arcLength, uint action, out uint outId);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_move_constraint(SmgCharacter character, uint id, float arcLength);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_remove_constraint(SmgCharacter character, uint id);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_clear_constraints(SmgCharacter character);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_set_style(SmgCharacter character, uint style);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_set_action(SmgCharacter character, uint action);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_set_error_threshold(SmgCharacter character, float metres);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_set_ik(SmgCharacter character, uint enabled);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_set_steering(SmgCharacter character, uint enabled);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_set_steering_limits(SmgCharacter character, float turnRate, float slideRatio, float stopSeconds);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_set_swing_clearance(SmgCharacter character, uint enabled, float clearance);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_set_ground_position(SmgCharacter character, float* position, float heading);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_get_ground_probes(SmgCharacter character, float* xz, uint count);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_set_ground(SmgCharacter character, SmgGround* ground);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_step(SmgCharacter character, float dt);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_get_state(SmgCharacter character, SmgCharacterState* outState);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_get_local_pose(SmgCharacter character, float* rootTranslation, float* rotations, uint jointCount);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_get_model_matrices(SmgCharacter character, SmgSpace space, float* matrices, uint jointCount);

        // --- After the step: events and root motion ---

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_get_events(SmgCharacter character, SmgEvent* events, uint capacity, out uint outCount);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_get_root_motion(SmgCharacter character, SmgRootMotion* outMotion);
    }
}
