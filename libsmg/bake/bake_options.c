/*
 * bake_options.c - smgb_options_resolve (bake_options.h).
 */
#include <math.h>
#include <string.h>

#include "bake_options.h"

static float or_default(float v, float def) { return v > 0.0f ? v : def; }

/* Every caller value that is not 0 (default) or in (0, max]. */
static uint32_t check(const smg_bake_options* in, smgb_report* report) {
  const struct {
    const char* name;
    float v, max;
  } f[] = {{"frame_rate", in->frame_rate, SMGB_MAX_FRAME_RATE},
           {"window_seconds", in->window_seconds, SMGB_MAX_WINDOW_SECONDS},
           {"transition_percentile", in->transition_percentile,
            SMGB_MAX_PERCENTILE},
           {"transition_threshold", in->transition_threshold,
            SMGB_MAX_TRANSITION_THRESHOLD},
           {"max_edge_seconds", in->max_edge_seconds,
            SMGB_MAX_EDGE_SECONDS_LIMIT},
           {"splice_percentile", in->splice_percentile, SMGB_MAX_PERCENTILE},
           {"splice_region_seconds", in->splice_region_seconds,
            SMGB_MAX_SPLICE_REGION_SECONDS},
           {"contact_height", in->contact_height, SMGB_MAX_CONTACT_HEIGHT},
           {"contact_speed", in->contact_speed, SMGB_MAX_CONTACT_SPEED}};
  uint32_t bad = 0;
  size_t i;
  for (i = 0; i < sizeof f / sizeof f[0]; ++i)
    if (!isfinite(f[i].v) || f[i].v < 0.0f || f[i].v > f[i].max) {
      smgb_fail(report, "options.%s = %g: must be 0 (default) or in (0, %g]",
                f[i].name, (double)f[i].v, (double)f[i].max);
      ++bad;
    }
  if (in->splices_per_region > SMGB_MAX_SPLICES_PER_REGION) {
    smgb_fail(report, "options.splices_per_region = %u: at most %u",
              in->splices_per_region, SMGB_MAX_SPLICES_PER_REGION);
    ++bad;
  }
  return bad;
}

smg_result smgb_options_resolve(const smg_bake_options* in, smgb_options* o,
                                smgb_report* report) {
  smg_bake_options z;
  smg_result r = SMG_OK;
  memset(&z, 0, sizeof z);
  if (!in || in->struct_size == 0) in = &z;
  if (check(in, report)) {
    in = &z;
    r = SMG_ERROR_INVALID_ARGUMENT;
  }
  /* With every value checked above, the derived frame counts are bounded
   * (window <= 10 s * 1000 Hz) and need no further test. */
  memset(o, 0, sizeof *o);
  o->frame_rate = or_default(in->frame_rate, SMGB_DEFAULT_FRAME_RATE);
  o->window_seconds =
      or_default(in->window_seconds, SMGB_DEFAULT_WINDOW_SECONDS);
  o->window = (uint32_t)lround(o->window_seconds * o->frame_rate);
  if (o->window < 2) o->window = 2;
  o->transition_percentile = or_default(in->transition_percentile,
                                        SMGB_DEFAULT_TRANSITION_PERCENTILE);
  o->transition_threshold = in->transition_threshold;
  o->max_edge_seconds =
      or_default(in->max_edge_seconds, SMGB_DEFAULT_MAX_EDGE_SECONDS);
  o->max_edge_frames = (uint32_t)lround(o->max_edge_seconds * o->frame_rate);
  if (o->max_edge_frames < 1) o->max_edge_frames = 1;
  o->splice_percentile =
      or_default(in->splice_percentile, SMGB_DEFAULT_SPLICE_PERCENTILE);
  o->splice_region_seconds = or_default(in->splice_region_seconds,
                                        SMGB_DEFAULT_SPLICE_REGION_SECONDS);
  o->splices_per_region = in->splices_per_region
                              ? in->splices_per_region
                              : SMGB_DEFAULT_SPLICES_PER_REGION;
  o->contact_height =
      or_default(in->contact_height, SMGB_DEFAULT_CONTACT_HEIGHT);
  o->contact_speed = or_default(in->contact_speed, SMGB_DEFAULT_CONTACT_SPEED);
  o->threads = in->threads ? in->threads : SMGB_DEFAULT_THREADS;
  if (o->threads > SMGB_MAX_THREADS) o->threads = SMGB_MAX_THREADS;
  o->no_mirror = in->no_mirror;
  return r;
}
