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

# Baker scale benchmark (not part of `make bench` or `make test`: minutes
# of baking): 1/8, 1/4, 1/2 and all of the Bandai Namco scale set from
# ../shared (unpacked under build/), wall / CPU time, peak memory, graph
# and blob sizes, growth exponents. Skips with a message without the data.
.PHONY: bench-bake-scale
bench-bake-scale: $(SMG_BAKE)
	sh bench/bake_scale.sh $(SMG_BAKE) $(SMG_SHARED) $(BUILD) "$(SCALE_FRACTIONS)"

SCALE_FRACTIONS ?= 8 4 2 1

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

# Installing the offline side for tools programmers: smg_bake.h,
# libsmg_bake.a, lib/pkgconfig/smg-bake.pc and the smg-bake / smg-synth
# command lines. The baker uses libsmg's blob writer and rotation codec,
# which libsmg.so keeps hidden, so smg-bake.pc links libsmg.a by path (and
# assimp, which the baker imports glTF/FBX with). `make install` is the
# runtime (mk/lib.mk) plus this.
.PHONY: install install-bake
install: install-runtime install-bake

install-bake: install-runtime $(LIBSMG_BAKE_A) $(SMG_BAKE) $(SMG_SYNTH)
	install -d $(DESTDIR)$(INCLUDEDIR) $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PKGCONFIGDIR) $(DESTDIR)$(BINDIR)
	install -m 644 include/smg_bake.h $(DESTDIR)$(INCLUDEDIR)/smg_bake.h
	install -m 644 $(LIBSMG_BAKE_A) $(DESTDIR)$(LIBDIR)/libsmg_bake.a
	install -m 755 $(SMG_BAKE) $(DESTDIR)$(BINDIR)/smg-bake
	install -m 755 $(SMG_SYNTH) $(DESTDIR)$(BINDIR)/smg-synth
	printf '%s\n' \
	  '# the baker needs libsmg internals that libsmg.so hides: link libsmg.a' \
	  'prefix=$(PREFIX)' \
	  'libdir=$(LIBDIR)' \
	  'includedir=$(INCLUDEDIR)' \
	  '' \
	  'Name: smg-bake' \
	  'Description: Splicing Motion Graphs offline baker (motion-capture clips to graph blobs)' \
	  'Version: $(LIB_VERSION)' \
	  'Libs: -L$${libdir} -lsmg_bake $${libdir}/libsmg.a -lassimp -lpthread -lm' \
	  'Cflags: -I$${includedir}' \
	  > $(DESTDIR)$(PKGCONFIGDIR)/smg-bake.pc
	chmod 644 $(DESTDIR)$(PKGCONFIGDIR)/smg-bake.pc
