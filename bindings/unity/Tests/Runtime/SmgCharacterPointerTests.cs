// A lease on a character's native pointer is a class: copies share it, and
// disposing it twice (or two copies) releases the character once.
using NUnit.Framework;

namespace Smg.Tests
{
    [TestFixture]
    public class SmgCharacterPointerTests
    {
        [Test]
        public void DoubleDisposeReleasesOnce()
        {
            using (SmgGraph graph = TestGraph.Load())
            {
                SmgCharacter ch = TestGraph.Walker(graph);
                SmgCharacter other = TestGraph.Walker(graph);
                SmgCharacterPointer lease = ch.AcquirePointer();
                SmgCharacterPointer copy = lease;
                ch.Dispose();
                Assert.AreEqual(2u, graph.Info.CharacterCount, "the lease keeps its character alive");
                Assert.AreEqual(SmgResult.Ok, SmgNativeRaw.smg_character_step(lease.Value, 1.0f / 60.0f));
                lease.Dispose();
                Assert.IsFalse(copy.IsHeld, "a copy is the same lease");
                Assert.AreEqual(1u, graph.Info.CharacterCount, "the character went with its lease");
                copy.Dispose();
                lease.Dispose();
                Assert.AreEqual(1u, graph.Info.CharacterCount, "more Dispose calls release nothing else");
                other.Step(1.0f / 60.0f); // the other character is untouched
                other.Dispose();
                Assert.AreEqual(0u, graph.Info.CharacterCount);
            }
        }

        [Test]
        public void LeasesOfOneCharacterAreCountedApart()
        {
            using (SmgGraph graph = TestGraph.Load())
            {
                SmgCharacter ch = TestGraph.Walker(graph);
                SmgCharacterPointer a = ch.AcquirePointer();
                SmgCharacterPointer b = ch.AcquirePointer();
                ch.Dispose();
                a.Dispose();
                a.Dispose();
                Assert.AreEqual(1u, graph.Info.CharacterCount, "b still holds the character");
                Assert.AreEqual(SmgResult.Ok, SmgNativeRaw.smg_character_step(b.Value, 1.0f / 60.0f));
                b.Dispose();
                Assert.AreEqual(0u, graph.Info.CharacterCount);
            }
        }
    }
}
