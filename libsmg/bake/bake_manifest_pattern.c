/*
 * bake_manifest_pattern.c - `*` patterns with captures and label
 * templates for manifest clip lines that bake a whole folder (see
 * bake_manifest_pattern.h).
 */
#include "bake_manifest_pattern.h"

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Backtracking match; each `*` tries its shortest extent first, so the
 * captures are leftmost-shortest. Patterns are short (a file name), and
 * the depth is bounded by SMGB_PATTERN_CAPTURES. */
static int match_at(const char* p, const char* s, smgb_pattern_match* m) {
  while (*p && *p != '*') {
    if (*p != *s) return 0;
    ++p;
    ++s;
  }
  if (!*p) return *s == '\0';
  {
    int slot = m->count;
    size_t len;
    if (slot >= SMGB_PATTERN_CAPTURES) return 0;
    m->count = slot + 1;
    for (len = 0;; ++len) {
      m->start[slot] = s;
      m->length[slot] = len;
      if (match_at(p + 1, s + len, m)) return 1;
      m->count = slot + 1; /* a deeper failed try may have grown it */
      if (s[len] == '\0' || s[len] == '/') break;
    }
    m->count = slot;
    return 0;
  }
}

int smgb_pattern_matches(const char* pattern, const char* name,
                         smgb_pattern_match* m) {
  if (!pattern || !name || !m) return 0;
  memset(m, 0, sizeof *m);
  return match_at(pattern, name, m);
}

int smgb_pattern_label(const char* tmpl, const smgb_pattern_match* m,
                       char* out, size_t size) {
  size_t n = 0;
  if (!tmpl || !m || !out || size == 0) return 0;
  while (*tmpl) {
    if (*tmpl == '{') {
      int c = tmpl[1] - '1';
      if (c < 0 || c >= m->count || tmpl[2] != '}') return 0;
      if (n + m->length[c] >= size) return 0;
      memcpy(out + n, m->start[c], m->length[c]);
      n += m->length[c];
      tmpl += 3;
    } else {
      if (*tmpl == '}' || n + 1 >= size) return 0;
      out[n++] = *tmpl++;
    }
  }
  out[n] = '\0';
  return 1;
}

static int name_cmp(const void* a, const void* b) {
  return strcmp((const char*)a, (const char*)b);
}

smg_result smgb_pattern_list(const char* dir, const char* pattern,
                             char (**names)[SMGB_PATTERN_NAME_MAX],
                             uint32_t* count, smgb_error* err) {
  DIR* d;
  struct dirent* e;
  char (*list)[SMGB_PATTERN_NAME_MAX] = NULL;
  uint32_t n = 0, cap = 0;
  *names = NULL;
  *count = 0;
  d = opendir(dir && *dir ? dir : ".");
  if (!d) {
    smgb_imp_errorf(err, "cannot read the folder '%s': %s",
                    dir && *dir ? dir : ".", strerror(errno));
    return SMG_ERROR_IO;
  }
  while ((e = readdir(d)) != NULL) {
    smgb_pattern_match m;
    char path[2048];
    struct stat st;
    if (e->d_name[0] == '.' || strlen(e->d_name) >= SMGB_PATTERN_NAME_MAX ||
        !smgb_pattern_matches(pattern, e->d_name, &m))
      continue;
    snprintf(path, sizeof path, "%s/%s", dir && *dir ? dir : ".", e->d_name);
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) continue;
    if (n == cap) {
      uint32_t nc = cap ? cap * 2u : 64u;
      char (*grown)[SMGB_PATTERN_NAME_MAX] = realloc(list, nc * sizeof *list);
      if (!grown) {
        free(list);
        closedir(d);
        smgb_imp_errorf(err, "out of memory listing '%s'", dir);
        return SMG_ERROR_OUT_OF_MEMORY;
      }
      list = grown;
      cap = nc;
    }
    snprintf(list[n++], SMGB_PATTERN_NAME_MAX, "%s", e->d_name);
  }
  closedir(d);
  /* readdir's order depends on the file system: sort for a reproducible
   * clip order (and so a reproducible blob) */
  if (n > 1) qsort(list, n, sizeof *list, name_cmp);
  *names = list;
  *count = n;
  return SMG_OK;
}
