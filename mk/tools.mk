# Baker CLI (smg-bake), the default blob baked from the synthetic clips, and
# the baker benchmark (`make bench-bake`).

SMG_BAKE := $(BUILD)/smg-bake
DEFAULT_BLOB := $(BUILD)/default.smg

ALL_TARGETS += $(SMG_BAKE) $(DEFAULT_BLOB)

$(SMG_BAKE): tools/smg_bake.c $(LIBSMG_BAKE_A) $(LIBSMG_A) $(LIB_HDR) $(BAKE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) $< -o $@ $(LIBSMG_BAKE_A) $(LIBSMG_A) $(BAKE_LDLIBS) -lpthread $(LDLIBS_M)

# The synthetic clips come from build/smg-gen-clips (mk/import.mk).
$(DEFAULT_BLOB): $(SMG_BAKE) $(SYNTHETIC_STAMP) data/synthetic.manifest
	$(SMG_BAKE) -q -m data/synthetic.manifest --data-dir $(SYNTHETIC_DIR) -o $@

# Baker benchmark (part of `make bench`): paper-size CMU set per stage
# beside the paper's times, a direct-evaluation baseline, all clips.
BENCH_BAKE := $(BUILD)/bench/bench_bake
BENCH_TARGETS += bench-bake

$(BENCH_BAKE): bench/bench_bake.c $(LIBSMG_BAKE_A) $(LIBSMG_A) $(LIB_HDR) $(BAKE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -DSMG_SHARED_DIR='"$(SMG_SHARED)"' $< -o $@ $(LIBSMG_BAKE_A) $(LIBSMG_A) $(BAKE_LDLIBS) -lpthread $(LDLIBS_M)

.PHONY: bench-bake
bench-bake: $(BENCH_BAKE)
	SMG_SHARED=$(SMG_SHARED) $(BENCH_BAKE)

# The paper-size CMU blob (build/cmu.smg) when ../shared holds the clips:
# the demo, eval and runtime tests use it for real figures.
CMU_BLOB := $(BUILD)/cmu.smg
.PHONY: cmu-blob
cmu-blob: $(CMU_BLOB)
$(CMU_BLOB): $(SMG_BAKE) data/cmu.manifest
	$(SMG_BAKE) -q -m data/cmu.manifest --data-dir $(SMG_SHARED)/mocap/cmu -o $@
ifneq ($(wildcard $(SMG_SHARED)/mocap/cmu/09_12.bvh),)
ALL_TARGETS += $(CMU_BLOB)
endif
