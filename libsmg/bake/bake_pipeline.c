/*
 * bake_pipeline.c - smg_bake_run: the whole preprocessing in stages, each
 * timed (wall clock) and reported through the progress callback.
 *
 *   import         load, crop, retarget to the first clip's skeleton,
 *                  resample to the working rate, ground, mirror; fill the
 *                  frame pool (FK, ground frames, foot contacts, phase)
 *   lower graph    Kovar graph of the locomotion clips, pruned to its
 *                  largest SCC
 *   upper graph    Kovar graph of the action clips, pruned per action
 *   simplify       chain merging (both graphs)
 *   splice search  splice candidates + Horn corrections
 *   internodal     transition frames, displacements, arc lengths, blob
 */
#include <errno.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#ifdef _WIN32
#include <io.h>
#include <windows.h>
#endif

#include "abi.h"
#include "bake_desc.h"
#include "bake_graph.h"
#include "bake_math.h"
#include "bake_retarget.h"
#include "blob.h"

void smgb_fail(smgb_bake* b, const char* fmt, ...) {
  va_list ap;
  if (b->error[0]) return; /* keep the first, most specific message */
  va_start(ap, fmt);
  vsnprintf(b->error, sizeof b->error, fmt, ap);
  va_end(ap);
}

void smgb_progress(smgb_bake* b, float fraction) {
  if (b->progress && b->stage) b->progress(b->stage, fraction, b->progress_user);
}

void smgb_bake_free(smgb_bake* b) {
  free(b->poses);
  free(b->frames);
  free(b->positions);
  free(b->clips);
  free(b->splices);
  smgb_graph_free(&b->lower);
  smgb_graph_free(&b->upper);
  smgb_body_free(&b->body);
  smgb_skeleton_free(&b->skel);
  memset(b, 0, sizeof *b);
}

static double now_seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void resolve_options(const smg_bake_options* in, smgb_options* o) {
  smg_bake_options z;
  memset(&z, 0, sizeof z);
  if (!in || in->struct_size == 0) in = &z;
  memset(o, 0, sizeof *o);
  o->frame_rate = in->frame_rate > 0.0f ? in->frame_rate : 30.0f;
  o->window_seconds = in->window_seconds > 0.0f ? in->window_seconds
                                                : 1.0f / 3.0f;
  o->window = (uint32_t)lround(o->window_seconds * o->frame_rate);
  if (o->window < 2) o->window = 2;
  o->transition_percentile =
      in->transition_percentile > 0.0f ? in->transition_percentile : 30.0f;
  if (o->transition_percentile > 100.0f) o->transition_percentile = 100.0f;
  o->transition_threshold = in->transition_threshold;
  o->max_edge_seconds = in->max_edge_seconds > 0.0f ? in->max_edge_seconds
                                                    : 1.0f;
  o->max_edge_frames = (uint32_t)lround(o->max_edge_seconds * o->frame_rate);
  if (o->max_edge_frames < 1) o->max_edge_frames = 1;
  o->splice_percentile =
      in->splice_percentile > 0.0f ? in->splice_percentile : 30.0f;
  o->splice_region_seconds = in->splice_region_seconds > 0.0f
                                 ? in->splice_region_seconds
                                 : 0.5f;
  o->splices_per_region =
      in->splices_per_region ? in->splices_per_region : 2u;
  o->contact_height = in->contact_height > 0.0f ? in->contact_height : 0.06f;
  o->contact_speed = in->contact_speed > 0.0f ? in->contact_speed : 0.6f;
  o->threads = in->threads ? in->threads : 2u;
  if (o->threads > 8) o->threads = 8;
  o->no_mirror = in->no_mirror;
}

/* Raw caller options: zero means default, anything else must be a finite,
 * non-negative number in range. */
static smg_result check_raw_options(smgb_bake* b, const smg_bake_options* in) {
  const struct {
    const char* name;
    float v, max;
  } f[] = {{"frame_rate", in->frame_rate, 1000.0f},
           {"window_seconds", in->window_seconds, 10.0f},
           {"transition_percentile", in->transition_percentile, 100.0f},
           {"transition_threshold", in->transition_threshold, 100.0f},
           {"max_edge_seconds", in->max_edge_seconds, 3600.0f},
           {"splice_percentile", in->splice_percentile, 100.0f},
           {"splice_region_seconds", in->splice_region_seconds, 3600.0f},
           {"contact_height", in->contact_height, 10.0f},
           {"contact_speed", in->contact_speed, 100.0f}};
  size_t i;
  if (in->struct_size == 0) return SMG_OK;
  for (i = 0; i < sizeof f / sizeof f[0]; ++i)
    if (!isfinite(f[i].v) || f[i].v < 0.0f || f[i].v > f[i].max) {
      smgb_fail(b, "options.%s = %g: must be 0 (default) or in (0, %g]",
                f[i].name, (double)f[i].v, (double)f[i].max);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
  if (in->splices_per_region > 1000u) {
    smgb_fail(b, "options.splices_per_region = %u: at most 1000",
              in->splices_per_region);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  return SMG_OK;
}

static smg_result validate_options(smgb_bake* b, const smgb_options* o) {
  if (!(o->frame_rate > 0.0f && o->frame_rate <= 1000.0f) ||
      !isfinite(o->window_seconds) || !isfinite(o->max_edge_seconds) ||
      !isfinite(o->transition_percentile) || !isfinite(o->splice_percentile) ||
      !isfinite(o->transition_threshold) || o->transition_threshold < 0.0f ||
      !isfinite(o->contact_height) || !isfinite(o->contact_speed) ||
      !isfinite(o->splice_region_seconds) || o->window > 10000u) {
    smgb_fail(b, "options: a value is out of range or not finite");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  return SMG_OK;
}

static const char* base_name(const char* path) {
  const char* s = strrchr(path, '/');
  return s ? s + 1 : path;
}

static int has_ext(const char* path, const char* ext) {
  size_t n = strlen(path), e = strlen(ext);
  size_t i;
  if (n < e) return 0;
  for (i = 0; i < e; ++i) {
    char c = path[n - e + i];
    if (c >= 'A' && c <= 'Z') c = (char)(c - 'A' + 'a');
    if (c != ext[i]) return 0;
  }
  return 1;
}

/* Where an error happened: "file:line" or "clip N". */
static void where(const smg_bake_clip_desc* d, uint32_t index, char* out,
                  size_t size) {
  if (d->source_line > 0)
    snprintf(out, size, "clip %u (manifest line %d)", index + 1,
             (int)d->source_line);
  else
    snprintf(out, size, "clip %u", index + 1);
}

static smg_result memory_clip(smgb_bake* b, const smg_bake_memory_clip* m,
                              const char* name, smgb_clip* out) {
  uint32_t j, J = m->joint_count;
  size_t n;
  memset(out, 0, sizeof *out);
  if (J == 0 || J > 1024 || !m->joint_names || !m->parents || !m->offsets ||
      !m->poses || m->frame_count == 0 || !(m->frame_rate > 0.0f) ||
      !isfinite(m->frame_rate)) {
    smgb_fail(b, "%s: in-memory clip needs joints, parents, offsets, poses, "
                 "frames and a frame rate", name);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  snprintf(out->name, sizeof out->name, "%s", name);
  out->skeleton.joint_count = J;
  out->skeleton.names = calloc(J, sizeof *out->skeleton.names);
  out->skeleton.parents = calloc(J, sizeof *out->skeleton.parents);
  out->skeleton.offsets = calloc(J, sizeof *out->skeleton.offsets);
  n = (size_t)m->frame_count * SMGB_STRIDE(J);
  out->poses = malloc(n * sizeof *out->poses);
  if (!out->skeleton.names || !out->skeleton.parents ||
      !out->skeleton.offsets || !out->poses) {
    smgb_clip_free(out);
    smgb_fail(b, "out of memory copying clip %s", name);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (j = 0; j < J; ++j) {
    if (!m->joint_names[j] ||
        (j == 0 ? m->parents[j] != -1
                : (m->parents[j] < 0 || (uint32_t)m->parents[j] >= j))) {
      smgb_clip_free(out);
      smgb_fail(b, "%s: joint %u has no name or its parent does not precede "
                   "it", name, j);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    snprintf(out->skeleton.names[j], SMGB_NAME_MAX, "%s", m->joint_names[j]);
    out->skeleton.parents[j] = m->parents[j];
    memcpy(out->skeleton.offsets[j], m->offsets + 3u * j, 3 * sizeof(float));
  }
  memcpy(out->poses, m->poses, n * sizeof *out->poses);
  for (j = 0; j < n; ++j)
    if (!isfinite(out->poses[j])) {
      smgb_clip_free(out);
      smgb_fail(b, "%s: pose value %u is not finite", name, j);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
  {
    /* translations within 100 km, rotations near unit length (normalised
     * here; a zero or wild quaternion is an error) */
    uint32_t f, stride = SMGB_STRIDE(J);
    for (f = 0; f < m->frame_count; ++f) {
      float* p = out->poses + (size_t)f * stride;
      if (fabsf(p[0]) > 1e5f || fabsf(p[1]) > 1e5f || fabsf(p[2]) > 1e5f) {
        smgb_clip_free(out);
        smgb_fail(b, "%s: frame %u root translation beyond 100 km", name, f);
        return SMG_ERROR_INVALID_ARGUMENT;
      }
      for (j = 0; j < J; ++j) {
        float* q = p + 3 + 4 * j;
        float len = sqrtf(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(len > 0.5f && len < 2.0f)) {
          smgb_clip_free(out);
          smgb_fail(b, "%s: frame %u joint %u rotation is not a unit "
                       "quaternion (length %g)", name, f, j, (double)len);
          return SMG_ERROR_INVALID_ARGUMENT;
        }
        q[0] /= len; q[1] /= len; q[2] /= len; q[3] /= len;
      }
    }
  }
  out->frame_count = m->frame_count;
  out->frame_rate = m->frame_rate;
  return SMG_OK;
}

static smg_result crop(smgb_bake* b, smgb_clip* c, uint32_t first,
                       uint32_t count, const char* at) {
  uint32_t stride = SMGB_STRIDE(c->skeleton.joint_count);
  if (first == 0 && (count == 0 || count == c->frame_count)) return SMG_OK;
  if (first >= c->frame_count) {
    smgb_fail(b, "%s: first_frame %u beyond the clip's %u frames", at, first,
              c->frame_count);
    return SMG_ERROR_OUT_OF_RANGE;
  }
  if (count == 0 || first + count > c->frame_count) {
    if (count != 0) {
      smgb_fail(b, "%s: frame range %u+%u beyond the clip's %u frames", at,
                first, count, c->frame_count);
      return SMG_ERROR_OUT_OF_RANGE;
    }
    count = c->frame_count - first;
  }
  memmove(c->poses, c->poses + (size_t)first * stride,
          (size_t)count * stride * sizeof(float));
  c->frame_count = count;
  return SMG_OK;
}

static uint32_t label_index(char (*labels)[SMGB_LABEL_MAX], uint32_t* count,
                            const char* name) {
  uint32_t i;
  for (i = 0; i < *count; ++i)
    if (strcmp(labels[i], name) == 0) return i;
  if (*count >= SMGB_MAX_LABELS) return SMGI_NONE;
  snprintf(labels[*count], SMGB_LABEL_MAX, "%s", name);
  return (*count)++;
}

/* The rig named by desc->target_path becomes the blob's skeleton. */
static smg_result load_target(smgb_bake* b, const smg_bake_desc* desc) {
  char path[2048];
  smgb_error err;
  smg_result r;
  if (desc->struct_size < sizeof *desc || !desc->target_path) return SMG_OK;
  if (!desc->target_path[0] || !isfinite(desc->target_unit_scale) ||
      desc->target_unit_scale < 0.0f) {
    smgb_fail(b, "target rig: empty path or invalid unit scale");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (desc->data_dir && desc->data_dir[0] && desc->target_path[0] != '/')
    snprintf(path, sizeof path, "%s/%s", desc->data_dir, desc->target_path);
  else
    snprintf(path, sizeof path, "%s", desc->target_path);
  err.message[0] = '\0';
  r = smgb_rig_load(path, desc->target_unit_scale, desc->target_animation,
                    &b->skel, &err);
  if (r != SMG_OK) {
    smgb_fail(b, "target rig %s: %s", path,
              err.message[0] ? err.message : smg_result_string(r));
    return r;
  }
  snprintf(b->target_name, sizeof b->target_name, "%.63s", base_name(path));
  return SMG_OK;
}

/* The clip's bone map; NULL for descriptors from before the field. */
static const char* clip_bones(const smg_bake_clip_desc* d) {
  return d->struct_size >= offsetof(smg_bake_clip_desc, bones) + sizeof d->bones
             ? d->bones
             : NULL;
}

static smg_result import_clips(smgb_bake* b, const smg_bake_desc* desc) {
  uint32_t i;
  smg_result r = load_target(b, desc);
  int have_lower = 0;
  for (i = 0; i < desc->clip_count && r == SMG_OK; ++i) {
    const smg_bake_clip_desc* d = &desc->clips[i];
    char at[96], path[2048], name[SMGB_NAME_MAX];
    smgb_clip raw, rs, mir;
    smgb_error err;
    uint32_t label, mirror;
    memset(&raw, 0, sizeof raw);
    memset(&rs, 0, sizeof rs);
    memset(&mir, 0, sizeof mir);
    err.message[0] = '\0';
    where(d, i, at, sizeof at);
    if (d->role != SMG_BAKE_ROLE_LOWER && d->role != SMG_BAKE_ROLE_UPPER) {
      smgb_fail(b, "%s: role must be lower or upper", at);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    if (!d->label || !d->label[0] || strlen(d->label) >= SMGB_LABEL_MAX) {
      smgb_fail(b, "%s: a label (style or action name) is required", at);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    if (d->role == SMG_BAKE_ROLE_UPPER && strcmp(d->label, "none") == 0) {
      smgb_fail(b, "%s: an upper-body clip cannot have the action label "
                   "'none' (action 0 is the locomotion's own upper body)", at);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    if (!d->path && !d->memory) {
      smgb_fail(b, "%s: neither a path nor an in-memory clip", at);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    /* A malformed bone map fails before any file is read. */
    if ((r = smgb_bone_map_check(clip_bones(d), at, &err)) != SMG_OK) {
      smgb_fail(b, "%s", err.message);
      return r;
    }
    if (d->path) {
      if (desc->data_dir && desc->data_dir[0] && d->path[0] != '/')
        snprintf(path, sizeof path, "%s/%s", desc->data_dir, d->path);
      else
        snprintf(path, sizeof path, "%s", d->path);
      snprintf(name, sizeof name, "%.63s", d->name ? d->name : base_name(path));
      if (has_ext(path, ".bvh"))
        r = smgb_bvh_load(path, d->unit_scale, d->skip_first_frame, &raw,
                          &err);
      else /* glTF, GLB, FBX, ... through assimp */
        r = smgb_assimp_load(path, d->unit_scale, d->animation_index, &raw,
                             &err);
      if (r != SMG_OK) {
        smgb_fail(b, "%s: %s", at, err.message[0] ? err.message : path);
        return r;
      }
    } else {
      snprintf(name, sizeof name, "%s", d->name ? d->name : "memory clip");
      if ((r = memory_clip(b, d->memory, name, &raw)) != SMG_OK) return r;
    }
    r = crop(b, &raw, d->first_frame, d->frame_count, at);
    if (r == SMG_OK && b->skel.joint_count == 0) {
      r = smgb_skeleton_copy(&raw.skeleton, &b->skel);
      if (r != SMG_OK) smgb_fail(b, "out of memory (skeleton)");
    }
    if (r == SMG_OK && b->J == 0) {
      b->J = b->skel.joint_count;
      b->stride = SMGB_STRIDE(b->J);
      r = b->target_name[0] ? smgb_body_init(b, NULL, b->target_name)
                            : smgb_body_init(b, clip_bones(d),
                                             d->path ? path : name);
      if (r != SMG_OK) {
        char tmp[512];
        snprintf(tmp, sizeof tmp, "%s", b->error);
        b->error[0] = '\0';
        if (b->target_name[0])
          smgb_fail(b, "target rig %s: %s", b->target_name, tmp);
        else
          smgb_fail(b, "%s (%s): %s", at, name, tmp);
      }
    }
    if (r == SMG_OK) {
      smgb_roles roles;
      r = smgb_roles_find(&raw.skeleton, clip_bones(d), d->path ? path : name,
                          &roles, &err);
      /* Same hierarchy and no rig: rotations kept as they are (the plain
       * path); otherwise full retargeting onto the blob's skeleton. */
      if (r == SMG_OK && !b->target_name[0] &&
          smgb_same_hierarchy(&raw.skeleton, &b->skel))
        r = smgb_clip_retarget_roles(&raw, &roles, &b->skel, &b->body.roles,
                                     &err);
      else if (r == SMG_OK) {
        /* Retarget at the working rate: resampling first changes nothing
         * that matters and saves the work on high-rate capture (CMU's
         * 120 Hz: a quarter of the frames). */
        if (raw.frame_rate != b->opt.frame_rate) {
          smgb_clip low;
          r = smgb_clip_resample(&raw, b->opt.frame_rate, &low);
          if (r == SMG_OK) {
            smgb_clip_free(&raw);
            raw = low;
          } else {
            snprintf(err.message, sizeof err.message, "resampling failed");
          }
        }
        if (r == SMG_OK)
          r = smgb_retarget_clip(&raw, &roles, &b->skel, &b->body.roles,
                                 b->target_name[0] ? b->target_name
                                                   : "the first clip's "
                                                     "skeleton",
                                 &err);
      }
      if (r != SMG_OK) smgb_fail(b, "%s (%s): %s", at, name, err.message);
    }
    if (r == SMG_OK) {
      if (raw.frame_rate != b->opt.frame_rate) {
        r = smgb_clip_resample(&raw, b->opt.frame_rate, &rs);
        if (r != SMG_OK) smgb_fail(b, "%s: resampling failed", at);
      } else {
        r = smgb_clip_copy(&raw, &rs);
        if (r != SMG_OK) smgb_fail(b, "out of memory (clip copy)");
      }
    }
    if (r == SMG_OK && rs.frame_count < 2u * b->opt.window + 2u) {
      smgb_fail(b, "%s (%s): only %u frames at %g Hz; need at least %u",
                at, name, rs.frame_count, (double)b->opt.frame_rate,
                2u * b->opt.window + 2u);
      r = SMG_ERROR_INVALID_ARGUMENT;
    }
    if (r == SMG_OK) {
      smgb_clip_ground(&rs);
      if (d->role == SMG_BAKE_ROLE_LOWER) {
        label = label_index(b->styles, &b->style_count, d->label);
        have_lower = 1;
      } else {
        label = label_index(b->actions, &b->action_count, d->label);
      }
      if (label == SMGI_NONE) {
        smgb_fail(b, "%s: more than %d labels", at, SMGB_MAX_LABELS);
        r = SMG_ERROR_CAPACITY;
      }
    }
    if (r == SMG_OK) {
      uint32_t flags = d->role == SMG_BAKE_ROLE_LOWER ? SMGI_CLIP_LOWER
                                                      : SMGI_CLIP_UPPER;
      uint32_t src = b->clip_count;
      r = smgb_pool_add_clip(b, &rs, name, label, flags, SMGI_NONE);
      mirror = d->mirror == SMG_BAKE_MIRROR_YES ||
               (d->mirror == SMG_BAKE_MIRROR_DEFAULT && !b->opt.no_mirror);
      if (r == SMG_OK && mirror) {
        char mname[SMGB_NAME_MAX];
        snprintf(mname, sizeof mname, "%.50s (mirror)", name);
        r = smgb_clip_mirror_partners(&rs, b->body.mirror, &mir);
        if (r != SMG_OK)
          smgb_fail(b, "%s: mirroring failed", at);
        else
          r = smgb_pool_add_clip(b, &mir, mname, label,
                                 flags | SMGI_CLIP_MIRROR, src);
        b->bake_flags |= 1u;
      }
    }
    smgb_clip_free(&raw);
    smgb_clip_free(&rs);
    smgb_clip_free(&mir);
    smgb_progress(b, (float)(i + 1) / (float)desc->clip_count);
  }
  if (r == SMG_OK && !have_lower) {
    smgb_fail(b, "no lower-body (locomotion) clip given");
    r = SMG_ERROR_INVALID_ARGUMENT;
  }
  b->source_frame_count = b->frame_count;
  return r;
}

static void stage_begin(smgb_bake* b, smg_bake_result* out, const char* name,
                        double* t0) {
  b->stage = name;
  *t0 = now_seconds();
  smgb_progress(b, 0.0f);
  (void)out;
}

static void stage_end(smgb_bake* b, smg_bake_result* out, double t0) {
  if (out->stage_count < SMG_BAKE_MAX_STAGES) {
    out->stages[out->stage_count].name = b->stage;
    out->stages[out->stage_count].seconds = now_seconds() - t0;
    ++out->stage_count;
  }
  smgb_progress(b, 1.0f);
}

/* The bake proper, on resolved full-size structs (smg_bake_run). */
static smg_result bake(const smg_bake_desc* desc, smg_bake_result* out) {
  smgb_bake* b;
  smg_result r;
  double t0, tstart = now_seconds();
  int attempt;
  b = calloc(1, sizeof *b);
  if (!b) {
    snprintf(out->error, sizeof out->error, "out of memory");
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  resolve_options(&desc->options, &b->opt);
  b->progress = desc->progress;
  b->progress_user = desc->progress_user;
  snprintf(b->actions[0], SMGB_LABEL_MAX, "none");
  b->action_count = 1;
  if ((r = check_raw_options(b, &desc->options)) != SMG_OK) goto done;
  if ((r = validate_options(b, &b->opt)) != SMG_OK) goto done;

  stage_begin(b, out, "import", &t0);
  r = import_clips(b, desc);
  if (r != SMG_OK) goto done;
  stage_end(b, out, t0);

  stage_begin(b, out, "lower graph", &t0);
  for (attempt = 0;; ++attempt) {
    r = smgb_build_graph(b, SMGI_CLIP_LOWER);
    if (r == SMG_OK) r = smgb_prune(b, SMGI_CLIP_LOWER);
    /* A style lost in pruning: relax the candidate percentile (per style
     * pair) and retry before giving up. */
    if (r != SMG_ERROR_NOT_FOUND || attempt >= 3 ||
        b->opt.transition_percentile >= 100.0f)
      break;
    b->error[0] = '\0';
    b->opt.transition_percentile *= 2.0f;
    if (b->opt.transition_percentile > 100.0f)
      b->opt.transition_percentile = 100.0f;
  }
  if (r != SMG_OK) goto done;
  b->lower_nodes_before = b->lower.node_count;
  b->lower_edges_before = b->lower.edge_count;
  stage_end(b, out, t0);

  stage_begin(b, out, "upper graph", &t0);
  for (;;) {
    uint64_t phase_free = b->upper_phase_free;
    r = smgb_build_graph(b, SMGI_CLIP_UPPER);
    if (r == SMG_OK) r = smgb_prune(b, SMGI_CLIP_UPPER);
    /* An action the phase rule left without a cycle is rebuilt without
     * the rule (reported in upper_phase_fallbacks); at most once per
     * action. */
    if (r != SMG_ERROR_NOT_FOUND || b->upper_phase_free == phase_free) break;
    b->error[0] = '\0';
  }
  if (r != SMG_OK) goto done;
  b->upper_nodes_before = b->upper.node_count;
  b->upper_edges_before = b->upper.edge_count;
  stage_end(b, out, t0);

  stage_begin(b, out, "simplify", &t0);
  if ((r = smgb_simplify(b, &b->lower)) != SMG_OK) goto done;
  if ((r = smgb_simplify(b, &b->upper)) != SMG_OK) goto done;
  if ((r = smgb_materialize_transitions(b)) != SMG_OK) goto done;
  stage_end(b, out, t0);

  stage_begin(b, out, "splice search", &t0);
  if ((r = smgb_find_splices(b)) != SMG_OK) goto done;
  stage_end(b, out, t0);

  stage_begin(b, out, "internodal + blob", &t0);
  r = smgb_write_blob(b, &out->blob, &out->blob_size);
  if (r != SMG_OK) goto done;
  stage_end(b, out, t0);

  {
    smg_bake_stats* s = &out->stats;
    uint32_t c;
    for (c = 0; c < b->clip_count; ++c)
      if (!(b->clips[c].flags & SMGI_CLIP_BLEND)) ++s->clip_count;
    s->source_frames = b->source_frame_count;
    s->blend_frames = b->frame_count - b->source_frame_count;
    s->lower_candidates = b->lower_candidates;
    s->upper_candidates = b->upper_candidates;
    s->lower_nodes_before = b->lower_nodes_before;
    s->lower_edges_before = b->lower_edges_before;
    s->lower_nodes = b->lower.node_count;
    s->lower_edges = b->lower.edge_count;
    s->upper_nodes_before = b->upper_nodes_before;
    s->upper_edges_before = b->upper_edges_before;
    s->upper_nodes = b->upper.node_count;
    s->upper_edges = b->upper.edge_count;
    s->splice_count = b->splice_count;
    s->splice_coverage = b->splice_coverage;
    s->splice_max_gap = b->splice_max_gap;
    s->style_count = b->style_count;
    s->action_count = b->action_count;
    for (c = 0; c < SMGB_MAX_LABELS; ++c)
      out->upper_phase_fallbacks += (uint32_t)(b->upper_phase_free >> c & 1u);
  }
done:
  if (r != SMG_OK) {
    if (out->blob) smgi_blob_free(out->blob, NULL);
    snprintf(out->error, sizeof out->error, "%s",
             b->error[0] ? b->error : smg_result_string(r));
    out->blob = NULL;
    out->blob_size = 0;
  }
  out->total_seconds = now_seconds() - tstart;
  smgb_bake_free(b);
  free(b);
  return r;
}

smg_result smg_bake_run(const smg_bake_desc* desc, smg_bake_result* out) {
  smg_bake_result full; /* the caller gets the prefix it knows about */
  smg_bake_desc resolved;
  smg_bake_clip_desc* clips;
  smg_result r;
  uint32_t size;
  if (!out || !smgi_struct_size_ok(out->struct_size, sizeof *out))
    return SMG_ERROR_INVALID_ARGUMENT;
  size = out->struct_size;
  memset(&full, 0, sizeof full);
  r = smgb_desc_resolve(desc, &resolved, &clips, full.error,
                        sizeof full.error);
  if (r == SMG_OK) r = bake(&resolved, &full);
  free(clips);
  /* a caller whose struct cannot hold the blob cannot free it either */
  if (!smgb_result_holds_blob(size) && full.blob) {
    smgi_blob_free(full.blob, NULL);
    full.blob = NULL;
  }
  full.struct_size = size;
  memcpy(out, &full, size);
  return r;
}

void smg_bake_result_free(smg_bake_result* result) {
  if (!result || !smgb_result_holds_blob(result->struct_size)) return;
  if (result->blob) smgi_blob_free(result->blob, NULL);
  result->blob = NULL;
  result->blob_size = 0;
}

/* The platform parts of writing a file in place. Windows has no file mode
 * bits to keep, flushes a descriptor with _commit, and its rename() refuses
 * an existing target: MoveFileEx replaces it (one call, atomic on NTFS
 * within a directory). */
#ifdef _WIN32
static void keep_mode(int fd, const char* path) {
  (void)fd;
  (void)path;
}
static int sync_fd(int fd) { return _commit(fd); }
static int replace_file(const char* from, const char* to) {
  return MoveFileExA(from, to, MOVEFILE_REPLACE_EXISTING |
                                   MOVEFILE_WRITE_THROUGH) ? 0 : -1;
}
static const char* path_base(const char* path) {
  const char* slash = strrchr(path, '/');
  const char* back = strrchr(path, '\\');
  if (back && (!slash || back > slash)) slash = back;
  return slash ? slash + 1 : path;
}
#else
/* mkstemp makes it private (0600): keep the old file's mode, else the
 * usual 0644 */
static void keep_mode(int fd, const char* path) {
  struct stat st;
  fchmod(fd, stat(path, &st) == 0 ? (st.st_mode & 07777) : 0644);
}
static int sync_fd(int fd) { return fsync(fd); }
static int replace_file(const char* from, const char* to) {
  return rename(from, to);
}
static const char* path_base(const char* path) {
  const char* slash = strrchr(path, '/');
  return slash ? slash + 1 : path;
}
#endif

/* The blob goes to a fresh temporary file beside `path` (same directory,
 * so the rename cannot cross file systems), is flushed to the disk, and
 * only then renamed over `path`: readers see the old file or the whole new
 * one, never a part, even if the bake fails or is killed half-way (an
 * interrupted write leaves only a hidden .NAME.XXXXXX beside it). */
smg_result smg_bake_write_file(const smg_bake_result* result,
                               const char* path, char* error,
                               size_t error_size) {
  char tmp[4096];
  const char* base;
  FILE* f;
  size_t n;
  int fd, ok;
  if (error && error_size) error[0] = '\0';
  if (!result || !smgb_result_holds_blob(result->struct_size) ||
      !result->blob || !path || !path[0]) {
    if (error && error_size)
      snprintf(error, error_size, "smg_bake_write_file: no blob or no path");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  base = path_base(path);
  if (snprintf(tmp, sizeof tmp, "%.*s.%s.XXXXXX", (int)(base - path), path,
               base) >= (int)sizeof tmp) {
    if (error && error_size)
      snprintf(error, error_size, "%s: path too long", path);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  fd = mkstemp(tmp);
  if (fd < 0) {
    if (error && error_size)
      snprintf(error, error_size, "%s: cannot create a file beside it (%s)",
               path, strerror(errno));
    return SMG_ERROR_IO;
  }
  keep_mode(fd, path);
  f = fdopen(fd, "wb");
  if (!f) {
    close(fd);
    remove(tmp);
    if (error && error_size)
      snprintf(error, error_size, "%s: cannot open for writing", tmp);
    return SMG_ERROR_IO;
  }
  n = fwrite(result->blob, 1, result->blob_size, f);
  ok = n == result->blob_size && fflush(f) == 0 && sync_fd(fd) == 0;
  if (fclose(f) != 0 || !ok) {
    remove(tmp);
    if (error && error_size)
      snprintf(error, error_size, "%s: write failed (disk full?); %s is "
               "unchanged", tmp, path);
    return SMG_ERROR_IO;
  }
  if (replace_file(tmp, path) != 0) {
    remove(tmp);
    if (error && error_size)
      snprintf(error, error_size, "%s: cannot rename to %s", tmp, path);
    return SMG_ERROR_IO;
  }
  return SMG_OK;
}
