// SmgMirrorX (the frame conversion SmgPathCharacter poses bones with)
// against libsmg's own world matrices: forward kinematics in the mirrored
// frame, from the mirrored local pose and rest offsets, must put every
// joint where libsmg's matrices put it, mirrored, with the mirrored
// orientation (M R M, M = diag(-1, 1, 1)).
using System;

namespace Smg.Tests
{
    static class MirrorTest
    {
        // v rotated by unit quaternion q (x, y, z, w at q[i..i+3])
        static void Rotate(float[] q, int i, float vx, float vy, float vz, out float rx, out float ry, out float rz)
        {
            float x = q[i], y = q[i + 1], z = q[i + 2], w = q[i + 3];
            float tx = 2 * (y * vz - z * vy), ty = 2 * (z * vx - x * vz), tz = 2 * (x * vy - y * vx);
            rx = vx + w * tx + (y * tz - z * ty);
            ry = vy + w * ty + (z * tx - x * tz);
            rz = vz + w * tz + (x * ty - y * tx);
        }

        public static void MatchesLibsmg(string blob)
        {
            using (SmgGraph graph = SmgGraph.LoadFile(blob))
            using (SmgCharacter ch = SmgCharacter.Create(graph, SmgCharacterDesc.Create()))
            {
                int n = graph.JointCount;
                var parents = new int[n];
                var offsets = new SmgFloat3[n];
                for (int j = 0; j < n; ++j)
                {
                    SmgJoint joint = graph.GetJoint(j);
                    parents[j] = joint.Parent;
                    offsets[j] = joint.RestOffset;
                }
                var root = new float[3];
                var local = new float[4 * n];
                var world = new float[4 * n];
                var matrices = new float[16 * n];
                var px = new float[n];
                var py = new float[n];
                var pz = new float[n];
                float[] sign = { -1, 1, 1 };
                double worst = 0;
                ch.SetPath(new float[] { 0, 0, 0, 6, -5, 10, -10, 4 });
                ch.AddTransition(6.0f, graph.Info.StyleCount - 1);
                for (int f = 1; f <= 600; ++f)
                {
                    ch.Step(1.0f / 60.0f);
                    if (f % 50 != 0)
                        continue;
                    ch.GetLocalPose(root, local);
                    ch.GetModelMatrices(SmgSpace.World, matrices);
                    SmgMirrorX.WorldRotations(local, parents, world);
                    for (int j = 0; j < n; ++j)
                    {
                        int p = parents[j];
                        if (p < 0)
                        {
                            px[j] = -root[0];
                            py[j] = root[1];
                            pz[j] = root[2];
                        }
                        else
                        {
                            float rx, ry, rz;
                            Rotate(world, 4 * p, -offsets[j].X, offsets[j].Y, offsets[j].Z, out rx, out ry, out rz);
                            px[j] = px[p] + rx;
                            py[j] = py[p] + ry;
                            pz[j] = pz[p] + rz;
                        }
                        int m = 16 * j;
                        worst = Math.Max(worst, Math.Abs(px[j] + matrices[m + 12]));
                        worst = Math.Max(worst, Math.Abs(py[j] - matrices[m + 13]));
                        worst = Math.Max(worst, Math.Abs(pz[j] - matrices[m + 14]));
                        for (int c = 0; c < 3; ++c) // column c of the rotation: the image of axis c
                        {
                            float ax = c == 0 ? 1 : 0, ay = c == 1 ? 1 : 0, az = c == 2 ? 1 : 0, rx, ry, rz;
                            Rotate(world, 4 * j, ax, ay, az, out rx, out ry, out rz);
                            worst = Math.Max(worst, Math.Abs(rx - sign[0] * sign[c] * matrices[m + 4 * c]));
                            worst = Math.Max(worst, Math.Abs(ry - sign[1] * sign[c] * matrices[m + 4 * c + 1]));
                            worst = Math.Max(worst, Math.Abs(rz - sign[2] * sign[c] * matrices[m + 4 * c + 2]));
                        }
                    }
                    // the mirrored heading's forward is libsmg's forward, mirrored
                    double h = ch.State.Heading, yaw = SmgMirrorX.HeadingToYawDegrees((float)h) * Math.PI / 180.0;
                    worst = Math.Max(worst, Math.Abs(Math.Sin(yaw) + Math.Sin(h)) + Math.Abs(Math.Cos(yaw) - Math.Cos(h)));
                    worst = Math.Max(worst, Math.Abs(SmgMirrorX.YawDegreesToHeading(SmgMirrorX.HeadingToYawDegrees((float)h)) - h));
                }
                Check.True(worst < 1e-4, "mirrored FK matches libsmg's matrices within 0.1 mm / 1e-4 (worst " + worst.ToString("G3") + ")");
            }
        }
    }
}
