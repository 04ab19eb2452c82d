// Handle lifetime: disposed handles, the graph outliving its characters,
// hooks that fail, GC churn with nothing leaked (a counting allocator sees
// every native block come back), no managed allocation per frame.
using System;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Threading;

namespace Smg.Tests
{
    /// <summary>Counts libsmg's live blocks; aligned blocks from the
    /// native heap (the original pointer is kept just before the block).</summary>
    sealed class CountingAllocator : ISmgAllocator
    {
        long live, total, requested;
        public bool Fail;
        public bool Throw;

        public long Live => Interlocked.Read(ref live);
        public long Total => Interlocked.Read(ref total);
        public long RequestedBytes => Interlocked.Read(ref requested);

        public unsafe IntPtr Allocate(ulong size, ulong align)
        {
            if (Throw)
                throw new InvalidOperationException("allocator throws");
            if (Fail)
                return IntPtr.Zero;
            ulong pad = align + (ulong)IntPtr.Size;
            IntPtr raw = Marshal.AllocHGlobal((IntPtr)(long)(size + pad));
            ulong aligned = ((ulong)raw + (ulong)IntPtr.Size + align - 1) & ~(align - 1);
            ((IntPtr*)aligned)[-1] = raw;
            Interlocked.Increment(ref live);
            Interlocked.Increment(ref total);
            Interlocked.Add(ref requested, (long)size);
            return (IntPtr)(long)aligned;
        }

        public unsafe void Free(IntPtr block)
        {
            if (block == IntPtr.Zero)
                return;
            Marshal.FreeHGlobal(((IntPtr*)block)[-1]);
            Interlocked.Decrement(ref live);
        }
    }

    static class LifetimeTest
    {
        static readonly float[] Path = { 0, 0, 0, 6, 4, 10, 10, 10 };

        public static void DisposedHandles(string blob)
        {
            SmgGraph graph = SmgGraph.LoadFile(blob);
            SmgCharacter ch = SmgCharacter.Create(graph, SmgCharacterDesc.Create());
            ch.SetPath(Path);
            ch.Step(0.1f);
            ch.Dispose();
            ch.Dispose();
            Check.Throws<ObjectDisposedException>(() => ch.Step(0.1f), "Step after Dispose");
            Check.Throws<ObjectDisposedException>(() => ch.GetModelMatrices(SmgSpace.World, new float[16 * graph.JointCount]), "pose after Dispose");
            Check.Throws<ObjectDisposedException>(() => { var s = ch.State; }, "State after Dispose");
            graph.Dispose();
            graph.Dispose();
            Check.Throws<ObjectDisposedException>(() => SmgCharacter.Create(graph, SmgCharacterDesc.Create()), "Create on a disposed graph");
            Check.Throws<ObjectDisposedException>(() => { var i = graph.Info; }, "Info after Dispose");
        }

        public static void GraphOutlivesCharacters(string blob)
        {
            var alloc = new CountingAllocator();
            SmgGraph graph = SmgGraph.LoadFile(blob, new SmgGraphOptions { Allocator = alloc });
            SmgCharacter a = SmgCharacter.Create(graph, SmgCharacterDesc.Create());
            SmgCharacter b = SmgCharacter.Create(graph, SmgCharacterDesc.Create());
            graph.Dispose(); // characters still hold the native graph
            Check.True(alloc.Live > 0, "graph memory still held");
            a.SetPath(Path);
            for (int i = 0; i < 30; ++i)
                a.Step(1.0f / 30);
            Check.True(a.State.PathDistance > 0, "a character on a disposed graph still walks");
            a.Dispose();
            Check.True(alloc.Live > 0, "graph memory held while b lives");
            b.Dispose();
            Check.Equal(0L, alloc.Live, "graph blocks left after the last character");
        }

        public static void AllocatorHooks(string blob)
        {
            using (SmgGraph graph = SmgGraph.LoadFile(blob))
            {
                var counting = new CountingAllocator();
                SmgCharacterDesc d = SmgCharacterDesc.Create();
                d.PathCapacity = 100;
                using (SmgCharacter ch = SmgCharacter.Create(graph, d, counting))
                {
                    Check.Equal((long)graph.CharacterMemorySize(d), counting.RequestedBytes, "bytes through the hook vs CharacterMemorySize");
                    Check.True(counting.Live > 0, "the character's memory came from the hook");
                }
                Check.Equal(0L, counting.Live, "blocks left after Dispose");

                var failing = new CountingAllocator { Fail = true };
                Check.Fails(SmgResult.ErrorOutOfMemory, () => SmgCharacter.Create(graph, SmgCharacterDesc.Create(), failing), "allocator returns null");
                var throwing = new CountingAllocator { Throw = true };
                Check.Fails(SmgResult.ErrorOutOfMemory, () => SmgCharacter.Create(graph, SmgCharacterDesc.Create(), throwing), "allocator throws");
                Check.Fails(SmgResult.ErrorOutOfMemory, () => SmgGraph.LoadFile(blob, new SmgGraphOptions { Allocator = failing }), "graph allocator null");
                Check.Equal(0u, graph.Info.CharacterCount, "failed creates leave no character");
            }
            byte[] bad = System.IO.File.ReadAllBytes(blob);
            bad[0] ^= 1;
            var options = new SmgGraphOptions { Logger = (level, line) => { throw new InvalidOperationException("logger throws"); } };
            Check.Throws<SmgException>(() => SmgGraph.LoadMemory(bad, options), "a throwing logger does not unwind through libsmg");
        }

        // Characters made and dropped without Dispose, some with their own
        // allocator; the graph too in the second round. The finalizers run
        // in any order; every native block must come back.
        public static void GcChurn(string blob)
        {
            var graphAlloc = new CountingAllocator();
            var charAlloc = new CountingAllocator();
            SmgGraph graph = SmgGraph.LoadFile(blob, new SmgGraphOptions { Allocator = graphAlloc });
            for (int round = 0; round < 20; ++round)
                MakeAndDrop(graph, charAlloc, 10);
            Collect();
            Check.Equal(0u, graph.Info.CharacterCount, "characters left after collection");
            Check.Equal(0L, charAlloc.Live, "character blocks left");
            Check.True(charAlloc.Total >= 100, "the churn used the character allocator");
            graph.Dispose();
            Check.Equal(0L, graphAlloc.Live, "graph blocks left after Dispose (destroy succeeded)");

            var graphAlloc2 = new CountingAllocator();
            MakeGraphAndDropAll(blob, graphAlloc2, charAlloc);
            Collect();
            Check.Equal(0L, charAlloc.Live, "character blocks left (graph also dropped)");
            Check.Equal(0L, graphAlloc2.Live, "graph blocks left (graph and characters finalized together)");
        }

        static void Collect()
        {
            for (int i = 0; i < 3; ++i)
            {
                GC.Collect();
                GC.WaitForPendingFinalizers();
            }
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        static void MakeAndDrop(SmgGraph graph, CountingAllocator alloc, int count)
        {
            for (int i = 0; i < count; ++i)
            {
                SmgCharacterDesc d = SmgCharacterDesc.Create();
                d.Seed = (uint)i;
                SmgCharacter ch = SmgCharacter.Create(graph, d, i % 2 == 0 ? alloc : null);
                ch.SetPath(Path);
                ch.Step(1.0f / 30);
            }
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        static void MakeGraphAndDropAll(string blob, CountingAllocator graphAlloc, CountingAllocator charAlloc)
        {
            SmgGraph graph = SmgGraph.LoadFile(blob, new SmgGraphOptions { Allocator = graphAlloc });
            MakeAndDrop(graph, charAlloc, 10);
        }

        public static void NoAllocationPerFrame(string blob)
        {
            using (SmgGraph graph = SmgGraph.LoadFile(blob))
            using (SmgCharacter ch = SmgCharacter.Create(graph, SmgCharacterDesc.Create()))
            {
                var root = new float[3];
                var rot = new float[4 * graph.JointCount];
                var mat = new float[16 * graph.JointCount];
                ch.SetPath(Path);
                Frames(ch, root, rot, mat, 10); // JIT and first-call work
                long before = GC.GetAllocatedBytesForCurrentThread();
                Frames(ch, root, rot, mat, 1000);
                long after = GC.GetAllocatedBytesForCurrentThread();
                Check.Equal(0L, after - before, "managed bytes allocated by 1000 frames");
            }
        }

        static void Frames(SmgCharacter ch, float[] root, float[] rot, float[] mat, int n)
        {
            Span<float> stackRoot = stackalloc float[3];
            for (int i = 0; i < n; ++i)
            {
                ch.Step(1.0f / 60);
                SmgCharacterState s = ch.State;
                ch.GetLocalPose(stackRoot, rot);
                ch.GetLocalPose(root, rot);
                ch.GetModelMatrices(SmgSpace.World, mat);
                ch.GetModelMatrices(SmgSpace.Character, new Span<float>(mat));
            }
        }
    }
}
