/*
 * bake_analyze.c - locomotion analysis of one clip (see bake_analyze.h).
 *
 * The clip is put through the baker's own import path (resample to the
 * working rate, ground, frame pool: FK, ground frames, contacts, phase), so
 * what is printed is exactly what a bake would label. Direction of travel:
 * the root's ground displacement over +-0.3 s (about half a stride, which
 * cancels the pelvis' side-to-side sway) against the circular mean of the
 * root heading over the same window.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_analyze.h"
#include "bake_options.h"
#include "bake_pool.h"
#include "bake_state.h"

#define PI 3.14159265358979323846

static double wrap_pi(double a) {
  while (a > PI) a -= 2.0 * PI;
  while (a <= -PI) a += 2.0 * PI;
  return a;
}

void smgb_analysis_free(smgb_analysis* a) {
  if (!a) return;
  free(a->contact);
  free(a->phase);
  free(a->speed);
  free(a->angle);
  free(a->dir);
  free(a->heading);
  free(a->foot);
  memset(a, 0, sizeof *a);
}

static void directions(const smgb_bake* b, const smgb_pool_clip* c,
                       float max_angle, float min_speed, smgb_analysis* a) {
  uint32_t n = c->count, f;
  uint32_t w = (uint32_t)lround(0.3 * b->opt.frame_rate);
  if (w < 1) w = 1;
  for (f = 0; f < n; ++f) {
    uint32_t lo = f >= w ? f - w : 0, hi = f + w < n ? f + w : n - 1, k;
    const float* p0 = b->frames[c->first + lo].root2d;
    const float* p1 = b->frames[c->first + hi].root2d;
    double dx = p1[0] - p0[0], dz = p1[1] - p0[1], sn = 0.0, cs = 0.0, v;
    double facing, travel;
    for (k = lo; k <= hi; ++k) {
      sn += sin(b->frames[c->first + k].root2d[2]);
      cs += cos(b->frames[c->first + k].root2d[2]);
    }
    facing = atan2(sn, cs);
    v = hi > lo ? sqrt(dx * dx + dz * dz) * b->opt.frame_rate / (hi - lo)
                : 0.0;
    travel = atan2(dx, dz);
    a->speed[f] = (float)v;
    a->angle[f] = (float)wrap_pi(travel - facing);
    if (v < min_speed)
      a->dir[f] = SMGB_DIR_STILL;
    else if (fabs(a->angle[f]) < max_angle)
      a->dir[f] = SMGB_DIR_FORWARD;
    else if (fabs(a->angle[f]) > PI - max_angle)
      a->dir[f] = SMGB_DIR_BACKWARD;
    else
      a->dir[f] = SMGB_DIR_SIDEWAYS;
  }
}

/* Lower of ankle/toe per foot: height above that joint's clip minimum and
 * horizontal speed (central difference). */
static void feet(const smgb_bake* b, const smgb_pool_clip* c,
                 smgb_analysis* a) {
  uint32_t n = c->count, f, s, k;
  for (s = 0; s < 2; ++s) {
    const uint32_t* leg = s ? b->body.right_leg : b->body.left_leg;
    double lo[2] = {1e30, 1e30};
    for (f = 0; f < n; ++f)
      for (k = 0; k < 2; ++k) {
        double y = b->positions[((size_t)(c->first + f) * b->J + leg[2 + k]) *
                                    3u + 1u];
        if (y < lo[k]) lo[k] = y;
      }
    for (f = 0; f < n; ++f) {
      uint32_t f0 = f ? f - 1 : f, f1 = f + 1 < n ? f + 1 : f;
      double best = 1e30, v = 0.0;
      for (k = 0; k < 2; ++k) {
        const float* p = b->positions +
                         ((size_t)(c->first + f) * b->J + leg[2 + k]) * 3u;
        const float* p0 = b->positions +
                          ((size_t)(c->first + f0) * b->J + leg[2 + k]) * 3u;
        const float* p1 = b->positions +
                          ((size_t)(c->first + f1) * b->J + leg[2 + k]) * 3u;
        double h = p[1] - lo[k];
        if (h < best) {
          double dx = p1[0] - p0[0], dz = p1[2] - p0[2];
          best = h;
          v = f1 > f0 ? sqrt(dx * dx + dz * dz) * b->opt.frame_rate /
                            (double)(f1 - f0)
                      : 0.0;
        }
      }
      a->foot[(size_t)f * 4u + 2u * s] = (float)best;
      a->foot[(size_t)f * 4u + 2u * s + 1u] = (float)v;
    }
  }
}

smg_result smgb_analyze_clip(const smgb_clip* clip, float frame_rate,
                             uint32_t file_offset, float max_angle,
                             float min_speed, smgb_analysis* out,
                             smgb_error* err) {
  smg_bake_options opt;
  smgb_bake* b;
  smgb_clip rs;
  smg_result r;
  uint32_t n, f;
  memset(out, 0, sizeof *out);
  memset(&rs, 0, sizeof rs);
  if (err) err->message[0] = '\0';
  if (!clip || !clip->poses || clip->frame_count < 2 ||
      !(frame_rate > 0.0f && frame_rate <= 1000.0f) ||
      !(clip->frame_rate > 0.0f)) {
    if (err) snprintf(err->message, sizeof err->message,
                      "analyze: empty clip or bad frame rate");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (!(max_angle > 0.0f)) max_angle = (float)(35.0 * PI / 180.0);
  if (!(min_speed > 0.0f)) min_speed = 0.3f;
  b = calloc(1, sizeof *b);
  if (!b) return SMG_ERROR_OUT_OF_MEMORY;
  /* a bake's options, at this working rate */
  memset(&opt, 0, sizeof opt);
  opt.struct_size = sizeof opt;
  opt.frame_rate = frame_rate;
  smgb_bake_init(b, NULL, NULL);
  r = smgb_options_resolve(&opt, &b->opt, &b->report);
  if (r == SMG_OK) r = smgb_skeleton_copy(&clip->skeleton, &b->skel);
  if (r == SMG_OK) {
    b->J = b->skel.joint_count;
    b->stride = SMGB_STRIDE(b->J);
    r = smgb_body_init(&b->body, &b->skel, NULL, clip->name, &b->report);
  }
  if (r == SMG_OK)
    r = clip->frame_rate != frame_rate
            ? smgb_clip_resample(clip, frame_rate, &rs)
            : smgb_clip_copy(clip, &rs);
  if (r == SMG_OK) {
    smgb_clip_ground(&rs);
    r = smgb_pool_add_clip(b, &rs, clip->name, 0, SMGI_CLIP_LOWER, SMGI_NONE);
  }
  if (r != SMG_OK) {
    if (err) snprintf(err->message, sizeof err->message, "analyze: %.490s",
                      smgb_report_first_error(&b->report)[0]
                          ? smgb_report_first_error(&b->report)
                          : smg_result_string(r));
    goto done;
  }
  n = b->clips[0].count;
  out->frame_count = n;
  out->frame_rate = frame_rate;
  out->source_rate = clip->frame_rate;
  out->file_offset = file_offset;
  out->contact = calloc(n, 1);
  out->phase = calloc(n, sizeof *out->phase);
  out->speed = calloc(n, sizeof *out->speed);
  out->angle = calloc(n, sizeof *out->angle);
  out->dir = calloc(n, 1);
  out->foot = calloc((size_t)n * 4u, sizeof *out->foot);
  out->heading = calloc(n, sizeof *out->heading);
  if (!out->contact || !out->phase || !out->speed || !out->angle ||
      !out->dir || !out->foot || !out->heading) {
    smgb_analysis_free(out);
    r = SMG_ERROR_OUT_OF_MEMORY;
    goto done;
  }
  for (f = 0; f < n; ++f) {
    const smgi_frame* fr = &b->frames[b->clips[0].first + f];
    out->contact[f] = (uint8_t)(((fr->flags & SMGI_FRAME_LEFT_CONTACT) ? 1u
                                                                     : 0u) |
                                ((fr->flags & SMGI_FRAME_RIGHT_CONTACT) ? 2u
                                                                      : 0u));
    out->phase[f] = fr->phase;
    out->heading[f] =
        f ? out->heading[f - 1] +
                (float)wrap_pi(fr->root2d[2] - (fr - 1)->root2d[2])
          : fr->root2d[2];
  }
  feet(b, &b->clips[0], out);
  directions(b, &b->clips[0], max_angle, min_speed, out);
done:
  smgb_clip_free(&rs);
  smgb_bake_free(b);
  free(b);
  return r;
}

uint32_t smgb_analysis_file_frame(const smgb_analysis* a, uint32_t frame) {
  double src = (double)frame * a->source_rate / a->frame_rate;
  return a->file_offset + (uint32_t)lround(src);
}

uint32_t smgb_analysis_strikes(const smgb_analysis* a, int foot,
                               uint32_t* out, uint32_t cap) {
  uint8_t bit = foot ? 2u : 1u;
  uint32_t f, n = 0;
  for (f = 1; f < a->frame_count; ++f)
    if ((a->contact[f] & bit) && !(a->contact[f - 1] & bit)) {
      if (n < cap) out[n] = f;
      ++n;
    }
  return n < cap ? n : cap;
}

uint32_t smgb_analysis_ranges(const smgb_analysis* a, uint8_t dir,
                              float min_seconds, uint32_t (*out)[2],
                              uint32_t cap) {
  uint32_t bridge = (uint32_t)lround(0.3 * a->frame_rate);
  uint32_t min_len = (uint32_t)lround(min_seconds * a->frame_rate);
  uint32_t f = 0, n = 0;
  while (f < a->frame_count) {
    uint32_t first, last;
    if (a->dir[f] != dir) {
      ++f;
      continue;
    }
    first = last = f;
    /* extend over runs of `dir`, bridging short interruptions */
    for (;;) {
      uint32_t g = last + 1;
      while (g < a->frame_count && a->dir[g] == dir) last = g++;
      while (g < a->frame_count && a->dir[g] != dir && g - last <= bridge)
        ++g;
      if (g < a->frame_count && a->dir[g] == dir && g - last <= bridge)
        last = g;
      else
        break;
    }
    if (last - first + 1 >= min_len) {
      if (n < cap) {
        out[n][0] = first;
        out[n][1] = last;
      }
      ++n;
    }
    f = last + 1;
  }
  return n < cap ? n : cap;
}

double smgb_analysis_planted_speed(const smgb_analysis* a) {
  double sum = 0.0;
  uint32_t f, n = 0, s;
  for (s = 0; s < 2; ++s)
    for (f = 1; f + 1 < a->frame_count; ++f) {
      uint8_t bit = s ? 2u : 1u;
      if (!(a->contact[f - 1] & bit) || !(a->contact[f] & bit) ||
          !(a->contact[f + 1] & bit))
        continue;
      sum += a->foot[(size_t)f * 4u + 2u * s + 1u];
      ++n;
    }
  return n ? sum / (double)n : 0.0;
}

/* ---- report (smg-bake --analyze) ------------------------------------------ */

static smg_result load_any(const char* path, float unit_scale, uint32_t skip,
                           smgb_clip* out, smgb_error* err) {
  size_t len = strlen(path);
  if (len >= 4 && (strcmp(path + len - 4, ".bvh") == 0 ||
                   strcmp(path + len - 4, ".BVH") == 0))
    return smgb_bvh_load(path, unit_scale, skip, out, err);
  return smgb_assimp_load(path, unit_scale, 0, out, err);
}

static int cmp_u32(const void* x, const void* y) {
  uint32_t a = *(const uint32_t*)x, b = *(const uint32_t*)y;
  return a < b ? -1 : a > b;
}

static void print_strikes(FILE* fp, const smgb_analysis* a, const char* foot,
                          const uint32_t* s, uint32_t n) {
  uint32_t i;
  fprintf(fp, "  %s strikes (%u), working frames:", foot, n);
  for (i = 0; i < n; ++i) fprintf(fp, " %u", s[i]);
  fprintf(fp, "\n    file frames:");
  for (i = 0; i < n; ++i) fprintf(fp, " %u", smgb_analysis_file_frame(a, s[i]));
  fputc('\n', fp);
}

/* Median of consecutive differences, seconds (0 if fewer than 2). */
static double median_period(const uint32_t* s, uint32_t n, float rate) {
  uint32_t* d;
  double m;
  uint32_t i;
  if (n < 2) return 0.0;
  d = malloc((n - 1) * sizeof *d);
  if (!d) return 0.0;
  for (i = 0; i + 1 < n; ++i) d[i] = s[i + 1] - s[i];
  qsort(d, n - 1, sizeof *d, cmp_u32);
  m = (n - 1) % 2 ? d[(n - 1) / 2] : 0.5 * (d[(n - 1) / 2 - 1] + d[(n - 1) / 2]);
  free(d);
  return m / rate;
}

/* Strikes of both feet in time order; counts consecutive same-foot pairs. */
static uint32_t alternation_breaks(const uint32_t* l, uint32_t nl,
                                   const uint32_t* r, uint32_t nr) {
  uint32_t i = 0, j = 0, breaks = 0;
  int last = -1;
  while (i < nl || j < nr) {
    int foot = (j >= nr || (i < nl && l[i] <= r[j])) ? 0 : 1;
    if (foot == last) ++breaks;
    last = foot;
    if (foot == 0) ++i; else ++j;
  }
  return breaks;
}

smg_result smgb_analyze_file(const char* path, const char* reference,
                             float unit_scale, uint32_t skip_first_frame,
                             float frame_rate, int verbose, FILE* fp,
                             smgb_error* err) {
  static const char* const dir_names[4] = {"still", "forward", "backward",
                                           "sideways"};
  smgb_clip clip;
  smgb_analysis a;
  smg_result r;
  uint32_t *ls = NULL, *rs = NULL, nl, nr, f;
  uint8_t d;
  memset(&clip, 0, sizeof clip);
  r = load_any(path, unit_scale, skip_first_frame, &clip, err);
  if (r != SMG_OK) return r;
  if (reference) {
    smgb_clip ref;
    memset(&ref, 0, sizeof ref);
    r = load_any(reference, unit_scale, skip_first_frame, &ref, err);
    if (r == SMG_OK) {
      fprintf(fp, "retargeted to the skeleton of %s (leg length %.3f m; "
                  "the clip's own %.3f m)\n", reference,
              (double)smgb_skeleton_leg_length(&ref.skeleton),
              (double)smgb_skeleton_leg_length(&clip.skeleton));
      r = smgb_clip_retarget(&clip, &ref.skeleton, err);
    }
    smgb_clip_free(&ref);
    if (r != SMG_OK) {
      smgb_clip_free(&clip);
      return r;
    }
  }
  if (!(frame_rate > 0.0f)) frame_rate = SMGB_DEFAULT_FRAME_RATE;
  r = smgb_analyze_clip(&clip, frame_rate, skip_first_frame ? 1u : 0u, 0.0f,
                        0.0f, &a, err);
  if (r != SMG_OK) {
    smgb_clip_free(&clip);
    return r;
  }
  ls = malloc(a.frame_count * sizeof *ls);
  rs = malloc(a.frame_count * sizeof *rs);
  if (!ls || !rs) {
    r = SMG_ERROR_OUT_OF_MEMORY;
    goto out;
  }
  nl = smgb_analysis_strikes(&a, 0, ls, a.frame_count);
  nr = smgb_analysis_strikes(&a, 1, rs, a.frame_count);
  fprintf(fp, "%s: %u frames at %g Hz -> %u at %g Hz (file frame = %u + "
              "%g x working frame)\n", path, clip.frame_count,
          (double)clip.frame_rate, a.frame_count, (double)frame_rate,
          a.file_offset, (double)(clip.frame_rate / frame_rate));
  {
    /* Units go wrong silently (a centimetre file read as metres walks at
     * 100 m/s): show the leg length they give. */
    smgb_roles roles;
    smgb_roles_guess(&clip.skeleton, &roles);
    fprintf(fp, "skeleton: %u joints, pelvis '%s', leg length %.3f m (unit "
                "%s)\n", clip.skeleton.joint_count,
            roles.joint[SMGB_ROLE_PELVIS] >= 0
                ? clip.skeleton.names[roles.joint[SMGB_ROLE_PELVIS]]
                : "?",
            (double)smgb_roles_leg_length(&clip.skeleton, &roles),
            unit_scale > 0.0f ? "given" : "guessed from the leg length");
  }
  fprintf(fp, "foot contacts (the baker's labels):\n");
  print_strikes(fp, &a, "left", ls, nl);
  print_strikes(fp, &a, "right", rs, nr);
  fprintf(fp, "  stride period (median, strike to strike of one foot): left "
              "%.2f s, right %.2f s; left/right alternation breaks: %u\n",
          median_period(ls, nl, frame_rate), median_period(rs, nr, frame_rate),
          alternation_breaks(ls, nl, rs, nr));
  fprintf(fp, "  planted-foot speed (mean over contact frames): %.3f m/s\n",
          smgb_analysis_planted_speed(&a));
  fprintf(fp, "direction of travel (root ground velocity vs facing over +-0.3 "
              "s; forward < 35 deg, backward > 145 deg, moving > 0.3 m/s), "
              "runs >= 1 s:\n");
  for (d = SMGB_DIR_FORWARD; d <= SMGB_DIR_SIDEWAYS; ++d) {
    uint32_t ranges[64][2], n = smgb_analysis_ranges(&a, d, 1.0f, ranges, 64);
    uint32_t i;
    for (i = 0; i < n; ++i) {
      double v = 0.0;
      for (f = ranges[i][0]; f <= ranges[i][1]; ++f) v += a.speed[f];
      v /= (double)(ranges[i][1] - ranges[i][0] + 1);
      fprintf(fp, "  %-8s frames=%u-%u  (working %u-%u, %.1f s, %.2f m/s, "
                  "turns %+.0f deg)\n",
              dir_names[d], smgb_analysis_file_frame(&a, ranges[i][0]),
              smgb_analysis_file_frame(&a, ranges[i][1]), ranges[i][0],
              ranges[i][1],
              (ranges[i][1] - ranges[i][0] + 1) / (double)frame_rate, v,
              (a.heading[ranges[i][1]] - a.heading[ranges[i][0]]) * 180.0 /
                  PI);
    }
  }
  if (verbose) {
    fprintf(fp, "frame file  L R  phase  speed  angle  dir       "
                "left cm, m/s   right cm, m/s\n");
    for (f = 0; f < a.frame_count; ++f)
      fprintf(fp, "%5u %5u  %c %c  %5.2f  %5.2f  %5.0f  %-8s  %5.1f %4.2f  "
                  "%5.1f %4.2f\n", f,
              smgb_analysis_file_frame(&a, f), (a.contact[f] & 1) ? 'L' : '.',
              (a.contact[f] & 2) ? 'R' : '.', (double)a.phase[f],
              (double)a.speed[f], (double)a.angle[f] * 180.0 / PI,
              dir_names[a.dir[f]], 100.0 * a.foot[4 * f],
              (double)a.foot[4 * f + 1], 100.0 * a.foot[4 * f + 2],
              (double)a.foot[4 * f + 3]);
  }
out:
  free(ls);
  free(rs);
  smgb_analysis_free(&a);
  smgb_clip_free(&clip);
  return r;
}
