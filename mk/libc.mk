# The same bits under another C library (tests/libc/run_cross_libc.sh):
# the host's smg-bake and smg-synth are run again with the C library of the
# Debian sid root the Godot tests provision (newer glibc, other rounding in
# its float math), and blobs and BVH output must be byte-identical.
#
#   make test-cross-libc   (part of `make test`)

TEST_TARGETS += test-cross-libc
.PHONY: test-cross-libc

# (the baker, smg-synth and the synthetic clips are defined in fragments
# read after this one: named by path here; GODOT_BIN is godot.mk's)
test-cross-libc: $(BUILD)/smg-bake $(BUILD)/smg-synth $(BUILD)/synthetic/README.txt $(GODOT_BIN)
	@sh tests/libc/run_cross_libc.sh $(SMG_GODOT_ROOT) $(BUILD)
