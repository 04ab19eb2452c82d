/*
 * stopping.c - stopping and starting motion of a frame pool (stopping.h).
 *
 * Per lower clip, the standing stretches (standing.c) are the rests. The
 * hips' speed at a frame is their ground travel over +-SMGI_STAND_SPAN
 * seconds (clamped to the clip): the gait's sway averages out. Before a
 * rest, the speed is followed back while it does not fall (by more than
 * the standing bound: a step's own speed wobble) to where it peaks: that
 * peak is the locomotion the clip stops from, and it must be at least
 * SMGI_STOP_MOVING leg lengths per second. The stop's slowing begins at
 * the last frame before the rest moving at SMGI_STOP_CRUISE of the peak;
 * the segment begins as many frames again earlier (steady motion of the
 * same clip leading in: the runtime enters a stop at a graph node, and
 * the more of them it has, the better the remaining travel matches the
 * path). It rests SMGI_STAND_SPAN after the standing stretch begins
 * (the speeds there are over windows that still reach into the motion).
 * A start is the mirror image after a rest, its segment beginning with
 * the whole standing stretch (the runtime enters it anywhere there and
 * stands on until it moves off).
 */
#include "stopping.h"

#include <math.h>

#include "standing.h"

float smgi_stopping_travel(const smgi_frame* frames, uint32_t a,
                           uint32_t b) {
  float d = 0.0f;
  for (uint32_t i = a; i < b; ++i) {
    const float dx = frames[i + 1u].root2d[0] - frames[i].root2d[0];
    const float dz = frames[i + 1u].root2d[1] - frames[i].root2d[1];
    d += sqrtf(dx * dx + dz * dz);
  }
  return d;
}

typedef struct clip_view {
  const smgi_frame* f;
  uint32_t first, end, span;
  float fps;
} clip_view;

static float speed_at(const clip_view* c, uint32_t i) {
  const uint32_t a = i >= c->first + c->span ? i - c->span : c->first;
  const uint32_t b = i + c->span < c->end ? i + c->span : c->end - 1u;
  if (b <= a) return 0.0f;
  const float dx = c->f[b].root2d[0] - c->f[a].root2d[0];
  const float dz = c->f[b].root2d[1] - c->f[a].root2d[1];
  return sqrtf(dx * dx + dz * dz) * c->fps / (float)(b - a);
}

/* Inserts s into out[0 .. *n) by `first` (pool order), counting it even
 * where there is no room. */
static void put(smgi_stop_seg* out, uint32_t cap, uint32_t* n,
                const smgi_stop_seg* s) {
  if (out && *n < cap) {
    uint32_t i = *n;
    while (i > 0 && out[i - 1u].first > s->first) {
      out[i] = out[i - 1u];
      --i;
    }
    out[i] = *s;
  }
  ++*n;
}

/* From frame `from` stepping by `dir` (-1 back, +1 on) while the speed
 * does not fall by more than `wobble`: the frame where it peaks. */
static uint32_t peak_from(const clip_view* c, uint32_t from, int dir,
                          float wobble) {
  uint32_t i = from;
  float best = speed_at(c, i);
  uint32_t at = i;
  for (;;) {
    if (dir < 0 ? i <= c->first : i + 1u >= c->end) break;
    i = dir < 0 ? i - 1u : i + 1u;
    const float v = speed_at(c, i);
    if (v < best - wobble) break;
    if (v > best) {
      best = v;
      at = i;
    }
  }
  return at;
}

uint32_t smgi_stopping_find(const smgi_frame* frames, uint32_t frame_count,
                            const smgi_clip* clips, uint32_t clip_count,
                            float frame_rate, float leg_length,
                            smgi_stop_seg* out, uint32_t cap) {
  if (!frames || !clips || !(frame_rate > 0.0f) || !(leg_length > 0.0f))
    return 0;
  const float moving = SMGI_STOP_MOVING * leg_length;
  const float wobble = SMGI_STAND_SPEED * leg_length;
  uint32_t found = 0;
  for (uint32_t c = 0; c < clip_count; ++c) {
    const smgi_clip* cl = &clips[c];
    if ((cl->flags & SMGI_CLIP_BLEND) || !(cl->flags & SMGI_CLIP_LOWER) ||
        cl->frame_count < 2u || cl->first_frame > frame_count ||
        cl->frame_count > frame_count - cl->first_frame)
      continue;
    const clip_view v = {frames, cl->first_frame,
                         cl->first_frame + cl->frame_count,
                         (uint32_t)(SMGI_STAND_SPAN * frame_rate + 0.5f),
                         frame_rate};
    smgi_stand st[16]; /* a clip with more keeps its first ones */
    const uint32_t k = smgi_standing_find(frames, frame_count, cl, 1u,
                                          frame_rate, leg_length, st, 16u);
    for (uint32_t s = 0; s < k && s < 16u; ++s) {
      const uint32_t a = st[s].first, b = st[s].first + st[s].count - 1u;
      const uint32_t settle = v.span < st[s].count ? v.span : st[s].count - 1u;
      smgi_stop_seg g;
      g.clip = c;
      g.style = cl->label;
      if (a > v.first) { /* a stop into this rest */
        const uint32_t p = peak_from(&v, a - 1u, -1, wobble);
        const float top = speed_at(&v, p);
        uint32_t j = a - 1u;
        while (j > p && speed_at(&v, j) < SMGI_STOP_CRUISE * top) --j;
        if (top >= moving) {
          const uint32_t lead = a - j;
          g.first = j >= v.first + lead ? j - lead : v.first;
          g.rest = a + settle;
          g.last = b;
          g.kind = SMGI_STOP_KIND_STOP;
          g.speed = top;
          g.travel = smgi_stopping_travel(frames, g.first, g.rest);
          put(out, cap, &found, &g);
        }
      }
      if (b + 1u < v.end) { /* a start from this rest */
        const uint32_t p = peak_from(&v, b + 1u, 1, wobble);
        const float top = speed_at(&v, p);
        uint32_t j = b + 1u;
        while (j < p && speed_at(&v, j) < SMGI_STOP_CRUISE * top) ++j;
        if (top >= moving) {
          g.rest = b - settle;
          g.first = a; /* all of the standing before it */
          g.last = j;
          g.kind = SMGI_STOP_KIND_START;
          g.speed = top;
          g.travel = smgi_stopping_travel(frames, g.rest, g.last);
          put(out, cap, &found, &g);
        }
      }
    }
  }
  return found;
}
