// One SmgGraph per graph asset, shared by every component that uses it,
// through this domain's SmgGraphRegistry (counted and thread-safe: the
// last Release disposes the graph; the native graph then goes away with
// its last character).
//
// With domain reload off (Enter Play Mode Options), statics outlive a play
// session: the registry is cleared when a session starts, so graphs left
// from the last one are disposed and assets edited since are loaded again.
using System.IO;
using UnityEngine;

namespace Smg.Unity
{
    public static class SmgGraphCache
    {
        /// <summary>The graph in a TextAsset (import a blob as NAME.smg.bytes
        /// so Unity makes it a TextAsset).</summary>
        public static SmgGraph Acquire(TextAsset asset)
        {
            return SmgGraphRegistry.Shared.Acquire("asset:" + asset.GetInstanceID(),
                                                   () => SmgGraph.LoadMemory(asset.bytes, Options(asset.name)));
        }

        /// <summary>A blob under Application.streamingAssetsPath, read as a
        /// file (desktop players and the editor; Android and WebGL keep
        /// streaming assets inside the package: load the bytes with
        /// UnityWebRequest and use SmgGraph.LoadMemory).</summary>
        public static SmgGraph AcquireStreamingAsset(string relativePath)
        {
            string path = Path.Combine(Application.streamingAssetsPath, relativePath);
            return SmgGraphRegistry.Shared.Acquire("file:" + path, () => SmgGraph.LoadFile(path, Options(relativePath)));
        }

        public static void Release(SmgGraph graph)
        {
            SmgGraphRegistry.Shared.Release(graph);
        }

        [RuntimeInitializeOnLoadMethod(RuntimeInitializeLoadType.SubsystemRegistration)]
        static void StartSession()
        {
            SmgGraphRegistry.Shared.Clear();
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
