# Offline baker: libsmg_bake.a from libsmg/bake (links assimp; never part of
# the runtime library).
BAKE_SRC := $(sort $(wildcard libsmg/bake/*.c))
BAKE_OBJ := $(BAKE_SRC:%.c=$(BUILD)/obj/%.o)
BAKE_HDR := $(wildcard libsmg/bake/*.h include/smg_bake.h)
LIBSMG_BAKE_A := $(BUILD)/libsmg_bake.a
BAKE_LDLIBS := -lassimp

ALL_TARGETS += $(LIBSMG_BAKE_A)

$(BUILD)/obj/libsmg/bake/%.o: libsmg/bake/%.c $(LIB_HDR) $(BAKE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -c $< -o $@

$(LIBSMG_BAKE_A): $(BAKE_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^
