/*
 * steer.c - root steering (docs/runtime.md, "Root steering").
 *
 * The planner chooses motion that follows the path as well as the data
 * can; where the data cannot turn as tightly as the path (a graph of a few
 * straight walks, a 90-degree polyline corner), the character would drift
 * off. Every step this stage adds a small correction to the character's
 * ground transform - a turn about the root's ground point and a
 * translation - on top of the motion:
 *
 *  - heading: the clip's own direction of travel (where its root is a
 *    moment ahead), turned by how far the clip's body faces off its
 *    travel, is turned towards a pursuit point on the path: the body,
 *    not its sideways drift, faces the way the path goes; the
 *    correction rate is bounded by a fraction of the clip's own turning
 *    plus an additive term that grows with the motion's speed up to a
 *    maximum rate (none while the motion stands);
 *  - position: the lateral error is removed at most at a fraction of the
 *    motion's ground speed; the clip's own sideways drift off its facing
 *    (a performer whose pelvis is turned from the way they walk, a
 *    turning step whose body leads the turn) is slid out as it happens,
 *    within the same bound, so that the path is walked facing it;
 *  - both rates change by a bounded amount per second, so the correction
 *    never pops when it starts, saturates or stops;
 *  - body: what that leaves of the body facing off the way the character
 *    really goes (a lead beyond the slide bound, a tight curl) is turned
 *    out of the pose alone, about the ground point (body_onto_travel).
 * The correction is applied to the pose just composed and to the queued
 * edges' placements (the two the pose samples at once, further ones
 * through the correction pending for them, smgi_lag_apply, when read), so
 * what is planned ahead moves with the character and the planner
 * continues from where the character really is. It runs
 * before forward kinematics and foot IK: a planted foot keeps its world
 * anchor while the body turns and slides above it.
 *
 * Coming to rest: near the end, the stage picks the queued frame with both
 * feet down from which the settling step (rest.c) brings the hips nearest
 * the last point (a frame with one foot down, or any, when the data has
 * none: by its root) and slows the playback down onto it, never below
 * SMGI_STEER_BRAKE_FLOOR of real time and only while both feet are down
 * (a swing is not drawn out), sliding the remaining offset out on the
 * way. There the playhead stays (the rest stage stands the character)
 * until the path changes. Where the path turns too tightly for the
 * available turning at the current speed, the character slows down: the
 * playback to no less than SMGI_STEER_RATE_MIN (slower is slow motion),
 * the rest by shorter strides (part of each step's travel slid back,
 * bounded by the slide ratio). What the planner should make of the
 * correction is smgi_steer_plan_view / _plan_reach (inline,
 * steer_envelope.h). When the correction since the plan was chosen adds
 * up, the stage asks the step to plan again (smgi_steer_wants_replan)
 * rather than planning itself.
 *
 * Deterministic, no allocation, O(frames planned ahead) near the end and
 * O(1) otherwise.
 */
#include <math.h>

#include "graph_derived.h"
#include "settle.h"
#include "steer.h"

/* v moved towards target by at most step. */
static float approach(float v, float target, float step) {
  if (target > v + step) return v + step;
  if (target < v - step) return v - step;
  return target;
}

void smgi_steer_init(smgi_steer* s, uint32_t enabled, float turn_limit,
                     float slide_ratio, float stop_seconds) {
  s->enabled = enabled;
  s->mode = SMGI_STEER_FOLLOW;
  smgi_steer_set_limits(s, turn_limit, slide_ratio, stop_seconds);
  s->have_prev = 0;
  s->own_turn = s->own_speed = 0.0f;
  s->own_face[0] = s->own_face[1] = 0.0f;
  s->own_travel[0] = s->own_travel[1] = 0.0f;
  s->out_travel[0] = s->out_travel[1] = 0.0f;
  s->body_face[0] = s->body_face[1] = 0.0f;
  s->body_turn = 0.0f;
  s->turn = 0.0f;
  s->slide[0] = s->slide[1] = 0.0f;
  s->rate = 1.0f;
  s->stride = 1.0f;
  s->cutting = 0;
  s->drift_turn = s->drift_move = 0.0f;
  s->heading_seg[0] = s->heading_seg[1] = SMGI_NONE;
  s->data_stop = 0;
}

void smgi_steer_set_limits(smgi_steer* s, float turn_limit,
                           float slide_ratio, float stop_seconds) {
  s->turn_limit = turn_limit;
  s->slide_ratio = slide_ratio;
  s->stop_seconds = stop_seconds;
  s->body_max = slide_ratio / sqrtf(1.0f + slide_ratio * slide_ratio);
}

void smgi_steer_path_changed(smgi_steer* s) {
  /* from rest the first step plays at a natural cadence, not as a slow
   * motion ramp from 0 */
  if (s->mode == SMGI_STEER_REST && s->rate < SMGI_STEER_BRAKE_FLOOR)
    s->rate = SMGI_STEER_BRAKE_FLOOR;
  s->mode = SMGI_STEER_FOLLOW;
  s->heading_seg[0] = s->heading_seg[1] = SMGI_NONE;
  s->drift_turn = s->drift_move = 0.0f; /* the planner starts afresh */
  s->data_stop = 0;
}

/* The path's point `ahead` metres past arc s, continued straight past the
 * end along the last segment (a character arriving keeps its line). */
static void point_ahead(const smgi_path* p, float s, uint32_t seg,
                        float* x, float* z) {
  float t = s;
  if (t > p->length) t = p->length;
  smgi_path_eval(p, t, &seg, x, z, NULL);
  if (s > p->length) {
    float h = smgi_path_heading(p, seg);
    float sh, ch;
    smgi_sincosf(h, &sh, &ch);
    *x += (s - p->length) * sh;
    *z += (s - p->length) * ch;
  }
}

/* The point the heading is turned towards: `look` metres past progress s
 * (point_ahead), or, for a character at (x, z) past the path's end (no
 * stop found yet), the end point itself: the planner then wants motion
 * that turns back to the end (plan_search.c), and a pursuit point ahead
 * of the end had the steering turn against it at its limit, the planted
 * feet skating under the two. */
static void pursuit_point(const smgi_path* p, float s, float look,
                          uint32_t seg, float x, float z, float* tx,
                          float* tz) {
  if (s >= p->length - SMGI_END_EPS) {
    const float* e = &p->xz[2u * (p->count - 1u)];
    float sh, ch;
    smgi_sincosf(smgi_path_heading(p, p->count - 2u), &sh, &ch);
    if ((x - e[0]) * sh + (z - e[1]) * ch > 0.0f) {
      *tx = e[0];
      *tz = e[1];
      return;
    }
  }
  point_ahead(p, s + look, seg, tx, tz);
}

/* Ground position of the frame k frames after the playhead (0 when the
 * queue is shorter). */
static int frame_ground(const smgi_lower* lower, const smg_graph* g,
                        uint32_t k, float* x, float* z, uint32_t* flags) {
  uint32_t entry, offset;
  if (!smgi_q_locate(lower, g->data.lower_edges, k, &entry, &offset))
    return 0;
  const smgi_qentry* q = smgi_q_at_c(lower, entry);
  const smgi_frame* f =
      &g->data.frames[g->data.lower_edges[q->edge].first_frame + offset];
  smgi_xf_point(smgi_q_placement(lower, entry), f->root2d[0], f->root2d[1],
                x, z);
  if (flags) *flags = f->flags;
  return 1;
}

/* (x, z), the ground point of the frame k frames after the playhead,
 * moved on to where the hips come to stand when the character stops on
 * that frame: the settling step (rest.c). */
static float frame_stand(const smgi_lower* lower, const smg_graph* g,
                         uint32_t k, float* x, float* z) {
  uint32_t entry, offset;
  if (!smgi_q_locate(lower, g->data.lower_edges, k, &entry, &offset))
    return 0.0f;
  const smgi_qentry* q = smgi_q_at_c(lower, entry);
  float dx, dz, wx, wz;
  smgi_settle_shift(g, g->data.lower_edges[q->edge].first_frame + offset,
                         &dx, &dz);
  smgi_rot2(smgi_q_placement(lower, entry).h, dx, dz, &wx, &wz);
  *x += wx;
  *z += wz;
  return sqrtf(dx * dx + dz * dz);
}

/* Whether the frame k frames after the playhead belongs to a style that
 * stops in one step, or the graph has none (graph_derived.h): a run's
 * frame with both feet down is a worse place to stop than a walk's. */
static int frame_stops(const smgi_lower* lower, const smg_graph* g,
                       uint32_t k) {
  const smgi_derived* dv = smgi_derived_of(g);
  uint32_t entry, offset;
  if (dv->stop_style == SMGI_NONE ||
      !smgi_q_locate(lower, g->data.lower_edges, k, &entry, &offset))
    return 1;
  const uint32_t label = g->data.lower_edges[smgi_q_at_c(lower, entry)->edge].label;
  return label >= g->data.style_count || dv->style_can_stop[label];
}

/* How high the swinging toe of the frame k frames after the playhead is
 * above the standing one (smgi_settle_lift; 0 when the queue is shorter). */
static float frame_lift(const smgi_lower* lower, const smg_graph* g,
                        uint32_t k) {
  uint32_t entry, offset;
  if (!smgi_q_locate(lower, g->data.lower_edges, k, &entry, &offset))
    return 0.0f;
  const smgi_qentry* q = smgi_q_at_c(lower, entry);
  return smgi_settle_lift(g, g->data.lower_edges[q->edge].first_frame + offset);
}

/* Frames from the playhead to (seq, offset), or a negative value when the
 * queue no longer holds that entry. */
static float frames_to(const smgi_lower* lower, const smg_graph* g,
                       uint32_t seq, uint32_t offset) {
  const smgi_edge* edges = g->data.lower_edges;
  float f = -lower->t;
  for (uint32_t i = 0; i < lower->count; ++i) {
    const smgi_qentry* q = smgi_q_at_c(lower, i);
    if (q->seq == seq) return f + (float)offset;
    f += (float)edges[q->edge].frame_count;
  }
  return -1.0f;
}

/* The shortest share of its strides a braking motion keeps
 * (brake_stride): 1 for a style that stops in one step (a walk's last
 * step is its own, graph_derived.h); a faster one (a run) shortens its
 * last strides down to the graph's stop speed (its fastest walk), as a
 * runner does, never below SMGI_STEER_STRIDE_STOP (the legs would
 * cycle on the spot). Without any style that stops, the steering's
 * own bound for tight turns. */
static float stride_floor(const smgi_steer* s, const smgi_step_in* in,
                          uint32_t style) {
  const smgi_derived* dv = smgi_derived_of(in->graph);
  if (style < in->graph->data.style_count && dv->style_can_stop[style])
    return 1.0f;
  if (dv->stop_style == SMGI_NONE || !(s->own_speed > dv->stop_speed))
    return 1.0f - s->slide_ratio;
  return fmaxf(dv->stop_speed / s->own_speed, SMGI_STEER_STRIDE_STOP);
}

/* A fast style (a run) slows over its last metres to the graph's stop
 * speed: at d metres from the end the hips move at most
 * sqrt(v_stop^2 + 2 a d), a = SMGI_STEER_STOP_DECEL g, by shorter
 * strides, not slower playback (stride_floor bounds them). The share of
 * the motion's strides that keeps to it; 1 for a style that stops in one
 * step. */
static float end_stride(const smgi_steer* s, const smgi_lower* lower,
                        const smgi_step_in* in) {
  const float floor = stride_floor(s, in, lower->style);
  if (floor >= 1.0f || !(s->own_speed > 0.0f)) return 1.0f;
  const smgi_derived* dv = smgi_derived_of(in->graph);
  const float v_stop = dv->stop_style != SMGI_NONE
                           ? dv->stop_speed
                           : floor * s->own_speed;
  const float d = fmaxf(in->path->length - in->progress, 0.0f);
  const float cap = sqrtf(v_stop * v_stop +
                          2.0f * SMGI_STEER_STOP_DECEL * SMGI_GRAVITY * d);
  return smgi_clampf(cap / s->own_speed, floor, 1.0f);
}

/* How far from the end (dx, dz: where the hips would stand less the end
 * point; (sh, ch) the sine and cosine of the path's last heading) a
 * stop `seconds` ahead leaves the character, as the steering
 * will show it: the planned motion may stray sideways (a turning clip
 * planned past the end), which the heading and position correction
 * removes on the way there (steer_envelope.h, the reach the planner
 * counts too); a fast style's stop beyond the end is brought back onto
 * it by shorter strides (brake_stride), down to `floor` (stride_floor) of the way
 * there; a stop short of it stays short. */
static float stop_miss(const smgi_steer* s, float floor, float sh,
                       float ch, float dx, float dz, float seconds) {
  const float way = s->own_speed * seconds;
  float along = dx * sh + dz * ch;
  if (along > 0.0f) along = fmaxf(along - (1.0f - floor) * way, 0.0f);
  const smgi_steer_envelope env = smgi_steer_envelope_of(s);
  const float reach = smgi_steer_plan_reach(&env, way, s->own_speed);
  const float side = fmaxf(fabsf(dx * ch - dz * sh) - reach, 0.0f);
  return sqrtf(along * along + side * side);
}

/* Near the end: choose the queued frame to come to rest on and start
 * braking once it is as many frames ahead as braking from the current
 * rate over stop_seconds covers. */
static void consider_stop(smgi_steer* s, const smgi_lower* lower,
                          const smgi_step_in* in) {
  const smgi_path* p = in->path;
  const smg_graph* g = in->graph;
  const float ex = p->xz[2u * (p->count - 1u)];
  const float ez = p->xz[2u * (p->count - 1u) + 1u];
  const float brake_frames = 0.5f * s->stop_seconds * in->fps * s->rate;
  /* nothing to decide while the end is further along the path than
   * braking needs (by progress: a loop may pass near its end early) */
  if (p->length - in->progress >
      s->own_speed * s->stop_seconds + SMGI_STEER_STOP_NEAR)
    return;
  const uint32_t ahead = (uint32_t)smgi_frames_ahead(lower);
  /* a gait cycle past the braking distance: a frame with both feet down
   * is always among them */
  const uint32_t limit =
      (uint32_t)(brake_frames + SMGI_STEER_STOP_SCAN * in->fps);
  const uint32_t both = SMGI_FRAME_LEFT_CONTACT | SMGI_FRAME_RIGHT_CONTACT;
  /* decide only on a plan that reaches that far (not just after a
   * re-plan left the edge playing alone) */
  if (ahead < limit) return;
  const float brake_way = 0.5f * s->own_speed * s->stride *
                          smgi_derived_of(g)->idle.swing_seconds;
  float best = INFINITY, x, z, sh, ch;
  uint32_t best_k = 0, prev = 0;
  int best_good = 0;
  smgi_sincosf(smgi_path_heading(p, p->count - 2u), &sh, &ch);
  const float floor = stride_floor(s, in, lower->style);
  if (!frame_ground(lower, g, 0, &x, &z, &prev)) return;
  for (uint32_t k = 1; k <= ahead && k <= limit; ++k) {
    uint32_t fl;
    if (!frame_ground(lower, g, k, &x, &z, &fl)) break;
    /* both feet down: labelled so, or where the label passes from one
     * foot to the other (contact labels may leave no frame between the
     * two supports, though both feet are on the floor there) */
    int down = (fl & both) == both ||
               ((fl | prev) == both && (fl & both) != 0 && fl != prev);
    /* where the hips will stand: on from the stop frame by the settling
     * step, worked out for every frame it can start from (a foot down:
     * a run has no frame with both) */
    const float way = fl ? frame_stand(lower, g, k, &x, &z) : 0.0f;
    float d = stop_miss(s, floor, sh, ch, x - ex, z - ez, (float)k / in->fps);
    if (!down) d += fl ? SMGI_STEER_ONE_FOOT : SMGI_STEER_NO_FOOT;
    if (!frame_stops(lower, g, k)) d += SMGI_STEER_ONE_FOOT;
    /* a foot still high in the air lands only after the hips stand */
    if (fl) d += frame_lift(lower, g, k);
    /* the hips cannot stop from the motion's speed in less than braking
     * evenly over the settling step: from a frame whose settling way is
     * shorter they would stand before the stepping foot lands (a run's
     * swinging foot, 15-50 cm up, still coming down at rest) */
    if (fl) d += fmaxf(brake_way - way, 0.0f);
    prev = fl;
    if (d < best) {
      best = d;
      best_k = k;
      best_good = down && frame_stops(lower, g, k);
    }
  }
  if (best_k == 0 || best > SMGI_STEER_STOP_NEAR + SMGI_STEER_NO_FOOT) return;
  /* no frame to stand on planned yet (a run's flight, the walk still
   * ahead in the plan): while the end is not passed, follow on and let
   * the planner bring one */
  if (!best_good && in->progress < p->length - SMGI_END_EPS) return;
  float frames = (float)best_k - (lower->t - floorf(lower->t));
  if (frames > brake_frames) return;
  uint32_t entry, offset;
  if (!smgi_q_locate(lower, g->data.lower_edges, best_k, &entry, &offset))
    return;
  s->stop_seq = smgi_q_at_c(lower, entry)->seq;
  s->stop_offset = offset;
  s->mode = SMGI_STEER_BRAKE;
}

/* A stop from the data (stop_match.h): the planner marked the frame its
 * hips rest on. Once that frame is queued it is the stop frame, at once:
 * the route's miss of the end is slid out over all of the way there
 * (steer_apply), not just its last steps, and the motion is the stop's
 * own, so it plays at normal rate to it (data_stop_frames). Returns 1 if
 * it is. */
static int follow_data_stop(smgi_steer* s, const smgi_lower* lower,
                            const smgi_step_in* in) {
  if (lower->stop_seq == SMGI_NONE ||
      frames_to(lower, in->graph, lower->stop_seq, lower->stop_offset) < 0.0f)
    return 0;
  s->stop_seq = lower->stop_seq;
  s->stop_offset = lower->stop_offset;
  s->mode = SMGI_STEER_BRAKE;
  s->data_stop = 1;
  return 1;
}

/* Frames a stop from the data plays this step, `left` before its rest:
 * at normal rate (the data slows itself), at rest on its frame. */
static float data_stop_frames(smgi_steer* s, float left, float full,
                              float dt) {
  s->rate = approach(s->rate, 1.0f, SMGI_STEER_RATE_ACCEL * dt);
  s->stride = approach(s->stride, 1.0f, SMGI_STEER_RATE_ACCEL * dt);
  const float frames = full * s->rate;
  if (frames < left) return frames;
  s->mode = SMGI_STEER_REST;
  s->rate = 0.0f;
  return left > 0.0f ? left : 0.0f;
}

/* Distance matching: the share of its travel the motion keeps so that
 * the hips come to stand on the end rather than where the stop frame,
 * `left` frames ahead, and its settling step would put them (a stop frame
 * beyond the end is chosen for it, stop_miss): the last strides shorten,
 * as a runner's do, down to stride_floor (the planted feet keep their
 * anchors, so the steps shorten). Measured along the path's last
 * direction, again every step, from where the character is. */
static float brake_stride(const smgi_steer* s, const smgi_lower* lower,
                          const smgi_step_in* in, float left) {
  const smgi_path* p = in->path;
  const uint32_t k = (uint32_t)(lower->t - floorf(lower->t) + left + 0.5f);
  float x, z;
  if (!s->have_prev || !frame_ground(lower, in->graph, k, &x, &z, NULL))
    return 1.0f;
  frame_stand(lower, in->graph, k, &x, &z);
  float sh, ch;
  smgi_sincosf(smgi_path_heading(p, p->count - 2u), &sh, &ch);
  const float motion = (x - s->prev_x) * sh + (z - s->prev_z) * ch;
  const float wanted = (p->xz[2u * (p->count - 1u)] - s->prev_x) * sh +
                       (p->xz[2u * (p->count - 1u) + 1u] - s->prev_z) * ch;
  if (motion < SMGI_STEER_SWAY) return 1.0f;
  return smgi_clampf(wanted / motion, stride_floor(s, in, lower->style), 1.0f);
}

/* The heading of path segment seg, remembered for the next calls: the
 * look-ahead asks for the segment at the character and, near its end,
 * the next one, every step (one remembered heading was recomputed
 * twice a step there). */
static float segment_heading(smgi_steer* st, const smgi_path* p,
                             uint32_t seg) {
  if (seg == st->heading_seg[0]) return st->heading[0];
  const uint32_t other = st->heading_seg[0];
  const float other_h = st->heading[0];
  st->heading[0] = seg == st->heading_seg[1] ? st->heading[1]
                                             : smgi_path_heading(p, seg);
  st->heading_seg[0] = seg;
  st->heading_seg[1] = other;
  st->heading[1] = other_h;
  return st->heading[0];
}

/* The share of the motion's full speed `full` (m/s) at which the steering
 * turns as tightly as a path turning `kappa` radians per metre: the turn
 * the path asks for beyond the motion's own `own_turn` within `limit`
 * (rad/s: the turn limit, or a cut's), and the body's sideways
 * acceleration within what friction gives (SMGI_STEER_GRIP: the speed
 * round a radius r is at most sqrt(a r)). */
static float turn_share(float limit, float kappa, float full,
                        float own_turn) {
  float want = 1.0f;
  const float need = fabsf(kappa * full - own_turn);
  if (need > limit) want = limit / need;
  const float k = fabsf(kappa);
  if (k * full * full > SMGI_STEER_GRIP * SMGI_GRAVITY)
    want = fminf(want, sqrtf(SMGI_STEER_GRIP * SMGI_GRAVITY / k) / full);
  return want;
}

/* The share of the full speed `full` to move at now to take a turn of
 * `kappa` radians per metre, `at` metres ahead, as a cut (share_ahead):
 * braking at what the grip gives (friction bounds the push along the
 * ground as it bounds the sideways one) down to the speed the turn
 * allows, no slower than smgi_steer_cut_floor. The turn allowed is the
 * cut's own (SMGI_STEER_CUT_TURN times the limit, as smgi_steer_apply
 * turns while cutting): bounding it by the plain limit slowed a runner
 * to half its speed for each of the scribble's curls, below the walk's
 * speed for a second on graphs whose walk is fast for their run. */
static float cut_share(const smgi_steer* st, float kappa, float full,
                       float own_turn, float at) {
  if (!(full > 1e-3f)) return 1.0f;
  const float v = fmaxf(turn_share(SMGI_STEER_CUT_TURN * st->turn_limit,
                                   kappa, full, own_turn),
                        smgi_steer_cut_floor(st->slide_ratio)) * full;
  return sqrtf(v * v + 2.0f * SMGI_STEER_GRIP * SMGI_GRAVITY * at) / full;
}

/* The share of the full speed `full` to move at now (1: no slowing) for
 * the path's turning from arc s on: the sharper of two halves of the next
 * SMGI_STEER_CURVE_AHEAD metres (a short tight loop is not averaged
 * away), and every tighter turn further on that the speed, changing by
 * SMGI_STEER_RATE_ACCEL of itself per second, must already come down
 * for; a turn no tight-turn share makes is cut instead (cut_share), so
 * the share may go below the tight-turn slowest down to
 * smgi_steer_cut_floor, and
 * *cut says whether such a turn lies ahead. */
static float share_ahead(smgi_steer* st, const smgi_path* p, float s,
                         uint32_t seg, float full, float speed,
                         uint32_t* cut) {
  const float half = 0.5f * SMGI_STEER_CURVE_AHEAD;
  uint32_t sg = smgi_path_segment(p, s, seg);
  /* how far on the slowest share is reached from the full speed: no
   * turn beyond that can ask for more slowing now */
  const float slowest = SMGI_STEER_RATE_MIN * (1.0f - st->slide_ratio);
  const float reach = speed * (1.0f - slowest) / SMGI_STEER_RATE_ACCEL;
  float h0 = segment_heading(st, p, sg), prev = 0.0f, want = 1.0f;
  *cut = 0;
  for (uint32_t i = 1u; i <= SMGI_STEER_AHEAD_SAMPLES; ++i) {
    const float d = (float)i * half;
    const uint32_t s1 = smgi_path_segment(p, s + d, sg);
    /* one heading per segment: the points mostly share one or two */
    float h1 = s1 == sg ? h0 : segment_heading(st, p, s1);
    float k = smgi_wrap_angle(h1 - h0) / half;
    /* the turn over [d - 2 half, d]: the sharper of its halves */
    float kk = i >= 2u && fabsf(prev) > fabsf(k) ? prev : k;
    if (i >= 2u) {
      /* the turn starts d - 2 half ahead: time to slow down till then */
      const float lead = d - 2.0f * half;
      const float room =
          speed > 1e-3f ? SMGI_STEER_RATE_ACCEL * lead / speed : INFINITY;
      const float share =
          turn_share(st->turn_limit, kk, full,
                     i == 2u ? st->own_turn : 0.0f);
      if (share >= slowest) {
        want = fminf(want, share + room);
      } else {
        /* a turn no share down to the slowest makes (a hairpin) is cut
         * as a runner cuts it: on at speed until shortly before it, then
         * braking as hard as the grip allows down to the speed the turn
         * allows (no slower than a cut goes), and off again past it;
         * slowing early and long would not follow it either. The turn
         * starts where its sharper half does. */
        *cut = 1;
        want = fminf(want, cut_share(st, kk, full,
                                     i == 2u ? st->own_turn : 0.0f,
                                     fabsf(prev) > fabsf(k) ? lead
                                                            : lead + half));
      }
      if (lead >= reach) break;
    }
    prev = k;
    h0 = h1;
    sg = s1;
  }
  return want;
}

int smgi_steer_wants_replan(const smgi_steer* s, const smgi_step_in* in) {
  return s->enabled && in->path->count >= 2u && s->mode == SMGI_STEER_FOLLOW &&
         (s->drift_turn > SMGI_STEER_REPLAN_TURN ||
          s->drift_move > SMGI_STEER_REPLAN_MOVE);
}

void smgi_steer_replanned(smgi_steer* s) {
  s->drift_turn = s->drift_move = 0.0f;
}

float smgi_steer_frames(smgi_steer* s, const smgi_lower* lower,
                        const smgi_step_in* in, float dt) {
  const float full = dt * in->fps;
  s->cutting = 0; /* only while following (below) */
  if (!s->enabled || in->path->count < 2u) {
    s->mode = SMGI_STEER_FOLLOW;
    s->data_stop = 0;
    s->rate = approach(s->rate, 1.0f, SMGI_STEER_RATE_ACCEL * dt);
    s->stride = approach(s->stride, 1.0f, SMGI_STEER_RATE_ACCEL * dt);
    return full * s->rate;
  }
  if (s->mode == SMGI_STEER_FOLLOW) {
    /* slow down where the path turns tighter than the steering can turn
     * at this speed, or than a body can turn at this speed, and ahead of
     * such a turn */
    float r = s->rate > 0.05f ? s->rate : 0.05f;
    /* playback no slower than SMGI_STEER_RATE_MIN (slower looks like
     * slow motion, every swing drawn out), the rest by shorter strides,
     * at most the slide ratio of them (a cut: smgi_steer_cut_floor) */
    const float full_speed = s->own_speed / r;
    float want = share_ahead(s, in->path, in->progress, in->seg, full_speed,
                             s->own_speed * s->stride, &s->cutting);
    want = smgi_clampf(want, smgi_steer_cut_floor(s->slide_ratio), 1.0f);
    const float rate = want > SMGI_STEER_RATE_MIN ? want : SMGI_STEER_RATE_MIN;
    /* strides change as fast as the grip brakes and pushes the body (a
     * cut), at least as fast as the playback */
    const float stride_accel =
        full_speed > 1e-3f
            ? fmaxf(SMGI_STEER_RATE_ACCEL,
                    SMGI_STEER_GRIP * SMGI_GRAVITY / full_speed)
            : SMGI_STEER_RATE_ACCEL;
    s->rate = approach(s->rate, rate, SMGI_STEER_RATE_ACCEL * dt);
    s->stride = approach(s->stride, fminf(want / rate, end_stride(s, lower, in)),
                         stride_accel * dt);
    if (!follow_data_stop(s, lower, in)) consider_stop(s, lower, in);
    if (s->mode == SMGI_STEER_FOLLOW) return full * s->rate;
    s->cutting = 0;
  }
  if (s->mode == SMGI_STEER_REST) {
    s->rate = 0.0f;
    return 0.0f;
  }
  /* braking: constant deceleration that ends on the stop frame, the
   * strides as short as land the hips on the end */
  float left = frames_to(lower, in->graph, s->stop_seq, s->stop_offset);
  if (left < 0.0f) { /* re-planned away: follow again */
    s->mode = SMGI_STEER_FOLLOW;
    s->data_stop = 0;
    return full * s->rate;
  }
  if (s->data_stop) return data_stop_frames(s, left, full, dt);
  s->stride = approach(s->stride,
                       fminf(brake_stride(s, lower, in, left),
                             end_stride(s, lower, in)),
                       SMGI_STEER_RATE_ACCEL * dt);
  float r = s->rate > SMGI_STEER_REST_RATE ? s->rate : SMGI_STEER_REST_RATE;
  float decel = left > 1e-3f ? in->fps * r * r / (2.0f * left) : INFINITY;
  float r1 = r - decel * dt;
  /* never slow motion: the last step plays at no less than
   * SMGI_STEER_BRAKE_FLOOR of real time, and the stage that takes over at
   * rest (rest.c) lets the hips glide on over the feet */
  if (r1 < SMGI_STEER_BRAKE_FLOOR && r >= SMGI_STEER_BRAKE_FLOOR)
    r1 = SMGI_STEER_BRAKE_FLOOR;
  /* nor is a foot in the air slowed: that draws its swing out past the
   * data's own (a long last step of the data longer still), so the
   * braking falls on the frames with both feet down */
  uint32_t fl = 0;
  const uint32_t both = SMGI_FRAME_LEFT_CONTACT | SMGI_FRAME_RIGHT_CONTACT;
  float gx, gz;
  if (frame_ground(lower, in->graph, 0, &gx, &gz, &fl) && (fl & both) != both)
    r1 = r;
  float frames = 0.5f * (r + (r1 > 0.0f ? r1 : 0.0f)) * full;
  if (r1 <= SMGI_STEER_REST_RATE || frames >= left) {
    s->mode = SMGI_STEER_REST;
    s->rate = 0.0f;
    return left > 0.0f ? left : 0.0f;
  }
  s->rate = r1;
  return frames;
}

/* Turn everything placed in the world by the correction: rotation by
 * `da` about (px, pz), then translation (tx, tz). */
typedef struct delta {
  float c, s, da, px, pz, tx, tz;
} delta;

static inline void delta_xf(const delta* d, smgi_xform2* x) {
  float vx = x->x - d->px, vz = x->z - d->pz;
  x->x = d->px + d->c * vx + d->s * vz + d->tx;
  x->z = d->pz - d->s * vx + d->c * vz + d->tz;
  x->h = smgi_wrap_angle(x->h + d->da);
}

/* The pending correction of the entries beyond the next two, followed by
 * d. With lag L(x) = R(a)(x - p) + p + t and D(x) = R(da)(x - g) + g + dt:
 * D(L(x)) = R(a + da)(x - p) + p + R(da)(t + p - g) - (p - g) + dt. The
 * turn's pivot p is moved to the character when the lag starts, so p - g
 * stays as small as the way walked since. */
static void lag_follow(smgi_lag* l, const delta* d) {
  if (l->c == 1.0f && l->s == 0.0f && l->t[0] == 0.0f &&
      l->t[1] == 0.0f) { /* identity: any pivot */
    l->p[0] = d->px;
    l->p[1] = d->pz;
  }
  float ux = l->p[0] - d->px, uz = l->p[1] - d->pz;
  float vx = l->t[0] + ux, vz = l->t[1] + uz;
  l->t[0] = d->c * vx + d->s * vz - ux + d->tx;
  l->t[1] = -d->s * vx + d->c * vz - uz + d->tz;
  float c = l->c * d->c - l->s * d->s;
  l->s = l->s * d->c + l->c * d->s;
  l->c = c;
  l->a = smgi_wrap_angle(l->a + d->da);
  l->steps++;
}

/* Write the pending correction into the entries beyond the next two and
 * start afresh: composed over many steps, its rounding (its cosine and
 * sine drift apart from a rotation's, its pivot falls behind) would grow
 * with the time since a re-plan, which following a gentle path can make
 * long. */
static void lag_write(smgi_lower* lower) {
  for (uint32_t i = 2u; i < lower->count; ++i)
    smgi_lower_lag_write_entry(lower, i);
  smgi_lag_reset(&lower->lag);
}

/* Move the pose just composed and every queued placement by d (its c and
 * s filled here): the plan moves with the character. */
static void move(smgi_pose* pose, smgi_lower* lower, delta* d) {
  const float gx = pose->ground[0], gz = pose->ground[1];
  const float gh = pose->heading;
  /* the half angle's sine and cosine give the pose's yaw quaternion and,
   * by the double-angle formulas, the turn itself: one sincos a step */
  float sh, chh;
  smgi_sincosf(0.5f * d->da, &sh, &chh);
  d->s = 2.0f * sh * chh;
  d->c = 1.0f - 2.0f * sh * sh;
  if (d->da == 0.0f && d->tx == 0.0f && d->tz == 0.0f) return;
  /* the pose just composed (turned about d's pivot) ... */
  float rx = pose->root[0] - d->px, rz = pose->root[2] - d->pz, q[4];
  float ux = gx - d->px, uz = gz - d->pz;
  const float yaw[4] = {0.0f, sh, 0.0f, chh};
  pose->root[0] = d->px + d->c * rx + d->s * rz + d->tx;
  pose->root[2] = d->pz - d->s * rx + d->c * rz + d->tz;
  smgi_q_mul(yaw, pose->rot, q);
  smgi_q_normalize(q);
  pose->rot[0] = q[0];
  pose->rot[1] = q[1];
  pose->rot[2] = q[2];
  pose->rot[3] = q[3];
  pose->ground[0] = d->px + d->c * ux + d->s * uz + d->tx;
  pose->ground[1] = d->pz - d->s * ux + d->c * uz + d->tz;
  pose->heading = smgi_wrap_angle(gh + d->da);
  /* ... and every queued placement, so the plan moves with it: the two
   * entries the pose samples now, further ones when read (writing every
   * planned entry every step was most of this stage's cache misses in
   * a crowd) */
  for (uint32_t i = 0; i < lower->count && i < 2u; ++i) {
    smgi_qentry* e = smgi_q_at(lower, i);
    delta_xf(d, &e->W);
    delta_xf(d, &e->M);
  }
  if (lower->count > 2u) {
    lag_follow(&lower->lag, d);
    if (lower->lag.steps >= SMGI_STEER_LAG_STEPS) lag_write(lower);
  } else {
    smgi_lag_reset(&lower->lag);
  }
}

/* (x, z) turned by d's rotation (its c and s filled). */
static void turn_vec(float* v, const delta* d) {
  const float x = v[0];
  v[0] = d->c * x + d->s * v[1];
  v[1] = -d->s * x + d->c * v[1];
}

void smgi_steer_move(smgi_steer* s, smgi_pose* pose, smgi_lower* lower,
                     float da, float px, float pz) {
  delta d;
  d.da = da;
  d.px = px;
  d.pz = pz;
  d.tx = d.tz = 0.0f;
  move(pose, lower, &d);
  /* the motion's facing and travel as seen so far turn with it (else a
   * walk off after a turn on the spot read the turn as a lead) */
  turn_vec(s->own_face, &d);
  turn_vec(s->own_travel, &d);
  turn_vec(s->out_travel, &d);
  turn_vec(s->body_face, &d);
  s->prev_x = pose->ground[0];
  s->prev_z = pose->ground[1];
  s->prev_h = pose->heading;
}

/* What the lead's removal leaves (a lead the slide bound cannot slide
 * out, a body turning no faster than its bound in a tight curl, the
 * slide back to the path bending the travel): the body is turned onto
 * the way the character really goes, (ox, oz) this step. The motion's
 * low-passed facing ((fs, fc): the sine and cosine of its heading this
 * step) against the low-passed direction of its travel after the
 * correction (unit steps, so a turn slowing down is not judged by its
 * faster way in), beyond the sway's residue, is turned out of the pose
 * alone, about the ground point, at most body_max (the angle the slide
 * bound lets the body crab); the plan and the ground transform are left
 * alone (turning them would turn the travel with the body). The two
 * low-passes already smooth it: a further one delayed it past the
 * lead's changes (a turning step coming in), and the body swung late
 * (other performers' p95 up to 10.6 degrees, 8.6 without). While
 * cutting, the heading turns and its turn rate changes SMGI_STEER_CUT_TURN
 * times as fast, so both low-passes are that much shorter: at the plain
 * time the facing's lead built up over a curl was seen only once the
 * curl was passed (the scribble run's pelvis p95 up to 9.9 degrees). The
 * facing is low-passed here, apart from the lead's (own_face), which
 * steers the heading and keeps its time. Angles this small are taken as
 * their sines. `on` 0 takes it back to none (at rest, steering off).
 * It stays on while braking onto the stop: the slide onto the stop
 * point crabs the body there, at a speed the turn still acts on (the
 * Bandai Namco scribble run faced 9-11 degrees off its travel for the
 * last second; the lead's removal fades out there so the stop is braked
 * along the motion's own line, which turning the pose alone leaves as
 * it is), and a stop slows the travel below SMGI_STEER_LEAD_SPEED, where
 * the turn is already going back to none, before the rest. */
static void body_onto_travel(smgi_steer* s, smgi_pose* pose, float fs,
                             float fc, float ox, float oz, float dt,
                             int on) {
  const float kl =
      dt / ((s->cutting ? SMGI_STEER_LEAD_SMOOTH / SMGI_STEER_CUT_TURN
                        : SMGI_STEER_LEAD_SMOOTH) + dt);
  float* t = s->out_travel;
  float* f = s->body_face;
  f[0] += kl * (fs - f[0]);
  f[1] += kl * (fc - f[1]);
  const float o2 = ox * ox + oz * oz;
  if (o2 > SMGI_STEER_LEAD_SPEED * SMGI_STEER_LEAD_SPEED * dt * dt) {
    const float inv = 1.0f / sqrtf(o2);
    t[0] += kl * (ox * inv - t[0]);
    t[1] += kl * (oz * inv - t[1]);
  }
  const float f2 = f[0] * f[0] + f[1] * f[1];
  const float t2 = t[0] * t[0] + t[1] * t[1];
  const float min2 = SMGI_STEER_LEAD_MIN * SMGI_STEER_LEAD_MIN;
  float want = 0.0f;
  if (on && s->own_speed > SMGI_STEER_LEAD_SPEED && f2 > min2 &&
      t2 > min2 && t[0] * f[0] + t[1] * f[1] > 0.0f) {
    const float off = (t[1] * f[0] - t[0] * f[1]) / sqrtf(f2 * t2);
    const float beyond = fabsf(off) - SMGI_STEER_LEAD_SWAY;
    if (beyond > 0.0f)
      want = off > 0.0f ? -(beyond < s->body_max ? beyond : s->body_max)
                         : (beyond < s->body_max ? beyond : s->body_max);
  }
  /* at most as fast as the heading correction turns: no pop where the
   * low-passed directions start to count (a walk's first steps) */
  s->body_turn = approach(s->body_turn, want, s->turn_limit * dt);
  if (s->body_turn == 0.0f) return;
  /* the half angle's sine and cosine by their series (|x| <= 0.13: the
   * next terms are below 1e-8), the turn's by the double angle */
  const float x = 0.5f * s->body_turn, x2 = x * x;
  const float sh = x * (1.0f - x2 * (1.0f / 6.0f) * (1.0f - x2 * 0.05f));
  const float chh = 1.0f - x2 * 0.5f * (1.0f - x2 * (1.0f / 12.0f));
  const float sn = 2.0f * sh * chh, c = 1.0f - 2.0f * sh * sh;
  const float rx = pose->root[0] - pose->ground[0];
  const float rz = pose->root[2] - pose->ground[1];
  pose->root[0] = pose->ground[0] + c * rx + sn * rz;
  pose->root[2] = pose->ground[1] - sn * rx + c * rz;
  /* the yaw (0, sh, 0, chh) times the root's rotation */
  float* r = pose->rot;
  const float qx = chh * r[0] + sh * r[2], qy = chh * r[1] + sh * r[3];
  const float qz = chh * r[2] - sh * r[0], qw = chh * r[3] - sh * r[1];
  r[0] = qx;
  r[1] = qy;
  r[2] = qz;
  r[3] = qw;
}

void smgi_steer_apply(smgi_steer* s, smgi_pose* pose, smgi_lower* lower,
                      const smgi_step_in* in, float dt) {
  const smg_graph* g = in->graph;
  const float gx = pose->ground[0], gz = pose->ground[1];
  const float gh = pose->heading;
  if (dt <= 0.0f) return;
  /* the motion's own speed and turning this step, low-passed */
  float k = dt / (SMGI_STEER_SMOOTH + dt);
  float travel_x = 0.0f, travel_z = 0.0f; /* the motion's, this step */
  float fs, fc;
  smgi_sincosf(gh, &fs, &fc);
  if (s->have_prev) {
    travel_x = gx - s->prev_x;
    travel_z = gz - s->prev_z;
    float vx = gx - s->prev_x, vz = gz - s->prev_z;
    float v = sqrtf(vx * vx + vz * vz) / dt;
    float w = smgi_wrap_angle(gh - s->prev_h) / dt;
    s->own_speed += k * (v - s->own_speed);
    s->own_turn += k * (w - s->own_turn);
    float kl = dt / (SMGI_STEER_LEAD_SMOOTH + dt);
    s->own_face[0] += kl * (fs - s->own_face[0]);
    s->own_face[1] += kl * (fc - s->own_face[1]);
    s->own_travel[0] += kl * (vx / dt - s->own_travel[0]);
    s->own_travel[1] += kl * (vz / dt - s->own_travel[1]);
  }
  s->have_prev = 1;
  float want_turn = 0.0f, want_sx = 0.0f, want_sz = 0.0f;
  /* the motion's low-passed travel turned onto its low-passed facing:
   * the slide that removes its sideways drift (lead: the angle between) */
  float lead = 0.0f, drift_x = 0.0f, drift_z = 0.0f;
  /* none over the last braking distance: the stop is chosen and braked
   * onto along the motion's own line (gone over the second braking
   * distance before it) */
  float end_fade = 1.0f;
  {
    const float brake = s->own_speed * s->stop_seconds;
    if (brake > 0.0f)
      end_fade = smgi_clampf((in->path->length - in->progress) / brake - 1.0f,
                             0.0f, 1.0f);
  }
  {
    const float* f = s->own_face;
    const float* t = s->own_travel;
    const float fl = sqrtf(f[0] * f[0] + f[1] * f[1]);
    const float tl = sqrtf(t[0] * t[0] + t[1] * t[1]);
    if (fl > SMGI_STEER_LEAD_MIN && tl > SMGI_STEER_LEAD_SPEED) {
      lead = smgi_atan2f(t[1] * f[0] - t[0] * f[1],
                         t[0] * f[0] + t[1] * f[1]);
      /* within the residue of the steps' sway the lead is left alone;
       * beyond it, the share past the residue is removed */
      const float al = fabsf(lead);
      float keep = al > SMGI_STEER_LEAD_SWAY
                       ? (al - SMGI_STEER_LEAD_SWAY) / al
                       : 0.0f;
      keep *= end_fade;
      lead *= keep;
      drift_x = keep * (tl * f[0] / fl - t[0]);
      drift_z = keep * (tl * f[1] / fl - t[1]);
    }
  }
  /* the speed the slide ratio is taken of: while following, the speed the
   * character moves at, its strides as shortened for a turn (of the
   * motion's own, a runner slowed by shorter strides slid sideways at up
   * to twice the angle the ratio means); braking onto the end point, the
   * motion's own (the stop's strides are shortened to land on it) */
  float slide_speed = s->own_speed;
  const smgi_path* p = in->path;
  if (s->enabled && p->count >= 2u && s->mode != SMGI_STEER_REST) {
    /* heading: the clip's direction of travel towards the pursuit point */
    float fx, fz, tx, tz, look;
    float dir = gh;
    if (frame_ground(lower, g, (uint32_t)(SMGI_STEER_FUTURE * in->fps), &fx,
                     &fz, NULL) &&
        (fx - gx) * (fx - gx) + (fz - gz) * (fz - gz) > 1e-4f)
      dir = smgi_atan2f(fx - gx, fz - gz);
    if (s->mode == SMGI_STEER_FOLLOW) dir = smgi_wrap_angle(dir + lead);
    /* from the speed the character moves at (its strides as shortened) */
    look = smgi_clampf(s->own_speed * s->stride * SMGI_STEER_LOOK_TIME,
                       SMGI_STEER_LOOK_MIN, SMGI_STEER_LOOK_MAX);
    pursuit_point(p, in->progress, look, in->seg, gx, gz, &tx, &tz);
    if ((tx - gx) * (tx - gx) + (tz - gz) * (tz - gz) > 1e-4f)
      want_turn = smgi_wrap_angle(smgi_atan2f(tx - gx, tz - gz) - dir) /
                  SMGI_STEER_HEADING_TIME;
    /* position: towards the path, or towards the end while braking */
    float qx, qz;
    if (s->mode == SMGI_STEER_BRAKE) {
      float left = frames_to(lower, g, s->stop_seq, s->stop_offset);
      uint32_t entry, offset;
      if (left > 0.0f &&
          smgi_q_locate(lower, g->data.lower_edges,
                        (uint32_t)(lower->t - floorf(lower->t) + left + 0.5f),
                        &entry, &offset)) {
        const smgi_qentry* q = smgi_q_at_c(lower, entry);
        const smgi_frame* f =
            &g->data.frames[g->data.lower_edges[q->edge].first_frame + offset];
        float sx, sz;
        smgi_xf_point(smgi_q_placement(lower, entry), f->root2d[0],
                      f->root2d[1], &sx, &sz);
        /* the hips then settle on by the settling step (rest.c) */
        frame_stand(lower, g,
                    (uint32_t)(lower->t - floorf(lower->t) + left + 0.5f),
                    &sx, &sz);
        /* the rest of the braking lasts 2 * left / (fps * rate); a stop
         * from the data plays on at its rate, and the miss its route
         * left (stop_match.h) is slid out evenly over all of it */
        float remain = (s->data_stop ? 1.0f : 2.0f) * left /
                       (in->fps * (s->rate > 0.05f ? s->rate : 0.05f));
        if (remain < SMGI_STEER_SLIDE_TIME) remain = SMGI_STEER_SLIDE_TIME;
        want_sx = (p->xz[2u * (p->count - 1u)] - sx) / remain;
        want_sz = (p->xz[2u * (p->count - 1u) + 1u] - sz) / remain;
      }
    } else {
      uint32_t sg = in->seg;
      smgi_path_eval(p, in->progress, &sg, &qx, &qz, NULL);
      /* the hips sway from side to side with every step: only the offset
       * beyond that is an error to remove */
      float ox = qx - gx, oz = qz - gz, ol = sqrtf(ox * ox + oz * oz);
      slide_speed = s->own_speed * s->stride;
      if (ol > SMGI_STEER_SWAY) {
        float k2 = (ol - SMGI_STEER_SWAY) / (ol * SMGI_STEER_SLIDE_TIME);
        want_sx = ox * k2;
        want_sz = oz * k2;
      }
    }
  }
  if (s->enabled && p->count >= 2u && s->mode == SMGI_STEER_FOLLOW) {
    want_sx += drift_x;
    want_sz += drift_z;
  }
  /* bounds relative to the motion itself. A body cutting a hairpin
   * (smgi_steer_frames) plants a foot and pivots over it rather than
   * crabbing back to the line: it turns at up to SMGI_STEER_CUT_TURN
   * times the turn limit (within the tightest turning circle) and slides
   * at SMGI_STEER_CUT_SLIDE of the ratio (sliding turns the body away
   * from its travel) */
  const float limit =
      s->cutting ? SMGI_STEER_CUT_TURN * s->turn_limit : s->turn_limit;
  float tb = SMGI_STEER_CLIP_SCALE * fabsf(s->own_turn) +
             fminf(limit, s->own_speed / SMGI_STEER_TURN_RADIUS);
  float sb = (s->cutting ? SMGI_STEER_CUT_SLIDE : 1.0f) * s->slide_ratio *
             slide_speed;
  want_turn = smgi_clampf(want_turn, -tb, tb);
  float wl = sqrtf(want_sx * want_sx + want_sz * want_sz);
  if (wl > sb) {
    want_sx *= sb / wl;
    want_sz *= sb / wl;
  }
  /* continuous: the correction's rates change by bounded steps; a pivot
   * reaches its doubled turn in the time a plain turn reaches its own
   * (at the plain rate of change the curl was passed before the pivot
   * turned at the rate its speed was chosen for) */
  const float turn_accel =
      (s->cutting ? SMGI_STEER_CUT_TURN : 1.0f) * SMGI_STEER_TURN_ACCEL;
  s->turn = smgi_clampf(approach(s->turn, want_turn, turn_accel * dt), -tb,
                        tb);
  s->slide[0] = approach(s->slide[0], want_sx, SMGI_STEER_SLIDE_ACCEL * dt);
  s->slide[1] = approach(s->slide[1], want_sz, SMGI_STEER_SLIDE_ACCEL * dt);
  float sl = sqrtf(s->slide[0] * s->slide[0] + s->slide[1] * s->slide[1]);
  if (sl > sb) {
    s->slide[0] *= sb / sl;
    s->slide[1] *= sb / sl;
  }
  /* shorter strides: the share of this step's travel not kept is slid
   * back (the planted feet keep their anchors, so the steps shorten) */
  const float back_x = (s->stride - 1.0f) * travel_x;
  const float back_z = (s->stride - 1.0f) * travel_z;
  delta d;
  d.da = s->turn * dt;
  d.px = gx;
  d.pz = gz;
  d.tx = s->slide[0] * dt + back_x;
  d.tz = s->slide[1] * dt + back_z;
  const float before_x = s->have_prev ? gx - travel_x : gx;
  const float before_z = s->have_prev ? gz - travel_z : gz;
  move(pose, lower, &d);
  s->drift_turn += fabsf(d.da);
  /* shorter strides move the plan back along the path with the
   * character, not off it: no reason to choose the edges again */
  s->drift_move += sqrtf((d.tx - back_x) * (d.tx - back_x) +
                         (d.tz - back_z) * (d.tz - back_z));
  s->prev_x = pose->ground[0];
  s->prev_z = pose->ground[1];
  s->prev_h = pose->heading;
  body_onto_travel(s, pose, fs, fc, pose->ground[0] - before_x,
                   pose->ground[1] - before_z, dt,
                   s->enabled && p->count >= 2u &&
                       s->mode != SMGI_STEER_REST);
}

void smgi_lag_follow(smgi_lag* l, float c, float sn, float da, float px,
                     float pz, float tx, float tz) {
  const delta d = {c, sn, da, px, pz, tx, tz};
  lag_follow(l, &d);
}
