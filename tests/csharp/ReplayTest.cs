// The call sequence of c_replay.c through the C# classes, compared byte for
// byte with the stream c_replay writes through the C API (see c_replay.c;
// keep the two sequences identical). The first difference is reported with
// its frame, character and item.
using System;
using System.Diagnostics;
using System.IO;
using System.Runtime.InteropServices;

namespace Smg.Tests
{
    sealed unsafe class ReplayTest
    {
        const int Characters = 3;
        static readonly float[] StartPath = { 0, 0, 0, 8, 6, 14, 14, 14, 20, 8, 20, 0, 12, -6, 4, -4 };
        static readonly float[] Ring = { 0, 4, 6, 10, 12, 4, 6, -2 };
        static readonly float[] Square = { 0, 0, 10, 0, 10, 10, 0, 10 };

        readonly Stream reference;
        readonly byte[] expected = new byte[1 << 16];
        long frame = -1;
        int character = -1;
        long position;

        ReplayTest(Stream reference)
        {
            this.reference = reference;
        }

        public static void Run(string cReplay, string blob, int frames)
        {
            var start = new ProcessStartInfo(cReplay, "\"" + blob + "\" " + frames)
            {
                UseShellExecute = false,
                RedirectStandardOutput = true,
            };
            using (Process c = Process.Start(start))
            {
                try
                {
                    new ReplayTest(c.StandardOutput.BaseStream).Replay(blob, frames);
                    Check.Equal(-1, c.StandardOutput.BaseStream.ReadByte(), "end of the C stream");
                }
                catch (Exception)
                {
                    c.Kill(); // it would wait on the pipe we stopped reading
                    throw;
                }
                c.WaitForExit();
                Check.Equal(0, c.ExitCode, "c_replay exit code");
            }
        }

        // Reads the next n bytes of the C stream and compares them with `data`.
        void Expect(byte* data, int n, string what)
        {
            int got = 0;
            while (got < n)
            {
                int r = reference.Read(expected, got, n - got);
                if (r <= 0)
                    throw new Exception("C stream ended early at " + What(what));
                got += r;
            }
            for (int i = 0; i < n; ++i)
            {
                if (expected[i] == data[i])
                    continue;
                string detail = "";
                if (n % 4 == 0)
                {
                    int k = i / 4;
                    fixed (byte* e = expected)
                        detail = ": float " + k + " is " + ((float*)e)[k].ToString("R") + " (0x" + ((uint*)e)[k].ToString("x8")
                                 + ") in C, " + ((float*)data)[k].ToString("R") + " (0x" + ((uint*)data)[k].ToString("x8") + ") in C#";
                }
                throw new Exception("C# differs from C at " + What(what) + ", byte " + i + detail);
            }
            position += n;
        }

        string What(string what)
        {
            return what + " (frame " + frame + ", character " + character + ", stream offset " + position + ")";
        }

        void ExpectResult(SmgResult r, string what)
        {
            int v = (int)r;
            Expect((byte*)&v, 4, what + " result");
        }

        void ExpectFloats(float[] data, string what)
        {
            fixed (float* p = data)
                Expect((byte*)p, data.Length * 4, what);
        }

        // The result of a binding call: Ok, or the code of its SmgException.
        static SmgResult Result(Action call)
        {
            try
            {
                call();
                return SmgResult.Ok;
            }
            catch (SmgException e)
            {
                return e.Result;
            }
        }

        void Replay(string blob, int frames)
        {
            using (SmgGraph graph = SmgGraph.LoadFile(blob))
            {
                SmgGraphInfo info = graph.Info;
                uint joints = info.JointCount;
                var root = new float[3];
                var rot = new float[4 * joints];
                var mat = new float[16 * joints];

                uint* header = stackalloc uint[4];
                header[0] = joints;
                header[1] = SmgCharacterState.Size;
                header[2] = Characters;
                header[3] = (uint)frames;
                Expect((byte*)header, 16, "header (joints, state size, characters, frames)");

                var ch = new SmgCharacter[Characters];
                var firstSplice = new uint[Characters];
                var firstTransition = new uint[Characters];
                for (int k = 0; k < Characters; ++k)
                {
                    character = k;
                    SmgCharacterDesc d = SmgCharacterDesc.Create();
                    d.Seed = 1u + (uint)k;
                    d.Position.X = 1.5f * k;
                    d.Position.Z = -1.0f;
                    d.Heading = 0.25f * k;
                    ch[k] = SmgCharacter.Create(graph, d);
                    SmgCharacter c = ch[k];
                    ExpectResult(Result(() => c.SetPath(StartPath)), "set_path");
                    ExpectResult(Result(() => firstSplice[k] = c.AddSplice(2.5f, info.ActionCount > 1 ? 1u : 0u)), "add_splice");
                    ExpectResult(Result(() => firstTransition[k] = c.AddTransition(4.0f, info.StyleCount - 1)), "add_transition");
                    ExpectResult(Result(() => c.AddSplice(9.0f, 0)), "add_splice");
                    ExpectResult(Result(() => c.AddTransition(16.0f, 0)), "add_transition");
                }

                var moved = new float[8];
                var probes = new float[6];
                var events = new SmgEvent[32 + 5];
                for (frame = 0; frame < frames; ++frame)
                {
                    character = -1;
                    if (frame > 0 && frame % 1500 == 0)
                    {
                        uint n = (uint)(frame / 1500);
                        for (int i = 0; i < 8; i += 2)
                        {
                            moved[i] = Ring[i] + 2.0f * n;
                            moved[i + 1] = Ring[i + 1];
                        }
                        for (int k = 0; k < Characters; ++k)
                        {
                            character = k;
                            SmgCharacter c = ch[k];
                            float length = 0;
                            ExpectResult(Result(() => c.AppendPath(moved)), "append_path");
                            ExpectResult(Result(() => length = c.PathLength), "get_path_length");
                            float copy = length;
                            Expect((byte*)&copy, 4, "path length");
                            ExpectResult(Result(() => c.AddSplice(length - 3.0f, n % info.ActionCount)), "add_splice");
                            ExpectResult(Result(() => c.AddTransition(length - 5.0f, n % info.StyleCount)), "add_transition");
                            if (n == 2)
                                ExpectResult(Result(() => c.MoveConstraint(firstSplice[k], 11.0f)), "move_constraint");
                            if (n == 3)
                                ExpectResult(Result(() => c.RemoveConstraint(firstTransition[k])), "remove_constraint");
                        }
                    }
                    if (frame == 3000)
                        ExpectResult(Result(() => ch[2].SetIk(false)), "set_ik");
                    if (frame == 4000)
                        ExpectResult(Result(() => ch[0].SetErrorThreshold(0.5f)), "set_error_threshold");
                    if (frame == 5000)
                    {
                        ExpectResult(Result(() => ch[1].SetStyle(0)), "set_style");
                        ExpectResult(Result(() => ch[1].SetAction(info.ActionCount - 1)), "set_action");
                    }
                    if (frame == 7000)
                        ExpectResult(Result(() => ch[0].SetPath(Square)), "set_path");
                    if (frame == 8000)
                        ExpectResult(Result(() => ch[1].ClearConstraints()), "clear_constraints");
                    if (frame == 8500)
                        ExpectResult(Result(() => ch[2].ClearPath()), "clear_path");
                    if (frame == 9000)
                        ExpectResult(Result(() => ch[2].SetPath(Square)), "set_path");

                    if (frame >= 2000 && frame < 6000)
                    {
                        character = 2;
                        ExpectResult(Result(() => ch[2].GetGroundProbes(probes)), "get_ground_probes");
                        ExpectFloats(probes, "ground probes");
                        var g = new SmgGround
                        {
                            FootHeight = new SmgFloat2(0.1f * probes[1], 0.1f * probes[3]),
                            RootHeight = 0.1f * probes[5],
                        };
                        ExpectResult(Result(() => ch[2].SetGround(g)), "set_ground");
                    }
                    if (frame == 6000)
                        ExpectResult(Result(() => ch[2].ClearGround()), "set_ground NULL");

                    float dt = frame % 97 == 0 ? 0.0f : frame % 7 == 3 ? 0.05f : 1.0f / 60.0f;
                    for (int k = 0; k < Characters; ++k)
                    {
                        character = k;
                        SmgCharacter c = ch[k];
                        ExpectResult(Result(() => c.Step(dt)), "step");
                        int count = 0;
                        Array.Clear(events, 0, events.Length);
                        ExpectResult(Result(() => count = c.GetEvents(events)), "get_events");
                        uint countCopy = (uint)count;
                        Expect((byte*)&countCopy, 4, "event count");
                        fixed (SmgEvent* e = events)
                            Expect((byte*)e, count * sizeof(SmgEvent), "events");
                        SmgRootMotion rm = default(SmgRootMotion);
                        ExpectResult(Result(() => rm = c.RootMotion), "get_root_motion");
                        SmgRootMotion rmCopy = rm;
                        Expect((byte*)&rmCopy, sizeof(SmgRootMotion), "root motion");
                        SmgCharacterState st = default(SmgCharacterState);
                        ExpectResult(Result(() => st = c.State), "get_state");
                        SmgCharacterState stCopy = st;
                        Expect((byte*)&stCopy, sizeof(SmgCharacterState), "state");
                        if (k == 0 && frame >= 1000 && frame < 2500)
                        {
                            var movedTo = new SmgFloat3(st.Position.X + 0.002f, st.Position.Y, st.Position.Z);
                            ExpectResult(Result(() => c.SetGroundPosition(movedTo, st.Heading)), "set_ground_position");
                        }
                        ExpectResult(Result(() => c.GetLocalPose(root, rot)), "get_local_pose");
                        ExpectFloats(root, "root translation");
                        ExpectFloats(rot, "local rotations");
                        ExpectResult(Result(() => c.GetModelMatrices(SmgSpace.World, mat)), "get_model_matrices");
                        ExpectFloats(mat, "world matrices");
                        if (frame % 10 == 0)
                        {
                            ExpectResult(Result(() => c.GetModelMatrices(SmgSpace.Character, mat)), "get_model_matrices character");
                            ExpectFloats(mat, "character matrices");
                        }
                    }
                }

                character = -1;
                for (int k = 0; k < Characters; ++k)
                {
                    ch[k].Dispose();
                    ExpectResult(SmgResult.Ok, "C character_destroy");
                }
                Check.Equal(0u, graph.Info.CharacterCount, "characters left on the graph");
                ExpectResult(SmgResult.Ok, "C graph_destroy");
            }
        }
    }
}
