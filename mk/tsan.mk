# Threads under ThreadSanitizer (part of `make test`): 4 threads step their
# own characters on one shared graph while 2 others load and destroy other
# graphs (tests/threads/tsan_shared_graph.c). The runtime sources are
# compiled into the program with -fsanitize=thread (GCC's libtsan, part of
# build-essential); any report fails the run.
#
#   make tsan    build build/tsan/tsan_shared_graph and run it on the
#                fixture and on build/default.smg

TSAN_BIN := $(BUILD)/tsan/tsan_shared_graph
TSAN_FLAGS := -std=c99 -O1 -g -fsanitize=thread $(CPPFLAGS_COMMON) -Ilibsmg/runtime -Itests

TEST_TARGETS += tsan

$(TSAN_BIN): tests/threads/tsan_shared_graph.c $(LIB_SRC) $(LIB_HDR) tests/fixture_graph.h
	@mkdir -p $(dir $@)
	$(CC) $(TSAN_FLAGS) $< $(LIB_SRC) -o $@ -lpthread -lm

.PHONY: tsan
tsan: $(TSAN_BIN) $(DEFAULT_BLOB)
	TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" $(TSAN_BIN)
	TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" $(TSAN_BIN) $(DEFAULT_BLOB)
