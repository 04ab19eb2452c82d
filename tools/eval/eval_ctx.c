/*
 * eval_ctx.c - report and check helpers shared by the evaluation sections.
 */
#include "eval_ctx.h"

#include <math.h>
#include <stdarg.h>
#include <string.h>
#include <time.h>

void eval_md(eval_ctx* ctx, const char* fmt, ...) {
  va_list ap;
  if (!ctx || !ctx->md) return;
  va_start(ap, fmt);
  vfprintf(ctx->md, fmt, ap);
  va_end(ap);
}

void eval_summary(eval_ctx* ctx, const char* fmt, ...) {
  va_list ap;
  if (!ctx || !ctx->summary) return;
  fputs("- ", ctx->summary);
  va_start(ap, fmt);
  vfprintf(ctx->summary, fmt, ap);
  va_end(ap);
  fputc('\n', ctx->summary);
}

int eval_check(eval_ctx* ctx, int ok, const char* fmt, ...) {
  va_list ap;
  fprintf(stdout, "%s ", ok ? "PASS" : "FAIL");
  va_start(ap, fmt);
  vfprintf(stdout, fmt, ap);
  va_end(ap);
  fputc('\n', stdout);
  fflush(stdout);
  if (!ok && ctx) ctx->failures++;
  return ok;
}

void eval_log(const char* fmt, ...) {
  va_list ap;
  fputs("smg-eval: ", stderr);
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fputc('\n', stderr);
}

void eval_img_path(const eval_ctx* ctx, const char* name, char* buf,
                   size_t size) {
  snprintf(buf, size, "%s/%s", ctx && ctx->img_dir ? ctx->img_dir : ".",
           name);
}

double eval_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void eval_cmu_clip(const eval_ctx* ctx, const char* id, char* buf,
                   size_t size) {
  snprintf(buf, size, "%s/%s.bvh", ctx->cmu_dir, id);
}

const char* eval_fmt(char* buf, size_t size, const char* fmt, double v) {
  if (!isfinite(v))
    snprintf(buf, size, "n/a");
  else
    snprintf(buf, size, fmt, v);
  return buf;
}
