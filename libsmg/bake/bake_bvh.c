/*
 * bake_bvh.c - BVH (Biovision hierarchy) reader and writer.
 *
 * The reader accepts any hierarchy (up to SMGB_BVH_MAX_JOINTS joints), any
 * subset of the six channels per joint in any order, and turns every frame
 * into the blob's pose layout: root translation + one local quaternion per
 * joint. A joint's rotation is the product of its per-channel rotations in
 * the listed order (for "Zrotation Xrotation Yrotation": R = Rz * Rx * Ry,
 * acting on column vectors, local to the parent).
 *
 * Position channels *replace* the matching OFFSET component: on the root they
 * give the per-frame root translation. A static root (all channels constant)
 * with one child whose position channels move - Bandai Namco's joint_Root
 * above Hips, MotionBuilder and game-rig exports - is folded into that
 * child, which becomes joint 0 and carries the translation. On other joints
 * position channels become the joint's fixed offset: their value when
 * constant (exporters that write 6 channels everywhere), their mean when
 * they wobble by at most 5 % of the bone (solver noise); real animated
 * translation below the root cannot be represented in the pose layout and
 * is rejected with SMG_ERROR_UNSUPPORTED naming the joint.
 *
 * The input is untrusted: every error names file:line and the problem, all
 * memory is bounded (joint, frame and byte caps, allocation never exceeds
 * what the remaining text could possibly hold) and nothing reads past
 * `size` (the text need not be NUL-terminated).
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_clip.h"
#include "bake_import_util.h"
#include "bake_math.h"

#define SMGB_BVH_MAX_JOINTS 512u
#define SMGB_BVH_MAX_FRAMES 10000000u
#define SMGB_BVH_MAX_POSE_BYTES ((size_t)1 << 30) /* 1 GiB of poses */
#define SMGB_BVH_MAX_FILE_BYTES ((size_t)1 << 30)
#define SMGB_BVH_MAX_VALUE 1e6
#define SMGB_BVH_TOKEN_MAX 64 /* including the terminating NUL */

enum { CH_XPOS, CH_YPOS, CH_ZPOS, CH_XROT, CH_YROT, CH_ZROT };

typedef struct bvh_joint {
  char name[SMGB_NAME_MAX];
  int32_t parent;
  double offset[3];
  uint32_t channel_count;
  uint8_t channels[6];
  uint32_t first_channel; /* index of its first value in a frame line */
  uint32_t channels_line; /* for errors about its channels */
  int has_offset, has_channels, has_children;
} bvh_joint;

typedef struct bvh_lexer {
  const char* p;
  const char* end;
  uint32_t line;
  const char* name;
  smgb_error* err;
  char tok[SMGB_BVH_TOKEN_MAX];
  size_t tok_len;
  uint32_t tok_line;
} bvh_lexer;

static int is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' ||
         c == '\f';
}

/* Next whitespace-separated token ('{' and '}' always stand alone).
 * Returns 1 on a token, 0 at end of input, -1 on an overlong token. */
static int lex_next(bvh_lexer* lx) {
  const char* start;
  while (lx->p < lx->end && is_space(*lx->p)) {
    if (*lx->p == '\n') lx->line++;
    lx->p++;
  }
  if (lx->p >= lx->end) {
    /* Report end of file at the last line that had a token. */
    lx->tok[0] = '\0';
    lx->tok_len = 0;
    if (lx->tok_line == 0) lx->tok_line = lx->line;
    return 0;
  }
  start = lx->p;
  lx->tok_line = lx->line;
  if (*lx->p == '{' || *lx->p == '}') {
    lx->p++;
  } else {
    while (lx->p < lx->end && !is_space(*lx->p) && *lx->p != '{' &&
           *lx->p != '}')
      lx->p++;
  }
  lx->tok_len = (size_t)(lx->p - start);
  if (lx->tok_len >= SMGB_BVH_TOKEN_MAX) {
    smgb_imp_errorf(lx->err, "%s:%u: token longer than %d characters",
                    lx->name, lx->tok_line, SMGB_BVH_TOKEN_MAX - 1);
    return -1;
  }
  memcpy(lx->tok, start, lx->tok_len);
  lx->tok[lx->tok_len] = '\0';
  return 1;
}

/* Printable copy of the current token for messages (control bytes -> '?'). */
static const char* tok_show(bvh_lexer* lx) {
  size_t i;
  for (i = 0; i < lx->tok_len; ++i)
    if (!isprint((unsigned char)lx->tok[i])) lx->tok[i] = '?';
  return lx->tok_len ? lx->tok : "end of file";
}

/* Clinger's fast path: a decimal with at most 15 significant digits and a
 * power of ten within +-22 converts with one correctly rounded operation,
 * giving exactly strtod's result ~10x faster (BVH motion is millions of
 * such numbers). Returns 0 when the token needs the general path. */
static int parse_decimal_fast(const char* s, size_t len, double* out) {
  static const double pow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,
                                   1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                   1e12, 1e13, 1e14, 1e15, 1e16, 1e17,
                                   1e18, 1e19, 1e20, 1e21, 1e22};
  const char* p = s;
  const char* end = s + len;
  uint64_t mant = 0;
  int digits = 0, frac = 0, neg = 0, any = 0, exp = 0;
  if (p < end && (*p == '-' || *p == '+')) neg = *p++ == '-';
  while (p < end && *p == '0') p++, any = 1; /* leading zeros: free */
  for (; p < end && *p >= '0' && *p <= '9'; ++p, any = 1) {
    if (++digits > 15) return 0;
    mant = mant * 10u + (uint64_t)(*p - '0');
  }
  if (p < end && *p == '.') {
    ++p;
    for (; p < end && *p >= '0' && *p <= '9'; ++p, any = 1) {
      if (mant == 0 && *p == '0') { /* zeros right after the point */
        ++frac;
        continue;
      }
      if (++digits > 15) return 0;
      mant = mant * 10u + (uint64_t)(*p - '0');
      ++frac;
    }
  }
  if (!any) return 0;
  if (p < end && (*p == 'e' || *p == 'E')) {
    int eneg = 0, ed = 0;
    ++p;
    if (p < end && (*p == '-' || *p == '+')) eneg = *p++ == '-';
    for (; p < end && *p >= '0' && *p <= '9'; ++p) {
      if (++ed > 3) return 0;
      exp = exp * 10 + (*p - '0');
    }
    if (ed == 0) return 0;
    if (eneg) exp = -exp;
  }
  if (p != end) return 0;
  exp -= frac;
  if (exp < -22 || exp > 22) return 0;
  *out = exp < 0 ? (double)mant / pow10[-exp] : (double)mant * pow10[exp];
  if (neg) *out = -*out;
  return 1;
}

/* Parse a finite number within +-SMGB_BVH_MAX_VALUE from a NUL-terminated
 * token. Returns 0 on success, 1 not numeric, 2 not finite, 3 too large. */
static int parse_number(const char* s, size_t len, double* out) {
  char* endp = NULL;
  double v;
  if (len == 0) return 1;
  if (parse_decimal_fast(s, len, &v)) {
    if (fabs(v) > SMGB_BVH_MAX_VALUE) return 3;
    *out = v;
    return 0;
  }
  errno = 0;
  v = strtod(s, &endp);
  if (endp != s + len) return 1;
  if (!isfinite(v)) return 2;
  if (fabs(v) > SMGB_BVH_MAX_VALUE) return 3;
  *out = v;
  return 0;
}

static const char* number_problem(int code) {
  switch (code) {
    case 1: return "is not a number";
    case 2: return "is not finite (NaN or infinity)";
    default: return "is too large (|v| > 1e6)";
  }
}

/* Next token as a number; on failure fills the error and returns 0. */
static int lex_number(bvh_lexer* lx, const char* what, double* out) {
  int r = lex_next(lx), code;
  if (r < 0) return 0;
  if (r == 0) {
    smgb_imp_errorf(lx->err, "%s:%u: unexpected end of file, expected %s",
                    lx->name, lx->tok_line, what);
    return 0;
  }
  code = parse_number(lx->tok, lx->tok_len, out);
  if (code) {
    smgb_imp_errorf(lx->err, "%s:%u: %s '%s' %s", lx->name, lx->tok_line, what,
                    tok_show(lx), number_problem(code));
    return 0;
  }
  return 1;
}

/* Next token must equal `word`. */
static int lex_expect(bvh_lexer* lx, const char* word, const char* context) {
  int r = lex_next(lx);
  if (r < 0) return 0;
  if (r == 0 || !smgb_name_ieq(lx->tok, word)) {
    smgb_imp_errorf(lx->err, "%s:%u: expected '%s' %s, found '%s'", lx->name,
                    lx->tok_line, word, context, tok_show(lx));
    return 0;
  }
  return 1;
}

static int channel_from_name(const char* s) {
  static const char* const names[6] = {"Xposition", "Yposition", "Zposition",
                                       "Xrotation", "Yrotation", "Zrotation"};
  int i;
  for (i = 0; i < 6; ++i)
    if (smgb_name_ieq(s, names[i])) return i;
  return -1;
}

/* ---- hierarchy ----------------------------------------------------------- */

typedef struct bvh_hier {
  bvh_joint* joints;
  uint32_t count;
  uint32_t channels; /* values per frame line */
  /* Static joints above the translating pelvis (Bandai's joint_Root):
   * joints 0..root-1 are folded into `root`, the clip's joint 0, with
   * their constant transform (fold_t, fold_q) applied to its motion. */
  uint32_t root;
  double fold_t[3], fold_q[4];
} bvh_hier;

static int hier_add_joint(bvh_lexer* lx, bvh_hier* h, int32_t parent) {
  bvh_joint* j;
  uint32_t i;
  int r;
  if (h->count >= SMGB_BVH_MAX_JOINTS) {
    smgb_imp_errorf(lx->err, "%s:%u: too many joints (limit %u)", lx->name,
                    lx->tok_line, SMGB_BVH_MAX_JOINTS);
    return -1;
  }
  r = lex_next(lx);
  if (r < 0) return -1;
  if (r == 0 || strcmp(lx->tok, "{") == 0 || strcmp(lx->tok, "}") == 0) {
    smgb_imp_errorf(lx->err, "%s:%u: expected a joint name, found '%s'",
                    lx->name, lx->tok_line, tok_show(lx));
    return -1;
  }
  for (i = 0; i < h->count; ++i) {
    if (strcmp(h->joints[i].name, lx->tok) == 0) {
      smgb_imp_errorf(lx->err, "%s:%u: duplicate joint name '%s'", lx->name,
                      lx->tok_line, tok_show(lx));
      return -1;
    }
  }
  j = &h->joints[h->count];
  memset(j, 0, sizeof *j);
  memcpy(j->name, lx->tok, lx->tok_len + 1); /* tok_len < SMGB_NAME_MAX */
  j->parent = parent;
  if (parent >= 0) h->joints[parent].has_children = 1;
  return (int)h->count++;
}

static int parse_offset(bvh_lexer* lx, double out[3]) {
  return lex_number(lx, "OFFSET x", &out[0]) &&
         lex_number(lx, "OFFSET y", &out[1]) &&
         lex_number(lx, "OFFSET z", &out[2]);
}

static int parse_channels(bvh_lexer* lx, bvh_hier* h, bvh_joint* j) {
  double n;
  uint32_t i, k;
  j->channels_line = lx->tok_line;
  if (!lex_number(lx, "channel count", &n)) return 0;
  if (n != floor(n) || n < 0 || n > 6) {
    smgb_imp_errorf(lx->err, "%s:%u: channel count '%s' must be 0..6",
                    lx->name, lx->tok_line, tok_show(lx));
    return 0;
  }
  j->channel_count = (uint32_t)n;
  j->first_channel = h->channels;
  for (i = 0; i < j->channel_count; ++i) {
    int c, r = lex_next(lx);
    if (r < 0) return 0;
    c = r ? channel_from_name(lx->tok) : -1;
    if (c < 0) {
      smgb_imp_errorf(lx->err,
                      "%s:%u: joint '%s' declares %u channels but channel %u "
                      "is '%s' (expected Xposition..Zrotation)",
                      lx->name, lx->tok_line, j->name, j->channel_count, i + 1,
                      tok_show(lx));
      return 0;
    }
    for (k = 0; k < i; ++k) {
      if (j->channels[k] == (uint8_t)c) {
        smgb_imp_errorf(lx->err, "%s:%u: joint '%s' lists channel '%s' twice",
                        lx->name, lx->tok_line, j->name, lx->tok);
        return 0;
      }
    }
    j->channels[i] = (uint8_t)c;
  }
  h->channels += j->channel_count;
  j->has_channels = 1;
  return 1;
}

/* HIERARCHY ... up to (not including) MOTION. Iterative: a hostile file
 * cannot exhaust the C stack with deep nesting. */
static int parse_hierarchy(bvh_lexer* lx, bvh_hier* h) {
  int32_t stack[SMGB_BVH_MAX_JOINTS + 2];
  int depth = 0, r, cur;
  int in_end_site = 0; /* inside an End Site block */
  int end_site_offset = 0;

  if (!lex_expect(lx, "HIERARCHY", "at the start of a BVH file")) return 0;
  if (!lex_expect(lx, "ROOT", "after HIERARCHY")) return 0;
  cur = hier_add_joint(lx, h, -1);
  if (cur < 0) return 0;
  if (!lex_expect(lx, "{", "after the ROOT name")) return 0;
  stack[depth++] = cur;

  while (depth > 0) {
    bvh_joint* j = &h->joints[stack[depth - 1]];
    r = lex_next(lx);
    if (r < 0) return 0;
    if (r == 0) {
      smgb_imp_errorf(lx->err,
                      "%s:%u: unexpected end of file inside %s '%s' "
                      "(unbalanced braces or truncated file)",
                      lx->name, lx->tok_line,
                      in_end_site ? "the End Site of" : "joint", j->name);
      return 0;
    }
    if (in_end_site) {
      if (smgb_name_ieq(lx->tok, "OFFSET") && !end_site_offset) {
        double tmp[3];
        if (!parse_offset(lx, tmp)) return 0;
        end_site_offset = 1;
      } else if (strcmp(lx->tok, "}") == 0) {
        if (!end_site_offset) {
          smgb_imp_errorf(lx->err, "%s:%u: End Site of '%s' has no OFFSET",
                          lx->name, lx->tok_line, j->name);
          return 0;
        }
        in_end_site = 0;
      } else {
        smgb_imp_errorf(lx->err,
                        "%s:%u: unexpected '%s' in the End Site of '%s' "
                        "(only one OFFSET allowed)",
                        lx->name, lx->tok_line, tok_show(lx), j->name);
        return 0;
      }
      continue;
    }
    if (smgb_name_ieq(lx->tok, "OFFSET")) {
      if (j->has_offset || j->has_children) {
        smgb_imp_errorf(lx->err, "%s:%u: misplaced or repeated OFFSET in '%s'",
                        lx->name, lx->tok_line, j->name);
        return 0;
      }
      if (!parse_offset(lx, j->offset)) return 0;
      j->has_offset = 1;
    } else if (smgb_name_ieq(lx->tok, "CHANNELS")) {
      if (j->has_channels || j->has_children) {
        smgb_imp_errorf(lx->err,
                        "%s:%u: misplaced or repeated CHANNELS in '%s'",
                        lx->name, lx->tok_line, j->name);
        return 0;
      }
      if (!parse_channels(lx, h, j)) return 0;
    } else if (smgb_name_ieq(lx->tok, "JOINT") || smgb_name_ieq(lx->tok, "End") ||
               strcmp(lx->tok, "}") == 0) {
      if (!j->has_offset) {
        smgb_imp_errorf(lx->err, "%s:%u: joint '%s' has no OFFSET", lx->name,
                        lx->tok_line, j->name);
        return 0;
      }
      if (!j->has_channels) {
        smgb_imp_errorf(lx->err, "%s:%u: joint '%s' has no CHANNELS",
                        lx->name, lx->tok_line, j->name);
        return 0;
      }
      if (lx->tok[0] == '}') {
        depth--;
      } else if (lx->tok[0] == 'E' || lx->tok[0] == 'e') {
        if (!lex_expect(lx, "Site", "after 'End'")) return 0;
        if (!lex_expect(lx, "{", "after 'End Site'")) return 0;
        j->has_children = 1;
        in_end_site = 1;
        end_site_offset = 0;
      } else {
        cur = hier_add_joint(lx, h, stack[depth - 1]);
        if (cur < 0) return 0;
        if (!lex_expect(lx, "{", "after the joint name")) return 0;
        stack[depth++] = cur;
      }
    } else {
      smgb_imp_errorf(lx->err,
                      "%s:%u: unexpected '%s' in joint '%s' (expected OFFSET, "
                      "CHANNELS, JOINT, End Site or '}')",
                      lx->name, lx->tok_line, tok_show(lx), j->name);
      return 0;
    }
  }
  if (h->channels == 0) {
    smgb_imp_errorf(lx->err, "%s:%u: the hierarchy has no channels", lx->name,
                    lx->tok_line);
    return 0;
  }
  return 1;
}

/* ---- motion -------------------------------------------------------------- */

/* Reads one frame line into `row`. Returns the number of values read (which
 * may differ from `want`; the caller reports it), or -1 on a bad value. Stops
 * after `want + 1` values. Leaves lx->p at the start of the next line. */
static long read_row(bvh_lexer* lx, double* row, uint32_t want) {
  long n = 0;
  const char* p = lx->p;
  const char* end = lx->end;
  while (p < end && *p != '\n') {
    const char* s;
    char buf[SMGB_BVH_TOKEN_MAX];
    size_t len;
    int code;
    double v;
    if (is_space(*p)) {
      p++;
      continue;
    }
    s = p;
    while (p < end && !is_space(*p)) p++;
    len = (size_t)(p - s);
    if (len >= sizeof buf) {
      smgb_imp_errorf(lx->err, "%s:%u: value longer than %d characters",
                      lx->name, lx->line, SMGB_BVH_TOKEN_MAX - 1);
      return -1;
    }
    memcpy(buf, s, len);
    buf[len] = '\0';
    code = parse_number(buf, len, &v);
    if (code) {
      size_t i;
      for (i = 0; i < len; ++i)
        if (!isprint((unsigned char)buf[i])) buf[i] = '?';
      smgb_imp_errorf(lx->err, "%s:%u: value %ld '%s' %s", lx->name, lx->line,
                      n + 1, buf, number_problem(code));
      return -1;
    }
    if ((uint32_t)n < want) row[n] = v;
    n++;
    if ((uint32_t)n > want) break; /* reported by the caller */
  }
  while (p < end && *p != '\n') p++;
  if (p < end) p++; /* the newline */
  lx->p = p;
  return n;
}

/* Local rotation of joint ji from its channels in `row`. */
static void joint_rotation(const bvh_joint* j, const double* row, double q[4]) {
  uint32_t c;
  q[0] = q[1] = q[2] = 0.0;
  q[3] = 1.0;
  for (c = 0; c < j->channel_count; ++c) {
    int ch = j->channels[c];
    if (ch > CH_ZPOS) {
      double r[4];
      smgb_q_axis(ch - CH_XROT, row[j->first_channel + c] * (SMGB_M_PI / 180.0),
                 r);
      smgb_q_mul(q, r, q);
    }
  }
  smgb_q_normalize(q);
}

/* Local translation of joint ji: its OFFSET with position channels
 * replacing the matching components. */
static void joint_translation(const bvh_joint* j, const double* row,
                              double t[3]) {
  uint32_t c;
  t[0] = j->offset[0];
  t[1] = j->offset[1];
  t[2] = j->offset[2];
  for (c = 0; c < j->channel_count; ++c)
    if (j->channels[c] <= CH_ZPOS) t[j->channels[c]] = row[j->first_channel + c];
}

/* Convert one parsed frame (row of channel values, file units) to a pose of
 * the joints h->root.. (the folded static joints above contribute their
 * constant transform to the root). */
static void row_to_pose(const bvh_hier* h, const double* row, double scale,
                        float* pose) {
  uint32_t ji;
  double root[3];
  for (ji = h->root; ji < h->count; ++ji) {
    double q[4];
    float* o = pose + 3 + 4 * (ji - h->root);
    joint_rotation(&h->joints[ji], row, q);
    if (ji == h->root && h->root > 0) {
      smgb_q_mul(h->fold_q, q, q);
      smgb_q_normalize(q);
    }
    o[0] = (float)q[0];
    o[1] = (float)q[1];
    o[2] = (float)q[2];
    o[3] = (float)q[3];
  }
  joint_translation(&h->joints[h->root], row, root);
  if (h->root > 0) {
    smgb_q_rotate(h->fold_q, root, root);
    root[0] += h->fold_t[0];
    root[1] += h->fold_t[1];
    root[2] += h->fold_t[2];
  }
  pose[0] = (float)(root[0] * scale);
  pose[1] = (float)(root[1] * scale);
  pose[2] = (float)(root[2] * scale);
}

/* Frame rate from the frame time; snapped to an integer rate when the file's
 * rounding is the only difference (".0083333" -> 120). */
static float rate_from_frame_time(double ft) {
  double rate = 1.0 / ft, r = floor(rate + 0.5);
  if (r >= 1.0 && fabs(rate - r) <= 1e-4 * r) return (float)r;
  return (float)rate;
}

/* Guess file units -> metres from the rest skeleton's leg (or, without
 * named legs, the hips height): smgb_unit_from_leg. */
static double guess_unit_scale(const bvh_hier* h, const double* first_row) {
  double size = 0.0;
  smgb_skeleton s;
  float(*offs)[3];
  char(*names)[SMGB_NAME_MAX];
  int32_t* parents;
  uint32_t k;
  offs = (float(*)[3])malloc(sizeof *offs * h->count);
  names = (char(*)[SMGB_NAME_MAX])malloc(sizeof *names * h->count);
  parents = (int32_t*)malloc(sizeof *parents * h->count);
  if (offs && names && parents) {
    for (k = 0; k < h->count; ++k) {
      offs[k][0] = (float)h->joints[k].offset[0];
      offs[k][1] = (float)h->joints[k].offset[1];
      offs[k][2] = (float)h->joints[k].offset[2];
      memcpy(names[k], h->joints[k].name, SMGB_NAME_MAX);
      parents[k] = h->joints[k].parent;
    }
    s.joint_count = h->count;
    s.names = names;
    s.parents = parents;
    s.offsets = offs;
    size = smgb_skeleton_leg_length(&s);
  }
  free(offs);
  free(names);
  free(parents);
  if (!(size > 0.0)) {
    /* Hips height: the root's Y position channel in the first frame. */
    const bvh_joint* r = &h->joints[h->root];
    for (k = 0; k < r->channel_count; ++k)
      if (r->channels[k] == CH_YPOS && first_row)
        size = fabs(first_row[r->first_channel + k]) * 0.9;
  }
  return smgb_unit_from_leg(size);
}

/* Is column `col` constant over the clip (to float rounding)? */
static int column_constant(const bvh_hier* h, const double* rows,
                           uint32_t frame_count, uint32_t col) {
  double v0 = rows[col];
  uint32_t f;
  for (f = 1; f < frame_count; ++f)
    if (fabs(rows[(size_t)f * h->channels + col] - v0) >
        1e-5 * (1.0 + fabs(v0)))
      return 0;
  return 1;
}

/* A static root above a translating pelvis (Bandai Namco's joint_Root over
 * Hips; MotionBuilder and game-rig exports): while joint `root` never moves
 * (all its channels constant), has exactly one child and that child's
 * position channels move, fold it into the child. Folding is lossless (the
 * child's world transform is the static one times its own) and makes the
 * translating pelvis joint 0, which the runtime requires. */
static void fold_static_root(bvh_hier* h, const double* rows,
                             uint32_t frame_count) {
  h->fold_t[0] = h->fold_t[1] = h->fold_t[2] = 0.0;
  h->fold_q[0] = h->fold_q[1] = h->fold_q[2] = 0.0;
  h->fold_q[3] = 1.0;
  h->root = 0;
  for (;;) {
    const bvh_joint* j = &h->joints[h->root];
    const bvh_joint* child;
    uint32_t c, k, children = 0;
    int child_moves = 0;
    double t[3], q[4];
    for (c = 0; c < j->channel_count; ++c)
      if (!column_constant(h, rows, frame_count, j->first_channel + c)) return;
    for (k = h->root + 1; k < h->count; ++k)
      if (h->joints[k].parent == (int32_t)h->root) ++children;
    /* The first child in file order is the next joint. */
    if (children != 1 || h->root + 1 >= h->count) return;
    child = &h->joints[h->root + 1];
    for (c = 0; c < child->channel_count; ++c)
      if (child->channels[c] <= CH_ZPOS &&
          !column_constant(h, rows, frame_count, child->first_channel + c))
        child_moves = 1;
    if (!child_moves) return;
    joint_translation(j, rows, t);
    joint_rotation(j, rows, q);
    smgb_q_rotate(h->fold_q, t, t);
    h->fold_t[0] += t[0];
    h->fold_t[1] += t[1];
    h->fold_t[2] += t[2];
    smgb_q_mul(h->fold_q, q, h->fold_q);
    smgb_q_normalize(h->fold_q);
    h->root++;
  }
}

/* Position channels of joints below the (folded) root. The pose layout
 * holds rotations only below the root, so each becomes a fixed offset:
 * constant channels give their value (a position channel replaces the
 * OFFSET); channels that wobble by at most SMGB_BVH_POSITION_WOBBLE of
 * the bone's length (solver noise, stretch markers) give their mean; a
 * joint that really translates is rejected, naming it. `rows` holds
 * frame_count rows of h->channels values. */
#define SMGB_BVH_POSITION_WOBBLE 0.05
static int fold_joint_positions(bvh_lexer* lx, bvh_hier* h,
                                const double* rows, uint32_t frame_count) {
  uint32_t ji, c, f;
  for (ji = h->root + 1; ji < h->count; ++ji) {
    bvh_joint* j = &h->joints[ji];
    double mean[3], lo[3], hi[3], len = 0.0, spread = 0.0;
    int has_pos = 0, axis;
    uint32_t worst_frame = 0;
    for (axis = 0; axis < 3; ++axis) {
      mean[axis] = lo[axis] = hi[axis] = j->offset[axis];
    }
    for (c = 0; c < j->channel_count; ++c) {
      uint32_t col = j->first_channel + c;
      double sum = 0.0;
      axis = j->channels[c];
      if (axis > CH_ZPOS) continue;
      has_pos = 1;
      lo[axis] = hi[axis] = rows[col];
      for (f = 0; f < frame_count; ++f) {
        double v = rows[(size_t)f * h->channels + col];
        sum += v;
        if (v < lo[axis]) lo[axis] = v;
        if (v > hi[axis]) {
          hi[axis] = v;
          worst_frame = f;
        }
      }
      mean[axis] = sum / frame_count;
    }
    if (!has_pos) continue;
    for (axis = 0; axis < 3; ++axis) {
      len += mean[axis] * mean[axis];
      if (hi[axis] - lo[axis] > spread) spread = hi[axis] - lo[axis];
    }
    len = sqrt(len);
    if (spread > 1e-5 * (1.0 + len) &&
        spread > SMGB_BVH_POSITION_WOBBLE * len) {
      smgb_imp_errorf(lx->err,
                      "%s:%u: joint '%s' has animated position channels "
                      "(they move %.4g units, e.g. at frame %u, on a bone "
                      "%.4g long); only the root, or the one joint below a "
                      "static root, may translate",
                      lx->name, j->channels_line, j->name, spread,
                      worst_frame, len);
      return 0;
    }
    for (axis = 0; axis < 3; ++axis) j->offset[axis] = mean[axis];
  }
  return 1;
}

/* The MOTION section's rows: the declared frame count and time, then
 * every frame line's channel values (frames * h->channels doubles). */
typedef struct bvh_motion {
  uint32_t frames;
  uint32_t frames_line;  /* for errors about the frame count */
  double frame_time;     /* seconds */
  double* rows;
} bvh_motion;

/* The frame count after "Frames:": a whole, positive number whose poses
 * fit in memory. */
static smg_result read_frame_count(bvh_lexer* lx, const bvh_hier* h,
                                   bvh_motion* m) {
  /* Not lex_number: a frame count may legitimately exceed 1e6 and then
   * deserves the "too many frames" capacity error below. */
  char* endp = NULL;
  double n;
  int r = lex_next(lx);
  if (r < 0) return SMG_ERROR_PARSE;
  n = r ? strtod(lx->tok, &endp) : 0.0;
  if (r == 0 || endp != lx->tok + lx->tok_len || !isfinite(n)) {
    smgb_imp_errorf(lx->err, "%s:%u: frame count '%s' is not a number",
                    lx->name, lx->tok_line, tok_show(lx));
    return SMG_ERROR_PARSE;
  }
  if (n != floor(n) || n < 0) {
    smgb_imp_errorf(lx->err, "%s:%u: frame count '%s' is not a whole number",
                    lx->name, lx->tok_line, lx->tok);
    return SMG_ERROR_PARSE;
  }
  if (n == 0) {
    smgb_imp_errorf(lx->err, "%s:%u: the clip has zero frames", lx->name,
                    lx->tok_line);
    return SMG_ERROR_PARSE;
  }
  if (n > SMGB_BVH_MAX_FRAMES ||
      n * SMGB_STRIDE(h->count) * sizeof(float) >
          (double)SMGB_BVH_MAX_POSE_BYTES) {
    smgb_imp_errorf(lx->err, "%s:%u: too many frames (%.0f frames of %u "
                    "joints exceed the 1 GiB limit)",
                    lx->name, lx->tok_line, n, h->count);
    return SMG_ERROR_CAPACITY;
  }
  m->frames = (uint32_t)n;
  return SMG_OK;
}

/* "MOTION / Frames: N / Frame Time: T", the last on a line of its own. */
static smg_result read_motion_header(bvh_lexer* lx, const bvh_hier* h,
                                     bvh_motion* m) {
  smg_result r;
  if (lex_next(lx) < 0) return SMG_ERROR_PARSE;
  if (!smgb_name_ieq(lx->tok, "MOTION")) {
    if (smgb_name_ieq(lx->tok, "ROOT"))
      smgb_imp_errorf(lx->err, "%s:%u: more than one ROOT is not supported",
                      lx->name, lx->tok_line);
    else
      smgb_imp_errorf(lx->err,
                      "%s:%u: expected 'MOTION' after the hierarchy, found "
                      "'%s' (missing MOTION section or unbalanced braces)",
                      lx->name, lx->tok_line, tok_show(lx));
    return SMG_ERROR_PARSE;
  }
  if (!lex_expect(lx, "Frames:", "after MOTION (missing frame count)"))
    return SMG_ERROR_PARSE;
  m->frames_line = lx->tok_line;
  if ((r = read_frame_count(lx, h, m)) != SMG_OK) return r;
  if (!lex_expect(lx, "Frame", "after the frame count (missing Frame Time)") ||
      !lex_expect(lx, "Time:", "after 'Frame'") ||
      !lex_number(lx, "frame time", &m->frame_time))
    return SMG_ERROR_PARSE;
  if (!(m->frame_time > 0.0) || m->frame_time > 10.0) {
    smgb_imp_errorf(lx->err, "%s:%u: frame time %s must be in (0, 10] "
                    "seconds", lx->name, lx->tok_line, lx->tok);
    return SMG_ERROR_PARSE;
  }
  while (lx->p < lx->end && *lx->p != '\n') {
    if (!is_space(*lx->p)) {
      smgb_imp_errorf(lx->err, "%s:%u: unexpected text after the frame time",
                      lx->name, lx->line);
      return SMG_ERROR_PARSE;
    }
    lx->p++;
  }
  if (lx->p < lx->end) {
    lx->p++;
    lx->line++;
  }
  return SMG_OK;
}

/* Every frame line: as many values as the hierarchy has channels, as many
 * lines as "Frames:" declares (blank lines skipped). */
static smg_result read_frame_rows(bvh_lexer* lx, const bvh_hier* h,
                                  bvh_motion* m) {
  /* Never allocate more than the remaining text could hold: every value
   * takes at least one character plus a separator. */
  size_t remaining = (size_t)(lx->end - lx->p);
  size_t max_by_bytes = remaining / (2u * (size_t)h->channels) + 1u;
  uint32_t nread = 0;
  uint32_t capacity =
      m->frames < max_by_bytes ? m->frames : (uint32_t)max_by_bytes;
  m->rows = (double*)malloc(sizeof *m->rows * (size_t)capacity * h->channels);
  if (!m->rows) {
    smgb_imp_errorf(lx->err, "%s: out of memory for %u frames", lx->name,
                    capacity);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  while (lx->p < lx->end) {
    uint32_t line = lx->line;
    long n;
    double* row =
        nread < capacity ? m->rows + (size_t)nread * h->channels : NULL;
    double scratch[1];
    if (!row) {
      /* Either more lines than Frames: says, or a blank tail. */
      const char* q = lx->p;
      while (q < lx->end && *q != '\n' && is_space(*q)) q++;
      if (q < lx->end && *q != '\n') {
        smgb_imp_errorf(lx->err, "%s:%u: more frame lines than 'Frames: %u' "
                        "(line %u) declares",
                        lx->name, line, m->frames, m->frames_line);
        return SMG_ERROR_PARSE;
      }
      n = read_row(lx, scratch, 0);
    } else {
      n = read_row(lx, row, h->channels);
    }
    lx->line++;
    if (n < 0) return SMG_ERROR_PARSE;
    if (n == 0) continue; /* blank line */
    if ((uint32_t)n != h->channels) {
      smgb_imp_errorf(lx->err, "%s:%u: frame %u has %s%ld values, the "
                      "hierarchy declares %u channels",
                      lx->name, line, nread,
                      (uint32_t)n > h->channels ? "more than " : "",
                      (uint32_t)n > h->channels ? (long)h->channels : n,
                      h->channels);
      return SMG_ERROR_PARSE;
    }
    nread++;
  }
  if (nread != m->frames) {
    smgb_imp_errorf(lx->err, "%s:%u: file ends after %u frame lines but "
                    "'Frames: %u' (line %u) declares %u (truncated file?)",
                    lx->name, lx->line, nread, m->frames, m->frames_line,
                    m->frames);
    return SMG_ERROR_PARSE;
  }
  return SMG_OK;
}

/* The clip of joints h->root.. (static joints above were folded) from
 * rows first.., in metres (`scale` per file unit). */
static smg_result build_clip(const bvh_hier* h, const bvh_motion* m,
                             uint32_t first, double scale, const char* name,
                             smgb_error* err, smgb_clip* clip) {
  uint32_t ji, f, kept = m->frames - first, count = h->count - h->root;
  uint32_t stride = SMGB_STRIDE(count);
  const char* base;
  clip->skeleton.joint_count = count;
  clip->skeleton.names =
      (char(*)[SMGB_NAME_MAX])calloc(count, sizeof *clip->skeleton.names);
  clip->skeleton.parents = (int32_t*)calloc(count, sizeof(int32_t));
  clip->skeleton.offsets =
      (float(*)[3])calloc(count, sizeof *clip->skeleton.offsets);
  clip->poses = (float*)malloc(sizeof(float) * (size_t)kept * stride);
  if (!clip->skeleton.names || !clip->skeleton.parents ||
      !clip->skeleton.offsets || !clip->poses) {
    smgb_imp_errorf(err, "%s: out of memory", name);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (ji = 0; ji < count; ++ji) {
    const bvh_joint* j = &h->joints[h->root + ji];
    memcpy(clip->skeleton.names[ji], j->name, SMGB_NAME_MAX);
    clip->skeleton.parents[ji] = ji == 0 ? -1 : j->parent - (int32_t)h->root;
    clip->skeleton.offsets[ji][0] = (float)(j->offset[0] * scale);
    clip->skeleton.offsets[ji][1] = (float)(j->offset[1] * scale);
    clip->skeleton.offsets[ji][2] = (float)(j->offset[2] * scale);
  }
  for (f = 0; f < kept; ++f) {
    float* pose = clip->poses + (size_t)f * stride;
    row_to_pose(h, m->rows + (size_t)(f + first) * h->channels, scale, pose);
    if (f > 0) {
      /* Hemisphere continuity: q and -q are the same rotation; keep
       * consecutive frames on the same side so interpolation is short. */
      const float* prev = pose - stride;
      for (ji = 0; ji < count; ++ji) {
        float* q = pose + 3 + 4 * ji;
        const float* p = prev + 3 + 4 * ji;
        if (q[0] * p[0] + q[1] * p[1] + q[2] * p[2] + q[3] * p[3] < 0.0f) {
          q[0] = -q[0]; q[1] = -q[1]; q[2] = -q[2]; q[3] = -q[3];
        }
      }
    }
  }
  clip->frame_count = kept;
  clip->frame_rate = rate_from_frame_time(m->frame_time);
  base = strrchr(name, '/');
  snprintf(clip->name, sizeof clip->name, "%s", base ? base + 1 : name);
  return SMG_OK;
}

smg_result smgb_bvh_parse(const char* text, size_t size, const char* name,
                          float unit_scale, uint32_t skip_first_frame,
                          smgb_clip* out, smgb_error* err) {
  bvh_lexer lx;
  bvh_hier h;
  bvh_motion m;
  smgb_clip clip;
  smg_result r;
  uint32_t first = skip_first_frame ? 1u : 0u;

  if (err) err->message[0] = '\0';
  if (!out || (!text && size) || (unit_scale != 0.0f && !(unit_scale > 0.0f)) ||
      !isfinite(unit_scale) || unit_scale > 1e3f) {
    smgb_imp_errorf(err, "%s: invalid argument to smgb_bvh_parse",
                    name ? name : "(bvh)");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (!name) name = "(bvh)";
  memset(&clip, 0, sizeof clip);
  memset(&h, 0, sizeof h);
  memset(&m, 0, sizeof m);
  memset(&lx, 0, sizeof lx);
  lx.p = text;
  lx.end = text + size;
  lx.line = 1;
  lx.name = name;
  lx.err = err;

  h.joints = (bvh_joint*)malloc(sizeof *h.joints * SMGB_BVH_MAX_JOINTS);
  if (!h.joints) {
    smgb_imp_errorf(err, "%s: out of memory", name);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  r = parse_hierarchy(&lx, &h) ? SMG_OK : SMG_ERROR_PARSE;
  if (r == SMG_OK) r = read_motion_header(&lx, &h, &m);
  if (r == SMG_OK) r = read_frame_rows(&lx, &h, &m);
  if (r == SMG_OK) {
    fold_static_root(&h, m.rows, m.frames);
    if (!fold_joint_positions(&lx, &h, m.rows, m.frames))
      r = SMG_ERROR_UNSUPPORTED;
  }
  if (r == SMG_OK && m.frames <= first) {
    smgb_imp_errorf(err, "%s:%u: no frames left after skipping the first "
                    "(T-pose) frame", name, m.frames_line);
    r = SMG_ERROR_PARSE;
  }
  if (r == SMG_OK) {
    double scale =
        unit_scale > 0.0f
            ? (double)unit_scale
            : guess_unit_scale(&h, m.rows + (size_t)first * h.channels);
    r = build_clip(&h, &m, first, scale, name, err, &clip);
  }
  if (r == SMG_OK) {
    *out = clip;
    memset(&clip, 0, sizeof clip);
  }
  smgb_clip_free(&clip);
  free(m.rows);
  free(h.joints);
  return r;
}

/* Read a whole file (bounded by SMGB_BVH_MAX_FILE_BYTES). */
static smg_result read_file(const char* path, char** out, size_t* out_size,
                            smgb_error* err) {
  FILE* fp = fopen(path, "rb");
  char* buf = NULL;
  size_t cap = 0, len = 0;
  if (!fp) {
    smgb_imp_errorf(err, "%s: cannot open: %s", path, strerror(errno));
    return SMG_ERROR_IO;
  }
  for (;;) {
    size_t got;
    if (len == cap) {
      size_t ncap = cap ? cap * 2 : 65536;
      char* nb;
      if (cap >= SMGB_BVH_MAX_FILE_BYTES) {
        smgb_imp_errorf(err, "%s: file larger than 1 GiB", path);
        free(buf);
        fclose(fp);
        return SMG_ERROR_CAPACITY;
      }
      nb = (char*)realloc(buf, ncap);
      if (!nb) {
        smgb_imp_errorf(err, "%s: out of memory reading file", path);
        free(buf);
        fclose(fp);
        return SMG_ERROR_OUT_OF_MEMORY;
      }
      buf = nb;
      cap = ncap;
    }
    got = fread(buf + len, 1, cap - len, fp);
    len += got;
    if (got == 0) break;
  }
  if (ferror(fp)) {
    smgb_imp_errorf(err, "%s: read error: %s", path, strerror(errno));
    free(buf);
    fclose(fp);
    return SMG_ERROR_IO;
  }
  fclose(fp);
  *out = buf;
  *out_size = len;
  return SMG_OK;
}

smg_result smgb_bvh_load(const char* path, float unit_scale,
                         uint32_t skip_first_frame, smgb_clip* out,
                         smgb_error* err) {
  char* text = NULL;
  size_t size = 0;
  smg_result r;
  if (err) err->message[0] = '\0';
  if (!path || !out) {
    smgb_imp_errorf(err, "smgb_bvh_load: NULL path or output");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  r = read_file(path, &text, &size, err);
  if (r != SMG_OK) return r;
  r = smgb_bvh_parse(text, size, path, unit_scale, skip_first_frame, out, err);
  free(text);
  if (r == SMG_OK) {
    /* Clip name: the file name without its directory. */
    const char* base = strrchr(path, '/');
    snprintf(out->name, sizeof out->name, "%s", base ? base + 1 : path);
  }
  return r;
}

/* ---- writer -------------------------------------------------------------- */

static int write_joint(FILE* fp, const smgb_clip* c, uint32_t j, int depth) {
  uint32_t k;
  int has_child = 0;
  const float* o = c->skeleton.offsets[j];
  for (k = 0; k < (uint32_t)depth; ++k) fputc('\t', fp);
  fprintf(fp, "%s %s\n", j == 0 ? "ROOT" : "JOINT", c->skeleton.names[j]);
  for (k = 0; k < (uint32_t)depth; ++k) fputc('\t', fp);
  fprintf(fp, "{\n");
  for (k = 0; k < (uint32_t)depth + 1; ++k) fputc('\t', fp);
  fprintf(fp, "OFFSET %.9g %.9g %.9g\n", o[0], o[1], o[2]);
  for (k = 0; k < (uint32_t)depth + 1; ++k) fputc('\t', fp);
  if (j == 0)
    fprintf(fp, "CHANNELS 6 Xposition Yposition Zposition Zrotation "
                "Yrotation Xrotation\n");
  else
    fprintf(fp, "CHANNELS 3 Zrotation Yrotation Xrotation\n");
  for (k = j + 1; k < c->skeleton.joint_count; ++k) {
    if (c->skeleton.parents[k] == (int32_t)j) {
      has_child = 1;
      write_joint(fp, c, k, depth + 1);
    }
  }
  if (!has_child) {
    /* A short End Site along the bone keeps viewers drawing the last bone. */
    double len = sqrt((double)o[0] * o[0] + (double)o[1] * o[1] + (double)o[2] * o[2]);
    double e[3] = {0.0, 0.05, 0.0};
    if (len > 1e-6) {
      e[0] = 0.25 * o[0]; e[1] = 0.25 * o[1]; e[2] = 0.25 * o[2];
    }
    for (k = 0; k < (uint32_t)depth + 1; ++k) fputc('\t', fp);
    fprintf(fp, "End Site\n");
    for (k = 0; k < (uint32_t)depth + 1; ++k) fputc('\t', fp);
    fprintf(fp, "{\n");
    for (k = 0; k < (uint32_t)depth + 2; ++k) fputc('\t', fp);
    fprintf(fp, "OFFSET %.9g %.9g %.9g\n", e[0], e[1], e[2]);
    for (k = 0; k < (uint32_t)depth + 1; ++k) fputc('\t', fp);
    fprintf(fp, "}\n");
  }
  for (k = 0; k < (uint32_t)depth; ++k) fputc('\t', fp);
  fprintf(fp, "}\n");
  return 1;
}

smg_result smgb_bvh_save(const char* path, const smgb_clip* clip,
                         smgb_error* err) {
  FILE* fp;
  uint32_t f, j, J, stride;
  if (err) err->message[0] = '\0';
  if (!path || !clip || clip->skeleton.joint_count == 0 ||
      !clip->skeleton.names || !clip->skeleton.parents ||
      !clip->skeleton.offsets || (clip->frame_count && !clip->poses) ||
      !(clip->frame_rate > 0.0f)) {
    smgb_imp_errorf(err, "%s: invalid clip for smgb_bvh_save",
                    path ? path : "(null)");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  J = clip->skeleton.joint_count;
  if (clip->skeleton.parents[0] != -1) {
    smgb_imp_errorf(err, "%s: joint 0 must be the root", path);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  for (j = 0; j < J; ++j) {
    const char* n = clip->skeleton.names[j];
    size_t k, len = strnlen(n, SMGB_NAME_MAX);
    if (j > 0 && (clip->skeleton.parents[j] < 0 ||
                  clip->skeleton.parents[j] >= (int32_t)j)) {
      smgb_imp_errorf(err, "%s: joint %u's parent must precede it", path, j);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    /* A BVH name is one token: no whitespace, braces or empty names. */
    if (len == 0 || len == SMGB_NAME_MAX) {
      smgb_imp_errorf(err, "%s: joint %u has an empty or unterminated name",
                      path, j);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    for (k = 0; k < len; ++k) {
      if (is_space(n[k]) || n[k] == '{' || n[k] == '}' ||
          !isprint((unsigned char)n[k])) {
        smgb_imp_errorf(err, "%s: joint name '%.63s' cannot be written to "
                        "BVH (whitespace, brace or control character)",
                        path, n);
        return SMG_ERROR_INVALID_ARGUMENT;
      }
    }
  }
  fp = fopen(path, "wb");
  if (!fp) {
    smgb_imp_errorf(err, "%s: cannot create: %s", path, strerror(errno));
    return SMG_ERROR_IO;
  }
  fprintf(fp, "HIERARCHY\n");
  write_joint(fp, clip, 0, 0);
  fprintf(fp, "MOTION\nFrames: %u\nFrame Time: %.9g\n", clip->frame_count,
          1.0 / (double)clip->frame_rate);
  stride = SMGB_STRIDE(J);
  for (f = 0; f < clip->frame_count; ++f) {
    const float* pose = clip->poses + (size_t)f * stride;
    fprintf(fp, "%.9g %.9g %.9g", pose[0], pose[1], pose[2]);
    for (j = 0; j < J; ++j) {
      double q[4], z, y, x;
      q[0] = pose[3 + 4 * j]; q[1] = pose[4 + 4 * j];
      q[2] = pose[5 + 4 * j]; q[3] = pose[6 + 4 * j];
      smgb_q_normalize(q);
      smgb_q_to_euler_zyx(q, &z, &y, &x);
      fprintf(fp, " %.9g %.9g %.9g", z * (180.0 / SMGB_M_PI),
              y * (180.0 / SMGB_M_PI), x * (180.0 / SMGB_M_PI));
    }
    fputc('\n', fp);
  }
  if (ferror(fp) || fclose(fp) != 0) {
    smgb_imp_errorf(err, "%s: write error", path);
    return SMG_ERROR_IO;
  }
  return SMG_OK;
}
