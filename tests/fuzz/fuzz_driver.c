/*
 * fuzz_driver.c - a standalone main() for fuzz targets (see fuzz.h), so
 * every target runs in `make test` without clang or libFuzzer.
 *
 *   fuzz_x FILE...             run each file once (reproduce a crash)
 *   fuzz_x [-n N] [-s SEED] [-i FILE]
 *                              run the seed input (the target's, or FILE),
 *                              then N mutants of it
 *                              (with the target's own seed, its further
 *                              seeds run as they are first)
 *   fuzz_x --write-seed FILE   write the target's seed 0 (mutation start)
 *   fuzz_x --write-seeds DIR   write every seed as DIR/seed-K (corpus)
 *   fuzz_x [-s SEED] --dump K FILE
 *                              write mutant K (0-based) of that run to FILE
 *                              instead of running anything: reproduce a
 *                              smoke-run failure with `fuzz_x FILE`
 *
 * Mutants are deterministic for a given SEED: 1 to 4 stacked edits among
 * bit flips, byte overwrites with boundary values, aligned 32-bit
 * overwrites with boundary values (the blob's indices and counts are
 * 32-bit), truncation, chunk copies inside the input, chunk deletion and
 * insertion. Each mutant is handed to the target in a buffer of exactly
 * its size so valgrind/ASan see any read past the end. An input that runs
 * longer than -t seconds (default 20) is reported as a hang with the
 * command that reproduces it, and the run fails.
 */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fuzz.h"

static uint64_t g_rng;
/* for the hang report (read in the signal handler) */
static volatile long g_current = -1; /* mutant index, -1 = the seed/file */
static unsigned long g_seed_arg = 1;
static const char* g_argv0 = "fuzz";

static void put_str(const char* s) {
  ssize_t ignored = write(2, s, strlen(s));
  (void)ignored;
}

static void put_ulong(unsigned long v) {
  char buf[24];
  int i = 23;
  buf[i] = '\0';
  do {
    buf[--i] = (char)('0' + v % 10);
    v /= 10;
  } while (v && i > 0);
  put_str(buf + i);
}

static void on_alarm(int sig) {
  (void)sig;
  put_str("fuzz: HANG: input ");
  if (g_current < 0) {
    put_str("(seed or file)");
  } else {
    put_ulong((unsigned long)g_current);
    put_str(" did not finish; reproduce with:\n  ");
    put_str(g_argv0);
    put_str(" -s ");
    put_ulong(g_seed_arg);
    put_str(" --dump ");
    put_ulong((unsigned long)g_current);
    put_str(" hang.bin && ");
    put_str(g_argv0);
    put_str(" hang.bin");
  }
  put_str("\n");
  _exit(1);
}

static uint64_t next_u64(void) { /* splitmix64: tiny, good enough */
  uint64_t z = (g_rng += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

static size_t below(size_t n) { return n ? (size_t)(next_u64() % n) : 0; }

static const uint32_t k_interesting32[] = {
    0u,          1u,          2u,          15u,         16u,
    31u,         32u,         64u,         127u,        255u,
    0x7fffu,     0xffffu,     0x10000u,    0x7fffffffu, 0x80000000u,
    0xfffffffeu, 0xffffffffu, 0x7f800000u /* +inf */,  0xffc00000u /* nan */,
    0x3f800000u /* 1.0f */};
static const uint8_t k_interesting8[] = {0, 1, 0x7f, 0x80, 0xff, 0x10, 0x20};

/* Apply one random edit to buf[0..*len) (capacity cap). */
static void mutate_once(uint8_t* buf, size_t* len, size_t cap) {
  size_t n = *len;
  switch (below(8)) {
    case 0: /* bit flip */
    case 1:
      if (n) buf[below(n)] ^= (uint8_t)(1u << below(8));
      break;
    case 2: /* byte to a boundary value or random */
      if (n)
        buf[below(n)] = below(2) ? k_interesting8[below(sizeof k_interesting8)]
                                 : (uint8_t)next_u64();
      break;
    case 3: /* aligned 32-bit boundary value, or +-1 of the current one */
      if (n >= 4) {
        size_t at = below(n / 4) * 4;
        uint32_t v;
        if (below(2)) {
          v = k_interesting32[below(sizeof k_interesting32 / 4)];
        } else {
          memcpy(&v, buf + at, 4);
          v += below(2) ? 1u : 0xffffffffu;
        }
        memcpy(buf + at, &v, 4);
      }
      break;
    case 4: /* truncate */
      if (n) *len = below(n);
      break;
    case 5: /* copy a chunk over another place */
      if (n >= 2) {
        size_t src = below(n), dst = below(n), k = 1 + below(64);
        if (k > n - src) k = n - src;
        if (k > n - dst) k = n - dst;
        memmove(buf + dst, buf + src, k);
      }
      break;
    case 6: /* delete a chunk */
      if (n >= 2) {
        size_t at = below(n), k = 1 + below(64);
        if (k > n - at) k = n - at;
        memmove(buf + at, buf + at + k, n - at - k);
        *len = n - k;
      }
      break;
    default: /* insert a chunk of random or copied bytes */
      if (n < cap) {
        size_t at = below(n + 1), k = 1 + below(32), i;
        if (k > cap - n) k = cap - n;
        memmove(buf + at + k, buf + at, n - at);
        for (i = 0; i < k; ++i) buf[at + i] = (uint8_t)next_u64();
        *len = n + k;
      }
      break;
  }
}

static int run_exact(const uint8_t* data, size_t size) {
  /* exact-size copy: valgrind/ASan then catch any overread */
  uint8_t* copy = (uint8_t*)malloc(size ? size : 1);
  if (!copy) return 1;
  if (size) memcpy(copy, data, size);
  LLVMFuzzerTestOneInput(copy, size);
  free(copy);
  return 0;
}

/* The whole file, malloc'ed (freed by the caller). */
static int read_file(const char* path, uint8_t** out, size_t* out_size) {
  FILE* f = fopen(path, "rb");
  uint8_t* buf = NULL;
  size_t size = 0, cap = 0, got;
  if (!f) {
    fprintf(stderr, "fuzz: cannot open %s\n", path);
    return 1;
  }
  do {
    if (size == cap) {
      uint8_t* nb;
      cap = cap ? cap * 2 : 65536;
      nb = (uint8_t*)realloc(buf, cap);
      if (!nb) {
        free(buf);
        fclose(f);
        return 1;
      }
      buf = nb;
    }
    got = fread(buf + size, 1, cap - size, f);
    size += got;
  } while (got > 0);
  fclose(f);
  *out = buf;
  *out_size = size;
  return 0;
}

static int run_file(const char* path) {
  uint8_t* buf;
  size_t size;
  if (read_file(path, &buf, &size) != 0) return 1;
  run_exact(buf, size);
  free(buf);
  printf("fuzz: ran %s (%zu bytes)\n", path, size);
  return 0;
}

static int write_bytes(const char* path, const uint8_t* data, size_t size) {
  FILE* f = fopen(path, "wb");
  if (!f || fwrite(data, 1, size, f) != size) {
    fprintf(stderr, "fuzz: cannot write %s\n", path);
    if (f) fclose(f);
    return 1;
  }
  fclose(f);
  return 0;
}

static int write_seed(uint32_t index, const char* path) {
  uint8_t* seed = NULL;
  size_t size = 0;
  int rc;
  if (fuzz_seed(index, &seed, &size) != 0) {
    fprintf(stderr, "fuzz: the target could not make its seed %u\n",
            (unsigned)index);
    return 1;
  }
  rc = write_bytes(path, seed, size);
  free(seed);
  return rc;
}

/* Every seed of the target as DIR/seed-K (DIR is made if missing). */
static int write_seeds(const char* dir) {
  uint8_t* seed = NULL;
  size_t size = 0;
  uint32_t k;
  int got;
  char path[4096];
  if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
    fprintf(stderr, "fuzz: cannot make %s\n", dir);
    return 1;
  }
  for (k = 0; (got = fuzz_seed(k, &seed, &size)) == 0; ++k) {
    snprintf(path, sizeof path, "%s/seed-%u", dir, (unsigned)k);
    got = write_bytes(path, seed, size);
    free(seed);
    seed = NULL;
    if (got != 0) return 1;
  }
  if (got != FUZZ_SEED_NONE || k == 0) {
    fprintf(stderr, "fuzz: the target could not make its seed %u\n",
            (unsigned)k);
    return 1;
  }
  return 0;
}

/* The target's seeds after seed 0, each run as it is. */
static int run_further_seeds(void) {
  uint8_t* seed = NULL;
  size_t size = 0;
  uint32_t k;
  int got;
  for (k = 1; (got = fuzz_seed(k, &seed, &size)) == 0; ++k) {
    run_exact(seed, size);
    free(seed);
    seed = NULL;
  }
  if (got != FUZZ_SEED_NONE) {
    fprintf(stderr, "fuzz: the target could not make its seed %u\n",
            (unsigned)k);
    return 1;
  }
  return 0;
}

int main(int argc, char** argv) {
  unsigned long n = 1000, s = 1, i, dump_index = 0, timeout = 20;
  const char* dump_path = NULL;
  const char* seed_path = NULL;
  uint8_t *seed = NULL, *buf;
  size_t seed_size = 0, cap;
  int argi, files = 0, rc = 0;
  clock_t t0 = clock();

  g_argv0 = argv[0];
  signal(SIGALRM, on_alarm);

  for (argi = 1; argi < argc; ++argi) {
    if (strcmp(argv[argi], "-n") == 0 && argi + 1 < argc) {
      n = strtoul(argv[++argi], NULL, 10);
    } else if (strcmp(argv[argi], "-s") == 0 && argi + 1 < argc) {
      s = strtoul(argv[++argi], NULL, 10);
    } else if (strcmp(argv[argi], "-i") == 0 && argi + 1 < argc) {
      seed_path = argv[++argi];
    } else if (strcmp(argv[argi], "-t") == 0 && argi + 1 < argc) {
      timeout = strtoul(argv[++argi], NULL, 10);
    } else if (strcmp(argv[argi], "--write-seed") == 0 && argi + 1 < argc) {
      return write_seed(0, argv[++argi]);
    } else if (strcmp(argv[argi], "--write-seeds") == 0 && argi + 1 < argc) {
      return write_seeds(argv[++argi]);
    } else if (strcmp(argv[argi], "--dump") == 0 && argi + 2 < argc) {
      dump_index = strtoul(argv[++argi], NULL, 10);
      dump_path = argv[++argi];
      n = dump_index + 1;
    } else if (argv[argi][0] == '-') {
      fprintf(stderr,
              "usage: %s [-n MUTATIONS] [-s SEED] [-i SEED_FILE] [-t SECONDS] "
              "| FILE... | "
              "--write-seed FILE | --write-seeds DIR | [-s SEED] --dump K FILE\n",
              argv[0]);
      return 2;
    } else {
      alarm((unsigned)timeout);
      rc |= run_file(argv[argi]);
      alarm(0);
      ++files;
    }
  }
  if (files) return rc;

  if (seed_path ? read_file(seed_path, &seed, &seed_size) != 0
                : fuzz_seed(0, &seed, &seed_size) != 0) {
    fprintf(stderr, "fuzz: no seed (%s)\n",
            seed_path ? seed_path : "the target could not make one");
    return 1;
  }
  g_rng = 0x5eed0000ull + s;
  g_seed_arg = s;
  cap = seed_size * 2 + 256;
  buf = (uint8_t*)malloc(cap);
  if (!buf) {
    free(seed);
    return 1;
  }
  if (!dump_path) {
    alarm((unsigned)timeout);
    run_exact(seed, seed_size);
    if (!seed_path && run_further_seeds() != 0) {
      free(buf);
      free(seed);
      return 1;
    }
  }
  for (i = 0; i < n; ++i) {
    size_t len = seed_size, k, edits = 1 + below(4);
    memcpy(buf, seed, seed_size);
    for (k = 0; k < edits; ++k) mutate_once(buf, &len, cap);
    if (dump_path) {
      if (i < dump_index) continue;
      rc = write_bytes(dump_path, buf, len);
      free(buf);
      free(seed);
      return rc;
    }
    g_current = (long)i;
    alarm((unsigned)timeout); /* re-armed per input */
    run_exact(buf, len);
  }
  alarm(0);
  printf("fuzz: %s: seed (%zu bytes) + %lu mutants (seed %lu) in %.2f s\n",
         argv[0], seed_size, n, s,
         (double)(clock() - t0) / CLOCKS_PER_SEC);
  free(buf);
  free(seed);
  return 0;
}
