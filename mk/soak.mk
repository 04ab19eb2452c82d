# Soak (tests/soak/soak.c): many characters, many frames, random use, with
# checks on every character-frame (finite, no root jump beyond the data's
# fastest motion, bounded path error, no allocation after create).
#
#   make soak       first proves the step-time check live: a short timed
#                   run whose stepping work grows by SOAK_GROW (50 %) by
#                   its end must be caught (--grow); then 100 characters
#                   x 10^4 timed steps on build/default.smg and, when
#                   ../shared holds the CMU clips, build/cmu.smg (10^6
#                   character-frames each, after 600 settling steps),
#                   with the step-time flatness check (--timing,
#                   tests/soak/soak_timing.c). Minutes; not in make test.
#   make test-soak  (part of `make test`) 10 characters x 10^3 steps
#                   (10^4 character-frames) on build/default.smg, no
#                   timing check (unit tests are never timed).

# (blobs named directly: tools.mk, which names them, is read later)
SOAK_BIN := $(BUILD)/soak/soak
SOAK_DEFAULT := $(BUILD)/default.smg
SOAK_GRAPHS := $(SOAK_DEFAULT) $(if $(wildcard $(SMG_SHARED)/mocap/cmu/09_12.bvh),$(BUILD)/cmu.smg)
SOAK_GROW := 0.5

TEST_TARGETS += test-soak

$(SOAK_BIN): tests/soak/soak.c tests/soak/soak_timing.c tests/soak/soak_timing.h $(LIBSMG_A) $(LIB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) tests/soak/soak.c tests/soak/soak_timing.c -o $@ $(LIBSMG_A) $(LDLIBS_M)

.PHONY: soak test-soak
soak: $(SOAK_BIN) $(SOAK_GRAPHS)
	$(SOAK_BIN) --timing --grow $(SOAK_GROW) --characters 100 --steps 3000 $(SOAK_DEFAULT)
	$(SOAK_BIN) --timing --characters 100 --steps 10000 $(SOAK_GRAPHS)

test-soak: $(SOAK_BIN) $(SOAK_DEFAULT)
	$(SOAK_BIN) --characters 10 --steps 1000 $(SOAK_DEFAULT)
