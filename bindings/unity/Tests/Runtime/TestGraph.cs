// The graph blob the package tests load: $SMG_TEST_BLOB (make test-csharp
// sets it), else the synthetic default graph the package's sample carries
// (Samples~/PathFollower/Graph, read in place from the package's folder).
using System;
using System.IO;
using NUnit.Framework;

namespace Smg.Tests
{
    static class TestGraph
    {
        const string InPackage = "Packages/com.libsmg.smg/Samples~/PathFollower/Graph/default.smg.bytes";

        public static string Path
        {
            get
            {
                string env = Environment.GetEnvironmentVariable("SMG_TEST_BLOB");
                // Unity resolves a package's "Packages/NAME/..." path to
                // where the package really is (its cache, a local folder)
                // in Path.GetFullPath
                string path = System.IO.Path.GetFullPath(!string.IsNullOrEmpty(env) ? env : InPackage);
                if (!File.Exists(path))
                    Assert.Ignore("no graph blob at " + path + " (set SMG_TEST_BLOB)");
                return path;
            }
        }

        public static SmgGraph Load()
        {
            return SmgGraph.LoadFile(Path);
        }

        /// <summary>A character walking a straight path.</summary>
        public static SmgCharacter Walker(SmgGraph graph)
        {
            SmgCharacter ch = SmgCharacter.Create(graph, SmgCharacterDesc.Create());
            ch.SetPath(new float[] { 0, 0, 0, 20 });
            return ch;
        }
    }
}
