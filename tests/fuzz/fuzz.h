/*
 * fuzz.h - the contract between a fuzz target and the fuzz drivers.
 *
 * A target file tests/fuzz/fuzz_<name>.c defines:
 *   int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
 *       Feed one input to the code under test. Must never crash, leak or
 *       read outside [data, data + size), whatever the bytes. Returns 0.
 *   int fuzz_seed(uint8_t** data, size_t* size);
 *       Produce one valid input (malloc'ed; the driver frees it) from which
 *       mutations start. Returns 0 on success.
 *
 * The same target builds two ways (mk/fuzz.mk):
 *   build/fuzz/fuzz_<name>      with fuzz_driver.c: deterministic
 *                               mutation smoke run, part of `make test`
 *   make fuzz-<name>            a real libFuzzer + ASan/UBSan binary (clang)
 *                               seeded with fuzz_seed's output
 */
#ifndef SMG_TESTS_FUZZ_H
#define SMG_TESTS_FUZZ_H

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
int fuzz_seed(uint8_t** data, size_t* size);

#endif /* SMG_TESTS_FUZZ_H */
