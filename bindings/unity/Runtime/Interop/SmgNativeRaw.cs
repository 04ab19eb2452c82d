// The per-frame functions again, taking the raw native pointer instead of
// the SafeHandle: for code that cannot hold a managed object, such as a
// Unity job (Burst or not), which may only contain blittable fields. The
// pointer comes from SmgCharacter.AcquirePointer(), which keeps the
// character alive until the lease is disposed; nothing here checks it.
using System;
using System.Runtime.InteropServices;

namespace Smg
{
    public static unsafe class SmgNativeRaw
    {
        const CallingConvention Cdecl = CallingConvention.Cdecl;

        [DllImport(SmgNative.Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_step(IntPtr character, float dt);

        [DllImport(SmgNative.Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_get_state(IntPtr character, SmgCharacterState* outState);

        [DllImport(SmgNative.Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_get_local_pose(IntPtr character, float* rootTranslation, float* rotations, uint jointCount);

        [DllImport(SmgNative.Library, CallingConvention = Cdecl)]
        public static extern SmgResult smg_character_get_model_matrices(IntPtr character, SmgSpace space, float* matrices, uint jointCount);
    }

    /// <summary>A character's native pointer, valid (the character cannot
    /// be released) until Dispose. A struct so that jobs can hold the
    /// pointer; dispose each lease exactly once.</summary>
    public struct SmgCharacterPointer : IDisposable
    {
        public readonly IntPtr Value;
        readonly SmgCharacter owner;

        internal SmgCharacterPointer(IntPtr value, SmgCharacter owner)
        {
            Value = value;
            this.owner = owner;
        }

        public void Dispose()
        {
            owner?.DangerousRelease();
        }
    }
}
