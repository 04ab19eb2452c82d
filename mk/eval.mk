# Evaluation (issue 7): the paper's Section IV reproduced on the CMU clips.
#
#   make eval       bakes the paper-size CMU set in-process, runs the runtime
#                   on five paths, measures splicing accuracy and upper/lower
#                   synchronisation, and writes docs/results.md plus
#                   docs/img/eval-*.svg (all produced by this run).
#   make eval-styles  the behaviour checks (section 2d) on one graph per
#                   performer style of the Bandai Namco scale set: performers
#                   the project was not tuned on (tools/eval/eval_styles.sh;
#                   not in `make test`, skips without the data)
#   make test-eval  (part of `make test`) a cheap subset with loose bounds;
#                   works without ../shared (the CMU parts are skipped with a
#                   message) and finishes well under two minutes.
#
# tools/eval/*.c except the driver form libsmg_eval.a (SVG plotting and the
# metrics), which the unit tests in tests/eval/ link as well.

SMG_SHARED ?= ../shared

EVAL_MAIN_SRC := tools/eval/smg_eval.c
EVAL_LIB_SRC := $(filter-out $(EVAL_MAIN_SRC),$(sort $(wildcard tools/eval/*.c)))
EVAL_LIB_OBJ := $(EVAL_LIB_SRC:%.c=$(BUILD)/obj/%.o)
EVAL_HDR := $(wildcard tools/eval/*.h)
LIBSMG_EVAL_A := $(BUILD)/libsmg_eval.a
SMG_EVAL := $(BUILD)/smg-eval
EVAL_CFLAGS := $(CFLAGS_TOOL) -Itools/eval

EVAL_TEST_SRC := $(sort $(wildcard tests/eval/test_*.c))
EVAL_TEST_BIN := $(patsubst tests/%.c,$(BUILD)/tests/%,$(EVAL_TEST_SRC))

ALL_TARGETS += $(SMG_EVAL)
TEST_TARGETS += test-eval

$(BUILD)/obj/tools/eval/%.o: tools/eval/%.c $(EVAL_HDR) $(LIB_HDR) $(BAKE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(EVAL_CFLAGS) -c $< -o $@

$(LIBSMG_EVAL_A): $(EVAL_LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

$(SMG_EVAL): $(EVAL_MAIN_SRC) $(LIBSMG_EVAL_A) $(LIBSMG_A) $(LIBSMG_BAKE_A) $(EVAL_HDR)
	$(CC) $(EVAL_CFLAGS) $< -o $@ $(LIBSMG_EVAL_A) $(LIBSMG_BAKE_A) $(LIBSMG_A) $(BAKE_LDLIBS) -lpthread -lm

# The eval unit tests also link libsmg_eval.a. A static pattern rule wins
# over the generic tests/%.c rule in mk/tests.mk for exactly these binaries.
$(EVAL_TEST_BIN): $(BUILD)/tests/eval/%: tests/eval/%.c $(LIBSMG_EVAL_A) $(LIBSMG_A) $(LIBSMG_BAKE_A) $(EVAL_HDR) $(wildcard tests/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(EVAL_CFLAGS) -Itests -DSMG_SHARED_DIR='"$(SMG_SHARED)"' -DSMG_BUILD_DIR='"$(BUILD)"' $< -o $@ $(LIBSMG_EVAL_A) $(LIBSMG_BAKE_A) $(LIBSMG_A) -lcmocka $(BAKE_LDLIBS) -lpthread -lm

.PHONY: eval eval-styles test-eval
eval: $(SMG_EVAL)
	$(SMG_EVAL) --shared $(SMG_SHARED) --out docs/results.md --img docs/img

eval-styles: $(SMG_EVAL)
	sh tools/eval/eval_styles.sh $(SMG_EVAL) $(SMG_SHARED) $(BUILD)

# build/default.smg (mk/tools.mk) is the synthetic graph checked when the
# CMU clips are absent (and in addition when they are present).
test-eval: $(SMG_EVAL) $(EVAL_TEST_BIN) $(BUILD)/default.smg
	@set -e; for t in $(EVAL_TEST_BIN); do echo "== $$t"; $$t; done
	SMG_SHARED=$(SMG_SHARED) $(SMG_EVAL) --check --shared $(SMG_SHARED) --default-blob $(BUILD)/default.smg
