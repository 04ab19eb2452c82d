// Name -> index lookups of one graph, remembered: the first lookup of a name
// encodes it to UTF-8 and asks libsmg; later ones are a dictionary hit that
// allocates nothing, so gameplay code may look names up every frame. A
// graph's names never change, so an entry never goes stale. The threads
// sharing a graph share its index: every access is locked.
using System;
using System.Collections.Generic;

namespace Smg
{
    sealed class SmgNameIndex
    {
        // names a graph does not have are remembered too (TryFindJoint asks
        // for bones that may not exist), up to this many
        const int MaxMisses = 256;

        readonly Dictionary<string, int> indices = new Dictionary<string, int>(StringComparer.Ordinal);
        int misses;

        public bool TryGet(string name, out int index)
        {
            if (name == null)
                throw new ArgumentNullException(nameof(name));
            lock (indices)
                return indices.TryGetValue(name, out index);
        }

        /// <summary>Remembers `index` for `name` (-1: not in the graph).</summary>
        public void Add(string name, int index)
        {
            lock (indices)
            {
                if (indices.ContainsKey(name))
                    return;
                if (index < 0)
                {
                    if (misses == MaxMisses)
                        return;
                    ++misses;
                }
                indices.Add(name, index);
            }
        }
    }
}
