// Allocator and logger hooks. libsmg calls plain C function pointers, so
// every hook goes through one static trampoline per kind: IL2CPP can only
// call static methods marked [MonoPInvokeCallback] from native code, and
// the static delegates behind the trampolines live as long as the program.
// The `user` pointer is a GCHandle to the SmgHookContext of the graph or
// character, which owns the managed allocator/logger and is freed only
// after the native object is destroyed (libsmg may call the hooks until
// then). No exception ever crosses into native code.
using System;
using System.Runtime.InteropServices;

namespace Smg
{
    /// <summary>Routes libsmg's memory through the engine. Called from
    /// smg_*_load / smg_*_create and from destroy, which for an undisposed
    /// handle runs on the finalizer thread: implementations must be
    /// thread-safe. Return IntPtr.Zero when out of memory; the block must
    /// be aligned to `align` (a power of two, at most 64).</summary>
    public interface ISmgAllocator
    {
        IntPtr Allocate(ulong size, ulong align);
        void Free(IntPtr block);
    }

    /// <summary>Receives libsmg's one-line explanations of failures.</summary>
    public delegate void SmgLogHandler(SmgLogLevel level, string message);

    /// <summary>IL2CPP recognises this attribute by name: it makes a static
    /// method callable from native code on AOT platforms.</summary>
    [AttributeUsage(AttributeTargets.Method)]
    sealed class MonoPInvokeCallbackAttribute : Attribute
    {
        public MonoPInvokeCallbackAttribute(Type delegateType)
        {
            DelegateType = delegateType;
        }

        public Type DelegateType { get; }
    }

    /// <summary>The managed hooks of one graph or character.</summary>
    sealed class SmgHookContext
    {
        readonly ISmgAllocator allocator;
        readonly SmgLogHandler logger;
        GCHandle self;

        /// <summary>The last error line libsmg logged through this context
        /// (read on the loading thread right after a failed load).</summary>
        internal string LastError;

        internal SmgHookContext(ISmgAllocator allocator, SmgLogHandler logger)
        {
            this.allocator = allocator;
            this.logger = logger;
            self = GCHandle.Alloc(this);
        }

        IntPtr User => GCHandle.ToIntPtr(self);

        /// <summary>The native allocator (all zero = malloc/free when no
        /// managed allocator was given).</summary>
        internal SmgAllocator NativeAllocator =>
            allocator == null
                ? default(SmgAllocator)
                : new SmgAllocator { Alloc = AllocPointer, Free = FreePointer, User = User };

        /// <summary>Always set: besides forwarding to the user's logger it
        /// keeps the error line for the exception message.</summary>
        internal SmgLogger NativeLogger => new SmgLogger { Func = LogPointer, User = User };

        /// <summary>Call once the native object is gone.</summary>
        internal void Release()
        {
            if (self.IsAllocated)
                self.Free();
        }

        static readonly SmgAllocFunc AllocDelegate = AllocTrampoline;
        static readonly SmgFreeFunc FreeDelegate = FreeTrampoline;
        static readonly SmgLogFunc LogDelegate = LogTrampoline;
        static readonly IntPtr AllocPointer = Marshal.GetFunctionPointerForDelegate(AllocDelegate);
        static readonly IntPtr FreePointer = Marshal.GetFunctionPointerForDelegate(FreeDelegate);
        static readonly IntPtr LogPointer = Marshal.GetFunctionPointerForDelegate(LogDelegate);

        static SmgHookContext From(IntPtr user)
        {
            return (SmgHookContext)GCHandle.FromIntPtr(user).Target;
        }

        [MonoPInvokeCallback(typeof(SmgAllocFunc))]
        static IntPtr AllocTrampoline(UIntPtr size, UIntPtr align, IntPtr user)
        {
            try
            {
                return From(user).allocator.Allocate((ulong)size, (ulong)align);
            }
            catch (Exception)
            {
                return IntPtr.Zero; // libsmg reports SMG_ERROR_OUT_OF_MEMORY
            }
        }

        [MonoPInvokeCallback(typeof(SmgFreeFunc))]
        static void FreeTrampoline(IntPtr block, IntPtr user)
        {
            try
            {
                From(user).allocator.Free(block);
            }
            catch (Exception)
            {
                // nothing can be reported from inside a destroy: the
                // allocator's own bookkeeping shows the lost block
            }
        }

        [MonoPInvokeCallback(typeof(SmgLogFunc))]
        static void LogTrampoline(uint level, IntPtr message, IntPtr user)
        {
            try
            {
                SmgHookContext ctx = From(user);
                string text = SmgUtf8.Decode(message);
                if (level == (uint)SmgLogLevel.Error)
                    ctx.LastError = text;
                if (ctx.logger != null)
                    ctx.logger((SmgLogLevel)level, text);
            }
            catch (Exception)
            {
                // a throwing logger must not unwind through libsmg
            }
        }
    }
}
