/*
 * bake_threads.h - run a stage's workers in parallel (bake_threads.c).
 */
#ifndef SMGB_BAKE_THREADS_H
#define SMGB_BAKE_THREADS_H

#include <stddef.h>
#include <stdint.h>

/* Runs run(worker 0 .. n-1) to completion, where worker t is at
 * (char*)workers + t * stride: worker 0 on the calling thread, the others
 * on threads of their own. A thread that cannot be created has its worker
 * run on the calling thread afterwards, so a bake never fails for want of
 * threads; what each worker wrote is the same either way. n is at most
 * SMGB_MAX_THREADS (bake_options.h); more are run on the calling thread. */
void smgb_run_workers(void* workers, size_t stride, uint32_t n,
                      void* (*run)(void*));

#endif
