// Error paths: libsmg's codes become SmgException with libsmg's text;
// argument mistakes the binding can see itself are ArgumentExceptions.
using System;
using System.Collections.Generic;
using System.IO;

namespace Smg.Tests
{
    static class ErrorTest
    {
        public static void GraphQueries(string blob)
        {
            using (SmgGraph graph = SmgGraph.LoadMemory(File.ReadAllBytes(blob)))
            {
                SmgGraphInfo info = graph.Info;
                Check.True(info.JointCount > 0 && info.StyleCount > 0 && info.ActionCount > 0, "a graph with joints, styles, actions");
                Check.Equal((ulong)new FileInfo(blob).Length, info.BlobSize, "blob size");
                Check.Equal((int)info.JointCount, graph.JointCount, "JointCount");
                SmgJoint root = graph.GetJoint(0);
                Check.Equal(SmgNative.NoParent, root.Parent, "root parent");
                for (int i = 0; i < graph.JointCount; ++i)
                {
                    SmgJoint j = graph.GetJoint(i);
                    int found;
                    Check.True(graph.TryFindJoint(j.Name, out found) && found == i, "joint " + j.Name + " found by name");
                    Check.True(j.Parent < i, "parents come first");
                }
                for (uint s = 0; s < info.StyleCount; ++s)
                    Check.Equal(s, graph.FindStyle(graph.GetStyleName(s)), "style by name");
                for (uint a = 0; a < info.ActionCount; ++a)
                    Check.Equal(a, graph.FindAction(graph.GetActionName(a)), "action by name");
                int none;
                Check.True(!graph.TryFindJoint("no such joint", out none) && none == -1, "unknown joint: false");
                Check.Fails(SmgResult.ErrorUnknownStyle, () => graph.FindStyle("no such style"), "FindStyle");
                Check.Fails(SmgResult.ErrorUnknownAction, () => graph.FindAction("no such action"), "FindAction");
                Check.Fails(SmgResult.ErrorUnknownStyle, () => graph.GetStyleName(info.StyleCount), "GetStyleName");
                Check.Fails(SmgResult.ErrorOutOfRange, () => graph.GetJoint(graph.JointCount), "GetJoint past the end");
                Check.True(graph.CharacterMemorySize(SmgCharacterDesc.Create()) > 0, "character memory size");
            }
        }

        public static void CorruptBlob(string blob)
        {
            byte[] good = File.ReadAllBytes(blob);
            var cases = new List<KeyValuePair<string, byte[]>>();
            byte[] flipped = (byte[])good.Clone();
            flipped[good.Length / 2] ^= 0x40;
            cases.Add(new KeyValuePair<string, byte[]>("a flipped payload byte", flipped));
            byte[] magic = (byte[])good.Clone();
            magic[0] ^= 0xff;
            cases.Add(new KeyValuePair<string, byte[]>("a bad magic", magic));
            var truncated = new byte[good.Length - 100];
            Array.Copy(good, truncated, truncated.Length);
            cases.Add(new KeyValuePair<string, byte[]>("a truncated blob", truncated));

            foreach (var c in cases)
            {
                var logged = new List<string>();
                var options = new SmgGraphOptions { Logger = (level, line) => logged.Add(level + ": " + line) };
                SmgException e = Check.Throws<SmgException>(() => SmgGraph.LoadMemory(c.Value, options), c.Key);
                Check.True(e.Result >= SmgResult.ErrorBlobTruncated && e.Result <= SmgResult.ErrorBlobValue,
                           c.Key + " gives an SMG_ERROR_BLOB_* code (got " + e.Result + ")");
                Check.Equal("smg_graph_load_memory", e.Function, c.Key + " function");
                string text = SmgException.ResultString(e.Result);
                Check.True(e.Message.Contains(text), c.Key + ": \"" + e.Message + "\" carries \"" + text + "\"");
                Check.True(logged.Count == 1 && logged[0].StartsWith("Error: graph blob rejected"),
                           c.Key + ": the logger got libsmg's line (got " + string.Join(" | ", logged) + ")");
                Check.True(e.Message.Contains(logged[0].Substring("Error: ".Length)), c.Key + ": the exception carries the logged line");
            }
            // the flipped byte is caught by the checksum alone: skipping it
            // loads (every structural check still runs)
            using (SmgGraph g = SmgGraph.LoadMemory(good, new SmgGraphOptions { Flags = SmgGraphFlags.SkipChecksum }))
                Check.True(g.JointCount > 0, "SkipChecksum loads a good blob");
        }

        public static void MissingFile()
        {
            string path = Path.Combine(Path.GetTempPath(), "smg-csharp-no-such-dir", "none.smg");
            SmgException e = Check.Fails(SmgResult.ErrorIo, () => SmgGraph.LoadFile(path), "LoadFile");
            Check.True(e.Message.Contains(path), "the message names the file: " + e.Message);
            SmgException empty = Check.Throws<SmgException>(() => SmgGraph.LoadMemory(new byte[0]), "empty blob");
            Check.True(empty.Result >= SmgResult.ErrorBlobTruncated && empty.Result <= SmgResult.ErrorBlobValue,
                       "an empty blob gives an SMG_ERROR_BLOB_* code (got " + empty.Result + ")");
        }

        public static unsafe void BadStructSizes(string blob)
        {
            using (SmgGraph graph = SmgGraph.LoadFile(blob))
            {
                SmgCharacterDesc d = SmgCharacterDesc.Create();
                d.StructSize = 2; // smaller than struct_size itself
                Check.Fails(SmgResult.ErrorInvalidArgument, () => SmgCharacter.Create(graph, d), "desc size 2");
                d.StructSize = SmgCharacterDesc.Size + 8;
                Check.Fails(SmgResult.ErrorInvalidArgument, () => SmgCharacter.Create(graph, d), "desc larger than libsmg knows");
                Check.Fails(SmgResult.ErrorInvalidArgument, () => graph.CharacterMemorySize(d), "memory size, desc too large");

                SmgGraphInfo info = SmgGraphInfo.Create();
                info.StructSize = 3;
                Check.Equal(SmgResult.ErrorInvalidArgument, SmgNative.smg_graph_get_info(graph, &info), "raw get_info size 3");
                SmgJointInfo joint = SmgJointInfo.Create();
                joint.StructSize = SmgJointInfo.Size + 4;
                Check.Equal(SmgResult.ErrorInvalidArgument, SmgNative.smg_graph_get_joint(graph, 0, &joint), "raw get_joint too large");
                using (SmgCharacter ch = SmgCharacter.Create(graph, SmgCharacterDesc.Create()))
                {
                    SmgCharacterState state = SmgCharacterState.Create();
                    state.StructSize = SmgCharacterState.Size + 4;
                    Check.Equal(SmgResult.ErrorInvalidArgument, SmgNative.smg_character_get_state(ch, &state), "raw get_state too large");
                }
                SmgGraphDesc desc = SmgGraphDesc.Create();
                desc.StructSize = 2;
                IntPtr none;
                fixed (byte* path = System.Text.Encoding.UTF8.GetBytes(blob + "\0"))
                    Check.Equal(SmgResult.ErrorInvalidArgument, SmgNative.smg_graph_load_file(path, &desc, out none), "raw load, desc size 2");
                Check.Equal(0u, graph.Info.CharacterCount, "no character was left");
            }
        }

        public static void BadArguments(string blob)
        {
            using (SmgGraph graph = SmgGraph.LoadFile(blob))
            using (SmgCharacter ch = SmgCharacter.Create(graph, SmgCharacterDesc.Create()))
            {
                int joints = graph.JointCount;
                var root = new float[3];
                Check.Fails(SmgResult.ErrorBufferTooSmall, () => ch.GetLocalPose(root, new float[4 * (joints - 1)]), "pose for too few joints");
                Check.Fails(SmgResult.ErrorBufferTooSmall, () => ch.GetModelMatrices(SmgSpace.World, new float[16 * (joints - 1)]), "matrices for too few joints");
                Check.Throws<ArgumentException>(() => ch.GetLocalPose(new float[2], new float[4 * joints]), "root of 2 floats");
                Check.Throws<ArgumentException>(() => ch.GetModelMatrices(SmgSpace.World, new float[16 * joints - 1]), "matrices not 16 per joint");
                Check.Throws<ArgumentException>(() => ch.SetPath(new float[] { 0, 0, 1 }), "odd path");
                Check.Fails(SmgResult.ErrorInvalidArgument, () => ch.Step(-1.0f), "negative dt");
                Check.Fails(SmgResult.ErrorInvalidArgument, () => ch.Step(float.NaN), "NaN dt");
                Check.Fails(SmgResult.ErrorInvalidArgument, () => ch.SetPath(new float[] { 0, 0, float.NaN, 1 }), "NaN in path");
                ch.SetPath(new float[] { 0, 0, 0, 5 });
                Check.Fails(SmgResult.ErrorUnknownStyle, () => ch.AddTransition(1.0f, 999), "unknown style");
                Check.Fails(SmgResult.ErrorUnknownAction, () => ch.AddSplice(1.0f, 999), "unknown action");
                Check.Fails(SmgResult.ErrorOutOfRange, () => ch.AddSplice(50.0f, 0), "splice beyond the path");
                Check.Fails(SmgResult.ErrorNotFound, () => ch.RemoveConstraint(12345), "unknown constraint id");
                Check.Fails(SmgResult.ErrorCapacity, () => ch.SetPath(new float[2 * 513]), "path over capacity");
                Check.Throws<ArgumentNullException>(() => SmgCharacter.Create(null, SmgCharacterDesc.Create()), "null graph");
            }
        }
    }
}
