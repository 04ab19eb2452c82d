# Godot 4 GDExtension in plain C (bindings/godot).
#
#   make godot-provision   Godot 4.6 in a cached Debian sid root (provision.sh)
#   make godot-ext         $(BUILD)/godot/libsmg_godot.so
#   make test-godot        headless Godot test (part of `make test`)
#   make test-godot-asan   the same with the extension and libsmg under ASan
#   make godot-demo        installs the addon and a graph into the demo project
#   make godot-screenshot  docs/img/godot-demo.png of the demo under Xvfb
#   make godot-dll         $(BUILD)/godot/windows/libsmg_godot.dll (MinGW-w64)
#   make godot-addon-zip   $(BUILD)/dist/libsmg-godot-addon-VERSION.zip, the
#                          installable addons/libsmg/ (Linux + Windows)
#   make test-godot-addon  the zip installed into a fresh project, headless
#                          (part of `make test`)
#
# The interface header and extension_api.json are dumped from the provisioned
# Godot at build time (never committed), and the method-bind hashes, enum
# values and type sizes the C code uses are generated from that JSON, so the
# extension always matches the Godot it is tested with. Every Godot run is
# wrapped in `timeout`, and test success is decided by the exact pass line:
# Godot exits 0 even after a script error.

SMG_GODOT_ROOT ?= /var/cache/smg-godot/root
GODOT_DIR := bindings/godot
GODOT_BUILD := $(BUILD)/godot
GODOT_BIN := $(SMG_GODOT_ROOT)/usr/bin/godot
GODOT_GD := env SMG_GODOT_ROOT=$(SMG_GODOT_ROOT) SMG_GODOT_BIND=$(abspath $(BUILD)) $(abspath $(GODOT_DIR))/gd
GODOT_TIMEOUT ?= 300
GODOT_API_DIR := $(GODOT_BUILD)/api
GODOT_IFACE := $(GODOT_API_DIR)/gdextension_interface.h
GODOT_API_JSON := $(GODOT_API_DIR)/extension_api.json
GODOT_GEN := $(GODOT_BUILD)/gen/smg_gd_api_gen.h
GODOT_SRC := $(sort $(wildcard $(GODOT_DIR)/src/*.c))
GODOT_HDR := $(wildcard $(GODOT_DIR)/src/*.h)
GODOT_OBJ := $(GODOT_SRC:$(GODOT_DIR)/src/%.c=$(GODOT_BUILD)/obj/%.o)
GODOT_EXT := $(GODOT_BUILD)/libsmg_godot.so
# C11 for _Static_assert/_Alignas and the dumped header; the header itself is
# a system include so its style does not meet our -Wpedantic -Werror.
# libsmg/runtime: the runtime's header-only quaternion math (rmath.h), which
# the bone map shares rather than keeping a copy.
GODOT_CFLAGS := -std=c11 $(WARN) $(OPT) -fPIC -fvisibility=hidden -D_POSIX_C_SOURCE=200809L \
	-Iinclude -Ilibsmg/runtime -isystem $(GODOT_API_DIR) -I$(GODOT_BUILD)/gen
GODOT_DEFAULT_SMG := $(BUILD)/default.smg
GODOT_TEST_PROJ := $(GODOT_BUILD)/test-project
GODOT_TEST_LOG := $(GODOT_BUILD)/test-godot.log
GODOT_TEST_EDITOR_LOG := $(GODOT_BUILD)/test-godot-editor.log
GODOT_DEMO := $(GODOT_DIR)/demo
# What goes into addons/libsmg/ as is (plugin.cfg, plugin.gd,
# smg.gdextension, icons); whoever installs it adds the libraries.
GODOT_ADDON_SRC := $(GODOT_DIR)/addon
GODOT_ADDON_FILES := $(shell find $(GODOT_ADDON_SRC) -type f)

TEST_TARGETS += test-godot test-godot-asan test-godot-addon

.PHONY: godot-provision godot-ext test-godot godot-demo godot-screenshot test-godot-asan godot-dll \
	godot-addon-zip test-godot-addon

godot-provision:
	@SMG_GODOT_ROOT=$(SMG_GODOT_ROOT) sh $(GODOT_DIR)/provision.sh

# provision.sh returns at once when the cached root matches its package list,
# so depending on the script re-provisions exactly when that list changed.
$(GODOT_BIN): $(GODOT_DIR)/provision.sh
	@SMG_GODOT_ROOT=$(SMG_GODOT_ROOT) sh $(GODOT_DIR)/provision.sh

# Both files come from one Godot run in a scratch folder.
$(GODOT_IFACE): $(GODOT_BIN)
	@rm -rf $(GODOT_API_DIR).tmp && mkdir -p $(GODOT_API_DIR).tmp
	cd $(GODOT_API_DIR).tmp && timeout 120 $(GODOT_GD) --headless --dump-gdextension-interface --dump-extension-api >/dev/null
	@test -s $(GODOT_API_DIR).tmp/gdextension_interface.h && test -s $(GODOT_API_DIR).tmp/extension_api.json
	@rm -rf $(GODOT_API_DIR) && mv $(GODOT_API_DIR).tmp $(GODOT_API_DIR)
$(GODOT_API_JSON): $(GODOT_IFACE)

$(GODOT_GEN): $(GODOT_API_JSON) $(GODOT_DIR)/src/binds.list $(GODOT_DIR)/tools/gen_api.py
	@mkdir -p $(dir $@)
	python3 $(GODOT_DIR)/tools/gen_api.py $(GODOT_API_JSON) $(GODOT_DIR)/src/binds.list $@

# The class reference (doc_classes/*.xml) compiled in for the editor's help.
GODOT_DOCS := $(sort $(wildcard $(GODOT_DIR)/doc_classes/*.xml))
GODOT_DOCS_GEN := $(GODOT_BUILD)/gen/smg_gd_docs_gen.h
$(GODOT_DOCS_GEN): $(GODOT_DOCS) $(GODOT_DIR)/tools/gen_docs.py
	@mkdir -p $(dir $@)
	python3 $(GODOT_DIR)/tools/gen_docs.py $@ $(GODOT_DOCS)

$(GODOT_BUILD)/obj/%.o: $(GODOT_DIR)/src/%.c $(GODOT_HDR) $(GODOT_GEN) $(GODOT_DOCS_GEN) $(GODOT_IFACE) include/smg.h
	@mkdir -p $(dir $@)
	$(CC) $(GODOT_CFLAGS) -c $< -o $@

# libsmg is linked in statically (its objects are -fPIC), so the extension
# is one self-contained .so; only smg_godot_init is exported.
$(GODOT_EXT): $(GODOT_OBJ) $(LIBSMG_A)
	$(CC) -shared -Wl,--no-undefined -Wl,--exclude-libs,ALL -o $@ $(GODOT_OBJ) $(LIBSMG_A) $(LDLIBS_M)

godot-ext: $(GODOT_EXT)

# The retargeted-rig test's inputs: the synthetic clips baked onto the
# generated test rig, and smg-synth's joint positions on that graph along
# the test's path (bindings/godot/test/rig_path.txt).
GODOT_RIG_SMG := $(GODOT_BUILD)/rig.smg
GODOT_RIG_REF := $(GODOT_BUILD)/rig_ref_positions.csv
GODOT_RIG_ENV = SMG_RIG_GRAPH=$(abspath $(GODOT_RIG_SMG)) SMG_RIG_REF=$(abspath $(GODOT_RIG_REF))

# (the baker, smg-synth and the synthetic clips are defined in fragments
# read after this one: named by path here)
$(GODOT_RIG_SMG): $(BUILD)/smg-bake $(BUILD)/synthetic/README.txt data/synthetic.manifest
	@mkdir -p $(dir $@)
	$(BUILD)/smg-bake -q -m data/synthetic.manifest --data-dir $(BUILD)/synthetic \
		--target $(BUILD)/synthetic/rig_mixamo_apose.bvh --target-unit 1 -o $@

$(GODOT_RIG_REF): $(GODOT_RIG_SMG) $(BUILD)/smg-synth $(GODOT_DIR)/test/rig_path.txt $(GODOT_DIR)/test/bvh_positions.py
	$(BUILD)/smg-synth -g $(GODOT_RIG_SMG) -p $(GODOT_DIR)/test/rig_path.txt --seconds 6 \
		--csv $(GODOT_BUILD)/rig_ref.csv -o $(GODOT_BUILD)/rig_ref.bvh
	python3 $(GODOT_DIR)/test/bvh_positions.py $(GODOT_BUILD)/rig_ref.bvh $(GODOT_BUILD)/rig_ref.csv $@

# The skinned-character check needs the generated body of the graph and
# smg-synth's poses along the same path (see test/test_skinned.gd).
GODOT_BODY_GLTF := $(GODOT_BUILD)/body.gltf
GODOT_SKINNED_BVH := $(GODOT_BUILD)/skinned.bvh
$(GODOT_BODY_GLTF): $(DEMO_BODYGLTF) $(GODOT_DEFAULT_SMG)
	@mkdir -p $(dir $@)
	$(DEMO_BODYGLTF) $(GODOT_DEFAULT_SMG) $@
$(GODOT_SKINNED_BVH): $(BUILD)/smg-synth $(GODOT_DEFAULT_SMG) $(GODOT_DIR)/test/skinned_path.txt
	@mkdir -p $(dir $@)
	$(BUILD)/smg-synth -g $(GODOT_DEFAULT_SMG) -p $(GODOT_DIR)/test/skinned_path.txt --seconds 8 --fps 30 -o $@

# The scripted headless test, then the test scene opened in the headless
# editor; bindings/godot/test/run_test.sh prepares a throw-away project
# copy and decides from the output (see check_log.sh).
test-godot: $(GODOT_EXT) $(GODOT_DEFAULT_SMG) $(GODOT_RIG_REF) $(GODOT_BODY_GLTF) $(GODOT_SKINNED_BVH)
	@$(GODOT_RIG_ENV) GODOT_GD="$(GODOT_GD)" GODOT_TIMEOUT=$(GODOT_TIMEOUT) GODOT_BODY=$(GODOT_BODY_GLTF) \
		GODOT_BVH=$(GODOT_SKINNED_BVH) sh $(GODOT_DIR)/test/run_test.sh \
		$(GODOT_EXT) $(GODOT_DEFAULT_SMG) $(GODOT_TEST_PROJ) $(GODOT_TEST_LOG) $(GODOT_TEST_EDITOR_LOG)

# The same scripted test with the extension and libsmg built with
# AddressSanitizer (the host's gcc runtime, preloaded into Godot together
# with a shim that drops RTLD_DEEPBIND, which the sanitizer refuses).
GODOT_ASAN := $(GODOT_BUILD)/asan
GODOT_ASAN_FLAGS := -O1 -g -fsanitize=address -fno-omit-frame-pointer
GODOT_ASAN_EXT := $(GODOT_ASAN)/libsmg_godot.so
GODOT_ASAN_SHIM := $(GODOT_ASAN)/nodeepbind.so

$(GODOT_ASAN_EXT): $(GODOT_SRC) $(GODOT_HDR) $(GODOT_GEN) $(GODOT_DOCS_GEN) $(GODOT_IFACE) $(LIB_SRC) $(LIB_HDR)
	@rm -rf $(GODOT_ASAN)/obj && mkdir -p $(GODOT_ASAN)/obj
	@set -e; for f in $(LIB_SRC); do \
		$(CC) $(CSTD) $(WARN) $(GODOT_ASAN_FLAGS) $(MATHFLAGS) -fPIC $(CPPFLAGS_COMMON) -Ilibsmg/runtime \
			-c $$f -o $(GODOT_ASAN)/obj/$$(echo $$f | tr / _).o; done
	@set -e; for f in $(GODOT_SRC); do \
		$(CC) $(GODOT_CFLAGS) $(GODOT_ASAN_FLAGS) -c $$f -o $(GODOT_ASAN)/obj/$$(echo $$f | tr / _).o; done
	$(CC) -shared -fsanitize=address -o $@ $(GODOT_ASAN)/obj/*.o $(LDLIBS_M)

$(GODOT_ASAN_SHIM): $(GODOT_DIR)/test/nodeepbind.c
	@mkdir -p $(dir $@)
	$(CC) -shared -fPIC -O1 -o $@ $< -ldl
	cp "$$($(CC) -print-file-name=libasan.so)" $(GODOT_ASAN)/libasan.so

test-godot-asan: $(GODOT_ASAN_EXT) $(GODOT_ASAN_SHIM) $(GODOT_DEFAULT_SMG) $(GODOT_RIG_REF)
	@$(GODOT_RIG_ENV) GODOT_GD="$(GODOT_GD)" GODOT_TIMEOUT=$(GODOT_TIMEOUT) \
		GODOT_PRELOAD=$(abspath $(GODOT_ASAN_SHIM)):$(abspath $(GODOT_ASAN))/libasan.so \
		ASAN_OPTIONS=detect_leaks=0:verify_asan_link_order=0:halt_on_error=1:abort_on_error=1 \
		sh $(GODOT_DIR)/test/run_test.sh $(GODOT_ASAN_EXT) $(GODOT_DEFAULT_SMG) $(GODOT_ASAN)/test-project \
		$(GODOT_ASAN)/test-godot-asan.log
	@echo "test-godot-asan: no AddressSanitizer report"

# The demo project runs from bindings/godot/demo in the editor once the
# addon (addons/libsmg/, as the zip installs it, with the Linux library) and
# a graph are copied in (all git-ignored). body.gltf is the generated
# skinned body of the graph's skeleton.
godot-demo: $(GODOT_EXT) $(GODOT_DEFAULT_SMG) $(DEMO_BODYGLTF) $(GODOT_ADDON_FILES)
	@rm -rf $(GODOT_DEMO)/addons/libsmg && mkdir -p $(GODOT_DEMO)/addons/libsmg/bin $(GODOT_DEMO)/.godot
	cp -R $(GODOT_ADDON_SRC)/. $(GODOT_DEMO)/addons/libsmg/
	cp $(GODOT_EXT) $(GODOT_DEMO)/addons/libsmg/bin/libsmg_godot.linux.x86_64.so
	cp $(GODOT_DEFAULT_SMG) $(GODOT_DEMO)/default.smg
	$(DEMO_BODYGLTF) $(GODOT_DEFAULT_SMG) $(GODOT_DEMO)/body.gltf
	@echo 'res://addons/libsmg/smg.gdextension' > $(GODOT_DEMO)/.godot/extension_list.cfg

godot-screenshot: godot-demo
	@mkdir -p docs/img
	sh $(GODOT_DIR)/screenshot.sh $(abspath $(GODOT_DEMO)) $(abspath docs/img/godot-demo.png)

# ---- Windows x86_64: the extension as one DLL (MinGW-w64) ----
# libsmg is compiled in, as on Linux, so the DLL needs nothing beside it but
# Windows' own DLLs (-static-libgcc). The MinGW C library's C99 printf
# (__USE_MINGW_ANSI_STDIO) formats %zu; GCC still checks printf formats
# against msvcrt's older rules there, hence -Wno-format for libsmg's sources.
WIN_CC ?= x86_64-w64-mingw32-gcc
WIN_OBJDUMP ?= x86_64-w64-mingw32-objdump
GODOT_WIN := $(GODOT_BUILD)/windows
GODOT_DLL := $(GODOT_WIN)/libsmg_godot.dll
GODOT_WIN_DEFS := -D__USE_MINGW_ANSI_STDIO=1
GODOT_WIN_LIB_OBJ := $(LIB_SRC:%.c=$(GODOT_WIN)/obj/%.o)
GODOT_WIN_OBJ := $(GODOT_SRC:$(GODOT_DIR)/src/%.c=$(GODOT_WIN)/obj/godot/%.o)

$(GODOT_WIN)/obj/libsmg/%.o: libsmg/%.c $(LIB_HDR)
	@mkdir -p $(dir $@)
	$(WIN_CC) $(CSTD) $(WARN) -Wno-format $(OPT) $(MATHFLAGS) $(GODOT_WIN_DEFS) $(CPPFLAGS_COMMON) -Ilibsmg/runtime \
		-c $< -o $@

$(GODOT_WIN)/obj/godot/%.o: $(GODOT_DIR)/src/%.c $(GODOT_HDR) $(GODOT_GEN) $(GODOT_DOCS_GEN) $(GODOT_IFACE) include/smg.h
	@mkdir -p $(dir $@)
	$(WIN_CC) $(GODOT_CFLAGS) $(GODOT_WIN_DEFS) -c $< -o $@

# Linked stripped and without the link time in its PE header: it is built
# for the addon zip, whose bytes depend only on the sources.
$(GODOT_DLL): $(GODOT_WIN_OBJ) $(GODOT_WIN_LIB_OBJ)
	$(WIN_CC) -shared -static-libgcc -s -Wl,--no-insert-timestamp -Wl,--no-undefined -o $@ $^

godot-dll: $(GODOT_DLL)

# ---- the installable addon ----
# $(GODOT_ADDON_SRC) plus both libraries, the class reference and the
# project's LICENSE (tools/pack_addon.py).
GODOT_ADDON_VERSION := $(shell sed -n 's/^\#define SMG_VERSION_\(MAJOR\|MINOR\|PATCH\) *\([0-9][0-9]*\).*/\2/p' \
	include/smg.h | paste -sd. -)
GODOT_ADDON_ZIP := $(BUILD)/dist/libsmg-godot-addon-$(GODOT_ADDON_VERSION).zip
GODOT_LICENSE := $(wildcard LICENSE)

# The Linux library as shipped: without debug information (the one under
# test keeps it).
GODOT_EXT_SHIP := $(GODOT_BUILD)/ship/libsmg_godot.linux.x86_64.so
$(GODOT_EXT_SHIP): $(GODOT_EXT)
	@mkdir -p $(dir $@)
	strip --strip-unneeded -o $@ $<

$(GODOT_ADDON_ZIP): $(GODOT_EXT_SHIP) $(GODOT_DLL) $(GODOT_ADDON_FILES) $(GODOT_DOCS) $(GODOT_LICENSE) \
		$(GODOT_DIR)/tools/pack_addon.py
	@mkdir -p $(dir $@)
	@[ -n "$(GODOT_LICENSE)" ] || echo "godot-addon-zip: warning: no LICENSE at the repository root, none packed" >&2
	python3 $(GODOT_DIR)/tools/pack_addon.py $@ $(GODOT_ADDON_SRC) $(GODOT_EXT_SHIP) $(GODOT_DLL) \
		$(GODOT_DIR)/doc_classes $(GODOT_LICENSE)

godot-addon-zip: $(GODOT_ADDON_ZIP)

# A Windows program that loads the DLL as Godot does (test/dll_load.c),
# run under Wine in a prefix of its own inside the build tree (made on
# first use: wineboot, about 10 s), quiet and without a display.
GODOT_DLL_LOADER := $(GODOT_WIN)/dll_load.exe
GODOT_WINEPREFIX := $(abspath $(GODOT_WIN))/wineprefix
GODOT_WINE_ENV := WINEPREFIX=$(GODOT_WINEPREFIX) WINEDEBUG=-all WINEDLLOVERRIDES=mscoree,mshtml= WINEARCH=win64 DISPLAY=
GODOT_WINE_STAMP := $(GODOT_WINEPREFIX)/.smg-ready

$(GODOT_DLL_LOADER): $(GODOT_DIR)/test/dll_load.c $(GODOT_IFACE)
	@mkdir -p $(dir $@)
	$(WIN_CC) -std=c11 $(WARN) -O2 -isystem $(GODOT_API_DIR) $< -o $@

$(GODOT_WINE_STAMP):
	@mkdir -p $(GODOT_WINEPREFIX)
	@env $(GODOT_WINE_ENV) wineboot --init >/dev/null 2>&1 || { echo "test-godot-addon: wineboot failed" >&2; exit 1; }
	@env $(GODOT_WINE_ENV) wineserver -w
	@touch $@

# The zip installed into a fresh project and opened, run and inspected
# (bindings/godot/test/addon_test.sh).
test-godot-addon: $(GODOT_ADDON_ZIP) $(GODOT_DEFAULT_SMG) $(GODOT_DLL_LOADER) $(GODOT_WINE_STAMP)
	@GODOT_GD="$(GODOT_GD)" GODOT_TIMEOUT=$(GODOT_TIMEOUT) WIN_OBJDUMP=$(WIN_OBJDUMP) \
		GODOT_WINE="env $(GODOT_WINE_ENV) wine" GODOT_DLL_LOADER=$(GODOT_DLL_LOADER) \
		sh $(GODOT_DIR)/test/addon_test.sh $(GODOT_ADDON_ZIP) $(GODOT_DEFAULT_SMG) $(GODOT_BUILD)/addon-test \
		$(GODOT_LICENSE); rc=$$?; env $(GODOT_WINE_ENV) wineserver -k 2>/dev/null; exit $$rc
