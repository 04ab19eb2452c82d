/*
 * fuzz.h - the contract between a fuzz target and the fuzz drivers.
 *
 * A target file tests/fuzz/fuzz_<name>.c defines:
 *   int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
 *       Feed one input to the code under test. Must never crash, leak or
 *       read outside [data, data + size), whatever the bytes. Returns 0.
 *   int fuzz_seed(uint32_t index, uint8_t** data, size_t* size);
 *       Produce valid input number `index` (malloc'ed; the driver frees
 *       it). Seed 0 is where mutations start; a target may have more
 *       (seeds 1, 2, ...: shapes seed 0 does not cover), each run as it is
 *       and given to libFuzzer as corpus. Returns 0 on success,
 *       FUZZ_SEED_NONE when the target has no seed `index` (the seeds are
 *       numbered without gaps), -1 when it could not make it.
 *
 * The same target builds two ways (mk/fuzz.mk):
 *   build/fuzz/fuzz_<name>      with fuzz_driver.c: deterministic
 *                               mutation smoke run, part of `make test`
 *   make fuzz-<name>            a real libFuzzer + ASan/UBSan binary (clang)
 *                               seeded with fuzz_seed's outputs
 * Seeds are generated, not committed: tests/fuzz/corpus/ holds only
 * inputs no generator makes, tests/fuzz/regress/ the findings.
 */
#ifndef SMG_TESTS_FUZZ_H
#define SMG_TESTS_FUZZ_H

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
#define FUZZ_SEED_NONE 1
int fuzz_seed(uint32_t index, uint8_t** data, size_t* size);

#endif /* SMG_TESTS_FUZZ_H */
