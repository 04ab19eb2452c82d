/*
 * settings.c - every per-character default of the runtime, settled in one
 * function from tuning.h (settings.h). character.c validates a desc or a
 * setter's arguments first, then settles them here; the stages get the
 * settled values and never see a 0 that means "default".
 */
#include "settings.h"

#include "tuning.h"

static float or_default(float v, float def) { return v > 0.0f ? v : def; }

void smgi_settle(const smg_graph* g, const smg_character_desc* d,
                 smgi_settings* out) {
  out->path_capacity =
      d->path_capacity ? d->path_capacity : SMGI_DEFAULT_PATH_CAPACITY;
  out->constraint_capacity = d->constraint_capacity
                                 ? d->constraint_capacity
                                 : SMGI_DEFAULT_CONSTRAINT_CAPACITY;
  out->horizon = or_default(d->horizon, SMGI_DEFAULT_HORIZON);
  out->error_threshold =
      or_default(d->error_threshold, SMGI_DEFAULT_THRESHOLD);
  out->turn_limit = or_default(d->steer_turn_rate, SMGI_STEER_TURN_LIMIT);
  out->slide_ratio =
      or_default(d->steer_slide_ratio, SMGI_STEER_SLIDE_RATIO);
  out->stop_seconds = or_default(d->stop_seconds, SMGI_STEER_STOP_SECONDS);
  /* about 3.5 cm on a human skeleton, whatever its unit and size */
  out->swing_default = SMGI_IK_SWING_CLEAR * g->data.info->leg_length;
  out->swing_clearance =
      (d->flags & SMG_CHARACTER_NO_SWING_CLEARANCE)
          ? 0.0f
          : or_default(d->swing_clearance, out->swing_default);
  const float window = g->data.info->window_seconds;
  out->fade_rate = 1.0f / (window > 1e-3f ? window : SMGI_DEFAULT_WINDOW);
}
