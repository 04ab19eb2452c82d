/*
 * bake_report.c - progress and the list of problems of one bake
 * (bake_report.h).
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_report.h"

void smgb_report_init(smgb_report* r, smg_bake_progress_fn progress,
                      void* user) {
  memset(r, 0, sizeof *r);
  r->progress = progress;
  r->progress_user = user;
}

void smgb_report_free(smgb_report* r) {
  free(r->problems);
  memset(r, 0, sizeof *r);
}

static void record(smgb_report* r, smgb_problem_kind kind, const char* fmt,
                   va_list ap) {
  char text[512];
  size_t n = 0;
  if (r->place[0]) {
    snprintf(text, sizeof text, "%s: ", r->place);
    n = strlen(text);
  }
  vsnprintf(text + n, sizeof text - n, fmt, ap);
  if (kind == SMGB_PROBLEM_ERROR) {
    if (!r->error_count)
      memcpy(r->first_error, text, sizeof r->first_error);
    ++r->error_count;
  } else {
    ++r->warning_count;
  }
  if (r->problem_count == r->problem_cap) {
    uint32_t cap = r->problem_cap ? 2u * r->problem_cap : 8u;
    smgb_problem* p = realloc(r->problems, cap * sizeof *p);
    if (!p) {
      ++r->dropped;
      return;
    }
    r->problems = p;
    r->problem_cap = cap;
  }
  r->problems[r->problem_count].kind = kind;
  memcpy(r->problems[r->problem_count].text, text, sizeof text);
  ++r->problem_count;
}

void smgb_fail(smgb_report* r, const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  record(r, SMGB_PROBLEM_ERROR, fmt, ap);
  va_end(ap);
}

void smgb_warn(smgb_report* r, const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  record(r, SMGB_PROBLEM_WARNING, fmt, ap);
  va_end(ap);
}

void smgb_report_place(smgb_report* r, const char* place) {
  snprintf(r->place, sizeof r->place, "%s", place ? place : "");
}

void smgb_report_stage(smgb_report* r, const char* name) {
  r->stage = name;
  smgb_progress(r, 0.0f);
}

void smgb_progress(smgb_report* r, float fraction) {
  if (r->progress && r->stage) r->progress(r->stage, fraction, r->progress_user);
}

uint32_t smgb_report_mark(const smgb_report* r) { return r->problem_count; }

void smgb_report_rewind(smgb_report* r, uint32_t mark) {
  uint32_t i;
  if (mark >= r->problem_count) return;
  for (i = mark; i < r->problem_count; ++i) {
    if (r->problems[i].kind == SMGB_PROBLEM_ERROR)
      --r->error_count;
    else
      --r->warning_count;
  }
  r->problem_count = mark;
  /* the first error may have been dropped with the attempt */
  r->first_error[0] = '\0';
  for (i = 0; i < mark; ++i)
    if (r->problems[i].kind == SMGB_PROBLEM_ERROR) {
      memcpy(r->first_error, r->problems[i].text, sizeof r->first_error);
      break;
    }
}

const char* smgb_report_first_error(const smgb_report* r) {
  return r->first_error;
}

/* Line `i` ("error: ..." / "warning: ...") into out; its length. */
static int problem_line(const smgb_problem* p, char* out, size_t size) {
  return snprintf(out, size, "%s: %s\n",
                  p->kind == SMGB_PROBLEM_ERROR ? "error" : "warning",
                  p->text);
}

uint32_t smgb_report_text(const smgb_report* r, char* out, size_t size) {
  /* room kept for the last line saying how many did not fit */
  const size_t tail = 64;
  size_t used = 0;
  uint32_t i, shown = 0, lost = r->dropped;
  char line[600];
  if (!out || size == 0) return 0;
  out[0] = '\0';
  for (i = 0; i < r->problem_count; ++i) {
    size_t n = (size_t)problem_line(&r->problems[i], line, sizeof line);
    int last = i + 1 == r->problem_count && !lost;
    if (used + n + (last ? 0 : tail) >= size) {
      lost += r->problem_count - i;
      break;
    }
    memcpy(out + used, line, n + 1);
    used += n;
    ++shown;
  }
  if (lost && used + tail <= size)
    snprintf(out + used, size - used, "%u more problem(s) not shown\n", lost);
  return shown;
}
