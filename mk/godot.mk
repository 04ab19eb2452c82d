# Godot 4 GDExtension in plain C (bindings/godot).
#
#   make godot-provision   Godot 4.6 in a cached Debian sid root (provision.sh)
#   make godot-ext         $(BUILD)/godot/libsmg_godot.so
#   make test-godot        headless Godot test (part of `make test`)
#   make godot-demo        copies the extension and graph into the demo project
#   make godot-screenshot  docs/img/godot-demo.png of the demo under Xvfb
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
GODOT_CFLAGS := -std=c11 $(WARN) $(OPT) -fPIC -fvisibility=hidden -D_POSIX_C_SOURCE=200809L \
	-Iinclude -isystem $(GODOT_API_DIR) -I$(GODOT_BUILD)/gen
GODOT_DEFAULT_SMG := $(BUILD)/default.smg
GODOT_TEST_PROJ := $(GODOT_BUILD)/test-project
GODOT_TEST_LOG := $(GODOT_BUILD)/test-godot.log
GODOT_TEST_EDITOR_LOG := $(GODOT_BUILD)/test-godot-editor.log
GODOT_DEMO := $(GODOT_DIR)/demo

TEST_TARGETS += test-godot

.PHONY: godot-provision godot-ext test-godot godot-demo godot-screenshot

godot-provision:
	@SMG_GODOT_ROOT=$(SMG_GODOT_ROOT) sh $(GODOT_DIR)/provision.sh

$(GODOT_BIN):
	SMG_GODOT_ROOT=$(SMG_GODOT_ROOT) sh $(GODOT_DIR)/provision.sh

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

$(GODOT_BUILD)/obj/%.o: $(GODOT_DIR)/src/%.c $(GODOT_HDR) $(GODOT_GEN) $(GODOT_IFACE) include/smg.h
	@mkdir -p $(dir $@)
	$(CC) $(GODOT_CFLAGS) -c $< -o $@

# libsmg is linked in statically (its objects are -fPIC), so the extension
# is one self-contained .so; only smg_godot_init is exported.
$(GODOT_EXT): $(GODOT_OBJ) $(LIBSMG_A)
	$(CC) -shared -Wl,--no-undefined -Wl,--exclude-libs,ALL -o $@ $(GODOT_OBJ) $(LIBSMG_A) $(LDLIBS_M)

godot-ext: $(GODOT_EXT)

# A throw-away copy of the test project: Godot writes .godot/ into it, and
# extension_list.cfg is written here because `godot --import` would crash
# (Godot issue #111048).
test-godot: $(GODOT_EXT) $(GODOT_DEFAULT_SMG)
	@rm -rf $(GODOT_TEST_PROJ) && mkdir -p $(GODOT_TEST_PROJ)/bin $(GODOT_TEST_PROJ)/.godot
	@cp $(GODOT_DIR)/test/project.godot $(GODOT_DIR)/test/*.gd $(GODOT_DIR)/test/*.tscn $(GODOT_TEST_PROJ)/
	@cp $(GODOT_DEMO)/smg.gdextension $(GODOT_TEST_PROJ)/
	@cp $(GODOT_EXT) $(GODOT_TEST_PROJ)/bin/
	@cp $(GODOT_DEFAULT_SMG) $(GODOT_TEST_PROJ)/default.smg
	@echo 'res://smg.gdextension' > $(GODOT_TEST_PROJ)/.godot/extension_list.cfg
	@echo "== godot headless test ($(GODOT_TEST_LOG))"
	@cd $(GODOT_TEST_PROJ) && SMG_TEST_GRAPH_ABS=$(abspath $(GODOT_DEFAULT_SMG)) \
		timeout $(GODOT_TIMEOUT) $(GODOT_GD) --headless --fixed-fps 30 --audio-driver Dummy \
		--path . --script res://test_smg.gd > $(abspath $(GODOT_TEST_LOG)) 2>&1; \
		echo "godot exit code $$? (not trusted; checking the pass line)"
	@grep -E '^(PASS|FAIL|godot:)' $(GODOT_TEST_LOG) || true
	@sh $(GODOT_DIR)/test/check_log.sh $(GODOT_TEST_LOG)
	@echo "== godot editor smoke test: open character.tscn in the headless editor ($(GODOT_TEST_EDITOR_LOG))"
	@cd $(GODOT_TEST_PROJ) && timeout $(GODOT_TIMEOUT) $(GODOT_GD) --headless --editor --audio-driver Dummy \
		--path . --quit-after 120 character.tscn > $(abspath $(GODOT_TEST_EDITOR_LOG)) 2>&1; rc=$$?; \
		if [ $$rc -ne 0 ] || grep -qE 'Program crashed|handle_crash|Segmentation fault|SmgGraph: .*(not found|not a valid)' \
			$(abspath $(GODOT_TEST_EDITOR_LOG)); then \
			echo "test-godot: editor run failed (exit $$rc), see $(GODOT_TEST_EDITOR_LOG)" >&2; tail -20 $(abspath $(GODOT_TEST_EDITOR_LOG)) >&2; exit 1; \
		fi; \
		grep -q 'open_scenes=PackedStringArray("res://character.tscn")' .godot/editor/editor_layout.cfg \
			|| { echo "test-godot: the editor did not open character.tscn" >&2; exit 1; }
	@echo "test-godot: editor opened the scene with the extension loaded and exited cleanly"

# The demo project runs from bindings/godot/demo in the editor once the
# extension and a graph are copied in (both git-ignored).
godot-demo: $(GODOT_EXT) $(GODOT_DEFAULT_SMG)
	@mkdir -p $(GODOT_DEMO)/bin $(GODOT_DEMO)/.godot
	cp $(GODOT_EXT) $(GODOT_DEMO)/bin/
	cp $(GODOT_DEFAULT_SMG) $(GODOT_DEMO)/default.smg
	@echo 'res://smg.gdextension' > $(GODOT_DEMO)/.godot/extension_list.cfg

godot-screenshot: godot-demo
	@mkdir -p docs/img
	sh $(GODOT_DIR)/screenshot.sh $(abspath $(GODOT_DEMO)) $(abspath docs/img/godot-demo.png)
