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
