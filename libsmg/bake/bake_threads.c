/*
 * bake_threads.c - run a stage's workers in parallel (bake_threads.h).
 */
#include "bake_threads.h"

#include <pthread.h>

#include "bake_options.h"

void smgb_run_workers(void* workers, size_t stride, uint32_t n,
                      void* (*run)(void*)) {
  pthread_t th[SMGB_MAX_THREADS];
  int started[SMGB_MAX_THREADS] = {0};
  char* base = (char*)workers;
  uint32_t t;
  for (t = 1; t < n && t < SMGB_MAX_THREADS; ++t)
    started[t] = pthread_create(&th[t], NULL, run, base + t * stride) == 0;
  if (n > 0) run(base);
  for (t = 1; t < n; ++t) {
    if (t < SMGB_MAX_THREADS && started[t])
      pthread_join(th[t], NULL);
    else
      run(base + t * stride);
  }
}
