// Uneven ground for one character, measured by the engine before each
// step: Read asks libsmg where (left foot, right foot, root), the engine
// measures the ground height at each probe (a ray cast down), SetHeight
// records it and Apply hands the heights to libsmg. Buffers are allocated
// once: nothing allocates per frame. Probe positions are given in the
// mirrored, left-handed frame (SmgMirrorX), where the engine casts its rays.
using System;

namespace Smg
{
    public sealed class SmgGroundProbes
    {
        public const int LeftFoot = 0;
        public const int RightFoot = 1;
        public const int Root = 2;
        public const int Count = 3;

        readonly float[] xz = new float[2 * Count];
        SmgGround ground = SmgGround.Create();

        /// <summary>Asks `character` where to measure for its next step.</summary>
        public void Read(SmgCharacter character)
        {
            if (character == null)
                throw new ArgumentNullException(nameof(character));
            character.GetGroundProbes(xz);
        }

        /// <summary>Probe `probe` (LeftFoot, RightFoot, Root) in the
        /// left-handed frame: x and z where to measure.</summary>
        public void GetMirrored(int probe, out float x, out float z)
        {
            Check(probe);
            x = -xz[2 * probe];
            z = xz[2 * probe + 1];
        }

        /// <summary>The ground height (world y) measured at `probe`.</summary>
        public void SetHeight(int probe, float height)
        {
            Check(probe);
            if (probe == Root)
                ground.RootHeight = height;
            else if (probe == LeftFoot)
                ground.FootHeight.X = height;
            else
                ground.FootHeight.Y = height;
        }

        /// <summary>Hands the heights to `character` for its next steps.</summary>
        public void Apply(SmgCharacter character)
        {
            if (character == null)
                throw new ArgumentNullException(nameof(character));
            character.SetGround(ground);
        }

        static void Check(int probe)
        {
            if ((uint)probe >= Count)
                throw new ArgumentOutOfRangeException(nameof(probe), "LeftFoot, RightFoot or Root");
        }
    }
}
