// The graph registry behind SmgGraphCache: one per application domain,
// emptied when a play session starts, and safe to use from many threads.
using System;
using System.Threading;
using NUnit.Framework;

namespace Smg.Tests
{
    [TestFixture]
    public class SmgGraphRegistryTests
    {
        [Test]
        public void SharedRegistryIsPerDomain()
        {
            string path = TestGraph.Path;
            SmgGraph graph = SmgGraphRegistry.Shared.Acquire("per-domain " + path, () => SmgGraph.LoadFile(path));
            AppDomain other = null;
            try
            {
                Assert.GreaterOrEqual(SmgGraphRegistry.Shared.Count, 1);
                try
                {
                    other = AppDomain.CreateDomain("smg-registry-test", null, AppDomain.CurrentDomain.SetupInformation);
                }
                catch (NotSupportedException)
                {
                    Assert.Ignore("this runtime has one application domain");
                }
                try
                {
                    other.DoCallBack(CountInThisDomain);
                }
                catch (System.IO.FileNotFoundException e)
                {
                    // Unity's editor keeps script assemblies where a new
                    // domain does not look for them
                    Assert.Ignore("the second domain cannot load the tests: " + e.Message);
                }
                Assert.AreEqual(0, (int)other.GetData("count"), "graphs held in another domain");
            }
            finally
            {
                if (other != null)
                    AppDomain.Unload(other);
                SmgGraphRegistry.Shared.Release(graph);
            }
        }

        static void CountInThisDomain()
        {
            AppDomain.CurrentDomain.SetData("count", SmgGraphRegistry.Shared.Count);
        }

        [Test]
        public void ClearStartsASessionAfresh()
        {
            string path = TestGraph.Path;
            var registry = new SmgGraphRegistry();
            int loads = 0;
            Func<SmgGraph> load = () => { ++loads; return SmgGraph.LoadFile(path); };
            SmgGraph old = registry.Acquire("a", load);
            registry.Clear();
            Assert.AreEqual(0, registry.Count);
            Assert.Throws<ObjectDisposedException>(() => { SmgGraphInfo i = old.Info; },
                                                   "the last session's graph is disposed");
            SmgGraph fresh = registry.Acquire("a", load);
            Assert.AreNotSame(old, fresh);
            Assert.AreEqual(2, loads, "loaded again in the new session");
            registry.Release(old); // a component of the last session going late
            Assert.AreEqual(1, registry.Count);
            Assert.AreEqual((uint)fresh.JointCount, fresh.Info.JointCount, "the new graph is in use");
            registry.Release(fresh);
            Assert.AreEqual(0, registry.Count);
            Assert.Throws<ObjectDisposedException>(() => { SmgGraphInfo i = fresh.Info; }, "the last Release disposes");
        }

        [Test]
        public void ThreadsShareOneGraphPerKey()
        {
            string path = TestGraph.Path;
            var registry = new SmgGraphRegistry();
            const int Threads = 8, Rounds = 200;
            int loading = 0, overlapped = 0, loads = 0, bad = 0;
            Func<SmgGraph> load = () =>
            {
                if (Interlocked.Increment(ref loading) != 1)
                    Interlocked.Increment(ref overlapped);
                Interlocked.Increment(ref loads);
                SmgGraph g = SmgGraph.LoadFile(path);
                Interlocked.Decrement(ref loading);
                return g;
            };
            var errors = new Exception[Threads];
            var threads = new Thread[Threads];
            for (int t = 0; t < Threads; ++t)
            {
                int index = t;
                threads[t] = new Thread(() =>
                {
                    try
                    {
                        for (int r = 0; r < Rounds; ++r)
                        {
                            string key = (r & 1) == 0 ? "even" : "odd";
                            SmgGraph a = registry.Acquire(key, load);
                            SmgGraph b = registry.Acquire(key, load);
                            if (a != b || a.IsClosed)
                                Interlocked.Increment(ref bad);
                            registry.Release(a);
                            if (a.IsClosed)
                                Interlocked.Increment(ref bad); // b still holds it
                            registry.Release(b);
                        }
                    }
                    catch (Exception e)
                    {
                        errors[index] = e;
                    }
                });
            }
            foreach (Thread t in threads)
                t.Start();
            foreach (Thread t in threads)
                t.Join();
            foreach (Exception e in errors)
                if (e != null)
                    throw e;
            Assert.AreEqual(0, bad, "acquires that got another or a disposed graph");
            Assert.AreEqual(0, overlapped, "loads run at the same time");
            Assert.AreEqual(0, registry.Count, "every graph released");
            Assert.Greater(loads, 0);
        }
    }
}
