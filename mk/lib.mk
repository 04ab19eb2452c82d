# libsmg runtime library: libsmg.a and libsmg.so.0 from libsmg/common and
# libsmg/runtime. Only smg_* symbols are exported (-fvisibility=hidden plus
# SMG_API on the public functions; `make test-symbols` checks it).
#
#   make install-runtime PREFIX=/usr/local DESTDIR=
#     installs include/smg.h, libsmg.a, libsmg.so.0.1.0 with the
#     libsmg.so.0 and libsmg.so links, and lib/pkgconfig/smg.pc
#     (`make install` adds the baker: mk/tools.mk).

SONAME_MAJOR := 0
LIB_VERSION := 0.1.0
LIB_SRC := $(sort $(wildcard libsmg/common/*.c libsmg/runtime/*.c))
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
LIB_HDR := $(wildcard include/*.h libsmg/common/*.h libsmg/runtime/*.h)
LIBSMG_A := $(BUILD)/libsmg.a
LIBSMG_SO := $(BUILD)/libsmg.so.$(LIB_VERSION)

LIBDIR ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
BINDIR ?= $(PREFIX)/bin
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig

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

.PHONY: install-runtime
install-runtime: $(LIBSMG_A) $(LIBSMG_SO)
	install -d $(DESTDIR)$(INCLUDEDIR) $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PKGCONFIGDIR) $(DESTDIR)$(PREFIX)/share/doc/libsmg
	install -m 644 LICENSE $(DESTDIR)$(PREFIX)/share/doc/libsmg/LICENSE
	install -m 644 include/smg.h $(DESTDIR)$(INCLUDEDIR)/smg.h
	install -m 644 $(LIBSMG_A) $(DESTDIR)$(LIBDIR)/libsmg.a
	install -m 755 $(LIBSMG_SO) $(DESTDIR)$(LIBDIR)/libsmg.so.$(LIB_VERSION)
	ln -sf libsmg.so.$(LIB_VERSION) $(DESTDIR)$(LIBDIR)/libsmg.so.$(SONAME_MAJOR)
	ln -sf libsmg.so.$(SONAME_MAJOR) $(DESTDIR)$(LIBDIR)/libsmg.so
	printf '%s\n' \
	  'prefix=$(PREFIX)' \
	  'libdir=$(LIBDIR)' \
	  'includedir=$(INCLUDEDIR)' \
	  '' \
	  'Name: smg' \
	  'Description: Splicing Motion Graphs runtime (path-following characters from motion capture)' \
	  'Version: $(LIB_VERSION)' \
	  'Libs: -L$${libdir} -lsmg' \
	  'Libs.private: -lm' \
	  'Cflags: -I$${includedir}' \
	  > $(DESTDIR)$(PKGCONFIGDIR)/smg.pc
	chmod 644 $(DESTDIR)$(PKGCONFIGDIR)/smg.pc
