# Fuzz targets: tests/fuzz/fuzz_<name>.c (see tests/fuzz/fuzz.h).
#   blob      graph-blob reader, graph load, a character on what loads
#   bvh       BVH reader and the clip operations after it
#   manifest  manifest parser and its bake descriptors
#   runtime   input bytes drive character calls on a loaded graph
#   assimp    glTF/GLB/FBX import through assimp
#
#   make test-fuzz    (part of `make test`) each target with the standalone
#                     driver: every committed input (tests/fuzz/corpus/<name>,
#                     tests/fuzz/regress/<name>) and every generated seed
#                     (fuzz_seed: built by the target, never committed),
#                     then seed 0 +
#                     FUZZ_SMOKE_RUNS deterministic mutants natively and
#                     FUZZ_VALGRIND_RUNS of them under valgrind (per-target
#                     counts below keep the slow targets' share small).
#   make fuzz-<name>  build build/libfuzzer/fuzz_<name> with clang's
#                     libFuzzer + ASan/UBSan and run it for FUZZ_SECONDS
#                     (default 60) on build/libfuzzer/corpus-<name>, seeded
#                     with the target's seeds and the committed inputs.
#                     Needs clang; clang is optional for everything else.
#                     Extra libFuzzer flags: FUZZ_ARGS="-jobs=2 ...".
# A campaign and its record: docs/reliability.md. Every finding gets its
# input committed in tests/fuzz/regress/<name>/ so test-fuzz replays it
# forever. fuzz-assimp keeps running past files that crash assimp itself:
# smgb_assimp_load reads each file in a child process first (also in the
# libFuzzer build), the target counts such inputs and prints the count at
# exit; an out-of-memory report of libFuzzer from that child (an
# assimp-oom-* artifact) is assimp's own allocation, and the file is
# refused.

FUZZ_TARGET_SRC := $(sort $(filter-out tests/fuzz/fuzz_driver.c,$(wildcard tests/fuzz/fuzz_*.c)))
FUZZ_NAMES := $(patsubst tests/fuzz/fuzz_%.c,%,$(FUZZ_TARGET_SRC))
FUZZ_BIN := $(patsubst tests/fuzz/%.c,$(BUILD)/fuzz/%,$(FUZZ_TARGET_SRC))
FUZZ_SMOKE_RUNS ?= 20000
FUZZ_VALGRIND_RUNS ?= 1000
# file-backed, assimp-backed and real-size (bvh, 75 KB) inputs cost up to
# ~1 ms each natively
FUZZ_SMOKE_RUNS_assimp := 2000
FUZZ_VALGRIND_RUNS_assimp := 30
FUZZ_SMOKE_RUNS_manifest := 5000
FUZZ_VALGRIND_RUNS_manifest := 200
FUZZ_SMOKE_RUNS_bvh := 5000
FUZZ_VALGRIND_RUNS_bvh := 100
FUZZ_VALGRIND_RUNS_runtime := 300
# Under valgrind the seed comes from a file the native binary wrote: the
# assimp seed is made with assimp's exporter, which writes uninitialised
# padding. assimp's own leaks on refused files: tests/fuzz/assimp.supp.
FUZZ_VALGRIND_SUPP_assimp := --suppressions=tests/fuzz/assimp.supp
FUZZ_LSAN_assimp := LSAN_OPTIONS=suppressions=$(CURDIR)/tests/fuzz/lsan-assimp.supp
# libFuzzer's largest input: real clips are up to ~2 MB of BVH text
FUZZ_MAX_LEN_bvh := 2097152
FUZZ_MAX_LEN_assimp := 1048576
FUZZ_MAX_LEN_manifest := 16384
FUZZ_MAX_LEN_runtime := 4096
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

# the committed inputs of one target (corpus and regressions)
fuzz_inputs = $(wildcard tests/fuzz/corpus/$(1)/* tests/fuzz/regress/$(1)/*)

.PHONY: test-fuzz
test-fuzz: $(FUZZ_BIN)
	@set -e; $(foreach n,$(FUZZ_NAMES), \
	  $(if $(call fuzz_inputs,$(n)),$(BUILD)/fuzz/fuzz_$(n) $(call fuzz_inputs,$(n)) >/dev/null;) \
	  $(if $(call fuzz_inputs,$(n)),$(VALGRIND) $(FUZZ_VALGRIND_SUPP_$(n)) $(BUILD)/fuzz/fuzz_$(n) $(call fuzz_inputs,$(n)) >/dev/null;) \
	  $(BUILD)/fuzz/fuzz_$(n) -n $(or $(FUZZ_SMOKE_RUNS_$(n)),$(FUZZ_SMOKE_RUNS)); \
	  rm -rf $(BUILD)/fuzz/seeds-$(n); \
	  $(BUILD)/fuzz/fuzz_$(n) --write-seeds $(BUILD)/fuzz/seeds-$(n); \
	  set -- $(BUILD)/fuzz/seeds-$(n)/seed-[1-9]*; \
	  if [ -e "$$1" ]; then $(VALGRIND) $(FUZZ_VALGRIND_SUPP_$(n)) $(BUILD)/fuzz/fuzz_$(n) "$$@" >/dev/null; fi; \
	  $(VALGRIND) $(FUZZ_VALGRIND_SUPP_$(n)) $(BUILD)/fuzz/fuzz_$(n) -i $(BUILD)/fuzz/seeds-$(n)/seed-0 -n $(or $(FUZZ_VALGRIND_RUNS_$(n)),$(FUZZ_VALGRIND_RUNS)) -s 2;)

# libFuzzer build: compile the library sources together with the target
# under the sanitizers (the normal objects are not instrumented; assimp,
# a system library, is not instrumented either).
$(BUILD)/libfuzzer/fuzz_%: tests/fuzz/fuzz_%.c $(LIB_SRC) $(BAKE_SRC) $(LIB_HDR) $(BAKE_HDR) $(wildcard tests/*.h)
	@command -v $(CLANG) >/dev/null || { echo "make fuzz-$*: needs clang (apt-get install clang); the standalone smoke run is make test-fuzz" >&2; exit 1; }
	@mkdir -p $(dir $@)
	$(CLANG) -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all $(CPPFLAGS_COMMON) -Ilibsmg/runtime -Ilibsmg/bake -Itests -Itests/fuzz \
	  $< $(LIB_SRC) $(if $(filter fuzz_blob fuzz_runtime,fuzz_$*),,$(BAKE_SRC) $(BAKE_LDLIBS) -lpthread) -lm -o $@

fuzz-%: $(BUILD)/libfuzzer/fuzz_% $(BUILD)/fuzz/fuzz_%
	@mkdir -p $(BUILD)/libfuzzer/corpus-$*
	$(BUILD)/fuzz/fuzz_$* --write-seeds $(BUILD)/libfuzzer/corpus-$*
	$(if $(call fuzz_inputs,$*),cp $(call fuzz_inputs,$*) $(BUILD)/libfuzzer/corpus-$*/)
	$(FUZZ_LSAN_$*) $(BUILD)/libfuzzer/fuzz_$* -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	  -artifact_prefix=$(BUILD)/libfuzzer/$*- \
	  $(if $(FUZZ_MAX_LEN_$*),-max_len=$(FUZZ_MAX_LEN_$*)) $(FUZZ_ARGS) $(BUILD)/libfuzzer/corpus-$*

# keep the libFuzzer binary between runs (it is an intermediate of fuzz-%)
.PRECIOUS: $(BUILD)/libfuzzer/fuzz_% $(BUILD)/fuzz/%
