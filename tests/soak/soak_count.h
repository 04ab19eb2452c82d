/*
 * soak_count.h - the soak's growth check (--instructions): the
 * instructions the soak characters' steps execute in the first and in the
 * last window of the timed steps, counted by callgrind. The soak must run
 * under
 *
 *   valgrind --tool=callgrind --instr-atstart=no --collect-atstart=no \
 *            --callgrind-out-file=OUT soak --instructions OUT ...
 *
 * Callgrind instruments only the two windows (the rest runs at
 * valgrind's plain speed) and collects only inside the steps; at the end
 * of each window it dumps its counts to OUT.<n>, which the soak reads
 * back. An instruction count is a property of the code and the data
 * alone: other processes on a shared machine, clock changes and caches
 * cannot move it, so two runs of one seed give the same counts. What it
 * does not see is a step that gets slower without executing more
 * instructions (more cache misses from a growing working set); the
 * runtime allocates nothing after create (the soak checks that), so a
 * character's memory cannot grow.
 */
#ifndef SOAK_COUNT_H
#define SOAK_COUNT_H

#include <stdint.h>

typedef struct soak_count {
  const char* out; /* callgrind's --callgrind-out-file */
  uint32_t dumps;  /* dumps written so far: callgrind numbers them 1, 2.. */
} soak_count;

/* 1 when running under valgrind (else the client requests do nothing). */
int soak_count_available(void);
/* A window starts: instrument, counts from zero. */
void soak_count_window_begin(void);
/* Count what runs between these two (the steps). */
void soak_count_on(void);
void soak_count_off(void);
/* The window ends: dump, stop instrumenting, read the count back into
 * *instructions. 0 when the dump cannot be read (message printed). */
int soak_count_window_end(soak_count* c, const char* label,
                          double* instructions);

#endif /* SOAK_COUNT_H */
