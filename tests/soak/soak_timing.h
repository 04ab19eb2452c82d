/*
 * soak_timing.h - the soak's step-time flatness measurement (--timing).
 *
 * Per frame, the thread CPU time of stepping every soak character once is
 * divided by the CPU time of a fixed reference workload run interleaved
 * with it in the same frame: the runtime's own steps, replayed. The
 * reference characters on the same graph follow a gently curving path;
 * after a warm-up their whole memory (every block their allocator handed
 * out) is saved, and every SOAK_REF_CYCLE steps it is restored in place,
 * so each one replays the same SOAK_REF_CYCLE steps - plain steps and
 * re-planning ones in the same proportions as in any stretch of motion -
 * over and over: the same instructions on the same data every cycle
 * (checked: the memory at the end of every cycle must equal the first
 * cycle's). There are as many as soak characters, so their memory competes
 * for the caches as the soak's does, and each is stepped once a frame,
 * as each soak character is, ten of them before each tenth of the soak's
 * characters: both see the same machine (clock speed, a busy sibling
 * core, caches shared with other processes) within a fraction of a
 * millisecond and the ratio cancels what the machine does to both. What the ratio keeps is
 * what differs between them: the soak characters' accumulated state. The
 * graph is read-only while stepping (make tsan), so a step that grows
 * slower over a run can only do so through its character's memory -
 * which the replay resets every cycle.
 *
 * A frame's soak time sums every character's step (a hundred in make
 * soak), so each frame already averages over the mix of plain and
 * re-planning steps; the flatness statistic is the lower quartile of the
 * per-frame ratio over a window (SOAK_TIMING_QUANTILE in soak_timing.c):
 * other processes only ever add time, not equally to both sides of a
 * ratio, so the frames they disturbed least compare best (measured: less
 * spread between runs than the median, docs/reliability.md).
 */
#ifndef SOAK_TIMING_H
#define SOAK_TIMING_H

#include <stddef.h>
#include <stdint.h>

#include "smg.h"

#define SOAK_REF_BLOCKS 4 /* allocations a character may make at create */

#define SOAK_REF_CYCLE 120 /* steps replayed: 2 s, a planning horizon */

typedef struct soak_replay {
  smg_character* ch;
  uint32_t blocks;
  void* block[SOAK_REF_BLOCKS];
  size_t size[SOAK_REF_BLOCKS];
  unsigned char* saved[SOAK_REF_BLOCKS];     /* at the start of a cycle */
  unsigned char* cycle_end[SOAK_REF_BLOCKS]; /* at the end of the first */
  uint32_t at;                               /* steps into the cycle */
  int has_cycled;
} soak_replay;

typedef struct soak_timing {
  soak_replay* ref;
  uint32_t refs, next; /* reference characters; the next one to step */
  uint32_t frames;
  double* step_seconds; /* per frame: all soak characters' steps */
  double* ref_seconds;  /* per frame: the interleaved reference steps */
  long diverged;        /* cycles that did not repeat the first one */
} soak_timing;

/* Thread CPU time, seconds: what other processes take is left out. */
double soak_cpu_seconds(void);

/* Creates and warms up `refs` reference characters on `graph` (as many
 * as the soak has: the same memory to keep in cache), room for `frames`
 * frames. 0 on failure (message printed). */
int soak_timing_init(soak_timing* t, smg_graph* graph,
                     const smg_graph_info* info, uint32_t refs,
                     uint32_t frames);

/* Steps the next n reference characters (in turn) once each, restoring
 * those at the end of their cycle first; returns the thread CPU seconds
 * of the steps. */
double soak_timing_reference_steps(soak_timing* t, uint32_t n);

/* Frame `frame` took `step` seconds for the soak characters and `ref`
 * seconds for its reference steps. */
void soak_timing_record(soak_timing* t, uint32_t frame, double step,
                        double ref);

/* SOAK_TIMING_QUANTILE of step / reference over the first and the last
 * 10 % of the frames. */
void soak_timing_windows(const soak_timing* t, double* first, double* last);

void soak_timing_free(soak_timing* t);

#endif /* SOAK_TIMING_H */
