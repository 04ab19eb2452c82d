// One SmgGraph per graph asset, shared by every component that uses it
// (a graph is immutable and shareable; loading it once per character would
// waste its memory). Counted: the last Release disposes it, and the native
// graph then goes away with its last character (SmgGraph's lifetime rule).
using System.Collections.Generic;
using System.IO;
using UnityEngine;

namespace Smg.Unity
{
    public static class SmgGraphCache
    {
        sealed class Entry
        {
            public SmgGraph Graph;
            public int Users;
        }

        static readonly Dictionary<string, Entry> Graphs = new Dictionary<string, Entry>();

        /// <summary>The graph in a TextAsset (import a blob as NAME.smg.bytes
        /// so Unity makes it a TextAsset).</summary>
        public static SmgGraph Acquire(TextAsset asset)
        {
            return Acquire("asset:" + asset.GetInstanceID(), () => SmgGraph.LoadMemory(asset.bytes, Options(asset.name)));
        }

        /// <summary>A blob under Application.streamingAssetsPath, read as a
        /// file (desktop players and the editor; Android and WebGL keep
        /// streaming assets inside the package: load the bytes with
        /// UnityWebRequest and use SmgGraph.LoadMemory).</summary>
        public static SmgGraph AcquireStreamingAsset(string relativePath)
        {
            string path = Path.Combine(Application.streamingAssetsPath, relativePath);
            return Acquire("file:" + path, () => SmgGraph.LoadFile(path, Options(relativePath)));
        }

        public static void Release(SmgGraph graph)
        {
            foreach (var pair in Graphs)
            {
                if (pair.Value.Graph != graph)
                    continue;
                if (--pair.Value.Users == 0)
                {
                    Graphs.Remove(pair.Key);
                    graph.Dispose();
                }
                return;
            }
        }

        static SmgGraph Acquire(string key, System.Func<SmgGraph> load)
        {
            Entry e;
            if (!Graphs.TryGetValue(key, out e))
            {
                e = new Entry { Graph = load() };
                Graphs.Add(key, e);
            }
            ++e.Users;
            return e.Graph;
        }

        // libsmg's explanation of a bad blob goes to the console.
        static SmgGraphOptions Options(string name)
        {
            return new SmgGraphOptions
            {
                Logger = (level, line) =>
                {
                    if (level == SmgLogLevel.Error)
                        Debug.LogError("libsmg (" + name + "): " + line);
                    else
                        Debug.Log("libsmg (" + name + "): " + line);
                },
            };
        }
    }
}
