// One character per thread: characters stepped concurrently on their own
// threads, through the raw pointers jobs use (SmgNativeRaw), pose exactly
// as the same characters stepped one after another through SmgCharacter.
using System;
using System.Threading;

namespace Smg.Tests
{
    static unsafe class ThreadTest
    {
        const int Characters = 4, Frames = 600;
        static readonly float[] Path = { 0, 0, 0, 10, 8, 16, 16, 10, 16, 0 };

        static SmgCharacter Make(SmgGraph graph, int k)
        {
            SmgCharacterDesc d = SmgCharacterDesc.Create();
            d.Seed = 7u + (uint)k;
            d.Position.X = (float)k;
            SmgCharacter ch = SmgCharacter.Create(graph, d);
            ch.SetPath(Path);
            ch.AddTransition(5.0f, graph.Info.StyleCount - 1);
            return ch;
        }

        public static void ParallelMatchesSerial(string blob)
        {
            using (SmgGraph graph = SmgGraph.LoadFile(blob))
            {
                int joints = graph.JointCount;
                var serial = new float[Characters][];
                var parallel = new float[Characters][];
                for (int k = 0; k < Characters; ++k)
                {
                    serial[k] = new float[Frames * 16 * joints];
                    parallel[k] = new float[Frames * 16 * joints];
                    using (SmgCharacter ch = Make(graph, k))
                        for (int f = 0; f < Frames; ++f)
                        {
                            ch.Step(1.0f / 60.0f);
                            ch.GetModelMatrices(SmgSpace.World, new Span<float>(serial[k], f * 16 * joints, 16 * joints));
                        }
                }

                var chars = new SmgCharacter[Characters];
                var leases = new SmgCharacterPointer[Characters];
                var threads = new Thread[Characters];
                var errors = new SmgResult[Characters];
                for (int k = 0; k < Characters; ++k)
                {
                    chars[k] = Make(graph, k);
                    leases[k] = chars[k].AcquirePointer();
                    chars[k].Dispose(); // the lease keeps it alive
                    IntPtr p = leases[k].Value;
                    float[] output = parallel[k];
                    int index = k;
                    threads[k] = new Thread(() =>
                    {
                        fixed (float* m = output)
                            for (int f = 0; f < Frames && errors[index] == SmgResult.Ok; ++f)
                            {
                                errors[index] = SmgNativeRaw.smg_character_step(p, 1.0f / 60.0f);
                                if (errors[index] == SmgResult.Ok)
                                    errors[index] = SmgNativeRaw.smg_character_get_model_matrices(p, SmgSpace.World, m + f * 16 * joints, (uint)joints);
                            }
                    });
                }
                foreach (Thread t in threads)
                    t.Start();
                foreach (Thread t in threads)
                    t.Join();
                Check.Equal((uint)Characters, graph.Info.CharacterCount, "leased characters alive after Dispose");
                foreach (SmgCharacterPointer lease in leases)
                    lease.Dispose();
                Check.Equal(0u, graph.Info.CharacterCount, "characters released with their leases");
                for (int k = 0; k < Characters; ++k)
                {
                    Check.Equal(SmgResult.Ok, errors[k], "thread " + k + " result");
                    fixed (float* a = serial[k])
                    fixed (float* b = parallel[k])
                        for (int i = 0; i < serial[k].Length; ++i)
                            if (((uint*)a)[i] != ((uint*)b)[i])
                                throw new Exception("character " + k + " float " + i + ": " + serial[k][i].ToString("R") + " serial, "
                                                + parallel[k][i].ToString("R") + " on its own thread");
                }
            }
        }
    }
}
