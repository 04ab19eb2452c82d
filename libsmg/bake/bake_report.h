/*
 * bake_report.h - what a bake tells its caller while it runs: progress per
 * stage, and every problem it meets.
 *
 * Every stage may record problems here; none needs the stage driver for
 * it. A problem is an error (the bake fails) or a warning (it goes on),
 * one line each, naming the file and the place when there is one. All of
 * them are kept, in the order they were met, so one run can report every
 * broken clip and option at once; the first error is the one a caller
 * that shows a single line sees.
 *
 * smgb_error is the one-message buffer of the functions that also run
 * outside a bake (importers, roles, retargeting; tests and tools call
 * them directly).
 */
#ifndef BAKE_REPORT_H
#define BAKE_REPORT_H

#include <stddef.h>
#include <stdint.h>

#include "printf_check.h"
#include "smg_bake.h"

/* Error detail filled by failing importers: file, line and problem. */
typedef struct smgb_error {
  char message[512];
} smgb_error;

typedef enum smgb_problem_kind {
  SMGB_PROBLEM_ERROR = 0,
  SMGB_PROBLEM_WARNING
} smgb_problem_kind;

typedef struct smgb_problem {
  smgb_problem_kind kind;
  char text[512];
} smgb_problem;

typedef struct smgb_report {
  smg_bake_progress_fn progress; /* optional */
  void* progress_user;
  const char* stage;             /* static name of the running stage */
  char place[256];               /* prefix of problems recorded now */
  smgb_problem* problems;
  uint32_t problem_count, problem_cap;
  uint32_t error_count, warning_count;
  uint32_t dropped;              /* problems lost to a failed allocation */
  char first_error[512];         /* kept even when storing one failed */
} smgb_report;

void smgb_report_init(smgb_report* r, smg_bake_progress_fn progress,
                      void* user);
void smgb_report_free(smgb_report* r);

/* Record an error / a warning (printf format). */
void smgb_fail(smgb_report* r, const char* fmt, ...)
    SMG_PRINTF_CHECK(2, 3)
    ;
void smgb_warn(smgb_report* r, const char* fmt, ...)
    SMG_PRINTF_CHECK(2, 3)
    ;

/* Problems recorded from now on start with "PLACE: " (e.g. "clip 3
 * (manifest line 7) (walk.bvh)"); NULL or "" clears it. */
void smgb_report_place(smgb_report* r, const char* place);

/* Start stage `name` (a static string) at fraction 0. */
void smgb_report_stage(smgb_report* r, const char* name);
/* Progress within the running stage, fraction in [0, 1]. */
void smgb_progress(smgb_report* r, float fraction);

/* A step that is retried drops what its failed attempt recorded: take a
 * mark before it, rewind to the mark before the retry. */
uint32_t smgb_report_mark(const smgb_report* r);
void smgb_report_rewind(smgb_report* r, uint32_t mark);

/* The first error, "" when there is none. */
const char* smgb_report_first_error(const smgb_report* r);

/* The problems, one per line ("error: ..." / "warning: ..."), into `out`
 * (NUL-terminated): whole lines while they fit in `size`, then one line
 * saying how many more there were. Returns the number of problems
 * written. */
uint32_t smgb_report_text(const smgb_report* r, char* out, size_t size);

#endif /* BAKE_REPORT_H */
