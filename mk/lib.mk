# libsmg runtime library: libsmg.a and libsmg.so.0 from libsmg/common and
# libsmg/runtime. Only smg_* symbols are exported (-fvisibility=hidden plus
# SMG_API on the public functions).

SONAME_MAJOR := 0
LIB_VERSION := 0.1.0
LIB_SRC := $(sort $(wildcard libsmg/common/*.c libsmg/runtime/*.c))
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
LIB_HDR := $(wildcard include/*.h libsmg/common/*.h libsmg/runtime/*.h)
LIBSMG_A := $(BUILD)/libsmg.a
LIBSMG_SO := $(BUILD)/libsmg.so.$(LIB_VERSION)

ALL_TARGETS += $(LIBSMG_A) $(LIBSMG_SO)

$(BUILD)/obj/libsmg/%.o: libsmg/%.c $(LIB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_LIB) -Ilibsmg/runtime -DSMG_BUILD_SHARED -c $< -o $@

$(LIBSMG_A): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

$(LIBSMG_SO): $(LIB_OBJ)
	$(CC) -shared -Wl,-soname,libsmg.so.$(SONAME_MAJOR) -Wl,--no-undefined -o $@ $^ $(LDLIBS_M)
	ln -sf libsmg.so.$(LIB_VERSION) $(BUILD)/libsmg.so.$(SONAME_MAJOR)
	ln -sf libsmg.so.$(SONAME_MAJOR) $(BUILD)/libsmg.so
