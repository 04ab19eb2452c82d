// libsmg's poses in a left-handed Y-up frame (Unity's). libsmg is
// right-handed (Y up, heading 0 faces +Z); mirroring the X axis maps one
// frame onto the other and keeps a left foot a left foot: points
// (x, y, z) -> (-x, y, z), rotations (x, y, z, w) -> (x, -y, -z, w), headings
// negated. Mirroring commutes with composing rotations, so world rotations
// can be accumulated in either frame. Plain floats, no engine types: the
// C# test checks it against libsmg's own model matrices.
using System;

namespace Smg
{
    public static class SmgMirrorX
    {
        /// <summary>Mirrored world rotation of every joint (4 floats x, y,
        /// z, w each) from a local pose (GetLocalPose's rotations) and the
        /// joints' parents (parents before children, -1 for the root).</summary>
        public static void WorldRotations(ReadOnlySpan<float> localRotations, ReadOnlySpan<int> parents, Span<float> world)
        {
            int n = parents.Length;
            if (localRotations.Length < 4 * n || world.Length < 4 * n)
                throw new ArgumentException("4 floats per joint");
            for (int j = 0; j < n; ++j)
            {
                int i = 4 * j;
                float x = localRotations[i], y = -localRotations[i + 1], z = -localRotations[i + 2], w = localRotations[i + 3];
                int p = parents[j];
                if (p < 0)
                {
                    world[i] = x;
                    world[i + 1] = y;
                    world[i + 2] = z;
                    world[i + 3] = w;
                    continue;
                }
                if (p >= j)
                    throw new ArgumentException("parents must come before their children");
                int k = 4 * p;
                float px = world[k], py = world[k + 1], pz = world[k + 2], pw = world[k + 3];
                // Hamilton product parent * local (Unity's Quaternion * order)
                world[i] = pw * x + px * w + py * z - pz * y;
                world[i + 1] = pw * y + py * w + pz * x - px * z;
                world[i + 2] = pw * z + pz * w + px * y - py * x;
                world[i + 3] = pw * w - px * x - py * y - pz * z;
            }
        }

        /// <summary>A libsmg heading (radians) as a yaw about +Y in degrees
        /// in the mirrored frame (Unity's eulerAngles.y).</summary>
        public static float HeadingToYawDegrees(float heading)
        {
            return -heading * (float)(180.0 / Math.PI);
        }

        /// <summary>The inverse of HeadingToYawDegrees.</summary>
        public static float YawDegreesToHeading(float yawDegrees)
        {
            return -yawDegrees * (float)(Math.PI / 180.0);
        }

        /// <summary>A point or displacement in the other frame (the same
        /// map both ways): (x, y, z) -> (-x, y, z).</summary>
        public static SmgFloat3 Point(SmgFloat3 p)
        {
            return new SmgFloat3(-p.X, p.Y, p.Z);
        }

        /// <summary>The root motion of the last step for a mover in the
        /// mirrored frame: the world displacement (metres) and the change
        /// of yaw about +Y in degrees (Unity's eulerAngles.y).</summary>
        public static void RootMotion(in SmgRootMotion motion, out SmgFloat3 displacement, out float yawDegrees)
        {
            displacement = Point(motion.Translation);
            yawDegrees = HeadingToYawDegrees(motion.Yaw);
        }

        /// <summary>Tells `character` where the mover put it: a position in
        /// the mirrored frame (y: the floor there) and a yaw in degrees.</summary>
        public static void SetGroundPosition(SmgCharacter character, SmgFloat3 position, float yawDegrees)
        {
            if (character == null)
                throw new ArgumentNullException(nameof(character));
            character.SetGroundPosition(Point(position), YawDegreesToHeading(yawDegrees));
        }
    }
}
