/*
 * rest.c - standing still (docs/runtime.md, "Stopping, standing,
 * starting").
 *
 * The steering brings a character to rest on a frame with both feet down
 * at the path's end, at no less than SMGI_STEER_BRAKE_FLOOR of real time.
 * From there this stage takes over:
 *
 *  - settling: the rear foot steps up beside the front one (lifted on an
 *    arc, placed by the foot IK), while the hips glide on over the feet,
 *    fast at first and slowing down, the way a walker's momentum dies out
 *    over the last step (shown on the pose only: the locomotion stays
 *    where its feet are, to walk on from there). With standing motion in the graph (idle.h) the
 *    front foot is where that motion's foot stands, the rear foot steps to
 *    where its other foot stands, and the motion fades in over the pose;
 *    without any (the CMU walks) the rear foot steps to hip width beside
 *    the front one and the stop pose stays, held by the IK;
 *  - standing: the standing motion plays on, forwards and backwards (no
 *    seam), under whatever action the upper body performs; with none, the
 *    upper body stands with it (not the stop pose's), for standing motion
 *    from an action with the arms as they hang there lowest (idle.h:
 *    its arms would wave unasked); the feet stay
 *    where they were placed;
 *  - a new path: where it starts ahead the locomotion takes over again
 *    (the standing motion fades out); where it starts behind the
 *    character (more than SMGI_REST_TURN_MIN off its facing) the
 *    character first turns on the spot, in steps of at most
 *    SMGI_REST_TURN_STEP alternating between the feet, the pose and its
 *    plan turning about the hips (smgi_steer_move), then walks off.
 *
 * Bounded work per step, no allocation; nothing happens while the
 * character follows its path.
 */
#include <math.h>
#include <string.h>

#include "rest.h"

#include "graph_derived.h"
#include "idle.h"
#include "settle.h"

/* How long a step at rest takes: as long as the graph's swings. */
static float step_seconds(const smgi_rest_io* io) {
  return smgi_derived_of(io->in->graph)->idle.swing_seconds;
}

static float ease_out(float u) {
  u = smgi_clampf(u, 0.0f, 1.0f);
  return 1.0f - (1.0f - u) * (1.0f - u);
}

static float smooth(float u) {
  u = smgi_clampf(u, 0.0f, 1.0f);
  return u * u * (3.0f - 2.0f * u);
}

/* Where toe f is shown (x, z): as the foot IK last left it, else as the
 * last forward kinematics put it. */
static void toe_shown(const smgi_rest_io* io, uint32_t f, float* out) {
  const smgi_foot* foot = &io->ik->feet[f];
  if (io->ik->enabled && foot->shown[0] < INFINITY) {
    out[0] = foot->shown[0];
    out[1] = foot->shown[1];
    return;
  }
  const smgi_info* info = io->in->graph->data.info;
  uint32_t j = f ? info->right_leg[3] : info->left_leg[3];
  if (j >= io->in->graph->data.joint_count) j = f ? info->right_leg[2] : info->left_leg[2];
  out[0] = io->pose->wpos[3u * j];
  out[1] = io->pose->wpos[3u * j + 2u];
}

/* The path's direction from the character, relative to its facing. */
static float path_turn(const smgi_rest_io* io) {
  const smgi_path* p = io->in->path;
  if (p->count < 2u) return 0.0f;
  float s = io->in->progress + SMGI_REST_PURSUIT, x, z;
  if (s > p->length) s = p->length;
  uint32_t seg = io->in->seg;
  smgi_path_eval(p, s, &seg, &x, &z, NULL);
  x -= io->pose->ground[0];
  z -= io->pose->ground[1];
  if (x * x + z * z < 1e-4f) return 0.0f;
  return smgi_wrap_angle(smgi_atan2f(x, z) - io->pose->heading);
}

/* The floor foot f stands on at the stop: the lowest its toe has stood
 * (the foot IK's stand_y, the same floor smgi_rest_feet puts the feet
 * on), else its toe's height as shown (`shown`). A run's stop frame can
 * hold both feet in the air: the standing motion laid on their heights
 * stood 3 cm above the floor. */
static float stop_floor(const smgi_rest_io* io, uint32_t f, float shown) {
  const float stand = io->ik->feet[f].stand_y;
  return stand < INFINITY ? stand : shown;
}

static void begin_settle(smgi_rest* r, const smgi_rest_io* io) {
  const smgi_idle* idle = &smgi_derived_of(io->in->graph)->idle;
  const smgi_info* info = io->in->graph->data.info;
  for (uint32_t f = 0; f < 2u; ++f) toe_shown(io, f, r->hold[f]);
  const float* hl = io->pose->wpos + 3u * info->left_leg[0];
  const float* hr = io->pose->wpos + 3u * info->right_leg[0];
  const float width = sqrtf((hl[0] - hr[0]) * (hl[0] - hr[0]) +
                            (hl[2] - hr[2]) * (hl[2] - hr[2]));
  smgi_settle sp;
  smgi_settle_plan(io->in->graph, (const float(*)[2])r->hold, io->pose->ground[0],
              io->pose->ground[1], io->pose->heading, width, &sp);
  if (idle->count > 0) {
    const float* g0 = io->in->graph->data.frames[idle->first].root2d;
    const smgi_xform2 F = {g0[0], g0[1], g0[2]};
    r->M = smgi_xf_mul(sp.G, smgi_xf_inv(F));
    /* its floor on the one the stop stands on (the lower toe as shown):
     * clips are grounded each on its own lowest point. The toes as shown
     * last step stand on the engine's ground where it gave one (ik.c
     * carries the body onto it after this stage): their heights above
     * it, in the data's frame this stage lays the motion over */
    const uint32_t tl = info->left_leg[3], tr = info->right_leg[3];
    const uint32_t J = io->in->graph->data.joint_count;
    const smgi_ground* ground = &io->ik->ground;
    float under[2] = {0.0f, 0.0f};
    for (uint32_t f = 0; f < 2u; ++f)
      if (ground->on && !isnan(ground->foot_y[f])) under[f] = ground->foot_y[f];
    if (tl < J && tr < J)
      r->rise = fminf(stop_floor(io, 0u, io->pose->wpos[3u * tl + 1u] - under[0]),
                      stop_floor(io, 1u, io->pose->wpos[3u * tr + 1u] - under[1])) -
                idle->floor;
    else
      r->rise = 0.0f;
  }
  r->glide[0] = sp.glide[0];
  r->glide[1] = sp.glide[1];
  r->glided = 0.0f;
  /* the hips keep their speed at first and slow down to a stop where
   * they stand: an ease-out over twice the way at that speed */
  const float way = sqrtf((sp.end[0] - io->pose->ground[0]) *
                              (sp.end[0] - io->pose->ground[0]) +
                          (sp.end[1] - io->pose->ground[1]) *
                              (sp.end[1] - io->pose->ground[1]));
  /* the speed the motion had (its strides as shortened for a turn),
   * less the steering's slide, which fades out on top of the glide */
  const float slide = sqrtf(io->steer->slide[0] * io->steer->slide[0] +
                            io->steer->slide[1] * io->steer->slide[1]);
  const float v =
      fmaxf(io->steer->own_speed * io->steer->stride - slide, 0.1f);
  r->settle_seconds = smgi_clampf(2.0f * way / v, SMGI_REST_SETTLE_MIN,
                                  SMGI_REST_SETTLE_MAX);
  /* the foot lands while the hips still move: a short last step, no
   * longer than a swing, down before the hips have less than
   * SMGI_REST_LAND_LEFT leg lengths to go, plus the standing motion's
   * sway (the hips stand anywhere within it: with it left out, an active
   * performer's weight shift brought them to stand, as seen from the
   * poses, with the foot still 2-3 cm up). The hips ease out, their way
   * left at u of the settling is (1 - u)^2 of it. */
  const float left = SMGI_REST_LAND_LEFT * info->leg_length + idle->sway;
  const float land =
      way > left ? fminf(SMGI_REST_STEP_SHARE, 1.0f - sqrtf(left / way))
                 : 0.0f;
  r->step_seconds = fminf(step_seconds(io),
                          fmaxf(SMGI_REST_STEP_MIN, land * r->settle_seconds));
  /* a stop that arrives with the hips already near where they stand (a
   * run's stop in mid-stance over the front foot, the rear foot still in
   * its swing) cannot land that quickly: the hips then keep `left` of
   * their way until the foot is down, and go the rest after it (with
   * the ease-out alone, a run's corner stop had its hips stand 2 frames
   * into the step, the swinging toe 6 cm up) */
  r->hips_cap = 1.0f;
  if (way > 0.0f &&
      way * (1.0f - ease_out(r->step_seconds / r->settle_seconds)) < left)
    r->hips_cap = fmaxf(1.0f - left / way, 0.0f);
  r->foot = sp.step;
  r->from[0] = r->hold[sp.step][0];
  r->from[1] = r->hold[sp.step][1];
  r->hold[sp.step][0] = sp.to[0];
  r->hold[sp.step][1] = sp.to[1];
  r->at = 0.0f;
  r->dir = 1.0f;
  r->phase = SMGI_REST_SETTLE;
  r->t = 0.0f;
}

/* The share of their way the hips have gone t into the settling: an
 * ease-out over settle_seconds; where that would take them past
 * hips_cap before the step lands, the same shape scaled down to reach
 * hips_cap at the landing, and from there an ease-out over the rest of
 * the way, as long again. */
static float hips_share(const smgi_rest* r, float t) {
  const float g = ease_out(t / r->settle_seconds);
  if (r->hips_cap >= 1.0f) return g;
  if (t < r->step_seconds)
    return r->hips_cap * g / ease_out(r->step_seconds / r->settle_seconds);
  return r->hips_cap + (1.0f - r->hips_cap) *
                           ease_out((t - r->step_seconds) / r->settle_seconds);
}

/* When the hips stand. */
static float settle_end(const smgi_rest* r) {
  return r->hips_cap >= 1.0f ? r->settle_seconds
                             : r->step_seconds + r->settle_seconds;
}

static void begin_turn(smgi_rest* r, const smgi_rest_io* io, float angle) {
  /* about the hips as last shown */
  r->pivot[0] = io->pose->wpos[0];
  r->pivot[1] = io->pose->wpos[2];
  r->turn = angle;
  r->turned = 0.0f;
  r->turn_seconds = fabsf(angle) / SMGI_REST_TURN_RATE;
  r->steps = (uint32_t)ceilf(fabsf(angle) / SMGI_REST_TURN_STEP);
  if (r->steps < 2u) r->steps = 2u;
  /* a step is never shorter than in walking */
  if (r->turn_seconds < (float)r->steps * step_seconds(io))
    r->turn_seconds = (float)r->steps * step_seconds(io);
  /* the foot on the side turned to opens the turn */
  r->foot = angle > 0.0f ? 1u : 0u; /* flipped by the first step */
  r->phase = SMGI_REST_TURN;
  r->t = 0.0f;
  r->step = SMGI_NONE;
  r->placed[0] = r->placed[1] = 0.0f;
}

static void begin_leave(smgi_rest* r) {
  r->w_from = r->w;
  r->glide_from = r->glided;
  r->keep = 3u;
  r->rejoin[0] = r->rejoin[1] = -1.0f;
  r->phase = SMGI_REST_LEAVE;
  r->t = 0.0f;
}

/* The turn's angle at time t (eased at both ends). */
static float turn_at(const smgi_rest* r, float t) {
  return r->turn * smooth(t / r->turn_seconds);
}

/* Turning: the body about the pivot, one foot at a time. */
static void turn_step(smgi_rest* r, const smgi_rest_io* io) {
  const float a = turn_at(r, r->t);
  const float da = a - r->turned;
  if (da != 0.0f) {
    smgi_steer_move(io->steer, io->pose, io->lower, da, r->pivot[0], r->pivot[1]);
    /* the standing motion turns with it */
    float x, z;
    smgi_rot2(da, r->M.x - r->pivot[0], r->M.z - r->pivot[1], &x, &z);
    r->M.x = r->pivot[0] + x;
    r->M.z = r->pivot[1] + z;
    r->M.h = smgi_wrap_angle(r->M.h + da);
    smgi_rot2(da, r->glide[0], r->glide[1], &x, &z);
    r->glide[0] = x;
    r->glide[1] = z;
    r->turned = a;
  }
  const float each = r->turn_seconds / (float)r->steps;
  const uint32_t k = (uint32_t)(r->t / each);
  if (k < r->steps && k != r->step) {
    /* a new step: the other foot, to where the turn puts it when the
     * step ends */
    r->step = k;
    r->foot ^= 1u;
    r->from[0] = r->hold[r->foot][0];
    r->from[1] = r->hold[r->foot][1];
    const float end = turn_at(r, (float)(k + 1u) * each);
    float x, z;
    smgi_rot2(end - r->placed[r->foot], r->from[0] - r->pivot[0],
              r->from[1] - r->pivot[1], &x, &z);
    r->placed[r->foot] = end;
    r->hold[r->foot][0] = r->pivot[0] + x;
    r->hold[r->foot][1] = r->pivot[1] + z;
  }
}

/* Standing motion from an action: its trunk above the spine base (whose
 * turn on the hips belongs to the hips' own sway, played as is) averaged
 * over SMGI_IDLE_TRUNK_SECONDS about frame i0 + a: the load-time boxes
 * about frames i0 and i0 + 1 (idle.h) blended by a, each turned to the
 * hemisphere of the rotation playing, so the one box slides on. */
static void calm_trunk(const smg_graph* g, const smgi_idle* idle,
                       uint32_t i0, float a, float* tmp) {
  const uint32_t J = g->data.joint_count;
  const uint32_t n = idle->calm_joints;
  const float* ca = idle->calm + 4u * (size_t)n * i0;
  const float* cb = ca + 4u * n;
  for (uint32_t j = 1; j < J; ++j) {
    if (!smgi_idle_calmed(g, j)) continue;
    const float* ref = tmp + 4u * j;
    const float da =
        ca[0] * ref[0] + ca[1] * ref[1] + ca[2] * ref[2] + ca[3] * ref[3];
    const float db =
        cb[0] * ref[0] + cb[1] * ref[1] + cb[2] * ref[2] + cb[3] * ref[3];
    const float wa = da < 0.0f ? a - 1.0f : 1.0f - a;
    const float wb = db < 0.0f ? -a : a;
    float sum[4];
    for (int c = 0; c < 4; ++c) sum[c] = wa * ca[c] + wb * cb[c];
    smgi_q_normalize(sum);
    memcpy(tmp + 4u * j, sum, sizeof sum);
    ca += 4;
    cb += 4;
  }
}

/* The standing motion at r->at laid over the pose with weight w. */
static void overlay(smgi_rest* r, const smgi_rest_io* io, float w) {
  const smg_graph* g = io->in->graph;
  const smgi_idle* idle = &smgi_derived_of(g)->idle;
  const uint32_t J = io->in->graph->data.joint_count;
  uint32_t i0 = (uint32_t)r->at;
  if (i0 >= idle->count) i0 = idle->count - 1u;
  const float a = smgi_clampf(r->at - (float)i0, 0.0f, 1.0f);
  const uint32_t fa = idle->first + i0;
  const uint32_t fb = i0 + 1u < idle->count ? fa + 1u : fa;
  const unsigned char* ra = smgi_graph_pose(g, fa);
  const unsigned char* rb = smgi_graph_pose(g, fb);
  float stack_tmp[4u * SMGI_POSE_STACK_JOINTS];
  float* tmp = J <= SMGI_POSE_STACK_JOINTS ? stack_tmp : io->pose->tmp;
  const smgi_joint* joints = g->data.joints;
  /* the upper body: the action's; else the standing motion's own, but
   * for one from an action (whose arms would wave unasked) with the arms
   * as they hang there lowest (idle.h) */
  const int action = io->upper->action != 0;
  smgi_sample_joints(g, ra, rb, a,
                     action ? SMGI_JOINTS_NOT_UPPER : SMGI_JOINTS_ALL, tmp);
  if (!action && !idle->whole) {
    calm_trunk(g, idle, i0, a, tmp);
    const unsigned char* arms = smgi_graph_pose(g, idle->arms);
    for (uint32_t j = 1; j < J; ++j) {
      if (joints[j].body_part != SMG_BODY_UPPER || smgi_idle_trunk(joints, j))
        continue;
      smgi_quat_unpack_raw(smgi_pose_rot(arms, j), tmp + 4u * j);
      smgi_q_normalize(tmp + 4u * j);
    }
  }
  /* the root, placed in the world */
  float pa[3], pb[3], qa[4], qb[4], q[4], yaw[4], root[4], x, z;
  smgi_pose_root(ra, pa);
  smgi_pose_root(rb, pb);
  smgi_quat_unpack_raw(smgi_pose_rot(ra, 0), qa);
  smgi_quat_unpack_raw(smgi_pose_rot(rb, 0), qb);
  smgi_q_nlerp(qa, qb, a, q);
  smgi_q_yaw(r->M.h, yaw);
  smgi_q_mul(yaw, q, root);
  smgi_xf_point(r->M, pa[0] + a * (pb[0] - pa[0]), pa[2] + a * (pb[2] - pa[2]),
                &x, &z);
  const float y =
      pa[1] + a * (pb[1] - pa[1]) - g->data.info->ground_height + r->rise;
  io->pose->root[0] += w * (x - io->pose->root[0]);
  io->pose->root[1] += w * (y - io->pose->root[1]);
  io->pose->root[2] += w * (z - io->pose->root[2]);
  smgi_q_nlerp(io->pose->rot, root, w, q);
  memcpy(io->pose->rot, q, sizeof q);
  /* the standing upper body comes in as the upper body's crossfade back
   * from an action goes (the pose has the fade from the action to the
   * locomotion's own): not at once where the action ends at rest */
  const float f = io->upper->fade;
  const float uw = w * (f >= 1.0f ? 1.0f : smooth(f));
  for (uint32_t j = 1; j < J; ++j) {
    const int upper = joints[j].body_part == SMG_BODY_UPPER;
    if (upper && action) continue;
    smgi_q_nlerp(io->pose->rot + 4u * j, tmp + 4u * j, upper ? uw : w, q);
    memcpy(io->pose->rot + 4u * j, q, sizeof q);
  }
}

float smgi_rest_frames(const smgi_rest* r, float frames) {
  return r->phase == SMGI_REST_TURN ? 0.0f : frames;
}

int smgi_rest_steers(const smgi_rest* r) {
  return r->phase != SMGI_REST_TURN;
}

int smgi_rest_pose(smgi_rest* r, const smgi_rest_io* io, float dt) {
  int replan = 0;
  /* the stage places the feet through the foot IK: without it the
   * character holds its stop pose (a blend of two stances would take the
   * feet through the floor) */
  const int resting = io->steer->enabled && io->ik->enabled &&
                      io->steer->mode == SMGI_STEER_REST;
  /* the step that comes to rest still played the motion up to the stop
   * frame: the settling starts with the next one */
  float step_dt = dt;
  if (r->phase == SMGI_REST_OFF) {
    if (!resting) return 0;
    begin_settle(r, io);
    step_dt = 0.0f;
  } else if (!resting &&
             (r->phase == SMGI_REST_SETTLE || r->phase == SMGI_REST_STAND)) {
    const float a = path_turn(io);
    if (fabsf(a) > SMGI_REST_TURN_MIN)
      begin_turn(r, io, a);
    else
      begin_leave(r);
  } else if (resting && r->phase == SMGI_REST_LEAVE) {
    begin_settle(r, io);
    step_dt = 0.0f;
  }
  r->t += step_dt;
  r->dt = dt;
  const smgi_idle* idle = &smgi_derived_of(io->in->graph)->idle;
  switch (r->phase) {
    case SMGI_REST_SETTLE: {
      const float g = hips_share(r, r->t);
      r->glided = g;
      r->w = idle->count ? g : 0.0f;
      if (r->t >= settle_end(r) && r->t >= r->step_seconds) {
        r->phase = SMGI_REST_STAND;
        r->t = 0.0f;
      }
      break;
    }
    case SMGI_REST_STAND:
      r->w = idle->count ? 1.0f : 0.0f;
      r->glided = 1.0f;
      break;
    case SMGI_REST_TURN:
      turn_step(r, io);
      if (r->t >= r->turn_seconds) {
        /* facing the path: the plan was made for the old facing */
        if (resting) {
          r->phase = SMGI_REST_STAND;
          r->t = 0.0f;
        } else {
          replan = 1;
          begin_leave(r);
        }
      }
      break;
    case SMGI_REST_LEAVE:
      r->w = r->w_from * (1.0f - smooth(r->t / SMGI_REST_FADE_OUT));
      r->glided = r->glide_from * (1.0f - smooth(r->t / SMGI_REST_FADE_OUT));
      if (r->t >= SMGI_REST_FADE_OUT &&
          (r->keep == 0u || r->t >= SMGI_REST_KEEP_SECONDS)) {
        r->phase = SMGI_REST_OFF;
        r->w = 0.0f;
        return replan;
      }
      break;
    default:
      break;
  }
  /* the hips over the feet: the glide is shown (and reported as the
   * character's position), not played, so that the locomotion walks on
   * from where its feet are; the steering has already taken the ground
   * point it compares the next step with */
  io->pose->root[0] += r->glided * r->glide[0];
  io->pose->root[2] += r->glided * r->glide[1];
  io->pose->ground[0] += r->glided * r->glide[0];
  io->pose->ground[1] += r->glided * r->glide[1];
  if (r->phase != SMGI_REST_LEAVE) {
    /* both feet stand (the IK holds them where this stage puts them) */
    io->pose->contacts = SMG_STATE_LEFT_CONTACT | SMG_STATE_RIGHT_CONTACT;
  }
  if (idle->count > 1u && r->w > 0.0f) {
    /* forwards and backwards through the standing motion */
    const float last = (float)(idle->count - 1u);
    r->at += r->dir * dt * io->in->fps;
    if (r->at > last) {
      r->at = fmaxf(2.0f * last - r->at, 0.0f);
      r->dir = -1.0f;
    } else if (r->at < 0.0f) {
      r->at = fminf(-r->at, last);
      r->dir = 1.0f;
    }
    overlay(r, io, r->w);
  }
  return replan;
}

/* How far the stepping foot (r->foot) is through its step, 0..1 (1: it
 * stands). */
static float step_progress(const smgi_rest* r) {
  float u = 1.0f;
  if (r->phase == SMGI_REST_SETTLE) {
    u = r->t / r->step_seconds;
  } else if (r->phase == SMGI_REST_TURN && r->step != SMGI_NONE) {
    const float each = r->turn_seconds / (float)r->steps;
    u = (r->t - (float)r->step * each) / each;
  }
  return smgi_clampf(u, 0.0f, 1.0f);
}

/* A step's shape at progress u: the foot rises on a sine arc and moves
 * over the ground only in the middle SMGI_REST_STEP_OVER of it, while it
 * is well off the floor. */
static float step_lift(const smgi_rest_io* io, float u) {
  float sn, cs; /* the library's own sine: the same bits on every libc */
  smgi_sincosf(SMGI_PI * u, &sn, &cs);
  return SMGI_REST_LIFT * io->in->graph->data.info->leg_length * sn;
}
static float step_over(float u) {
  return smooth((u - 0.5f) / SMGI_REST_STEP_OVER + 0.5f);
}

/* Whether a foot kept where it stood (hold, x and z) is further from the
 * locomotion's own foot (toe, world x y z) than the foot IK lets a
 * planted foot drift (SMGI_IK_RELEASE): held on until the locomotion's
 * contact ends, the leg would stretch after the body walking on and the
 * toe lift off the floor for as long (where the steering slides the body
 * away from a held foot: with the slide measured from the hips, a CMU
 * start held a foot 0.4 m behind its locomotion's for 0.6 s, a swing of
 * 1 s). It steps there instead. */
static int held_too_far(const float* hold, const float* toe, float leg) {
  const float dx = toe[0] - hold[0], dz = toe[2] - hold[1];
  return dx * dx + dz * dz > (SMGI_IK_RELEASE * leg) * (SMGI_IK_RELEASE * leg);
}

void smgi_rest_feet(smgi_rest* r, const smgi_rest_io* io) {
  if (r->phase == SMGI_REST_OFF || !io->ik->enabled) return;
  if (r->phase == SMGI_REST_LEAVE) {
    /* a foot stays where it stood until the locomotion's own contact
     * for it ends: then it swings, and the IK lets the difference go in
     * the air instead of sliding it along the floor */
    const uint32_t bits[2] = {SMG_STATE_LEFT_CONTACT, SMG_STATE_RIGHT_CONTACT};
    const smgi_info* info = io->in->graph->data.info;
    for (uint32_t f = 0; f < 2u; ++f) {
      if (!(r->keep & (1u << f))) continue;
      uint32_t toe = f ? info->right_leg[3] : info->left_leg[3];
      if (toe >= io->in->graph->data.joint_count) toe = f ? info->right_leg[2] : info->left_leg[2];
      const float* ap = io->pose->wpos + 3u * toe;
      /* the locomotion's foot has left the floor when its contact has
       * ended and it is lifted or moves over the ground like a swinging
       * foot (some data slides the toe along the floor into the swing) */
      const smgi_foot* ft = &io->ik->feet[f];
      float speed = 0.0f;
      if (ft->toe[1] < INFINITY && r->dt > 0.0f)
        speed = sqrtf((ap[0] - ft->toe[0]) * (ap[0] - ft->toe[0]) +
                      (ap[2] - ft->toe[2]) * (ap[2] - ft->toe[2])) /
                r->dt;
      if (r->rejoin[f] < 0.0f &&
          ((!(io->pose->contacts & bits[f]) &&
            (speed > SMGI_IK_SWING_SLOW * info->leg_length ||
             ap[1] > ft->stand_y + SMGI_IK_CLEAR * info->leg_length)) ||
           held_too_far(r->hold[f], ap, info->leg_length)))
        r->rejoin[f] = 0.0f;
      if (r->rejoin[f] < 0.0f) {
        smgi_ik_guide(io->ik, f, r->hold[f][0], r->hold[f][1], 0.0f);
        continue;
      }
      /* released by the locomotion: joins its foot in the air, on an
       * arc of its own (some data swings its toes within a centimetre
       * of the floor), short enough to end within the locomotion's
       * swing */
      const float u = r->rejoin[f] / SMGI_REST_REJOIN_SECONDS;
      const float s = step_over(u);
      smgi_ik_guide(io->ik, f, r->hold[f][0] + s * (ap[0] - r->hold[f][0]),
                    r->hold[f][1] + s * (ap[2] - r->hold[f][1]),
                    step_lift(io, u));
      r->rejoin[f] += r->dt;
      if (r->rejoin[f] >= SMGI_REST_REJOIN_SECONDS) r->keep &= ~(1u << f);
    }
    return;
  }
  /* heights from the floor the foot last stood on, not from the pose: a
   * stop pose may hold a foot in the air (a run's flight) */
  const smgi_info* info = io->in->graph->data.info;
  const float u = step_progress(r);
  for (uint32_t f = 0; f < 2u; ++f) {
    uint32_t toe = f ? info->right_leg[3] : info->left_leg[3];
    if (toe >= io->in->graph->data.joint_count)
      toe = f ? info->right_leg[2] : info->left_leg[2];
    const float stand = io->ik->feet[f].stand_y;
    const float down =
        stand < INFINITY ? stand - io->pose->wpos[3u * toe + 1u] : 0.0f;
    if (f == r->foot && u < 1.0f) {
      const float s = step_over(u);
      smgi_ik_guide(io->ik, f,
                    r->from[0] + s * (r->hold[f][0] - r->from[0]),
                    r->from[1] + s * (r->hold[f][1] - r->from[1]),
                    down + step_lift(io, u));
    } else {
      smgi_ik_guide(io->ik, f, r->hold[f][0], r->hold[f][1], down);
    }
  }
}

/* Foot f's ankle turned so that its toe is at height y (its direction
 * over the ground kept), by `amount` (0..1) of that turn. */
static void flatten_foot(const smgi_rest_io* io, uint32_t f, float y,
                         float amount) {
  const smgi_info* info = io->in->graph->data.info;
  const uint32_t ankle = f ? info->right_leg[2] : info->left_leg[2];
  const uint32_t toe = f ? info->right_leg[3] : info->left_leg[3];
  const uint32_t J = io->in->graph->data.joint_count;
  if (toe >= J || ankle >= J || io->in->graph->data.joints[toe].parent < 0)
    return;
  float* wpos = io->pose->wpos;
  float* wrot = io->pose->wrot;
  const float v[3] = {wpos[3u * toe] - wpos[3u * ankle],
                      wpos[3u * toe + 1u] - wpos[3u * ankle + 1u],
                      wpos[3u * toe + 2u] - wpos[3u * ankle + 2u]};
  const float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const float flat = sqrtf(v[0] * v[0] + v[2] * v[2]);
  if (len < 1e-4f || flat < 1e-4f) return;
  float ty = v[1] + amount * (y - wpos[3u * toe + 1u]);
  ty = smgi_clampf(ty, -0.99f * len, 0.99f * len);
  const float k = sqrtf(len * len - ty * ty) / flat;
  const float w[3] = {v[0] * k, ty, v[2] * k};
  float dq[4], q[4], pc[4];
  smgi_q_from_to(v, w, dq);
  smgi_q_mul(dq, wrot + 4u * ankle, q);
  smgi_q_normalize(q);
  memcpy(wrot + 4u * ankle, q, sizeof q);
  /* the local rotation under the knee's world rotation */
  const uint32_t knee = (uint32_t)io->in->graph->data.joints[ankle].parent;
  smgi_q_conj(wrot + 4u * knee, pc);
  smgi_q_mul(pc, q, io->pose->rot + 4u * ankle);
  smgi_q_normalize(io->pose->rot + 4u * ankle);
  const uint32_t* list = io->ik->leg_joints + (size_t)f * J;
  smgi_fk_joints(io->pose, io->in->graph, list + 3u + io->ik->leg_side[f], io->ik->leg_below[f]);
}

void smgi_rest_flatten(const smgi_rest* r, const smgi_rest_io* io) {
  if (r->phase == SMGI_REST_OFF || !io->ik->enabled) return;
  if (r->phase == SMGI_REST_LEAVE) {
    /* the feet take the locomotion's shape again as it fades in (a foot
     * kept where it stood rolls onto its toe with the locomotion's) */
    const float amount = 1.0f - smooth(r->t / SMGI_REST_FADE_OUT);
    for (uint32_t f = 0; f < 2u; ++f) {
      const smgi_foot* foot = &io->ik->feet[f];
      if (!(r->keep & (1u << f)) || !io->ik->leg_ok[f] ||
          !(foot->stand_y < INFINITY) || amount <= 0.0f)
        continue;
      const float u = r->rejoin[f] < 0.0f
                          ? 0.0f
                          : r->rejoin[f] / SMGI_REST_REJOIN_SECONDS;
      flatten_foot(io, f, foot->stand_y, amount * (1.0f - smooth(u)));
    }
    return;
  }
  /* the standing foot turns flat over the settling; the stepping one is
   * carried flat (the IK raises the ankle by the step's arc) */
  const float amount =
      r->phase == SMGI_REST_SETTLE ? smooth(r->t / SMGI_REST_FOOT_FLAT) : 1.0f;
  const float u = step_progress(r);
  for (uint32_t f = 0; f < 2u; ++f) {
    const smgi_foot* foot = &io->ik->feet[f];
    if (!io->ik->leg_ok[f] || !(foot->stand_y < INFINITY)) continue;
    flatten_foot(io, f, foot->stand_y,
                 f == r->foot && u < 1.0f ? 1.0f : amount);
  }
}
