# Windows x86_64 builds with Debian's MinGW-w64 cross compiler, tested under
# Wine (docs/windows.md).
#
#   make windows       $(WIN_BUILD)/libsmg.dll (+ libsmg.dll.a import
#                      library, libsmg.def), libsmg.a, smg-synth.exe,
#                      smg-bake.exe
#   make test-windows  (part of `make test`) libsmg.dll exports only smg_*;
#                      the runtime and core unit tests as Windows programs
#                      under Wine; smg-synth.exe writes the same bytes as
#                      the Linux smg-synth; smg-bake.exe bakes the same blob
#
# Other parts building for Windows (the Godot extension) reuse WIN_CC,
# WIN_CFLAGS_LIB, WIN_BUILD, WIN_LIBSMG_A and WINE_RUN.
#
# The baker is built without assimp (Debian has no assimp for MinGW): it
# reads BVH, and glTF/FBX clips fail with an error that says so. The
# programs are linked statically against MinGW's own runtime (libgcc,
# winpthreads) so they need no DLL beside them but libsmg.dll.

WIN_CC := x86_64-w64-mingw32-gcc
WIN_AR := x86_64-w64-mingw32-ar
WIN_CXX := x86_64-w64-mingw32-g++
WIN_OBJDUMP := x86_64-w64-mingw32-objdump
WIN_BUILD := $(BUILD)/windows
# MinGW's own C99 printf (%zu, correctly rounded %f/%g), not the Microsoft
# C library's: smg-synth's text output must match the Linux build's bytes.
WIN_CPPFLAGS := -D__USE_MINGW_ANSI_STDIO=1 $(CPPFLAGS_COMMON)
WIN_CFLAGS_LIB := $(CSTD) $(WARN) $(OPT) $(MATHFLAGS) $(WIN_CPPFLAGS) -Ilibsmg/runtime
WIN_CFLAGS_TOOL := $(CSTD) $(WARN) $(OPT) $(WIN_CPPFLAGS) -Ilibsmg/bake -Ilibsmg/runtime
WIN_LDFLAGS_EXE := -static
# what ships (the DLL and the two programs) is linked stripped, and without
# the link time in its PE header, so the same sources give the same bytes
WIN_LDFLAGS_SHIP := -s -Wl,--no-insert-timestamp

WIN_LIBSMG_DLL := $(WIN_BUILD)/libsmg.dll
WIN_LIBSMG_IMPLIB := $(WIN_BUILD)/libsmg.dll.a
# the export list, for MSVC's `lib /def:libsmg.def` (docs/windows.md)
WIN_LIBSMG_DEF := $(WIN_BUILD)/libsmg.def
WIN_LIBSMG_A := $(WIN_BUILD)/libsmg.a
WIN_LIBSMG_BAKE_A := $(WIN_BUILD)/libsmg_bake.a
WIN_SMG_SYNTH := $(WIN_BUILD)/smg-synth.exe
WIN_SMG_BAKE := $(WIN_BUILD)/smg-bake.exe
WIN_OUTPUTS := $(WIN_LIBSMG_DLL) $(WIN_LIBSMG_A) $(WIN_SMG_SYNTH) $(WIN_SMG_BAKE)

# The DLL's objects export the API (SMG_BUILD_SHARED: dllexport); the
# static library's do not, so programs linking it export nothing.
WIN_DLL_OBJ := $(LIB_SRC:%.c=$(WIN_BUILD)/obj-dll/%.o)
WIN_LIB_OBJ := $(LIB_SRC:%.c=$(WIN_BUILD)/obj/%.o)
WIN_BAKE_SRC := $(filter-out libsmg/bake/bake_assimp.c,$(BAKE_SRC)) libsmg/bake/without_assimp/bake_assimp_absent.c
WIN_BAKE_OBJ := $(WIN_BAKE_SRC:%.c=$(WIN_BUILD)/obj/%.o)

# Wine in its own prefix under the build tree (created on first use, which
# takes a while; later runs reuse it), quiet: no debug channels, no
# Mono/Gecko installers, no display needed.
WINE ?= wine
WINEPREFIX_DIR := $(abspath $(WIN_BUILD)/wineprefix)
WINE_ENV := WINEPREFIX=$(WINEPREFIX_DIR) WINEDEBUG=-all WINEDLLOVERRIDES=mscoree,mshtml= WINEARCH=win64 DISPLAY=
WINE_RUN := env $(WINE_ENV) $(WINE)
WINE_STAMP := $(WINEPREFIX_DIR)/.smg-ready

# Unit tests run under Wine: the runtime and core suites, built against a
# cmocka-compatible harness (tests/windows/cmocka.h: Debian has no cmocka
# for MinGW). Left out: test_synth (drives the POSIX smg-synth through a
# shell; test-windows compares smg-synth.exe with it instead).
WIN_TEST_SRC := $(filter-out tests/runtime/test_synth.c,$(sort $(wildcard tests/runtime/test_*.c tests/core/test_*.c)))
WIN_TEST_BIN := $(patsubst tests/%.c,$(WIN_BUILD)/tests/%.exe,$(WIN_TEST_SRC))
WIN_HARNESS_OBJ := $(WIN_BUILD)/obj/tests/windows/cmocka_harness.o

TEST_TARGETS += test-windows

.PHONY: windows test-windows wine-prefix
windows: $(WIN_OUTPUTS)

$(WIN_BUILD)/obj-dll/%.o: %.c $(LIB_HDR)
	@mkdir -p $(dir $@)
	$(WIN_CC) $(WIN_CFLAGS_LIB) -DSMG_BUILD_SHARED -c $< -o $@

$(WIN_BUILD)/obj/libsmg/common/%.o: libsmg/common/%.c $(LIB_HDR)
	@mkdir -p $(dir $@)
	$(WIN_CC) $(WIN_CFLAGS_LIB) -c $< -o $@

$(WIN_BUILD)/obj/libsmg/runtime/%.o: libsmg/runtime/%.c $(LIB_HDR)
	@mkdir -p $(dir $@)
	$(WIN_CC) $(WIN_CFLAGS_LIB) -c $< -o $@

$(WIN_BUILD)/obj/libsmg/bake/%.o: libsmg/bake/%.c $(LIB_HDR) $(BAKE_HDR)
	@mkdir -p $(dir $@)
	$(WIN_CC) $(WIN_CFLAGS_TOOL) -c $< -o $@

# libgcc inside the DLL: users ship libsmg.dll alone
$(WIN_LIBSMG_DLL): $(WIN_DLL_OBJ)
	$(WIN_CC) -shared -static-libgcc $(WIN_LDFLAGS_SHIP) -Wl,--out-implib,$(WIN_LIBSMG_IMPLIB) \
	  -Wl,--output-def,$(WIN_LIBSMG_DEF) -o $@ $^
$(WIN_LIBSMG_IMPLIB) $(WIN_LIBSMG_DEF): $(WIN_LIBSMG_DLL)

$(WIN_LIBSMG_A): $(WIN_LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	$(WIN_AR) rcs $@ $^

$(WIN_LIBSMG_BAKE_A): $(WIN_BAKE_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	$(WIN_AR) rcs $@ $^

# smg-synth's glTF export (tools/gltf) with the demo's body generator
# (C++ with GLM), as on Linux. GLM is header-only; the cross compiler gets
# a folder holding only a link to it, never the host's /usr/include (whose
# C library headers are not MinGW's).
WIN_GLM_DIR := $(WIN_BUILD)/glm-include
WIN_GLTF_OBJ := $(GLTF_SRC:%.c=$(WIN_BUILD)/obj/%.o) \
	$(WIN_BUILD)/obj/tools/gltf/gltf_body.o $(WIN_BUILD)/obj/demo/body.o $(WIN_BUILD)/obj/demo/body_graph.o
WIN_CXXFLAGS := -std=c++17 -Wall -Wextra -Werror $(OPT) -Iinclude -isystem $(WIN_GLM_DIR)

$(WIN_GLM_DIR)/glm:
	@mkdir -p $(dir $@)
	ln -sfn /usr/include/glm $@

$(WIN_BUILD)/obj/tools/gltf/%.o: tools/gltf/%.c $(GLTF_HDR) include/smg.h
	@mkdir -p $(dir $@)
	$(WIN_CC) $(WIN_CFLAGS_TOOL) -Itools/gltf -c $< -o $@

$(WIN_BUILD)/obj/tools/gltf/gltf_body.o: tools/gltf/gltf_body.cpp $(GLTF_HDR) demo/body.h demo/body_graph.h include/smg.h | $(WIN_GLM_DIR)/glm
	@mkdir -p $(dir $@)
	$(WIN_CXX) $(WIN_CXXFLAGS) -Itools/gltf -c $< -o $@

$(WIN_BUILD)/obj/demo/%.o: demo/%.cpp demo/body.h demo/body_graph.h include/smg.h | $(WIN_GLM_DIR)/glm
	@mkdir -p $(dir $@)
	$(WIN_CXX) $(WIN_CXXFLAGS) -c $< -o $@

$(WIN_SMG_SYNTH): tools/smg_synth.c $(WIN_GLTF_OBJ) $(WIN_LIBSMG_A) include/smg.h
	$(WIN_CC) $(WIN_CFLAGS_TOOL) -Itools/gltf -c $< -o $(WIN_BUILD)/obj/smg_synth.o
	$(WIN_CXX) $(WIN_LDFLAGS_EXE) $(WIN_LDFLAGS_SHIP) $(WIN_BUILD)/obj/smg_synth.o -o $@ $(WIN_GLTF_OBJ) $(WIN_LIBSMG_A)

$(WIN_SMG_BAKE): tools/smg_bake.c $(WIN_LIBSMG_BAKE_A) $(WIN_LIBSMG_A) $(LIB_HDR) $(BAKE_HDR)
	$(WIN_CC) $(WIN_CFLAGS_TOOL) $(WIN_LDFLAGS_EXE) $(WIN_LDFLAGS_SHIP) $< -o $@ $(WIN_LIBSMG_BAKE_A) $(WIN_LIBSMG_A) -lpthread

$(WIN_HARNESS_OBJ): tests/windows/cmocka_harness.c tests/windows/cmocka.h
	@mkdir -p $(dir $@)
	$(WIN_CC) $(WIN_CFLAGS_TOOL) -Itests/windows -c $< -o $@

# The tests read the blobs and clips the Linux build made (the blob format
# is the same bytes on every platform).
$(WIN_BUILD)/tests/%.exe: tests/%.c $(WIN_HARNESS_OBJ) tests/windows/posix_memalign.h $(WIN_LIBSMG_BAKE_A) $(WIN_LIBSMG_A) $(LIB_HDR) $(wildcard tests/*.h tests/*/*.h)
	@mkdir -p $(dir $@)
	$(WIN_CC) $(WIN_CFLAGS_TOOL) -Itests/windows -include tests/windows/posix_memalign.h -Itests -DSMG_SHARED_DIR='"$(SMG_SHARED)"' -DSMG_BUILD_DIR='"$(BUILD)"' \
	  $(WIN_LDFLAGS_EXE) $< -o $@ $(WIN_HARNESS_OBJ) $(WIN_LIBSMG_BAKE_A) $(WIN_LIBSMG_A) -lpthread

wine-prefix: $(WINE_STAMP)
$(WINE_STAMP):
	@mkdir -p $(WINEPREFIX_DIR)
	@$(WINE_ENV) wineboot --init >/dev/null 2>&1 || { echo "test-windows: wineboot failed" >&2; exit 1; }
	@$(WINE_ENV) wineserver -w
	@touch $@

test-windows: $(WIN_OUTPUTS) $(WIN_TEST_BIN) $(WINE_STAMP) $(SMG_SYNTH) $(SMG_BAKE) $(DEFAULT_BLOB) \
  $(if $(wildcard $(SMG_SHARED)/mocap/cmu/09_12.bvh),$(CMU_BLOB))
	@sh tests/windows/check_dll.sh $(WIN_OBJDUMP) $(WIN_LIBSMG_DLL) include/smg.h
	@for t in $(WIN_TEST_BIN); do echo "== wine $$t"; \
	  SMG_SHARED=$(SMG_SHARED) $(WINE_RUN) $$t > $$t.log 2>&1; rc=$$?; tr -d '\r' < $$t.log; \
	  [ $$rc = 0 ] || { echo "test-windows: FAILED: $$t (status $$rc)"; $(WINE_ENV) wineserver -k; exit 1; }; done
	@sh tests/windows/check_same_output.sh "$(WINE_RUN)" $(BUILD) $(WIN_BUILD) $(SMG_SHARED) || \
	  { $(WINE_ENV) wineserver -k; exit 1; }
	@$(WINE_ENV) wineserver -k 2>/dev/null || true
