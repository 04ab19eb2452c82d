# The runtime on a big graph (issue 25; not part of `make test` or `make
# bench`: the graph is baked from a 421 MB clip set that CI does not have):
#
#   make bench-big-graph  bakes all of the Bandai Namco scale set from
#                         ../shared once (bench/big_graph_blob.sh, kept in
#                         build/big-graph/), then measures its load
#                         (bench-load) and runs bench/bench_big_graph.c:
#                         the eight data/paths/ against the small graphs'
#                         path and foot targets and style changes between
#                         two performers on a straight line, all from the
#                         exported hips and toes; PASS/FAIL per check.
#                         Skips with a message without the data.
#
# `make bench-runtime` adds the same graph to its runs when the data is
# there (mk/runtime.mk).

# eval.mk, demo.mk and tools.mk are read after this file: their outputs
# are named by path here, and SMG_SHARED is used only in recipes.
BENCH_BIG_GRAPH := $(BUILD)/bench/bench_big_graph
BIG_GRAPH_BLOB_SH = sh bench/big_graph_blob.sh $(BUILD)/smg-bake $(SMG_SHARED) $(BUILD)

$(BENCH_BIG_GRAPH): bench/bench_big_graph.c $(BUILD)/libsmg_eval.a $(LIBSMG_BAKE_A) $(LIBSMG_A) $(LIB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -Itools/eval $< -o $@ $(BUILD)/libsmg_eval.a $(LIBSMG_BAKE_A) $(LIBSMG_A) $(BAKE_LDLIBS) -lpthread $(LDLIBS_M)

.PHONY: bench-big-graph
bench-big-graph: $(BENCH_BIG_GRAPH) $(BUILD)/smg-bake $(BUILD)/tests/core/bench_load
	@blob=$$($(BIG_GRAPH_BLOB_SH)); \
	if [ -z "$$blob" ]; then echo "bench-big-graph: skipped (no scale set)"; exit 0; fi; \
	$(BUILD)/tests/core/bench_load $$blob; \
	failed=0; \
	$(BENCH_BIG_GRAPH) $$blob walk:active walk:exhausted || failed=1; \
	$(BENCH_BIG_GRAPH) $$blob walk:exhausted walk:active || failed=1; \
	exit $$failed
