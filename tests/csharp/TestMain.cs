// The C# binding test (make test-csharp): runs the interop layer in
// bindings/unity/Runtime/Interop against the real libsmg.so, outside Unity.
//
//   mono smg-csharp-tests.exe --layout LAYOUT.txt --exports EXPORTS.txt
//        --replay C_REPLAY --frames N --blob BLOB [--blob BLOB ...]
//        [--library LIBSMG_SO_REALPATH]
//
// LAYOUT.txt comes from the C program gen_c_layout.py writes, EXPORTS.txt
// from nm on libsmg.so, C_REPLAY is c_replay.c built against the same
// library. Each check prints "ok NAME" or "FAIL NAME: why"; the last line
// is the count of both.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace Smg.Tests
{
    static partial class TestMain
    {
        static int passed, failed;

        static void Run(string name, Action test)
        {
            try
            {
                test();
                ++passed;
                Console.WriteLine("ok   " + name);
            }
            catch (Exception e)
            {
                ++failed;
                Console.WriteLine("FAIL " + name + ": " + e);
            }
        }

        static int Main(string[] args)
        {
            string layout = null, exports = null, replay = null, library = null;
            int frames = 10000;
            var blobs = new List<string>();
            for (int i = 0; i + 1 < args.Length; i += 2)
            {
                switch (args[i])
                {
                    case "--layout": layout = args[i + 1]; break;
                    case "--exports": exports = args[i + 1]; break;
                    case "--replay": replay = args[i + 1]; break;
                    case "--frames": frames = int.Parse(args[i + 1]); break;
                    case "--blob": blobs.Add(args[i + 1]); break;
                    case "--library": library = args[i + 1]; break;
                    default:
                        Console.Error.WriteLine("unknown option " + args[i]);
                        return 2;
                }
            }
            if (layout == null || exports == null || replay == null || blobs.Count == 0 || args.Length % 2 != 0)
            {
                Console.Error.WriteLine("usage: smg-csharp-tests.exe --layout F --exports F --replay C_REPLAY [--frames N] --blob BLOB...");
                return 2;
            }
            string first = blobs[0];

            Run("version matches the header mirrored", () => Check.Equal(SmgNative.Version, SmgNative.smg_version(), "smg_version()"));
            if (library != null)
                Run("DllImport(\"smg\") loaded " + library, () => CheckLoaded(library));
            Run("struct layouts and constants match C", () => LayoutTest.Run(File.ReadAllLines(layout)));
            Run("every exported smg_ function has a DllImport", () => ExportTest.Run(File.ReadAllLines(exports)));
            foreach (string blob in blobs)
                Run("replay " + Path.GetFileName(blob) + " bit for bit vs C (" + frames + " frames)",
                    () => ReplayTest.Run(replay, blob, frames));
            Run("graph queries", () => ErrorTest.GraphQueries(first));
            Run("corrupt blob bytes give libsmg's message", () => ErrorTest.CorruptBlob(first));
            Run("missing file gives libsmg's message", () => ErrorTest.MissingFile());
            Run("bad struct sizes are rejected", () => ErrorTest.BadStructSizes(first));
            Run("bad arguments are rejected", () => ErrorTest.BadArguments(first));
            Run("disposed handles throw; double dispose is safe", () => LifetimeTest.DisposedHandles(first));
            Run("graph disposed before its characters outlives them", () => LifetimeTest.GraphOutlivesCharacters(first));
            Run("allocator hooks: sizes, failing and throwing hooks", () => LifetimeTest.AllocatorHooks(first));
            Run("handles released under GC churn, nothing leaked", () => LifetimeTest.GcChurn(first));
            foreach (string blob in blobs)
                Run("left-handed conversion matches libsmg's matrices (" + Path.GetFileName(blob) + ")", () => MirrorTest.MatchesLibsmg(blob));
            Run("one character per thread, raw pointers, same poses as serial", () => ThreadTest.ParallelMatchesSerial(first));
            Run("step and pose reads allocate no managed memory", () => LifetimeTest.NoAllocationPerFrame(first));

            Console.WriteLine("test-csharp: " + passed + " passed, " + failed + " failed");
            return failed == 0 ? 0 : 1;
        }
    }

    static partial class TestMain
    {
        // The file the process mapped for "smg" (Linux: /proc/self/maps)
        // must be the library under test, not another libsmg on the system.
        static void CheckLoaded(string library)
        {
            string expected = new FileInfo(library).FullName;
            var mapped = new List<string>();
            foreach (string line in File.ReadAllLines("/proc/self/maps"))
            {
                int slash = line.IndexOf('/');
                if (slash >= 0 && line.Contains("libsmg"))
                    mapped.Add(line.Substring(slash));
            }
            Check.True(mapped.Contains(expected), expected + " is mapped (libsmg files mapped: " + string.Join(", ", mapped.Distinct()) + ")");
        }
    }

    static class Check
    {
        public static void True(bool condition, string what)
        {
            if (!condition)
                throw new Exception("expected: " + what);
        }

        public static void Equal<T>(T expected, T actual, string what)
        {
            if (!EqualityComparer<T>.Default.Equals(expected, actual))
                throw new Exception(what + ": expected " + expected + ", got " + actual);
        }

        /// <summary>Runs `call`, which must throw TException; returns it.</summary>
        public static TException Throws<TException>(Action call, string what) where TException : Exception
        {
            try
            {
                call();
            }
            catch (TException e)
            {
                return e;
            }
            catch (Exception e)
            {
                throw new Exception(what + ": expected " + typeof(TException).Name + ", got " + e.GetType().Name + ": " + e.Message);
            }
            throw new Exception(what + ": expected " + typeof(TException).Name + ", nothing was thrown");
        }

        /// <summary>`call` must fail with `result`, and the message must
        /// carry smg_result_string's text for it.</summary>
        public static SmgException Fails(SmgResult result, Action call, string what)
        {
            SmgException e = Throws<SmgException>(call, what);
            Equal(result, e.Result, what + " result");
            string text = SmgUtf8Test.Decode(SmgNative.smg_result_string(result));
            True(e.Message.Contains(text), what + ": message \"" + e.Message + "\" contains \"" + text + "\"");
            return e;
        }
    }

    static unsafe class SmgUtf8Test
    {
        // the test's own decoder, independent of the binding's
        public static string Decode(IntPtr p)
        {
            var bytes = new List<byte>();
            for (byte* b = (byte*)p; *b != 0; ++b)
                bytes.Add(*b);
            return System.Text.Encoding.UTF8.GetString(bytes.ToArray());
        }
    }
}
