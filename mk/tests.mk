# Tests: every tests/<part>/test_*.c is one cmocka program, linked against
# libsmg.a, libsmg_bake.a (when the baker exists), cmocka, assimp and libm.
# `make test-unit` runs them natively, `make test-valgrind` runs the same
# programs under valgrind (any error or leak fails). Tests that need the CMU
# clips read them from $(SMG_SHARED) and skip with a message when absent.
# Under valgrind SMG_TEST_QUICK=1 is set: heavy tests shrink their data.

SMG_SHARED ?= $(abspath ../shared)
TEST_SRC := $(sort $(wildcard tests/*/test_*.c))
TEST_BIN := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))
TEST_LIBS := $(LIBSMG_A) $(LIBSMG_BAKE_A)
TEST_LDLIBS := -lcmocka $(BAKE_LDLIBS) -lpthread -lm
VALGRIND := valgrind --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect,possible --show-leak-kinds=definite,indirect,possible -q

TEST_TARGETS += test-unit test-valgrind
ALL_TARGETS +=

$(BUILD)/tests/%: tests/%.c $(TEST_LIBS) $(LIB_HDR) $(wildcard tests/*.h tests/*/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -Itests -DSMG_SHARED_DIR='"$(SMG_SHARED)"' -DSMG_BUILD_DIR='"$(abspath $(BUILD))"' $< -o $@ $(TEST_LIBS) $(TEST_LDLIBS)

.PHONY: test-unit test-valgrind tests-build
tests-build: $(TEST_BIN)

test-unit: $(TEST_BIN)
	@set -e; for t in $(TEST_BIN); do echo "== $$t"; SMG_SHARED=$(SMG_SHARED) $$t; done

test-valgrind: $(TEST_BIN)
	@set -e; for t in $(TEST_BIN); do echo "== valgrind $$t"; SMG_SHARED=$(SMG_SHARED) SMG_TEST_QUICK=1 $(VALGRIND) $$t; done
