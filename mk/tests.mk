# Tests: every tests/<part>/test_*.c is one cmocka program, linked against
# libsmg.a, libsmg_bake.a (when the baker exists), cmocka, assimp and libm.
# `make test-unit` runs them natively, `make test-valgrind` runs the same
# programs under valgrind (any error or leak fails). Tests that need the CMU
# clips read them from $(SMG_SHARED) and skip with a message when absent.
# Under valgrind SMG_TEST_QUICK=1 is set: heavy tests shrink their data.
#
# ABI and packaging checks (tests/abi/):
#   test-symbols   libsmg.so exports only smg_* and every smg.h function
#   test-header    smg.h compiles as strict C99 and C++11 and links from C++
#   test-install   make install into a temp prefix, consumer via pkg-config
# Not part of `make test` (slower, rebuilds everything):
#   make sanitize  unit tests built and run with -fsanitize=address,undefined

# Relative paths (no machine paths compiled in): make runs the tests from
# the repository root.
SMG_SHARED ?= ../shared
TEST_SRC := $(sort $(wildcard tests/*/test_*.c))
TEST_BIN := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))
# the baker library uses the blob writer in libsmg.a: list it first
TEST_LIBS := $(LIBSMG_BAKE_A) $(LIBSMG_A)
TEST_LDLIBS := -lcmocka $(BAKE_LDLIBS) -lpthread -lm
VALGRIND := valgrind --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect,possible --show-leak-kinds=definite,indirect,possible -q

TEST_TARGETS += test-unit test-valgrind test-symbols test-header test-install
ALL_TARGETS +=

$(BUILD)/tests/%: tests/%.c $(TEST_LIBS) $(LIB_HDR) $(wildcard tests/*.h tests/*/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -Itests -DSMG_SHARED_DIR='"$(SMG_SHARED)"' -DSMG_BUILD_DIR='"$(BUILD)"' $< -o $@ $(TEST_LIBS) $(TEST_LDLIBS)

.PHONY: test-unit test-valgrind tests-build test-symbols test-header test-install sanitize
tests-build: $(TEST_BIN)

test-unit: $(TEST_BIN)
	@set -e; for t in $(TEST_BIN); do echo "== $$t"; SMG_SHARED=$(SMG_SHARED) $$t; done

test-valgrind: $(TEST_BIN)
	@set -e; for t in $(TEST_BIN); do echo "== valgrind $$t"; SMG_SHARED=$(SMG_SHARED) SMG_TEST_QUICK=1 $(VALGRIND) $$t; done

test-symbols: $(LIBSMG_SO)
	@sh tests/abi/check_symbols.sh $(LIBSMG_SO) include/smg.h

HEADER_WARN := -Wall -Wextra -Wpedantic -Werror
test-header: $(LIBSMG_A)
	@mkdir -p $(BUILD)/tests/abi
	$(CC) -std=c99 $(HEADER_WARN) -Iinclude tests/abi/header_check.c -o $(BUILD)/tests/abi/header_c $(LIBSMG_A) -lm
	$(CXX) -std=c++11 $(HEADER_WARN) -Iinclude -x c++ tests/abi/header_check.c -x none -o $(BUILD)/tests/abi/header_cxx $(LIBSMG_A) -lm
	@$(BUILD)/tests/abi/header_c
	@$(BUILD)/tests/abi/header_cxx

# the baker parts come from later fragments (tools.mk, runtime.mk): by name
test-install: $(LIBSMG_A) $(LIBSMG_SO) $(LIBSMG_BAKE_A) $(BUILD)/smg-bake $(BUILD)/smg-synth $(BUILD)/synthetic/README.txt
	@sh tests/abi/check_install.sh "$(MAKE)" "$(BUILD)" "$(CC)"

# Unit tests under AddressSanitizer + UBSan, in their own build tree.
SANITIZE_FLAGS := -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
# The unit tests also read the default blob and run smg-synth from their
# build directory: make those in the sanitizer build too.
sanitize:
	$(MAKE) --no-print-directory BUILD=$(BUILD)/sanitize OPT="$(SANITIZE_FLAGS)" \
	  $(BUILD)/sanitize/default.smg $(BUILD)/sanitize/smg-synth test-unit

# Graph load cost vs a memcpy baseline, on the default blob when it exists.
BENCH_TARGETS += bench-load
.PHONY: bench-load
$(BUILD)/tests/core/bench_load: tests/core/bench_load.c $(LIBSMG_A) $(LIB_HDR) tests/fixture_graph.h
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -Itests $< -o $@ $(LIBSMG_A) -lm
bench-load: $(BUILD)/tests/core/bench_load
	@$(BUILD)/tests/core/bench_load
	@if [ -f $(BUILD)/default.smg ]; then $(BUILD)/tests/core/bench_load $(BUILD)/default.smg; fi
