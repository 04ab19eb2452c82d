// `make bench-csharp`: what the C# binding adds to a character's frame.
//
//   mono bench-csharp.exe C_HELPER ROUNDS BLOB...
//
// For each blob, ROUNDS times alternately: the C helper (bench_csharp_c.c,
// a fresh process) and the same loop through SmgCharacter here (fresh
// graph and characters): 16 characters, 300 warm-up frames, 600 timed
// frames of Step + State + GetLocalPose, thread CPU time. Both sides make
// identical calls, so they do identical work; the ratio is the binding's
// overhead (goal: C# within 1.5x of C). Prints medians; never fails on time.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Runtime.InteropServices;

namespace Smg.Bench
{
    static unsafe class BenchCsharp
    {
        const int Characters = 16, Warmup = 300, Frames = 600;
        static readonly float[] Path = { 0, 0, 0, 30, 30, 30, 30, 0, 0, 0, 0, 30 };

        [StructLayout(LayoutKind.Sequential)]
        struct Timespec
        {
            public long Seconds, Nanoseconds;
        }

        [DllImport("libc")]
        static extern int clock_gettime(int clock, Timespec* ts);

        static double ThreadSeconds()
        {
            Timespec ts;
            clock_gettime(3 /* CLOCK_THREAD_CPUTIME_ID */, &ts);
            return ts.Seconds + 1e-9 * ts.Nanoseconds;
        }

        static double Managed(string blob)
        {
            using (SmgGraph graph = SmgGraph.LoadFile(blob))
            {
                var ch = new SmgCharacter[Characters];
                for (int k = 0; k < Characters; ++k)
                {
                    SmgCharacterDesc d = SmgCharacterDesc.Create();
                    d.Seed = 1u + (uint)k;
                    d.Position.X = 0.5f * k;
                    ch[k] = SmgCharacter.Create(graph, d);
                    ch[k].SetPath(Path);
                }
                Span<float> root = stackalloc float[3];
                var rot = new float[4 * graph.JointCount];
                double start = 0;
                for (int f = 0; f < Warmup + Frames; ++f)
                {
                    if (f == Warmup)
                        start = ThreadSeconds();
                    for (int k = 0; k < Characters; ++k)
                    {
                        ch[k].Step(1.0f / 60.0f);
                        SmgCharacterState st = ch[k].State;
                        ch[k].GetLocalPose(root, rot);
                    }
                }
                double seconds = ThreadSeconds() - start;
                foreach (SmgCharacter c in ch)
                    c.Dispose();
                return 1e9 * seconds / ((double)Characters * Frames);
            }
        }

        static double Native(string helper, string blob)
        {
            var start = new ProcessStartInfo(helper, string.Format("\"{0}\" {1} {2} {3}", blob, Characters, Warmup, Frames))
            {
                UseShellExecute = false,
                RedirectStandardOutput = true,
            };
            using (Process p = Process.Start(start))
            {
                string output = p.StandardOutput.ReadToEnd();
                p.WaitForExit();
                if (p.ExitCode != 0)
                    throw new Exception(helper + " failed");
                return double.Parse(output.Trim(), CultureInfo.InvariantCulture);
            }
        }

        static double Median(List<double> v)
        {
            v.Sort();
            return v.Count % 2 == 1 ? v[v.Count / 2] : 0.5 * (v[v.Count / 2 - 1] + v[v.Count / 2]);
        }

        static int Main(string[] args)
        {
            if (args.Length < 3)
            {
                Console.Error.WriteLine("usage: bench-csharp.exe C_HELPER ROUNDS BLOB...");
                return 2;
            }
            int rounds = int.Parse(args[1]);
            Managed(args[2]); // JIT and first-load work outside the rounds
            for (int b = 2; b < args.Length; ++b)
            {
                var c = new List<double>();
                var managed = new List<double>();
                for (int r = 0; r < rounds; ++r)
                {
                    c.Add(Native(args[0], args[b]));
                    managed.Add(Managed(args[b]));
                }
                double mc = Median(c), mm = Median(managed);
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                    "bench-csharp {0}: step+state+local pose per character: C {1:F2} us, C# {2:F2} us; C#/C {3:F3} (goal <= 1.5); median of {4} alternating rounds, {5} characters x {6} frames, thread CPU time",
                    System.IO.Path.GetFileName(args[b]), mc / 1000, mm / 1000, mm / mc, rounds, Characters, Frames));
            }
            return 0;
        }
    }
}
