/*
 * standing.c - standing stretches of a frame pool (standing.h).
 *
 * Per clip, a frame stands when, over +-SMGI_STAND_SPAN seconds (clamped
 * to the clip), its ground point moves slower than SMGI_STAND_SPEED leg
 * lengths per second and turns slower than SMGI_STAND_TURN, and both feet
 * carry the contact label. Runs of standing frames of at least
 * SMGI_STAND_MIN_SECONDS are kept; a run whose ground point strays more
 * than SMGI_STAND_DRIFT leg lengths from where it began is cut there and
 * continues as a new run (a slow shuffle is not standing still).
 */
#include "standing.h"

#include <math.h>

static float wrap_pi(float a) {
  const float two_pi = 6.2831853f;
  a = fmodf(a, two_pi);
  if (a > 3.14159265f) a -= two_pi;
  if (a < -3.14159265f) a += two_pi;
  return a;
}

static int stands(const smgi_frame* f, uint32_t first, uint32_t count,
                  uint32_t i, uint32_t span, float fps, float speed,
                  float turn) {
  const uint32_t both = SMGI_FRAME_LEFT_CONTACT | SMGI_FRAME_RIGHT_CONTACT;
  if ((f[i].flags & both) != both) return 0;
  uint32_t a = i >= first + span ? i - span : first;
  uint32_t b = i + span < first + count ? i + span : first + count - 1u;
  if (b <= a) return 0;
  const float t = (float)(b - a) / fps;
  const float dx = f[b].root2d[0] - f[a].root2d[0];
  const float dz = f[b].root2d[1] - f[a].root2d[1];
  return sqrtf(dx * dx + dz * dz) <= speed * t &&
         fabsf(wrap_pi(f[b].root2d[2] - f[a].root2d[2])) <= turn * t;
}

uint32_t smgi_standing_find(const smgi_frame* frames, uint32_t frame_count,
                            const smgi_clip* clips, uint32_t clip_count,
                            float frame_rate, float leg_length,
                            smgi_stand* out, uint32_t cap) {
  if (!frames || !clips || !(frame_rate > 0.0f) || !(leg_length > 0.0f))
    return 0;
  const uint32_t span = (uint32_t)(SMGI_STAND_SPAN * frame_rate + 0.5f);
  const uint32_t min_len =
      (uint32_t)ceilf(SMGI_STAND_MIN_SECONDS * frame_rate - 1e-3f);
  const float speed = SMGI_STAND_SPEED * leg_length;
  const float drift = SMGI_STAND_DRIFT * leg_length;
  uint32_t found = 0;
  for (uint32_t c = 0; c < clip_count; ++c) {
    const smgi_clip* cl = &clips[c];
    if ((cl->flags & SMGI_CLIP_BLEND) || cl->frame_count < 2u ||
        cl->first_frame > frame_count ||
        cl->frame_count > frame_count - cl->first_frame)
      continue;
    const uint32_t first = cl->first_frame, end = first + cl->frame_count;
    uint32_t run = SMGI_NONE;
    for (uint32_t i = first; i <= end; ++i) {
      int still = i < end && stands(frames, first, cl->frame_count, i, span,
                                    frame_rate, speed, SMGI_STAND_TURN);
      if (still && run != SMGI_NONE) {
        const float dx = frames[i].root2d[0] - frames[run].root2d[0];
        const float dz = frames[i].root2d[1] - frames[run].root2d[1];
        if (dx * dx + dz * dz > drift * drift) still = 0; /* cut here */
      }
      if (!still && run != SMGI_NONE) {
        if (i - run >= min_len) {
          if (found < cap && out) {
            out[found].first = run;
            out[found].count = i - run;
            out[found].clip = c;
            out[found].reserved = 0;
          }
          ++found;
        }
        run = SMGI_NONE;
        /* a cut frame may begin the next run */
        if (i < end && stands(frames, first, cl->frame_count, i, span,
                              frame_rate, speed, SMGI_STAND_TURN))
          run = i;
      } else if (still && run == SMGI_NONE) {
        run = i;
      }
    }
  }
  return found;
}
