// The per-frame functions again, taking the raw native pointer instead of
// the SafeHandle: for code that cannot hold a managed object, such as a
// Unity job (Burst or not), which may only contain blittable fields. The
// pointer comes from SmgCharacter.AcquirePointer(), which keeps the
// character alive until the lease is disposed; nothing here checks it.
using System;
using System.Runtime.InteropServices;
using System.Threading;

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

    /// <summary>A lease on a character's native pointer: the character
    /// cannot be released until the lease is disposed (or, when forgotten,
    /// finalized). A class, so copies share one lease and a second Dispose
    /// does nothing. Jobs, which may hold only blittable fields, take
    /// <c>Value</c> (an IntPtr) and the lease stays with managed code.</summary>
    public sealed class SmgCharacterPointer : IDisposable
    {
        public readonly IntPtr Value;
        SmgCharacter owner;

        internal SmgCharacterPointer(IntPtr value, SmgCharacter owner)
        {
            Value = value;
            this.owner = owner;
        }

        /// <summary>True until the first Dispose.</summary>
        public bool IsHeld => Volatile.Read(ref owner) != null;

        public void Dispose()
        {
            Release();
            GC.SuppressFinalize(this);
        }

        ~SmgCharacterPointer()
        {
            Release();
        }

        // exactly one caller gets the owner, however many threads dispose
        void Release()
        {
            SmgCharacter o = Interlocked.Exchange(ref owner, null);
            o?.DangerousRelease();
        }
    }
}
