# Soak (tests/soak/soak.c): many characters, many frames, random use, with
# checks on every character-frame (finite, no root jump beyond the data's
# fastest motion, bounded path error, no allocation after create).
#
#   make soak       first proves the growth check live: a short run whose
#                   stepping work grows by SOAK_GROW (50 %) by its end must
#                   be caught (--grow); then, under callgrind, 50
#                   characters x 10^4 steps (after 600 settling steps) on
#                   build/default.smg and, when ../shared holds the CMU
#                   clips, build/cmu.smg: the instructions of the steps in
#                   the last 1000 frames must be within 10 % of the first
#                   1000's (--instructions, tests/soak/soak_count.h); then
#                   natively 100 characters x 10^4 steps on the same graphs
#                   (10^6 character-frames each). A few minutes; not in
#                   make test.
#   make test-soak  (part of `make test`) 10 characters x 10^3 steps
#                   (10^4 character-frames) on build/default.smg, natively,
#                   no counting (unit tests are never timed).

# (blobs named directly: tools.mk, which names them, is read later)
SOAK_BIN := $(BUILD)/soak/soak
SOAK_DEFAULT := $(BUILD)/default.smg
SOAK_GRAPHS := $(SOAK_DEFAULT) $(if $(wildcard $(SMG_SHARED)/mocap/cmu/09_12.bvh),$(BUILD)/cmu.smg)
SOAK_GROW := 0.5

TEST_TARGETS += test-soak

$(SOAK_BIN): tests/soak/soak.c tests/soak/soak_count.c tests/soak/soak_count.h $(LIBSMG_A) $(LIB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) tests/soak/soak.c tests/soak/soak_count.c -o $@ $(LIBSMG_A) $(LDLIBS_M)

# callgrind instruments only the counted windows and collects only the
# steps (soak_count.h); its dumps go to $(SOAK_CG).<n>
SOAK_CG := $(BUILD)/soak/callgrind.out
SOAK_CALLGRIND := valgrind --tool=callgrind --instr-atstart=no --collect-atstart=no \
  --callgrind-out-file=$(SOAK_CG)

.PHONY: soak test-soak
soak: $(SOAK_BIN) $(SOAK_GRAPHS)
	rm -f $(SOAK_CG) $(SOAK_CG).*
	$(SOAK_CALLGRIND) -q $(SOAK_BIN) --instructions $(SOAK_CG) --grow $(SOAK_GROW) --characters 50 --steps 2000 --window 200 $(SOAK_DEFAULT)
	rm -f $(SOAK_CG) $(SOAK_CG).*
	$(SOAK_CALLGRIND) -q $(SOAK_BIN) --instructions $(SOAK_CG) --characters 50 --steps 10000 --window 1000 $(SOAK_GRAPHS)
	rm -f $(SOAK_CG) $(SOAK_CG).*
	$(SOAK_BIN) --characters 100 --steps 10000 $(SOAK_GRAPHS)

test-soak: $(SOAK_BIN) $(SOAK_DEFAULT)
	$(SOAK_BIN) --characters 10 --steps 1000 $(SOAK_DEFAULT)
