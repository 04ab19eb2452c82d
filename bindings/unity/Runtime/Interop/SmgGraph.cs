// A loaded graph blob: immutable, shareable by any number of characters on
// any number of threads. A SafeHandle, so it is released exactly once
// (Dispose, or the finalizer when forgotten) and never while characters
// use it: each SmgCharacter holds a reference on it (DangerousAddRef), and
// Dispose with live characters only marks the graph closed; the native
// smg_graph_destroy runs when the last character is released.
using System;
using System.Runtime.InteropServices;

namespace Smg
{
    /// <summary>Options for loading a graph; null means all defaults.</summary>
    public sealed class SmgGraphOptions
    {
        public SmgGraphFlags Flags;
        /// <summary>null: malloc/free.</summary>
        public ISmgAllocator Allocator;
        /// <summary>Gets libsmg's explanation of a failure (which section,
        /// record and field of a blob is bad).</summary>
        public SmgLogHandler Logger;
    }

    /// <summary>A joint of the graph's skeleton.</summary>
    public struct SmgJoint
    {
        public int Index;
        public int Parent; // SmgNative.NoParent for the root (joint 0)
        public string Name;
        public SmgFloat3 RestOffset;
        public SmgBodyPart BodyPart;
    }

    public sealed unsafe class SmgGraph : SafeHandle
    {
        SmgHookContext hooks;
        IntPtr blobBlock; // aligned copy of the bytes given to LoadMemory
        uint jointCount;
        readonly SmgNameIndex jointIndex = new SmgNameIndex();
        readonly SmgNameIndex styleIndex = new SmgNameIndex();
        readonly SmgNameIndex actionIndex = new SmgNameIndex();

        SmgGraph() : base(IntPtr.Zero, true)
        {
        }

        public override bool IsInvalid => handle == IntPtr.Zero;

        /// <summary>Joints in the skeleton (buffers for the pose calls are
        /// sized from this).</summary>
        public int JointCount => (int)jointCount;

        /// <summary>Reads and validates a blob file.</summary>
        public static SmgGraph LoadFile(string path, SmgGraphOptions options = null)
        {
            byte[] utf8 = SmgUtf8.Encode(path);
            return Load(options, IntPtr.Zero, (SmgGraphDesc* desc, out IntPtr h) =>
            {
                fixed (byte* p = utf8)
                    return SmgNative.smg_graph_load_file(p, desc, out h);
            }, "smg_graph_load_file");
        }

        /// <summary>Validates a blob held in memory. The bytes are copied
        /// once into an aligned native block the graph owns (libsmg uses
        /// blob memory in place), so the array may be reused at once.</summary>
        public static SmgGraph LoadMemory(ReadOnlySpan<byte> blob, SmgGraphOptions options = null)
        {
            // 16-byte alignment is required: over-allocate and round up
            // (at least one byte, so an empty blob reaches libsmg's own
            // check with a valid pointer).
            IntPtr block = Marshal.AllocHGlobal(Math.Max(blob.Length, 1) + 15);
            byte* data = (byte*)(((long)block + 15) & ~15L);
            blob.CopyTo(new Span<byte>(data, blob.Length));
            UIntPtr size = (UIntPtr)(ulong)blob.Length;
            return Load(options, block, (SmgGraphDesc* desc, out IntPtr h) =>
                SmgNative.smg_graph_load_memory(data, size, desc, out h), "smg_graph_load_memory");
        }

        delegate SmgResult LoadCall(SmgGraphDesc* desc, out IntPtr handle);

        // Owns `block` from here on: the graph frees it, or this does when
        // the load fails.
        static SmgGraph Load(SmgGraphOptions options, IntPtr block, LoadCall call, string function)
        {
            var graph = new SmgGraph();
            var hooks = new SmgHookContext(options?.Allocator, options?.Logger);
            bool ok = false;
            try
            {
                SmgGraphDesc desc = SmgGraphDesc.Create();
                desc.Flags = options != null ? options.Flags : SmgGraphFlags.None;
                desc.Allocator = hooks.NativeAllocator;
                desc.Logger = hooks.NativeLogger;
                IntPtr h;
                SmgResult r = call(&desc, out h);
                if (r != SmgResult.Ok)
                    throw new SmgException(r, function, hooks.LastError);
                graph.SetHandle(h);
                graph.hooks = hooks;
                graph.blobBlock = block;
                SmgGraphInfo info = graph.Info;
                graph.jointCount = info.JointCount;
                ok = true;
                return graph;
            }
            finally
            {
                if (!ok && graph.IsInvalid)
                {
                    hooks.Release();
                    if (block != IntPtr.Zero)
                        Marshal.FreeHGlobal(block);
                    graph.SetHandleAsInvalid();
                }
                else if (!ok)
                {
                    graph.Dispose(); // releases hooks and block through ReleaseHandle
                }
            }
        }

        protected override bool ReleaseHandle()
        {
            // Characters hold references, so none is alive here; IN_USE can
            // only come from characters made through SmgNative directly, and
            // then leaking beats freeing memory that is still in use.
            if (SmgNative.smg_graph_destroy(handle) != SmgResult.Ok)
                return false;
            hooks?.Release();
            if (blobBlock != IntPtr.Zero)
                Marshal.FreeHGlobal(blobBlock);
            return true;
        }

        public SmgGraphInfo Info
        {
            get
            {
                SmgGraphInfo info = SmgGraphInfo.Create();
                SmgException.Check(SmgNative.smg_graph_get_info(this, &info), "smg_graph_get_info");
                return info;
            }
        }

        public SmgJoint GetJoint(int index)
        {
            if (index < 0)
                throw new ArgumentOutOfRangeException(nameof(index));
            SmgJointInfo j = SmgJointInfo.Create();
            SmgException.Check(SmgNative.smg_graph_get_joint(this, (uint)index, &j), "smg_graph_get_joint");
            return new SmgJoint
            {
                Index = index,
                Parent = j.Parent,
                Name = SmgUtf8.Decode(j.Name),
                RestOffset = j.RestOffset,
                BodyPart = j.BodyPart,
            };
        }

        /// <summary>Joint index by name; false when the skeleton has no
        /// such joint. Allocates nothing after a name's first lookup.</summary>
        public bool TryFindJoint(string name, out int index)
        {
            ThrowIfDisposed();
            if (jointIndex.TryGet(name, out index))
                return index >= 0;
            byte[] utf8 = SmgUtf8.Encode(name);
            uint i;
            SmgResult r;
            fixed (byte* p = utf8)
                r = SmgNative.smg_graph_find_joint(this, p, out i);
            index = r == SmgResult.Ok ? (int)i : -1;
            if (r == SmgResult.ErrorNotFound)
            {
                jointIndex.Add(name, -1);
                return false;
            }
            SmgException.Check(r, "smg_graph_find_joint");
            jointIndex.Add(name, index);
            return true;
        }

        public string GetStyleName(uint style)
        {
            IntPtr name;
            SmgException.Check(SmgNative.smg_graph_get_style_name(this, style, out name), "smg_graph_get_style_name");
            return SmgUtf8.Decode(name);
        }

        /// <summary>Style index by name (SmgException ErrorUnknownStyle
        /// when the graph has none). Allocates nothing after a name's first
        /// successful lookup.</summary>
        public uint FindStyle(string name)
        {
            int known;
            ThrowIfDisposed();
            if (styleIndex.TryGet(name, out known))
                return (uint)known;
            byte[] utf8 = SmgUtf8.Encode(name);
            uint style;
            fixed (byte* p = utf8)
                SmgException.Check(SmgNative.smg_graph_find_style(this, p, out style), "smg_graph_find_style");
            styleIndex.Add(name, (int)style);
            return style;
        }

        public string GetActionName(uint action)
        {
            IntPtr name;
            SmgException.Check(SmgNative.smg_graph_get_action_name(this, action, out name), "smg_graph_get_action_name");
            return SmgUtf8.Decode(name);
        }

        /// <summary>Action index by name (SmgException ErrorUnknownAction
        /// when the graph has none). Allocates nothing after a name's first
        /// successful lookup.</summary>
        public uint FindAction(string name)
        {
            int known;
            ThrowIfDisposed();
            if (actionIndex.TryGet(name, out known))
                return (uint)known;
            byte[] utf8 = SmgUtf8.Encode(name);
            uint action;
            fixed (byte* p = utf8)
                SmgException.Check(SmgNative.smg_graph_find_action(this, p, out action), "smg_graph_find_action");
            actionIndex.Add(name, (int)action);
            return action;
        }

        // what a call through the disposed handle would throw, also when the
        // answer is remembered
        void ThrowIfDisposed()
        {
            if (IsClosed)
                throw new ObjectDisposedException(nameof(SmgGraph));
        }

        /// <summary>Bytes a character with this desc would allocate.</summary>
        public ulong CharacterMemorySize(SmgCharacterDesc desc)
        {
            if (desc.StructSize == 0)
                desc.StructSize = SmgCharacterDesc.Size;
            UIntPtr bytes;
            SmgException.Check(SmgNative.smg_character_memory_size(this, &desc, out bytes), "smg_character_memory_size");
            return (ulong)bytes;
        }
    }
}
