/*
 * bake_import.c - the import stage: every clip of the description is
 * loaded (BVH, assimp formats, or an in-memory clip), cropped to its frame
 * range, put on the blob's skeleton, resampled to the working rate,
 * grounded, labelled, mirrored when asked, and added to the frame pool.
 * The first clip (or the target rig) fixes the blob's skeleton and body.
 *
 * A clip that fails is reported and skipped, and the next one is still
 * read, so one run names every broken clip; only a failure of the blob's
 * skeleton or of memory stops the stage at once. A clip marked
 * SMG_BAKE_CLIP_SKIP_UNUSABLE (a manifest folder pattern's) that fails
 * that way is a warning instead: the bake goes on without it.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_clip.h"
#include "bake_import.h"
#include "bake_import_util.h"
#include "bake_pool.h"
#include "bake_retarget.h"
#include "bake_threads.h"

static const char* base_name(const char* path) {
  const char* s = strrchr(path, '/');
  return s ? s + 1 : path;
}

/* `file` joined to the description's data folder unless absolute. */
static void join_data_dir(const smg_bake_desc* desc, const char* file,
                          char* out, size_t size) {
  if (desc->data_dir && desc->data_dir[0] && file[0] != '/')
    snprintf(out, size, "%s/%s", desc->data_dir, file);
  else
    snprintf(out, size, "%s", file);
}

/* Where an error happened: "clip N (manifest line L)" or "clip N". */
static void where(const smg_bake_clip_desc* d, uint32_t index, char* out,
                  size_t size) {
  if (d->source_line > 0)
    snprintf(out, size, "clip %u (manifest line %d)", index + 1,
             (int)d->source_line);
  else
    snprintf(out, size, "clip %u", index + 1);
}

/* The clip's bone map; NULL for descriptors from before the field. */
static const char* clip_bones(const smg_bake_clip_desc* d) {
  return d->struct_size >= offsetof(smg_bake_clip_desc, bones) + sizeof d->bones
             ? d->bones
             : NULL;
}

/* Translations within 100 km, rotations near unit length (normalised
 * here; a zero or wild quaternion is an error). */
static smg_result check_memory_poses(smgb_bake* b, const char* name,
                                     smgb_clip* c) {
  uint32_t f, j, J = c->skeleton.joint_count, stride = SMGB_STRIDE(J);
  size_t i, n = (size_t)c->frame_count * stride;
  for (i = 0; i < n; ++i)
    if (!isfinite(c->poses[i])) {
      smgb_fail(&b->report, "%s: pose value %u is not finite", name,
                (uint32_t)i);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
  for (f = 0; f < c->frame_count; ++f) {
    float* p = c->poses + (size_t)f * stride;
    if (fabsf(p[0]) > 1e5f || fabsf(p[1]) > 1e5f || fabsf(p[2]) > 1e5f) {
      smgb_fail(&b->report, "%s: frame %u root translation beyond 100 km",
                name, f);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    for (j = 0; j < J; ++j) {
      float* q = p + 3 + 4 * j;
      float len = sqrtf(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (!(len > 0.5f && len < 2.0f)) {
        smgb_fail(&b->report, "%s: frame %u joint %u rotation is not a unit "
                              "quaternion (length %g)", name, f, j,
                  (double)len);
        return SMG_ERROR_INVALID_ARGUMENT;
      }
      q[0] /= len; q[1] /= len; q[2] /= len; q[3] /= len;
    }
  }
  return SMG_OK;
}

/* Copy an in-memory clip (smg_bake_memory_clip) and check it. */
static smg_result memory_clip(smgb_bake* b, const smg_bake_memory_clip* m,
                              const char* name, smgb_clip* out) {
  uint32_t j, J = m->joint_count;
  size_t n;
  smg_result r;
  memset(out, 0, sizeof *out);
  if (J == 0 || J > 1024 || !m->joint_names || !m->parents || !m->offsets ||
      !m->poses || m->frame_count == 0 || !(m->frame_rate > 0.0f) ||
      !isfinite(m->frame_rate)) {
    smgb_fail(&b->report, "%s: in-memory clip needs joints, parents, "
                          "offsets, poses, frames and a frame rate", name);
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
    smgb_fail(&b->report, "out of memory copying clip %s", name);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (j = 0; j < J; ++j) {
    if (!m->joint_names[j] ||
        (j == 0 ? m->parents[j] != -1
                : (m->parents[j] < 0 || (uint32_t)m->parents[j] >= j))) {
      smgb_clip_free(out);
      smgb_fail(&b->report, "%s: joint %u has no name or its parent does "
                            "not precede it", name, j);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    snprintf(out->skeleton.names[j], SMGB_NAME_MAX, "%s", m->joint_names[j]);
    out->skeleton.parents[j] = m->parents[j];
    memcpy(out->skeleton.offsets[j], m->offsets + 3u * j, 3 * sizeof(float));
  }
  memcpy(out->poses, m->poses, n * sizeof *out->poses);
  out->frame_count = m->frame_count;
  out->frame_rate = m->frame_rate;
  if ((r = check_memory_poses(b, name, out)) != SMG_OK) smgb_clip_free(out);
  return r;
}

static smg_result crop(smgb_bake* b, smgb_clip* c, uint32_t first,
                       uint32_t count, const char* at) {
  uint32_t stride = SMGB_STRIDE(c->skeleton.joint_count);
  if (first == 0 && (count == 0 || count == c->frame_count)) return SMG_OK;
  if (first >= c->frame_count) {
    smgb_fail(&b->report, "%s: first_frame %u beyond the clip's %u frames",
              at, first, c->frame_count);
    return SMG_ERROR_OUT_OF_RANGE;
  }
  if (count == 0 || first + count > c->frame_count) {
    if (count != 0) {
      smgb_fail(&b->report, "%s: frame range %u+%u beyond the clip's %u "
                            "frames", at, first, count, c->frame_count);
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
    smgb_fail(&b->report, "target rig: empty path or invalid unit scale");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  join_data_dir(desc, desc->target_path, path, sizeof path);
  err.message[0] = '\0';
  r = smgb_rig_load(path, desc->target_unit_scale, desc->target_animation,
                    &b->skel, &err);
  if (r != SMG_OK) {
    smgb_fail(&b->report, "target rig %s: %s", path,
              err.message[0] ? err.message : smg_result_string(r));
    return r;
  }
  snprintf(b->target_name, sizeof b->target_name, "%.63s", base_name(path));
  return SMG_OK;
}

/* One clip on its way into the pool. */
typedef struct clip_job {
  const smg_bake_clip_desc* d;
  char at[96];                 /* "clip N (manifest line L)" */
  char path[2048];             /* file, joined to the data folder */
  char name[SMGB_NAME_MAX];
  const char* source;          /* file or name, for role errors */
  smgb_clip clip;
} clip_job;

/* What the description says, checked before any file is read. */
static smg_result check_desc(smgb_bake* b, const clip_job* job) {
  const smg_bake_clip_desc* d = job->d;
  smgb_error err;
  smg_result r;
  if (d->role != SMG_BAKE_ROLE_LOWER && d->role != SMG_BAKE_ROLE_UPPER) {
    smgb_fail(&b->report, "%s: role must be lower or upper", job->at);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (!d->label || !d->label[0] || strlen(d->label) >= SMGB_LABEL_MAX) {
    smgb_fail(&b->report, "%s: a label (style or action name) is required",
              job->at);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (d->role == SMG_BAKE_ROLE_UPPER && strcmp(d->label, "none") == 0) {
    smgb_fail(&b->report, "%s: an upper-body clip cannot have the action "
                          "label 'none' (action 0 is the locomotion's own "
                          "upper body)", job->at);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (!d->path && !d->memory) {
    smgb_fail(&b->report, "%s: neither a path nor an in-memory clip",
              job->at);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  err.message[0] = '\0';
  if ((r = smgb_bone_map_check(clip_bones(d), job->at, &err)) != SMG_OK)
    smgb_fail(&b->report, "%s", err.message);
  return r;
}

/* A BVH file parsed ahead (parse_ahead). */
typedef struct parsed {
  int done;                    /* parsed: r, err and clip are its result */
  smg_result r;
  smgb_error err;
  smgb_clip clip;
} parsed;

/* Clips taken per batch of parse_ahead. */
#define IMPORT_BATCH 64u

typedef struct parse_worker {
  const smg_bake_desc* desc;
  parsed* out;
  uint32_t i0, n, t, nt;
} parse_worker;

static void* parse_run(void* arg) {
  const parse_worker* w = arg;
  uint32_t u;
  for (u = w->t; u < w->n; u += w->nt) {
    const smg_bake_clip_desc* d = &w->desc->clips[w->i0 + u];
    parsed* p = &w->out[u];
    char path[2048];
    if (!d->path) continue;
    join_data_dir(w->desc, d->path, path, sizeof path);
    if (!smgb_has_ext(path, ".bvh")) continue;
    p->err.message[0] = '\0';
    p->r = smgb_bvh_load(path, d->unit_scale, d->skip_first_frame, &p->clip,
                         &p->err);
    p->done = 1;
  }
  return NULL;
}

/* The BVH files of clips [i0, i0 + n) parsed in parallel: parsing is most
 * of the import's work and each file's is its own. The clips are then
 * taken in order as before (read_clip uses the parse), so what is kept
 * and reported does not depend on the thread count. Other files (assimp)
 * are read in order. */
static void parse_ahead(const smgb_bake* b, const smg_bake_desc* desc,
                        uint32_t i0, uint32_t n, parsed* out) {
  parse_worker w[SMGB_MAX_THREADS];
  uint32_t t, nt = b->opt.threads < 1u ? 1u : b->opt.threads;
  if (nt > SMGB_MAX_THREADS) nt = SMGB_MAX_THREADS;
  memset(out, 0, n * sizeof *out);
  for (t = 0; t < nt; ++t) {
    w[t].desc = desc;
    w[t].out = out;
    w[t].i0 = i0;
    w[t].n = n;
    w[t].t = t;
    w[t].nt = nt;
  }
  smgb_run_workers(w, sizeof w[0], nt, parse_run);
}

/* Frees what a batch parsed and no clip took. */
static void drop_parsed(parsed* pre) {
  uint32_t u;
  for (u = 0; u < IMPORT_BATCH; ++u)
    if (pre[u].done) smgb_clip_free(&pre[u].clip);
  memset(pre, 0, IMPORT_BATCH * sizeof *pre);
}

/* The clip from its file (BVH, else glTF/GLB/FBX/... through assimp) or
 * from memory, cropped to its frame range. `pre`: its file parsed ahead
 * (NULL or not done: parse it now). */
static smg_result read_clip(smgb_bake* b, const smg_bake_desc* desc,
                            clip_job* job, parsed* pre) {
  const smg_bake_clip_desc* d = job->d;
  smg_result r;
  if (d->path) {
    smgb_error err;
    err.message[0] = '\0';
    join_data_dir(desc, d->path, job->path, sizeof job->path);
    snprintf(job->name, sizeof job->name, "%.63s",
             d->name ? d->name : base_name(job->path));
    job->source = job->path;
    if (smgb_has_ext(job->path, ".bvh") && pre && pre->done) {
      r = pre->r;
      err = pre->err;
      job->clip = pre->clip; /* taken over */
      memset(pre, 0, sizeof *pre);
    } else if (smgb_has_ext(job->path, ".bvh")) {
      r = smgb_bvh_load(job->path, d->unit_scale, d->skip_first_frame,
                        &job->clip, &err);
    } else
      r = smgb_assimp_load(job->path, d->unit_scale, d->animation_index,
                           &job->clip, &err);
    if (r != SMG_OK) {
      smgb_fail(&b->report, "%s: %s", job->at,
                err.message[0] ? err.message : job->path);
      return r;
    }
  } else {
    snprintf(job->name, sizeof job->name, "%s",
             d->name ? d->name : "memory clip");
    job->source = job->name;
    if ((r = memory_clip(b, d->memory, job->name, &job->clip)) != SMG_OK)
      return r;
  }
  return crop(b, &job->clip, d->first_frame, d->frame_count, job->at);
}

/* The first clip's skeleton becomes the blob's unless a target rig gave
 * one; then the body (roles, tables) of that skeleton. */
static smg_result fix_skeleton(smgb_bake* b, const clip_job* job) {
  char place[256];
  smg_result r;
  if (b->skel.joint_count == 0 &&
      smgb_skeleton_copy(&job->clip.skeleton, &b->skel) != SMG_OK) {
    smgb_fail(&b->report, "out of memory (skeleton)");
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  b->J = b->skel.joint_count;
  b->stride = SMGB_STRIDE(b->J);
  if (b->target_name[0])
    snprintf(place, sizeof place, "target rig %s", b->target_name);
  else
    snprintf(place, sizeof place, "%s (%s)", job->at, job->name);
  smgb_report_place(&b->report, place);
  r = b->target_name[0]
          ? smgb_body_init(&b->body, &b->skel, NULL, b->target_name,
                           &b->report)
          : smgb_body_init(&b->body, &b->skel, clip_bones(job->d),
                           job->source, &b->report);
  smgb_report_place(&b->report, NULL);
  return r;
}

/* The clip on the blob's skeleton. Same hierarchy and no rig: rotations
 * kept as they are (the plain path); otherwise full retargeting. */
static smg_result put_on_skeleton(smgb_bake* b, clip_job* job) {
  smgb_roles roles;
  smgb_error err;
  smg_result r;
  err.message[0] = '\0';
  r = smgb_roles_find(&job->clip.skeleton, clip_bones(job->d), job->source,
                      &roles, &err);
  if (r == SMG_OK && !b->target_name[0] &&
      smgb_same_hierarchy(&job->clip.skeleton, &b->skel)) {
    r = smgb_clip_retarget_roles(&job->clip, &roles, &b->skel,
                                 &b->body.roles, &err);
  } else if (r == SMG_OK) {
    /* Retarget at the working rate: resampling first changes nothing
     * that matters and saves the work on high-rate capture (CMU's
     * 120 Hz: a quarter of the frames). */
    if (job->clip.frame_rate != b->opt.frame_rate) {
      smgb_clip low;
      r = smgb_clip_resample(&job->clip, b->opt.frame_rate, &low);
      if (r == SMG_OK) {
        smgb_clip_free(&job->clip);
        job->clip = low;
      } else {
        snprintf(err.message, sizeof err.message, "resampling failed");
      }
    }
    if (r == SMG_OK)
      r = smgb_retarget_clip(&job->clip, &roles, &b->skel, &b->body.roles,
                             b->target_name[0] ? b->target_name
                                               : "the first clip's skeleton",
                             &err);
  }
  if (r != SMG_OK)
    smgb_fail(&b->report, "%s (%s): %s", job->at, job->name, err.message);
  return r;
}

/* The clip at the working rate, long enough for two transition windows,
 * on the floor. */
static smg_result to_working_rate(smgb_bake* b, clip_job* job,
                                  smgb_clip* out) {
  uint32_t need = 2u * b->opt.window + 2u;
  smg_result r;
  if (job->clip.frame_rate != b->opt.frame_rate) {
    r = smgb_clip_resample(&job->clip, b->opt.frame_rate, out);
    if (r != SMG_OK) smgb_fail(&b->report, "%s: resampling failed", job->at);
  } else {
    r = smgb_clip_copy(&job->clip, out);
    if (r != SMG_OK) smgb_fail(&b->report, "out of memory (clip copy)");
  }
  if (r != SMG_OK) return r;
  if (out->frame_count < need) {
    smgb_fail(&b->report, "%s (%s): only %u frames at %g Hz; need at least "
                          "%u", job->at, job->name, out->frame_count,
              (double)b->opt.frame_rate, need);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  smgb_clip_ground(out);
  return SMG_OK;
}

/* The clip, and its mirror when asked, into the pool under its label. */
static smg_result add_to_pool(smgb_bake* b, const clip_job* job,
                              const smgb_clip* rs) {
  const smg_bake_clip_desc* d = job->d;
  int lower = d->role == SMG_BAKE_ROLE_LOWER;
  uint32_t label = lower ? label_index(b->styles, &b->style_count, d->label)
                         : label_index(b->actions, &b->action_count, d->label);
  uint32_t flags = lower ? SMGI_CLIP_LOWER : SMGI_CLIP_UPPER;
  uint32_t src = b->clip_count;
  smgb_clip mir;
  char mname[SMGB_NAME_MAX];
  smg_result r;
  if (label == SMGI_NONE) {
    smgb_fail(&b->report, "%s: more than %d labels", job->at,
              SMGB_MAX_LABELS);
    return SMG_ERROR_CAPACITY;
  }
  r = smgb_pool_append_clip(b, rs, job->name, label, flags, SMGI_NONE);
  if (r != SMG_OK ||
      !(d->mirror == SMG_BAKE_MIRROR_YES ||
        (d->mirror == SMG_BAKE_MIRROR_DEFAULT && !b->opt.no_mirror)))
    return r;
  memset(&mir, 0, sizeof mir);
  snprintf(mname, sizeof mname, "%.50s (mirror)", job->name);
  r = smgb_clip_mirror_partners(rs, b->body.mirror, &mir);
  if (r != SMG_OK)
    smgb_fail(&b->report, "%s: mirroring failed", job->at);
  else
    r = smgb_pool_append_clip(b, &mir, mname, label,
                              flags | SMGI_CLIP_MIRROR, src);
  b->bake_flags |= 1u;
  smgb_clip_free(&mir);
  return r;
}

/* Clip `i` of `desc` into the pool. *fatal is set when the failure leaves
 * nothing later clips could be put on (the blob's skeleton, memory). */
static smg_result import_clip(smgb_bake* b, const smg_bake_desc* desc,
                              uint32_t i, parsed* pre, int* fatal) {
  clip_job job;
  smgb_clip rs;
  smg_result r;
  memset(&job, 0, sizeof job);
  memset(&rs, 0, sizeof rs);
  job.d = &desc->clips[i];
  where(job.d, i, job.at, sizeof job.at);
  r = check_desc(b, &job);
  if (r == SMG_OK) r = read_clip(b, desc, &job, pre);
  if (r == SMG_OK && b->J == 0) {
    r = fix_skeleton(b, &job);
    if (r != SMG_OK) *fatal = 1;
  }
  if (r == SMG_OK) r = put_on_skeleton(b, &job);
  if (r == SMG_OK) r = to_working_rate(b, &job, &rs);
  if (r == SMG_OK) {
    r = add_to_pool(b, &job, &rs);
    if (r != SMG_OK) *fatal = 1;
  }
  if (r == SMG_ERROR_OUT_OF_MEMORY) *fatal = 1;
  smgb_clip_free(&job.clip);
  smgb_clip_free(&rs);
  return r;
}

/* Clip `i` failed (not fatally) and may be left out: its errors become
 * one warning naming it and the first of them. */
static void skip_clip(smgb_bake* b, const smg_bake_desc* desc, uint32_t i,
                      uint32_t mark) {
  char why[512], at[96];
  const smgb_report* rep = &b->report;
  const char* file = desc->clips[i].path ? desc->clips[i].path : "";
  const char* slash = strrchr(file, '/');
  snprintf(why, sizeof why, "%s",
           mark < rep->problem_count ? rep->problems[mark].text : "");
  const char* reason = why;
  smgb_report_rewind(&b->report, mark);
  where(&desc->clips[i], i, at, sizeof at);
  /* the error starts with the clip's place, which the warning names */
  if (strncmp(why, at, strlen(at)) == 0 && strstr(why, ": "))
    reason = strstr(why, ": ") + 2;
  smgb_warn(&b->report, "%s (%s) skipped, it cannot be used: %s", at,
            slash ? slash + 1 : file, reason);
  ++b->skipped_clips;
}

smg_result smgb_import_clips(smgb_bake* b, const smg_bake_desc* desc) {
  smg_result r = load_target(b, desc), first = SMG_OK;
  int fatal = r != SMG_OK, have_lower = 0;
  uint32_t i;
  /* without memory for it, every file is parsed in order */
  parsed* pre = calloc(IMPORT_BATCH, sizeof *pre);
  for (i = 0; i < desc->clip_count && !fatal; ++i) {
    uint32_t mark = smgb_report_mark(&b->report);
    if (pre && i % IMPORT_BATCH == 0) {
      drop_parsed(pre);
      parse_ahead(b, desc, i,
                  desc->clip_count - i < IMPORT_BATCH ? desc->clip_count - i
                                                      : IMPORT_BATCH,
                  pre);
    }
    r = import_clip(b, desc, i, pre ? &pre[i % IMPORT_BATCH] : NULL,
                    &fatal);
    if (r == SMG_OK)
      have_lower |= desc->clips[i].role == SMG_BAKE_ROLE_LOWER;
    else if (!fatal && (desc->clips[i].flags & SMG_BAKE_CLIP_SKIP_UNUSABLE))
      skip_clip(b, desc, i, mark);
    else if (first == SMG_OK)
      first = r;
    smgb_progress(&b->report, (float)(i + 1) / (float)desc->clip_count);
  }
  if (pre) drop_parsed(pre);
  free(pre);
  /* FK, ground frames, contacts and phase of every clip, in parallel */
  smgb_pool_derive_clips(b, 0, b->opt.threads);
  if (first == SMG_OK && fatal) first = r;
  if (first == SMG_OK && !have_lower) {
    smgb_fail(&b->report, "no lower-body (locomotion) clip given");
    first = SMG_ERROR_INVALID_ARGUMENT;
  }
  b->source_frame_count = b->frame_count;
  return first;
}
