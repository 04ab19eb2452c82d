// Uneven ground for SmgPathCharacter: before each step, a ray cast down
// at each of libsmg's probes (left foot, right foot, root) against the
// given layers; the highest hit that is not part of the character itself
// (its CharacterController, ragdoll colliders) is the ground there. A probe
// that hits nothing keeps its last height. Buffers are allocated once:
// nothing allocates per frame.
using UnityEngine;

namespace Smg.Unity
{
    sealed class SmgGroundSensor
    {
        readonly SmgGroundProbes probes = new SmgGroundProbes();
        readonly RaycastHit[] hits = new RaycastHit[8];
        readonly float[] last = new float[SmgGroundProbes.Count];

        public SmgGroundSensor(float startHeight)
        {
            for (int p = 0; p < last.Length; ++p)
                last[p] = startHeight;
        }

        /// <summary>Measures the ground for `character`'s next step: rays
        /// from `above` metres over the character's height down to `below`
        /// metres under it.</summary>
        public void Measure(SmgCharacter character, Transform self, LayerMask layers, float above, float below)
        {
            probes.Read(character);
            float top = self.position.y + above;
            for (int p = 0; p < SmgGroundProbes.Count; ++p)
            {
                probes.GetMirrored(p, out float x, out float z);
                var ray = new Ray(new Vector3(x, top, z), Vector3.down);
                int n = Physics.RaycastNonAlloc(ray, hits, above + below, layers, QueryTriggerInteraction.Ignore);
                bool found = false;
                float best = 0.0f;
                for (int h = 0; h < n; ++h)
                {
                    if (hits[h].collider.transform.IsChildOf(self))
                        continue;
                    float y = hits[h].point.y;
                    if (!found || y > best)
                        best = y;
                    found = true;
                }
                if (found)
                    last[p] = best;
                probes.SetHeight(p, last[p]);
            }
            probes.Apply(character);
        }
    }
}
