/*
 * character.c - character lifetime (one allocation at create, carved into
 * every buffer the character will use), path and constraint edits,
 * immediate controls, per-frame entry point, the state/pose getters and
 * what puts a character into a game scene (events, root motion for the
 * engine's mover, uneven ground: events.c, root_motion.c, ik.c).
 * Arguments are validated here; their defaults are settled in
 * settings.c; edits that invalidate the plan have it chosen again
 * (smgi_character_replan, step.c).
 */
#include <math.h>
#include <string.h>

#include "abi.h"
#include "alloc.h"
#include "character_state.h"
#include "settings.h"

static size_t align16(size_t n) { return (n + 15u) & ~(size_t)15u; }

typedef struct layout {
  size_t constraints, events, queue, rot, tmp, snap, wpos, wrot, decoded,
      legs, xz, cum, total;
} layout;

/* Hot data first: what every step touches (the struct, the pose and its
 * world transforms, the queue head) sits in as few pages as possible -
 * with thousands of characters, TLB and cache misses dominate the cost -
 * and rarely used buffers (crossfade snapshot, constraints, the path) come
 * after. */
static void compute_layout(uint32_t J, uint32_t path_cap, uint32_t cons_cap,
                           layout* l) {
  size_t o = align16(sizeof(smg_character));
  l->rot = o;
  o += align16(sizeof(float) * 4u * J);
  l->wpos = o;
  o += align16(sizeof(float) * 3u * J);
  l->wrot = o;
  o += align16(sizeof(float) * 4u * J);
  l->decoded = o;
  o += align16(sizeof(float) * 2u * smgi_decoded_floats(J));
  l->legs = o;
  o += align16(sizeof(uint32_t) * 2u * J);
  l->queue = o;
  o += align16(sizeof(smgi_qentry) * SMGI_QUEUE_CAP);
  l->tmp = o;
  /* crossfade scratch: on the stack for skeletons up to
   * SMGI_POSE_STACK_JOINTS joints (pose.c) */
  if (J > SMGI_POSE_STACK_JOINTS) o += align16(sizeof(float) * 4u * J);
  l->snap = o;
  o += align16(sizeof(float) * 4u * J);
  l->constraints = o;
  o += align16(sizeof(smgi_constraint) * cons_cap);
  l->events = o;
  o += align16(sizeof(smg_event) * smgi_events_capacity(cons_cap));
  l->xz = o;
  o += align16(sizeof(float) * 2u * (size_t)path_cap);
  l->cum = o;
  o += align16(sizeof(float) * (size_t)path_cap);
  l->total = o;
}

/* Steering limits: 0 (the default, settled in settings.c, which the
 * setter shares) up to their maxima (false for NaN too). Finite is not
 * enough: a stop time of 1e30 s made the braking frame count infinite, and
 * a slide ratio of 1000 moved the root at 1000 times the motion's speed
 * (both found by the runtime fuzz target). */
static int limits_ok(float turn, float slide, float stop) {
  return turn >= 0.0f && turn <= SMG_MAX_STEER_TURN_RATE && slide >= 0.0f &&
         slide <= SMG_MAX_STEER_SLIDE_RATIO && stop >= 0.0f &&
         stop <= SMG_MAX_STOP_SECONDS;
}

/* Swing clearance: 0 (the default) to SMG_MAX_SWING_CLEARANCE metres (a
 * foot lifted further would only stretch the leg; far beyond, the leg
 * solve's squared distances overflow). */
static int clearance_ok(float c) {
  return isfinite(c) && c >= 0.0f && c <= SMG_MAX_SWING_CLEARANCE;
}

/* Resolve desc (NULL, partial struct_size) into a full one, validated;
 * 0 still means the default (smgi_settle). */
static smg_result resolve_desc(const smg_graph* g, const smg_character_desc* in,
                               smg_character_desc* d) {
  memset(d, 0, sizeof *d);
  if (in) {
    if (!smgi_struct_size_ok(in->struct_size, sizeof *d))
      return SMG_ERROR_INVALID_ARGUMENT;
    memcpy(d, in, in->struct_size);
  }
  d->struct_size = sizeof *d;
  /* a flag this library does not know (from a newer header) is refused,
   * not silently ignored */
  if (d->flags & ~(uint32_t)(SMG_CHARACTER_NO_IK | SMG_CHARACTER_NO_STEERING |
                             SMG_CHARACTER_NO_SWING_CLEARANCE))
    return SMG_ERROR_INVALID_ARGUMENT;
  if (d->initial_style >= g->data.style_count) return SMG_ERROR_UNKNOWN_STYLE;
  if (d->initial_action >= g->data.action_count)
    return SMG_ERROR_UNKNOWN_ACTION;
  const float ground[2] = {d->position[0], d->position[2]};
  if (!smgi_coords_ok(ground, 2) || !isfinite(d->position[1]) ||
      !isfinite(d->heading) ||
      !isfinite(d->horizon) || !isfinite(d->error_threshold) ||
      d->horizon < 0.0f || d->horizon > SMGI_MAX_HORIZON ||
      d->error_threshold < 0.0f ||
      !limits_ok(d->steer_turn_rate, d->steer_slide_ratio, d->stop_seconds) ||
      !clearance_ok(d->swing_clearance))
    return SMG_ERROR_INVALID_ARGUMENT;
  if (d->path_capacity > SMGI_MAX_PATH_CAPACITY ||
      d->constraint_capacity > SMGI_MAX_CONSTRAINT_CAPACITY)
    return SMG_ERROR_INVALID_ARGUMENT;
  if ((d->allocator.alloc == NULL) != (d->allocator.free == NULL))
    return SMG_ERROR_INVALID_ARGUMENT;
  return SMG_OK;
}

SMG_API smg_result smg_character_memory_size(const smg_graph* graph,
                                             const smg_character_desc* desc,
                                             size_t* out_bytes) {
  if (!graph || !out_bytes) return SMG_ERROR_INVALID_ARGUMENT;
  smg_character_desc d;
  smg_result r = resolve_desc(graph, desc, &d);
  if (r != SMG_OK) return r;
  smgi_settings st;
  smgi_settle(graph, &d, &st);
  layout l;
  compute_layout(graph->data.joint_count, st.path_capacity,
                 st.constraint_capacity, &l);
  *out_bytes = l.total;
  return SMG_OK;
}

/* The character's planning phase (0..1 of a step, see smgi_plan), from
 * what tells characters apart in their desc: seed, start position and
 * heading. Deterministic, so equal descs still give equal characters. */
static float plan_phase(const smg_character_desc* d) {
  const float v[4] = {d->position[0], d->position[1], d->position[2],
                      d->heading};
  uint32_t h = d->seed * 0x9e3779b9u;
  for (int i = 0; i < 4; ++i) {
    uint32_t b;
    memcpy(&b, &v[i], sizeof b);
    h = (h ^ b) * 0x85ebca6bu;
    h ^= h >> 13;
  }
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return (float)(h >> 8) * (1.0f / 16777216.0f);
}

SMG_API smg_result smg_character_create(smg_graph* graph,
                                        const smg_character_desc* desc,
                                        smg_character** out_character) {
  if (!graph || !out_character || !graph->derived)
    return SMG_ERROR_INVALID_ARGUMENT;
  smg_character_desc d;
  smg_result r = resolve_desc(graph, desc, &d);
  if (r != SMG_OK) return r;
  smg_allocator a;
  r = smgi_allocator_resolve(&d.allocator, &a);
  if (r != SMG_OK) return r;
  smgi_settings st;
  smgi_settle(graph, &d, &st);
  const uint32_t J = graph->data.joint_count;
  layout l;
  compute_layout(J, st.path_capacity, st.constraint_capacity, &l);
  uint8_t* mem = (uint8_t*)smgi_alloc(&a, l.total, 16);
  if (!mem) return SMG_ERROR_OUT_OF_MEMORY;
  memset(mem, 0, l.total);
  smg_character* ch = (smg_character*)mem;
  ch->graph = graph;
  ch->allocator = a;
  ch->joint_count = J;
  ch->flags = d.flags;
  ch->ik.enabled = (d.flags & SMG_CHARACTER_NO_IK) ? 0u : 1u;
  ch->ik.swing_clearance = st.swing_clearance;
  ch->ik.swing_default = st.swing_default;
  smgi_steer_init(&ch->steer,
                  (d.flags & SMG_CHARACTER_NO_STEERING) ? 0u : 1u,
                  st.turn_limit, st.slide_ratio, st.stop_seconds);
  ch->rng = d.seed ? d.seed : 0x9e3779b9u;
  ch->plan.phase = plan_phase(&d);
  ch->plan.horizon = st.horizon;
  ch->plan.error_threshold = st.error_threshold;
  ch->fps = graph->data.info->frame_rate;
  ch->upper.fade_rate = st.fade_rate;
  ch->cons.items = (smgi_constraint*)(mem + l.constraints);
  ch->cons.capacity = st.constraint_capacity;
  ch->events.items = (smg_event*)(mem + l.events);
  ch->events.capacity = smgi_events_capacity(st.constraint_capacity);
  smgi_events_reset(&ch->events);
  smgi_ground_reset(&ch->ik.ground);
  ch->cons.next_id = 1;
  ch->lower.queue = (smgi_qentry*)(mem + l.queue);
  ch->pose.rot = (float*)(mem + l.rot);
  ch->pose.tmp = J > SMGI_POSE_STACK_JOINTS ? (float*)(mem + l.tmp) : NULL;
  ch->upper.snap = (float*)(mem + l.snap);
  ch->pose.wpos = (float*)(mem + l.wpos);
  ch->pose.wrot = (float*)(mem + l.wrot);
  ch->pose.decoded.rot =
      smgi_decoded_floats(J) ? (float*)(mem + l.decoded) : NULL;
  ch->pose.decoded.frame[0] = ch->pose.decoded.frame[1] = SMGI_NONE;
  ch->ik.leg_joints = (uint32_t*)(mem + l.legs);
  /* the crossfade snapshot (4J floats, unused until the first switch) as
   * J bytes of scratch: ch->pose.tmp no longer exists for skeletons that fit
   * the stack */
  smgi_ik_init_legs(&ch->ik, graph, mem + l.snap);
  memset(mem + l.snap, 0, J); /* scratch back to how create found it */
  smgi_ik_reset(&ch->ik);
  ch->path.xz = (float*)(mem + l.xz);
  ch->path.cum = (float*)(mem + l.cum);
  ch->path.capacity = st.path_capacity;
  ch->cons.base_style = d.initial_style;
  ch->cons.base_action = d.initial_action;
  ch->cons.base_style_arc = -1.0f;
  ch->cons.base_action_arc = -1.0f;
  ch->anchor[0] = d.position[0];
  ch->anchor[1] = d.position[2];
  smgi_sync_reset(&ch->sync);
  ch->lower.last_frame = 0xffffffffu;
  {
    const smgi_step_in in = smgi_step_in_of(ch);
    const smgi_steer_envelope env = smgi_steer_envelope_of(&ch->steer);
    r = smgi_plan_start(&ch->plan, &ch->lower, &in, &env, &ch->rng,
                        d.position[0], d.position[2], d.heading);
  }
  if (r != SMG_OK) {
    smgi_free(&a, mem);
    return r;
  }
  smgi_graph_retain(graph);
  smgi_upper_start(&ch->upper, graph, &ch->rng, ch->pose.rot,
                   ch->cons.base_action);
  smgi_sync_reset(&ch->sync);
  /* a valid pose before the first step */
  smgi_step(ch, 0.0f);
  *out_character = ch;
  return SMG_OK;
}

SMG_API smg_result smg_character_destroy(smg_character* ch) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  smg_graph* g = ch->graph;
  smg_allocator a = ch->allocator;
  smgi_free(&a, ch);
  smgi_graph_release(g);
  return SMG_OK;
}

/* ---- path edits ---- */

SMG_API smg_result smg_character_set_path(smg_character* ch, const float* xz,
                                          uint32_t count) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  if (count == 0) return smg_character_clear_path(ch);
  if (!xz) return SMG_ERROR_INVALID_ARGUMENT;
  if (count > ch->path.capacity) return SMG_ERROR_CAPACITY;
  if (!smgi_coords_ok(xz, 2u * count)) return SMG_ERROR_INVALID_ARGUMENT;
  float dist = 0.0f;
  ch->seg = 0;
  ch->progress = smgi_path_load(&ch->path, xz, 0, count, 1, ch->pose.ground[0],
                                ch->pose.ground[1], &ch->seg, &dist);
  ch->path_error = dist;
  ch->cons.base_style_arc = ch->cons.base_style_arc < 0.0f ? -1.0f : 0.0f;
  ch->cons.base_action_arc = ch->cons.base_action_arc < 0.0f ? -1.0f : 0.0f;
  ch->end_reached = 0;
  smgi_steer_path_changed(&ch->steer);
  smgi_character_replan(ch);
  return SMG_OK;
}

SMG_API smg_result smg_character_append_path(smg_character* ch,
                                             const float* xz, uint32_t count) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  if (count == 0) return SMG_OK;
  if (!xz) return SMG_ERROR_INVALID_ARGUMENT;
  if (count > ch->path.capacity - ch->path.count) return SMG_ERROR_CAPACITY;
  if (!smgi_coords_ok(xz, 2u * count)) return SMG_ERROR_INVALID_ARGUMENT;
  uint32_t old = ch->path.count;
  float dist = 0.0f;
  /* O(appended): only a path that was empty needs the projection */
  float s = smgi_path_load(&ch->path, xz, old, count, old == 0,
                           ch->pose.ground[0], ch->pose.ground[1], &ch->seg, &dist);
  if (old == 0) {
    ch->progress = s;
    ch->path_error = dist;
  }
  ch->end_reached = 0;
  smgi_steer_path_changed(&ch->steer);
  smgi_character_replan(ch);
  return SMG_OK;
}

SMG_API smg_result smg_character_clear_path(smg_character* ch) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  smgi_path_reset(&ch->path);
  ch->progress = 0.0f;
  ch->seg = 0;
  ch->path_error = 0.0f;
  ch->end_reached = 0;
  smgi_steer_path_changed(&ch->steer);
  /* stay around the end of the motion already committed */
  const smgi_qentry* h = smgi_q_at(&ch->lower, 0);
  const smgi_edge* e = &ch->graph->data.lower_edges[h->edge];
  smgi_xform2 d = {e->displacement[0], e->displacement[1],
                   e->displacement[2]};
  smgi_xform2 end = smgi_xf_mul(h->W, d);
  ch->anchor[0] = end.x;
  ch->anchor[1] = end.z;
  smgi_character_replan(ch);
  return SMG_OK;
}

SMG_API smg_result smg_character_get_path_length(const smg_character* ch,
                                                 float* out_length) {
  if (!ch || !out_length) return SMG_ERROR_INVALID_ARGUMENT;
  *out_length = ch->path.length;
  return SMG_OK;
}

/* ---- constraints (constraints.c holds them) ---- */

SMG_API smg_result smg_character_add_transition(smg_character* ch, float arc,
                                                uint32_t style,
                                                uint32_t* out_id) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  if (!isfinite(arc)) return SMG_ERROR_INVALID_ARGUMENT;
  if (style >= ch->graph->data.style_count) return SMG_ERROR_UNKNOWN_STYLE;
  smg_result r = smgi_constraints_add(&ch->cons, ch->path.length, arc,
                                      SMGI_CONSTRAINT_TRANSITION, style,
                                      out_id);
  if (r == SMG_OK) smgi_character_replan(ch);
  return r;
}

SMG_API smg_result smg_character_add_splice(smg_character* ch, float arc,
                                            uint32_t action,
                                            uint32_t* out_id) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  if (!isfinite(arc)) return SMG_ERROR_INVALID_ARGUMENT;
  if (action >= ch->graph->data.action_count)
    return SMG_ERROR_UNKNOWN_ACTION;
  smg_result r = smgi_constraints_add(&ch->cons, ch->path.length, arc,
                                      SMGI_CONSTRAINT_SPLICE, action, out_id);
  if (r == SMG_OK) smgi_character_replan(ch);
  return r;
}

SMG_API smg_result smg_character_move_constraint(smg_character* ch,
                                                 uint32_t id, float arc) {
  if (!ch || id == 0) return SMG_ERROR_INVALID_ARGUMENT;
  smg_result r = smgi_constraints_move(&ch->cons, ch->path.length, id, arc);
  if (r == SMG_OK) smgi_character_replan(ch);
  return r;
}

SMG_API smg_result smg_character_remove_constraint(smg_character* ch,
                                                   uint32_t id) {
  if (!ch || id == 0) return SMG_ERROR_INVALID_ARGUMENT;
  smg_result r = smgi_constraints_remove(&ch->cons, id);
  if (r == SMG_OK) smgi_character_replan(ch);
  return r;
}

SMG_API smg_result smg_character_clear_constraints(smg_character* ch) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  smgi_constraints_clear(&ch->cons);
  smgi_character_replan(ch);
  return SMG_OK;
}

/* ---- immediate controls ---- */

SMG_API smg_result smg_character_set_style(smg_character* ch,
                                           uint32_t style) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  if (style >= ch->graph->data.style_count) return SMG_ERROR_UNKNOWN_STYLE;
  ch->cons.base_style = style;
  ch->cons.base_style_arc = ch->progress;
  smgi_character_replan(ch);
  return SMG_OK;
}

SMG_API smg_result smg_character_set_action(smg_character* ch,
                                            uint32_t action) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  if (action >= ch->graph->data.action_count)
    return SMG_ERROR_UNKNOWN_ACTION;
  ch->cons.base_action = action;
  /* just behind the character so the look-ahead sees it at once */
  ch->cons.base_action_arc = ch->progress;
  return SMG_OK;
}

SMG_API smg_result smg_character_set_error_threshold(smg_character* ch,
                                                     float metres) {
  if (!ch || !isfinite(metres) || metres < 0.0f)
    return SMG_ERROR_INVALID_ARGUMENT;
  smg_character_desc d;
  smgi_settings st;
  memset(&d, 0, sizeof d);
  d.error_threshold = metres;
  smgi_settle(ch->graph, &d, &st);
  ch->plan.error_threshold = st.error_threshold;
  smgi_character_replan(ch);
  return SMG_OK;
}

SMG_API smg_result smg_character_set_ik(smg_character* ch, uint32_t enabled) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  ch->ik.enabled = enabled ? 1u : 0u;
  return SMG_OK;
}

SMG_API smg_result smg_character_set_steering(smg_character* ch,
                                              uint32_t enabled) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  ch->steer.enabled = enabled ? 1u : 0u;
  /* a character resting at the end walks on with the graph alone; the
   * correction itself fades out at its bounded rate (steer.c) */
  if (!ch->steer.enabled) smgi_steer_path_changed(&ch->steer);
  return SMG_OK;
}

SMG_API smg_result smg_character_set_swing_clearance(smg_character* ch,
                                                     uint32_t enabled,
                                                     float clearance) {
  if (!ch || !clearance_ok(clearance)) return SMG_ERROR_INVALID_ARGUMENT;
  smg_character_desc d;
  smgi_settings st;
  memset(&d, 0, sizeof d);
  d.flags = enabled ? 0u : SMG_CHARACTER_NO_SWING_CLEARANCE;
  d.swing_clearance = clearance;
  smgi_settle(ch->graph, &d, &st);
  ch->ik.swing_clearance = st.swing_clearance;
  return SMG_OK;
}

SMG_API smg_result smg_character_set_steering_limits(smg_character* ch,
                                                     float turn_rate,
                                                     float slide_ratio,
                                                     float stop_seconds) {
  if (!ch || !limits_ok(turn_rate, slide_ratio, stop_seconds))
    return SMG_ERROR_INVALID_ARGUMENT;
  smg_character_desc d;
  smgi_settings st;
  memset(&d, 0, sizeof d);
  d.steer_turn_rate = turn_rate;
  d.steer_slide_ratio = slide_ratio;
  d.stop_seconds = stop_seconds;
  smgi_settle(ch->graph, &d, &st);
  smgi_steer_set_limits(&ch->steer, st.turn_limit, st.slide_ratio,
                        st.stop_seconds);
  return SMG_OK;
}

/* ---- per frame ---- */

SMG_API smg_result smg_character_step(smg_character* ch, float dt) {
  if (!ch || !isfinite(dt) || dt < 0.0f || dt > 1.0f)
    return SMG_ERROR_INVALID_ARGUMENT;
  if (dt == 0.0f) return SMG_OK;
  return smgi_step(ch, dt);
}

SMG_API smg_result smg_character_get_state(const smg_character* ch,
                                           smg_character_state* out) {
  if (!ch || !out ||
      !smgi_struct_size_ok(out->struct_size, sizeof(smg_character_state)))
    return SMG_ERROR_INVALID_ARGUMENT;
  smg_character_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = out->struct_size;
  s.flags = ch->pose.contacts;
  if (ch->path.count > 0) s.flags |= SMG_STATE_HAS_PATH;
  if (ch->end_reached) s.flags |= SMG_STATE_PATH_END_REACHED;
  s.style = ch->lower.style;
  s.action = ch->upper.action;
  s.position[0] = ch->pose.ground[0];
  s.position[1] = ch->pose.ground_y;
  s.position[2] = ch->pose.ground[1];
  s.heading = ch->pose.heading;
  s.path_distance = ch->progress;
  s.path_error = ch->path_error;
  s.time = ch->time;
  s.lower_node = ch->lower.node;
  s.upper_node = ch->upper.node;
  s.sync_rate = ch->sync.rate;
  s.steer_turn_rate = ch->steer.turn;
  s.steer_slide_speed = sqrtf(ch->steer.slide[0] * ch->steer.slide[0] +
                              ch->steer.slide[1] * ch->steer.slide[1]);
  s.playback_rate = ch->steer.rate;
  memcpy(out, &s, out->struct_size);
  return SMG_OK;
}

SMG_API smg_result smg_character_get_local_pose(const smg_character* ch,
                                                float* root_translation,
                                                float* rotations,
                                                uint32_t joint_count) {
  if (!ch || !root_translation || !rotations)
    return SMG_ERROR_INVALID_ARGUMENT;
  if (joint_count < ch->joint_count) return SMG_ERROR_BUFFER_TOO_SMALL;
  if (joint_count != ch->joint_count) return SMG_ERROR_INVALID_ARGUMENT;
  memcpy(root_translation, ch->pose.root, sizeof(float) * 3u);
  memcpy(rotations, ch->pose.rot, sizeof(float) * 4u * ch->joint_count);
  return SMG_OK;
}

SMG_API smg_result smg_character_get_model_matrices(const smg_character* ch,
                                                    uint32_t space,
                                                    float* matrices,
                                                    uint32_t joint_count) {
  if (!ch || !matrices) return SMG_ERROR_INVALID_ARGUMENT;
  if (space != SMG_SPACE_WORLD && space != SMG_SPACE_CHARACTER)
    return SMG_ERROR_INVALID_ARGUMENT;
  if (joint_count < ch->joint_count) return SMG_ERROR_BUFFER_TOO_SMALL;
  if (joint_count != ch->joint_count) return SMG_ERROR_INVALID_ARGUMENT;
  /* world transforms were cached by the last step; only convert */
  smgi_pose_model_matrices(&ch->pose, ch->joint_count, space, matrices);
  return SMG_OK;
}

/* ---- in a game scene ---- */

SMG_API smg_result smg_character_get_events(const smg_character* ch,
                                            smg_event* events,
                                            uint32_t capacity,
                                            uint32_t* out_count) {
  if (!ch || !out_count || (!events && capacity > 0u))
    return SMG_ERROR_INVALID_ARGUMENT;
  const smgi_events* ev = &ch->events;
  if (!events) {
    *out_count = ev->count;
    return SMG_OK;
  }
  /* the first element's struct_size is the array's element size: at
   * least this version's event, a whole number of floats */
  const uint32_t stride = events[0].struct_size;
  if (stride < sizeof(smg_event) || stride % sizeof(float) != 0u ||
      stride > 65536u)
    return SMG_ERROR_INVALID_ARGUMENT;
  if (capacity < ev->count) {
    *out_count = ev->count;
    return SMG_ERROR_BUFFER_TOO_SMALL;
  }
  unsigned char* out = (unsigned char*)events;
  for (uint32_t i = 0; i < ev->count; ++i) {
    smg_event e = ev->items[i];
    e.struct_size = stride;
    memcpy(out + (size_t)i * stride, &e, sizeof e);
  }
  *out_count = ev->count;
  return SMG_OK;
}

SMG_API smg_result smg_character_get_root_motion(const smg_character* ch,
                                                 smg_root_motion* out) {
  if (!ch || !out ||
      !smgi_struct_size_ok(out->struct_size, sizeof(smg_root_motion)))
    return SMG_ERROR_INVALID_ARGUMENT;
  const smgi_root_motion* rm = &ch->root_motion;
  smg_root_motion m;
  memset(&m, 0, sizeof m);
  m.struct_size = out->struct_size;
  m.translation[0] = rm->delta[0];
  m.translation[1] = rm->delta[1];
  m.translation[2] = rm->delta[2];
  m.yaw = rm->delta[3];
  /* in the frame of the heading the step started with: x left, z forward */
  float s, c;
  smgi_sincosf(rm->before[3], &s, &c);
  m.local_translation[0] = c * rm->delta[0] - s * rm->delta[2];
  m.local_translation[1] = rm->delta[1];
  m.local_translation[2] = s * rm->delta[0] + c * rm->delta[2];
  memcpy(out, &m, out->struct_size);
  return SMG_OK;
}

SMG_API smg_result smg_character_set_ground_position(smg_character* ch,
                                                     const float* position,
                                                     float heading) {
  if (!ch || !position || !isfinite(heading) ||
      fabsf(heading) > SMG_MAX_COORDINATE)
    return SMG_ERROR_INVALID_ARGUMENT;
  if (!smgi_coords_ok(position, 3))
    return SMG_ERROR_INVALID_ARGUMENT;
  smgi_root_motion_place(&ch->root_motion, &ch->pose, &ch->lower, &ch->steer,
                         &ch->ik, &ch->rest, ch->joint_count, ch->anchor,
                         position, heading);
  /* progress along the path from the new place */
  if (ch->path.count > 0u) {
    float dist = 0.0f;
    ch->progress = smgi_path_project_local(&ch->path, ch->pose.ground[0],
                                           ch->pose.ground[1], &ch->seg,
                                           &dist);
    ch->path_error = dist;
  }
  return SMG_OK;
}

SMG_API smg_result smg_character_get_ground_probes(const smg_character* ch,
                                                   float* xz,
                                                   uint32_t count) {
  if (!ch || !xz || count != 3u) return SMG_ERROR_INVALID_ARGUMENT;
  float p[6];
  smgi_ground_probes(&ch->ik, &ch->pose, ch->graph, p);
  /* the root: carried on by its last step's root motion */
  p[4] = ch->pose.ground[0] + ch->root_motion.delta[0];
  p[5] = ch->pose.ground[1] + ch->root_motion.delta[2];
  memcpy(xz, p, sizeof p);
  return SMG_OK;
}

SMG_API smg_result smg_character_set_ground(smg_character* ch,
                                            const smg_ground* ground) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  smgi_ground* g = &ch->ik.ground;
  if (!ground) {
    /* the data's flat floor again: the body and feet go back to it at
     * once, as they were before any ground was given */
    smgi_ground_reset(g);
    return SMG_OK;
  }
  if (!smgi_struct_size_ok(ground->struct_size, sizeof(smg_ground)))
    return SMG_ERROR_INVALID_ARGUMENT;
  smg_ground in;
  memset(&in, 0, sizeof in);
  memcpy(&in, ground, ground->struct_size);
  const float h[3] = {in.foot_height[0], in.foot_height[1], in.root_height};
  if (in.flags != 0u || !smgi_coords_ok(h, 3))
    return SMG_ERROR_INVALID_ARGUMENT;
  g->on = 1u;
  g->foot[0] = h[0];
  g->foot[1] = h[1];
  g->root = h[2];
  return SMG_OK;
}
