# Fuzz targets: tests/fuzz/fuzz_<name>.c (see tests/fuzz/fuzz.h).
#
#   make test-fuzz    (part of `make test`) each target with the standalone
#                     driver: seed + FUZZ_SMOKE_RUNS deterministic mutants
#                     natively, FUZZ_VALGRIND_RUNS of them under valgrind.
#   make fuzz-<name>  build build/libfuzzer/fuzz_<name> with clang's
#                     libFuzzer + ASan/UBSan and run it for FUZZ_SECONDS
#                     (default 60) on a corpus seeded by the target
#                     (build/libfuzzer/corpus-<name>). Needs clang; clang is
#                     optional for everything else. Extra libFuzzer flags:
#                     FUZZ_ARGS="-jobs=2 ...".

FUZZ_TARGET_SRC := $(sort $(filter-out tests/fuzz/fuzz_driver.c,$(wildcard tests/fuzz/fuzz_*.c)))
FUZZ_BIN := $(patsubst tests/fuzz/%.c,$(BUILD)/fuzz/%,$(FUZZ_TARGET_SRC))
FUZZ_SMOKE_RUNS ?= 20000
FUZZ_VALGRIND_RUNS ?= 1000
FUZZ_SECONDS ?= 60
FUZZ_ARGS ?=
CLANG ?= clang
FUZZ_CFLAGS := $(CFLAGS_TOOL) -Itests -Itests/fuzz

TEST_TARGETS += test-fuzz

# (libraries named directly: tests.mk, which defines TEST_LIBS, is read later)
FUZZ_LIBS := $(LIBSMG_A) $(LIBSMG_BAKE_A)
$(BUILD)/fuzz/%: tests/fuzz/%.c tests/fuzz/fuzz_driver.c tests/fuzz/fuzz.h $(FUZZ_LIBS) $(LIB_HDR) $(wildcard tests/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(FUZZ_CFLAGS) $< tests/fuzz/fuzz_driver.c -o $@ $(FUZZ_LIBS) $(BAKE_LDLIBS) -lpthread -lm

.PHONY: test-fuzz
test-fuzz: $(FUZZ_BIN)
	@set -e; for t in $(FUZZ_BIN); do \
	  $$t -n $(FUZZ_SMOKE_RUNS); \
	  $(VALGRIND) $$t -n $(FUZZ_VALGRIND_RUNS) -s 2; \
	done

# libFuzzer build: compile the library sources together with the target
# under the sanitizers (the normal objects are not instrumented).
$(BUILD)/libfuzzer/fuzz_%: tests/fuzz/fuzz_%.c $(LIB_SRC) $(BAKE_SRC) $(LIB_HDR) $(BAKE_HDR)
	@command -v $(CLANG) >/dev/null || { echo "make fuzz-$*: needs clang (apt-get install clang); the standalone smoke run is make test-fuzz" >&2; exit 1; }
	@mkdir -p $(dir $@)
	$(CLANG) -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all $(CPPFLAGS_COMMON) -Ilibsmg/runtime -Ilibsmg/bake -Itests -Itests/fuzz \
	  $< $(LIB_SRC) $(if $(filter fuzz_blob,fuzz_$*),,$(BAKE_SRC) $(BAKE_LDLIBS) -lpthread) -lm -o $@

fuzz-%: $(BUILD)/libfuzzer/fuzz_% $(BUILD)/fuzz/fuzz_%
	@mkdir -p $(BUILD)/libfuzzer/corpus-$*
	$(BUILD)/fuzz/fuzz_$* --write-seed $(BUILD)/libfuzzer/corpus-$*/seed
	$(BUILD)/libfuzzer/fuzz_$* -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 $(FUZZ_ARGS) $(BUILD)/libfuzzer/corpus-$*

# keep the libFuzzer binary between runs (it is an intermediate of fuzz-%)
.PRECIOUS: $(BUILD)/libfuzzer/fuzz_% $(BUILD)/fuzz/%
