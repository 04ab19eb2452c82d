# Baker import part: the synthetic clip generator CLI, the synthetic clip
# folder `make` bakes the default blob from, and the deterministic BVH fuzz
# smoke run by `make test`.

SMG_GEN_CLIPS := $(BUILD)/smg-gen-clips
SYNTHETIC_DIR := $(BUILD)/synthetic
SYNTHETIC_STAMP := $(SYNTHETIC_DIR)/README.txt

ALL_TARGETS += $(SMG_GEN_CLIPS) $(SYNTHETIC_STAMP)

$(SMG_GEN_CLIPS): tools/smg_gen_clips.c $(LIBSMG_BAKE_A) $(LIBSMG_A) $(LIB_HDR) $(BAKE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) $< -o $@ $(LIBSMG_BAKE_A) $(LIBSMG_A) $(BAKE_LDLIBS) $(LDLIBS_M)

# The clips depend only on the generator; README.txt is written last.
$(SYNTHETIC_STAMP): $(SMG_GEN_CLIPS)
	$(SMG_GEN_CLIPS) $(SYNTHETIC_DIR)

.PHONY: synthetic-clips
synthetic-clips: $(SYNTHETIC_STAMP)

# Import benchmark (part of `make bench`): BVH parse vs a read+scan
# baseline, resample, mirror, synthetic generation.
BENCH_IMPORT := $(BUILD)/bench/bench_import
BENCH_TARGETS += bench-import

$(BENCH_IMPORT): bench/bench_import.c $(LIBSMG_BAKE_A) $(LIBSMG_A) $(LIB_HDR) $(BAKE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -DSMG_SHARED_DIR='"$(SMG_SHARED)"' $< -o $@ $(LIBSMG_BAKE_A) $(LIBSMG_A) $(BAKE_LDLIBS) $(LDLIBS_M)

.PHONY: bench-import
bench-import: $(BENCH_IMPORT)
	SMG_SHARED=$(SMG_SHARED) $(BENCH_IMPORT)
