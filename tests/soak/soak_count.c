/*
 * soak_count.c - instruction counts of the soak's steps through
 * callgrind's client requests (soak_count.h).
 */
#include "soak_count.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <valgrind/callgrind.h>

int soak_count_available(void) { return RUNNING_ON_VALGRIND ? 1 : 0; }

void soak_count_window_begin(void) {
  CALLGRIND_START_INSTRUMENTATION;
  CALLGRIND_ZERO_STATS;
}

void soak_count_on(void) { CALLGRIND_TOGGLE_COLLECT; }

void soak_count_off(void) { CALLGRIND_TOGGLE_COLLECT; }

int soak_count_window_end(soak_count* c, const char* label,
                          double* instructions) {
  char path[1024], line[256];
  FILE* f;
  int found = 0;
  CALLGRIND_DUMP_STATS_AT(label);
  CALLGRIND_STOP_INSTRUMENTATION;
  c->dumps++;
  snprintf(path, sizeof path, "%s.%u", c->out, c->dumps);
  f = fopen(path, "r");
  if (!f) {
    fprintf(stderr,
            "soak: cannot read callgrind's dump %s (run the soak under "
            "valgrind --tool=callgrind --callgrind-out-file=%s)\n",
            path, c->out);
    return 0;
  }
  /* "summary: <instructions>" (the only event collected: Ir) */
  while (fgets(line, sizeof line, f))
    if (strncmp(line, "summary:", 8) == 0) {
      *instructions = strtod(line + 8, NULL);
      found = 1;
    }
  fclose(f);
  if (!found) fprintf(stderr, "soak: no summary line in %s\n", path);
  return found;
}
