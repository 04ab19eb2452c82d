# Runtime part (issue 4): the smg-synth CLI (libsmg.a and the glTF writer
# for --glb, build/libsmg_gltf.a from mk/gltf.mk; no baker, no assimp) and
# the runtime benchmark.
#
#   build/smg-synth       offline driver: blob + path file -> BVH (+ CSV)
#   make bench-runtime    step+pose cost per character vs plain clip
#                         playback, edit-frame p99, blob load, memory,
#                         characters per 60 Hz frame (part of `make bench`);
#                         measures build/default.smg, build/cmu.smg when a
#                         CMU bake is there (make demo-cmu makes one), and
#                         the test fixture; with the Bandai Namco scale set
#                         in ../shared also the big graph baked from all of
#                         it (bench/big_graph_blob.sh, mk/big_graph.mk),
#                         compared with the CMU graph in the same run
#   make synth-example    smg-synth on the synthetic default blob
#   make synth-compare SYNTH_BASE=REV
#                         smg-synth's BVH and CSV, byte for byte, against
#                         the ones git revision REV (default: HEAD) gives
#                         on the same blobs: default and, when baked, CMU;
#                         paths, IK, transitions, splices
#                         (tests/runtime/synth_compare.sh)

SMG_SYNTH := $(BUILD)/smg-synth
BENCH_RUNTIME := $(BUILD)/bench/bench_runtime

ALL_TARGETS += $(SMG_SYNTH)
BENCH_TARGETS += bench-runtime

# C, linked as C++: the glTF writer carries the (C++) generated body.
$(BUILD)/obj/tools/smg_synth.o: tools/smg_synth.c include/smg.h $(GLTF_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -Itools/gltf -c $< -o $@

$(SMG_SYNTH): $(BUILD)/obj/tools/smg_synth.o $(LIBSMG_GLTF_A) $(LIBSMG_A)
	@mkdir -p $(dir $@)
	$(CXX) $(OPT) $< -o $@ $(LIBSMG_GLTF_A) $(LIBSMG_A) $(GLTF_LDLIBS)

# The benchmark builds the fixture graph in-process (tests/fixture_graph.h)
# and also measures build/default.smg when it exists.
$(BENCH_RUNTIME): bench/bench_runtime.c $(LIBSMG_A) $(LIB_HDR) tests/fixture_graph.h
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -O2 -Itests -DSMG_BUILD_DIR='"$(BUILD)"' $< -o $@ $(LIBSMG_A) -lpthread $(LDLIBS_M)

.PHONY: bench-runtime synth-example synth-compare
bench-runtime: $(BENCH_RUNTIME) $(BUILD)/smg-bake
	@big=$$($(BIG_GRAPH_BLOB_SH)); \
	echo $(BENCH_RUNTIME) $(if $(wildcard $(BUILD)/cmu.smg),--ref $(BUILD)/cmu.smg) $$big; \
	$(BENCH_RUNTIME) $(if $(wildcard $(BUILD)/cmu.smg),--ref $(BUILD)/cmu.smg) $$big

synth-example: $(SMG_SYNTH)
	@mkdir -p $(BUILD)/synth
	printf '0 0\n0 4\n3 7\n8 7\n' > $(BUILD)/synth/example-path.txt
	$(SMG_SYNTH) -g $(BUILD)/default.smg -p $(BUILD)/synth/example-path.txt \
	  --seconds 10 --fps 30 --csv $(BUILD)/synth/example.csv -o $(BUILD)/synth/example.bvh

SYNTH_BASE ?= HEAD
synth-compare: $(SMG_SYNTH) $(BUILD)/default.smg
	sh tests/runtime/synth_compare.sh $(SYNTH_BASE) "$(MAKE)" $(BUILD)
