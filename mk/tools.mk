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
