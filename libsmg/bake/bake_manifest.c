/*
 * bake_manifest.c - line-based manifest parser (format: docs/manifest.md).
 *
 * One statement per line, whitespace-separated tokens, '#' starts a comment,
 * "double quotes" allow spaces in a token. Settings (unit, skip_first_frame,
 * mirror, animation, bones) apply to the clip lines that follow them; a clip line
 * may override them with key=value options. Every error names file:line.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bake_import_util.h"
#include "bake_manifest.h"
#include "bake_manifest_pattern.h"
#include "bake_roles.h"

#define LINE_MAX_CHARS 4096
#define MAX_TOKENS 16

smg_result smgb_manifest_init(smgb_manifest* m, const char* root) {
  if (!m) return SMG_ERROR_INVALID_ARGUMENT;
  memset(m, 0, sizeof *m);
  if (root && strlen(root) >= sizeof m->root) return SMG_ERROR_INVALID_ARGUMENT;
  snprintf(m->root, sizeof m->root, "%s", root ? root : "");
  return SMG_OK;
}

void smgb_manifest_free(smgb_manifest* m) {
  if (!m) return;
  free(m->clips);
  memset(m, 0, sizeof *m);
}

/* "file:line: " prefix for messages. */
static void where(const smgb_manifest* m, int32_t line, char* buf, size_t n) {
  if (m->path[0] && line > 0)
    snprintf(buf, n, "%s:%d: ", m->path, (int)line);
  else if (m->path[0])
    snprintf(buf, n, "%s: ", m->path);
  else
    buf[0] = '\0';
}

static int valid_label(const char* s) {
  size_t n = strlen(s), i;
  if (n == 0 || n >= SMGB_NAME_MAX) return 0;
  for (i = 0; i < n; ++i) {
    char c = s[i];
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
          (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.' ||
          c == ':'))
      return 0;
  }
  return 1;
}

smg_result smgb_manifest_add(smgb_manifest* m, const smgb_manifest_clip* clip,
                             const char* file, int check_exists,
                             smgb_error* err) {
  char at[SMGB_PATH_MAX + 32];
  smgb_manifest_clip c;
  int n;
  if (!m || !clip || !file) {
    smgb_imp_errorf(err, "smgb_manifest_add: invalid argument");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  where(m, clip->line, at, sizeof at);
  if (!*file) { /* a manifest's "" (found by the manifest fuzzer) */
    smgb_imp_errorf(err, "%sempty clip file name", at);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (clip->role != SMG_BAKE_ROLE_LOWER && clip->role != SMG_BAKE_ROLE_UPPER) {
    smgb_imp_errorf(err, "%sclip role must be lower or upper", at);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (!valid_label(clip->label)) {
    smgb_imp_errorf(err,
                    "%sinvalid label '%.63s' (1-63 characters of A-Z a-z 0-9 "
                    "_ . - :)",
                    at, clip->label);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (clip->role == SMG_BAKE_ROLE_UPPER && strcmp(clip->label, "none") == 0) {
    smgb_imp_errorf(err,
                    "%sthe action label 'none' is reserved for the "
                    "locomotion's own upper body",
                    at);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (clip->mirror > SMG_BAKE_MIRROR_NO || clip->skip_first_frame > 1 ||
      !(clip->unit_scale >= 0.0f) || clip->unit_scale > 1e3f) {
    smgb_imp_errorf(err, "%sinvalid mirror, skip_first_frame or unit", at);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (m->clip_count >= SMGB_MANIFEST_MAX_CLIPS) {
    smgb_imp_errorf(err, "%stoo many clips (limit %u)", at,
                    SMGB_MANIFEST_MAX_CLIPS);
    return SMG_ERROR_CAPACITY;
  }
  c = *clip;
  c.label[SMGB_NAME_MAX - 1] = '\0';
  c.name[SMGB_NAME_MAX - 1] = '\0';
  if (file[0] == '/' || m->root[0] == '\0')
    n = snprintf(c.path, sizeof c.path, "%s", file);
  else
    n = snprintf(c.path, sizeof c.path, "%s/%s", m->root, file);
  if (n < 0 || (size_t)n >= sizeof c.path) {
    smgb_imp_errorf(err, "%sclip path too long: %.200s", at, file);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (check_exists) {
    struct stat st;
    if (stat(c.path, &st) != 0 || access(c.path, R_OK) != 0) {
      smgb_imp_errorf(err, "%sclip file '%s' not found or unreadable (%s): %s",
                      at, file, c.path, strerror(errno));
      return SMG_ERROR_IO;
    }
    if (!S_ISREG(st.st_mode)) {
      smgb_imp_errorf(err, "%sclip file '%s' (%s) is not a regular file", at,
                      file, c.path);
      return SMG_ERROR_IO;
    }
  }
  if (m->clip_count == m->clip_capacity) {
    uint32_t cap = m->clip_capacity ? m->clip_capacity * 2 : 16;
    smgb_manifest_clip* nc =
        (smgb_manifest_clip*)realloc(m->clips, sizeof *nc * cap);
    if (!nc) {
      smgb_imp_errorf(err, "%sout of memory", at);
      return SMG_ERROR_OUT_OF_MEMORY;
    }
    m->clips = nc;
    m->clip_capacity = cap;
  }
  m->clips[m->clip_count++] = c;
  return SMG_OK;
}

/* Split a line into tokens in place. Returns the count or -1 (error set). */
static int tokenize(char* line, char** tok, const char* at, smgb_error* err) {
  int n = 0;
  char* p = line;
  for (;;) {
    while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') p++;
    if (*p == '\0' || *p == '#') return n;
    if (n == MAX_TOKENS) {
      smgb_imp_errorf(err, "%stoo many words on one line (limit %d)", at,
                      MAX_TOKENS);
      return -1;
    }
    if (*p == '"') {
      tok[n++] = ++p;
      while (*p && *p != '"') p++;
      if (*p != '"') {
        smgb_imp_errorf(err, "%sunterminated quoted string", at);
        return -1;
      }
      *p++ = '\0';
      if (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') {
        smgb_imp_errorf(err, "%stext right after a closing quote", at);
        return -1;
      }
    } else {
      tok[n++] = p;
      while (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') p++;
      if (*p) *p++ = '\0';
      else return n;
    }
  }
}

/* Parse helpers: 1 on success. */
static int parse_u32(const char* s, uint32_t max, uint32_t* out) {
  char* end;
  unsigned long v;
  if (!*s || *s == '-' || *s == '+') return 0;
  errno = 0;
  v = strtoul(s, &end, 10);
  if (*end || errno || v > max) return 0;
  *out = (uint32_t)v;
  return 1;
}

static int parse_float(const char* s, float lo, float hi, float* out) {
  char* end;
  double v;
  if (!*s) return 0;
  v = strtod(s, &end);
  if (*end || !isfinite(v) || v < lo || v > hi) return 0;
  *out = (float)v;
  return 1;
}

static int parse_mirror(const char* s, uint32_t* out) {
  if (strcmp(s, "1") == 0 || strcmp(s, "yes") == 0) *out = SMG_BAKE_MIRROR_YES;
  else if (strcmp(s, "0") == 0 || strcmp(s, "no") == 0) *out = SMG_BAKE_MIRROR_NO;
  else if (strcmp(s, "default") == 0) *out = SMG_BAKE_MIRROR_DEFAULT;
  else return 0;
  return 1;
}

typedef struct defaults {
  float unit;
  uint32_t skip, mirror, animation;
  char bone[SMGB_ROLE_COUNT][SMGB_NAME_MAX]; /* `bones`: joint per role */
} defaults;

/* The current `bones` setting as bone map text (bake_roles.h). */
static void bones_text(const defaults* d, char* out, size_t size) {
  size_t used = 0;
  int r;
  out[0] = '\0';
  for (r = 0; r < SMGB_ROLE_COUNT; ++r) {
    int k;
    if (!d->bone[r][0]) continue;
    k = snprintf(out + used, size - used, "%s=%s\n",
                 smgb_role_name((smgb_role)r), d->bone[r]);
    if (k > 0 && (size_t)k < size - used) used += (size_t)k;
  }
}

/* `bones none` or `bones ROLE=JOINT ...` (words after the keyword). */
static int parse_bones(defaults* d, char** tok, int n, const char* at,
                       smgb_error* err) {
  int i;
  if (n == 2 && strcmp(tok[1], "none") == 0) {
    memset(d->bone, 0, sizeof d->bone);
    return 1;
  }
  if (n < 2) {
    smgb_imp_errorf(err, "%sbones needs ROLE=JOINT pairs or 'none'", at);
    return 0;
  }
  for (i = 1; i < n; ++i) {
    char* eq = strchr(tok[i], '=');
    int role;
    if (!eq || eq == tok[i] || !eq[1] || strlen(eq + 1) >= SMGB_NAME_MAX ||
        strchr(eq + 1, '\n')) {
      smgb_imp_errorf(err,
                      "%sbones: expected ROLE=JOINT, found '%.100s' (quote "
                      "the pair when the joint name has spaces)",
                      at, tok[i]);
      return 0;
    }
    *eq = '\0';
    role = smgb_role_from_name(tok[i]);
    if (role < 0) {
      smgb_imp_errorf(err,
                      "%sbones: unknown role '%.60s' (pelvis, spine_base, "
                      "neck, head, left_/right_ + upper_leg, lower_leg, foot, "
                      "toes, upper_arm, lower_arm, hand, shoulder, fingers)",
                      at, tok[i]);
      return 0;
    }
    snprintf(d->bone[role], SMGB_NAME_MAX, "%s", eq + 1);
  }
  return 1;
}

/* Frame range "A-B" or "A-end" in file frame numbers (0 = the file's first
 * frame, T-pose included) -> desc first_frame/frame_count. */
static int parse_frames(const char* s, uint32_t skip, uint32_t* first,
                        uint32_t* count, const char* at, smgb_error* err) {
  char a[32], *dash;
  uint32_t lo, hi = 0;
  int to_end;
  if (strlen(s) >= sizeof a || !(dash = strchr(s, '-'))) goto bad;
  memcpy(a, s, (size_t)(dash - s));
  a[dash - s] = '\0';
  to_end = strcmp(dash + 1, "end") == 0;
  if (!parse_u32(a, 100000000u, &lo)) goto bad;
  if (!to_end && !parse_u32(dash + 1, 100000000u, &hi)) goto bad;
  if (!to_end && hi < lo) {
    smgb_imp_errorf(err, "%sframes=%s: the range ends before it starts", at, s);
    return 0;
  }
  if (lo < skip) {
    smgb_imp_errorf(err,
                    "%sframes=%s starts at frame 0, the T-pose that "
                    "skip_first_frame drops (start at 1)",
                    at, s);
    return 0;
  }
  *first = lo - skip;
  *count = to_end ? 0u : hi - lo + 1u;
  return 1;
bad:
  smgb_imp_errorf(err,
                  "%sframes=%s: expected FIRST-LAST or FIRST-end (file frame "
                  "numbers from 0)",
                  at, s);
  return 0;
}

/* Every file of the pattern's folder that matches it, in name order
 * (every `every`-th), each with its label from the template. */
static smg_result add_pattern(smgb_manifest* m, const smgb_manifest_clip* c,
                              const char* tmpl, const char* file,
                              uint32_t every, const char* at,
                              smgb_error* err) {
  char dir[SMGB_PATH_MAX], rel[SMGB_PATH_MAX];
  const char* slash = strrchr(file, '/');
  const char* pattern = slash ? slash + 1 : file;
  char (*names)[SMGB_PATTERN_NAME_MAX] = NULL;
  uint32_t n = 0, i, added = 0;
  smg_result r;
  int k;
  if (slash && memchr(file, '*', (size_t)(slash - file))) {
    smgb_imp_errorf(err, "%s'*' may only appear in the file name, not in "
                    "its folder: %.200s", at, file);
    return SMG_ERROR_PARSE;
  }
  /* the folder: root joined like a clip path */
  if (slash)
    k = file[0] == '/' || !m->root[0]
            ? snprintf(dir, sizeof dir, "%.*s", (int)(slash - file), file)
            : snprintf(dir, sizeof dir, "%s/%.*s", m->root,
                       (int)(slash - file), file);
  else
    k = snprintf(dir, sizeof dir, "%s", m->root);
  if (k < 0 || (size_t)k >= sizeof dir) {
    smgb_imp_errorf(err, "%sfolder path too long: %.200s", at, file);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  r = smgb_pattern_list(dir, pattern, &names, &n, err);
  if (r != SMG_OK) {
    char tmp[sizeof err->message];
    snprintf(tmp, sizeof tmp, "%s", err->message);
    smgb_imp_errorf(err, "%s%s", at, tmp);
    return r;
  }
  for (i = 0; i < n && r == SMG_OK; i += every) {
    smgb_pattern_match pm;
    smgb_manifest_clip one = *c;
    smgb_pattern_matches(pattern, names[i], &pm);
    if (!smgb_pattern_label(tmpl, &pm, one.label, sizeof one.label)) {
      smgb_imp_errorf(err, "%slabel '%.63s' for '%.200s': each {N} must name "
                      "one of the pattern's %d '*'", at, tmpl, names[i],
                      pm.count);
      r = SMG_ERROR_PARSE;
      break;
    }
    k = slash ? snprintf(rel, sizeof rel, "%.*s/%s", (int)(slash - file),
                         file, names[i])
              : snprintf(rel, sizeof rel, "%s", names[i]);
    if (k < 0 || (size_t)k >= sizeof rel) {
      smgb_imp_errorf(err, "%sclip path too long: %.200s", at, names[i]);
      r = SMG_ERROR_INVALID_ARGUMENT;
      break;
    }
    r = smgb_manifest_add(m, &one, rel, 1, err);
    ++added;
  }
  free(names);
  if (r == SMG_OK && added == 0) {
    smgb_imp_errorf(err, "%sno file in '%s' matches '%.200s'", at, dir,
                    pattern);
    r = SMG_ERROR_IO;
  }
  return r;
}

static smg_result parse_clip_line(smgb_manifest* m, char** tok, int n,
                                  int32_t line, const defaults* d,
                                  const char* at, smgb_error* err) {
  smgb_manifest_clip c;
  const char* frames = NULL;
  int i, pattern = strchr(tok[2 < n ? 2 : 0], '*') != NULL;
  uint32_t every = 1;
  char label_check[SMGB_NAME_MAX];
  if (n < 3) {
    smgb_imp_errorf(err, "%s'%s' needs a label and a file: %s LABEL FILE "
                    "[options]", at, tok[0], tok[0]);
    return SMG_ERROR_PARSE;
  }
  memset(&c, 0, sizeof c);
  c.role = strcmp(tok[0], "lower") == 0 ? SMG_BAKE_ROLE_LOWER
                                        : SMG_BAKE_ROLE_UPPER;
  /* a pattern's label is a template: check it with its {N} taken out */
  {
    const char* t = tok[1];
    size_t o = 0;
    while (*t && o + 1 < sizeof label_check) {
      if (pattern && t[0] == '{' && t[1] >= '1' && t[1] <= '9' &&
          t[2] == '}') {
        label_check[o++] = 'x';
        t += 3;
      } else {
        label_check[o++] = *t++;
      }
    }
    label_check[o] = '\0';
    if (*t) label_check[0] = '\0'; /* too long */
  }
  if (!valid_label(label_check)) {
    smgb_imp_errorf(err,
                    "%sinvalid label '%.63s' (1-63 characters of A-Z a-z 0-9 "
                    "_ . - :%s)",
                    at, tok[1], pattern ? ", and {1}..{9} in a pattern" : "");
    return SMG_ERROR_PARSE;
  }
  snprintf(c.label, sizeof c.label, "%s", tok[1]);
  c.unit_scale = d->unit;
  c.skip_first_frame = d->skip;
  c.mirror = d->mirror;
  c.animation_index = d->animation;
  c.line = line;
  c.from_folder = (uint32_t)pattern;
  bones_text(d, c.bones, sizeof c.bones);
  for (i = 3; i < n; ++i) {
    char* eq = strchr(tok[i], '=');
    const char* v;
    int ok = 1;
    if (!eq) {
      smgb_imp_errorf(err, "%sexpected key=value, found '%.100s'", at, tok[i]);
      return SMG_ERROR_PARSE;
    }
    *eq = '\0';
    v = eq + 1;
    if (strcmp(tok[i], "frames") == 0) frames = v;
    else if (strcmp(tok[i], "mirror") == 0) ok = parse_mirror(v, &c.mirror);
    else if (strcmp(tok[i], "unit") == 0) ok = parse_float(v, 0.0f, 1e3f, &c.unit_scale);
    else if (strcmp(tok[i], "skip_first_frame") == 0) ok = parse_u32(v, 1, &c.skip_first_frame);
    else if (strcmp(tok[i], "animation") == 0) ok = parse_u32(v, 1000000u, &c.animation_index);
    else if (strcmp(tok[i], "every") == 0 && pattern)
      ok = parse_u32(v, 1000000u, &every) && every >= 1;
    else if (strcmp(tok[i], "name") == 0 && !pattern) {
      if (strlen(v) == 0 || strlen(v) >= sizeof c.name) ok = 0;
      else snprintf(c.name, sizeof c.name, "%s", v);
    } else {
      smgb_imp_errorf(err,
                      "%sunknown option '%.60s' (frames, mirror, unit, "
                      "skip_first_frame, animation, %s)",
                      at, tok[i], pattern ? "every" : "name");
      return SMG_ERROR_PARSE;
    }
    if (!ok) {
      smgb_imp_errorf(err, "%sbad value '%.100s' for %s", at, v, tok[i]);
      return SMG_ERROR_PARSE;
    }
  }
  /* Frames are interpreted after all options: skip_first_frame may follow. */
  if (frames && !parse_frames(frames, c.skip_first_frame, &c.first_frame,
                              &c.frame_count, at, err))
    return SMG_ERROR_PARSE;
  if (pattern) return add_pattern(m, &c, tok[1], tok[2], every, at, err);
  return smgb_manifest_add(m, &c, tok[2], 1, err);
}

static void dir_of(const char* path, char* out, size_t n) {
  const char* slash = strrchr(path, '/');
  if (!slash) snprintf(out, n, ".");
  else if (slash == path) snprintf(out, n, "/");
  else snprintf(out, n, "%.*s", (int)(slash - path), path);
}

/* `target RIG [unit=U] [animation=N]`: the rig every clip is retargeted
 * onto (docs/manifest.md); RIG is relative to the manifest's folder. */
static int parse_target(smgb_manifest* m, const char* path, char** tok,
                        int n, const char* at, smgb_error* err) {
  char base[SMGB_PATH_MAX];
  int k, i;
  if (n < 2) {
    smgb_imp_errorf(err, "%starget needs a rig file", at);
    return 0;
  }
  if (m->target[0]) {
    smgb_imp_errorf(err, "%s'target' may appear only once", at);
    return 0;
  }
  dir_of(path, base, sizeof base);
  k = tok[1][0] == '/'
          ? snprintf(m->target, sizeof m->target, "%s", tok[1])
          : snprintf(m->target, sizeof m->target, "%s/%s", base, tok[1]);
  if (k < 0 || (size_t)k >= sizeof m->target) {
    smgb_imp_errorf(err, "%starget path too long", at);
    return 0;
  }
  if (access(m->target, R_OK) != 0) {
    smgb_imp_errorf(err, "%starget rig '%s' not found or unreadable (%s)",
                    at, tok[1], m->target);
    return 0;
  }
  for (i = 2; i < n; ++i) {
    if (strncmp(tok[i], "unit=", 5) == 0) {
      if (!parse_float(tok[i] + 5, 0.0f, 1e3f, &m->target_unit)) {
        smgb_imp_errorf(err, "%starget unit '%.60s' must be in [0, 1000]", at,
                        tok[i] + 5);
        return 0;
      }
    } else if (strncmp(tok[i], "animation=", 10) == 0) {
      if (!parse_u32(tok[i] + 10, 1000000u, &m->target_animation)) {
        smgb_imp_errorf(err, "%starget animation must be an index >= 0", at);
        return 0;
      }
    } else {
      smgb_imp_errorf(err, "%sunknown target option '%.60s' (unit, animation)",
                      at, tok[i]);
      return 0;
    }
  }
  return 1;
}

smg_result smgb_manifest_load(const char* path, const char* data_dir_override,
                              smgb_manifest* out, smgb_error* err) {
  smgb_manifest m;
  FILE* fp;
  char line[LINE_MAX_CHARS + 2];
  char at[SMGB_PATH_MAX + 32];
  char* tok[MAX_TOKENS];
  int32_t lineno = 0;
  int seen_root = 0;
  defaults d;
  smg_result r = SMG_ERROR_PARSE;
  uint32_t lower = 0, i;

  if (err) err->message[0] = '\0';
  if (!path || !out || strlen(path) >= SMGB_PATH_MAX ||
      (data_dir_override && strlen(data_dir_override) >= SMGB_PATH_MAX)) {
    smgb_imp_errorf(err, "smgb_manifest_load: invalid argument");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  memset(out, 0, sizeof *out);
  memset(&m, 0, sizeof m);
  snprintf(m.path, sizeof m.path, "%s", path);
  if (data_dir_override && *data_dir_override)
    snprintf(m.root, sizeof m.root, "%s", data_dir_override);
  else
    dir_of(path, m.root, sizeof m.root);
  d.unit = 0.0f;
  d.skip = 0;
  d.mirror = SMG_BAKE_MIRROR_DEFAULT;
  d.animation = 0;
  memset(d.bone, 0, sizeof d.bone);

  fp = fopen(path, "r");
  if (!fp) {
    smgb_imp_errorf(err, "%s: cannot open manifest: %s", path, strerror(errno));
    return SMG_ERROR_IO;
  }
  while (fgets(line, sizeof line, fp)) {
    size_t len = strlen(line);
    int n;
    lineno++;
    where(&m, lineno, at, sizeof at);
    if (len > LINE_MAX_CHARS || (len > 0 && line[len - 1] != '\n' && !feof(fp))) {
      smgb_imp_errorf(err, "%sline longer than %d characters", at,
                      LINE_MAX_CHARS - 1);
      goto fail;
    }
    n = tokenize(line, tok, at, err);
    if (n < 0) goto fail;
    if (n == 0) continue;
    if (strcmp(tok[0], "lower") == 0 || strcmp(tok[0], "upper") == 0) {
      r = parse_clip_line(&m, tok, n, lineno, &d, at, err);
      if (r != SMG_OK) goto fail;
      r = SMG_ERROR_PARSE;
      continue;
    }
    if (strcmp(tok[0], "bones") == 0) {
      if (!parse_bones(&d, tok, n, at, err)) goto fail;
      continue;
    }
    if (strcmp(tok[0], "target") == 0) {
      if (!parse_target(&m, path, tok, n, at, err)) goto fail;
      continue;
    }
    if (n != 2) {
      smgb_imp_errorf(err,
                      "%sexpected 'lower ...', 'upper ...', 'bones ...' or "
                      "one of frame_rate/root/unit/skip_first_frame/mirror/"
                      "animation followed by one value, found '%.60s' with "
                      "%d words",
                      at, tok[0], n);
      goto fail;
    }
    if (strcmp(tok[0], "frame_rate") == 0) {
      if (!parse_float(tok[1], 1e-3f, 1000.0f, &m.frame_rate)) {
        smgb_imp_errorf(err, "%sframe_rate '%.60s' must be in (0, 1000]", at,
                        tok[1]);
        goto fail;
      }
    } else if (strcmp(tok[0], "root") == 0) {
      if (seen_root || m.clip_count) {
        smgb_imp_errorf(err, "%s'root' must appear once, before the first clip",
                        at);
        goto fail;
      }
      seen_root = 1;
      if (!(data_dir_override && *data_dir_override)) {
        char base[SMGB_PATH_MAX];
        int k;
        dir_of(path, base, sizeof base);
        if (tok[1][0] == '/')
          k = snprintf(m.root, sizeof m.root, "%s", tok[1]);
        else
          k = snprintf(m.root, sizeof m.root, "%s/%s", base, tok[1]);
        if (k < 0 || (size_t)k >= sizeof m.root) {
          smgb_imp_errorf(err, "%sroot path too long", at);
          goto fail;
        }
      }
    } else if (strcmp(tok[0], "unit") == 0) {
      if (!parse_float(tok[1], 0.0f, 1e3f, &d.unit)) {
        smgb_imp_errorf(err, "%sunit '%.60s' must be a number in [0, 1000] "
                        "(0 = guess)", at, tok[1]);
        goto fail;
      }
    } else if (strcmp(tok[0], "skip_first_frame") == 0) {
      if (!parse_u32(tok[1], 1, &d.skip)) {
        smgb_imp_errorf(err, "%sskip_first_frame must be 0 or 1", at);
        goto fail;
      }
    } else if (strcmp(tok[0], "mirror") == 0) {
      if (!parse_mirror(tok[1], &d.mirror)) {
        smgb_imp_errorf(err, "%smirror must be 0, 1 or default", at);
        goto fail;
      }
    } else if (strcmp(tok[0], "animation") == 0) {
      if (!parse_u32(tok[1], 1000000u, &d.animation)) {
        smgb_imp_errorf(err, "%sanimation must be an index >= 0", at);
        goto fail;
      }
    } else {
      smgb_imp_errorf(err, "%sunknown statement '%.60s'", at, tok[0]);
      goto fail;
    }
  }
  if (ferror(fp)) {
    smgb_imp_errorf(err, "%s: read error", path);
    r = SMG_ERROR_IO;
    goto fail;
  }
  for (i = 0; i < m.clip_count; ++i)
    if (m.clips[i].role == SMG_BAKE_ROLE_LOWER) lower++;
  if (lower == 0) {
    smgb_imp_errorf(err, "%s:%d: the manifest has no 'lower' (locomotion) clip",
                    path, (int)lineno);
    goto fail;
  }
  fclose(fp);
  *out = m;
  return SMG_OK;

fail:
  fclose(fp);
  smgb_manifest_free(&m);
  return r;
}

smg_result smgb_manifest_descs(const smgb_manifest* m,
                               smg_bake_clip_desc* descs, uint32_t capacity) {
  uint32_t i;
  if (!m || (!descs && m->clip_count)) return SMG_ERROR_INVALID_ARGUMENT;
  if (capacity < m->clip_count) return SMG_ERROR_BUFFER_TOO_SMALL;
  for (i = 0; i < m->clip_count; ++i) {
    const smgb_manifest_clip* c = &m->clips[i];
    smg_bake_clip_desc* d = &descs[i];
    memset(d, 0, sizeof *d);
    d->struct_size = sizeof *d;
    d->role = c->role;
    d->path = c->path;
    d->label = c->label;
    d->name = c->name[0] ? c->name : NULL;
    d->first_frame = c->first_frame;
    d->frame_count = c->frame_count;
    d->mirror = c->mirror;
    d->skip_first_frame = c->skip_first_frame;
    d->unit_scale = c->unit_scale;
    d->animation_index = c->animation_index;
    d->source_line = c->line;
    d->bones = c->bones[0] ? c->bones : NULL;
    d->flags = c->from_folder ? SMG_BAKE_CLIP_SKIP_UNUSABLE : 0u;
  }
  return SMG_OK;
}
