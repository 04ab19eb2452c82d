// Graphs shared by name: one SmgGraph per key (an asset, a file), counted,
// for every user that asks for the same graph (a graph is immutable and
// shareable; one copy per character would waste its memory). The last
// Release disposes it; the native graph then goes away with its last
// character (SmgGraph's lifetime rule).
//
// Thread-safe: Acquire, Release and Clear lock the registry, and a key is
// loaded once even when threads ask for it together. Shared is a static,
// so there is one per application domain; an engine that keeps statics
// across play sessions (Unity with domain reload off) calls Clear when a
// new session starts.
using System;
using System.Collections.Generic;

namespace Smg
{
    public sealed class SmgGraphRegistry
    {
        sealed class Entry
        {
            public SmgGraph Graph;
            public int Users;
        }

        readonly Dictionary<string, Entry> graphs = new Dictionary<string, Entry>(StringComparer.Ordinal);

        /// <summary>This application domain's registry.</summary>
        public static SmgGraphRegistry Shared { get; } = new SmgGraphRegistry();

        /// <summary>Graphs held (keys with at least one user).</summary>
        public int Count
        {
            get
            {
                lock (graphs)
                    return graphs.Count;
            }
        }

        /// <summary>The graph for `key`, loaded by `load` when no one holds
        /// it; every Acquire needs one Release.</summary>
        public SmgGraph Acquire(string key, Func<SmgGraph> load)
        {
            if (key == null)
                throw new ArgumentNullException(nameof(key));
            if (load == null)
                throw new ArgumentNullException(nameof(load));
            lock (graphs)
            {
                Entry e;
                if (!graphs.TryGetValue(key, out e))
                {
                    // loading under the lock: a second thread asking for the
                    // same key waits for this load instead of making another
                    e = new Entry { Graph = load() };
                    graphs.Add(key, e);
                }
                ++e.Users;
                return e.Graph;
            }
        }

        /// <summary>Gives back one Acquire; the last one disposes the
        /// graph. A graph the registry does not hold (after Clear) is left
        /// alone.</summary>
        public void Release(SmgGraph graph)
        {
            if (graph == null)
                return;
            SmgGraph dispose = null;
            lock (graphs)
            {
                foreach (var pair in graphs)
                {
                    if (pair.Value.Graph != graph)
                        continue;
                    if (--pair.Value.Users == 0)
                    {
                        graphs.Remove(pair.Key);
                        dispose = graph;
                    }
                    break;
                }
            }
            dispose?.Dispose();
        }

        /// <summary>Forgets every graph and disposes them (characters still
        /// using one keep it alive until they go).</summary>
        public void Clear()
        {
            var held = new List<SmgGraph>();
            lock (graphs)
            {
                foreach (Entry e in graphs.Values)
                    held.Add(e.Graph);
                graphs.Clear();
            }
            foreach (SmgGraph g in held)
                g.Dispose();
        }
    }
}
