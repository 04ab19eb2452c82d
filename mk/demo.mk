# SDL2 + OpenGL 3.3 demo (demo/): build/smg-demo links libsmg only through
# include/smg.h, like any engine. C++17 with GLM and Dear ImGui (Debian's
# libimgui-dev ships imgui plus its SDL2/OpenGL3 backends in libimgui.a).
#
#   make demo              run on real motion capture when $(SMG_SHARED) has it
#                          (the Bandai Namco set, data/bandai.manifest: turning
#                          walks, runs, waving spliced on; baked once into
#                          build/bandai.smg), else on the synthetic default
#                          graph (build/default.smg)
#   make demo DEMO_ARGS="--characters 50"
#   make demo DEMO_REAL_MANIFEST=M DEMO_REAL_DATA=DIR   other real clips
#   make demo-cmu          bake the CMU set from $(SMG_SHARED) and run on it
#   make test-demo         headless smoke test (part of `make test`)
#   make demo-pictures     regenerate docs/img/demo-*.png from the CMU set

SMG_SHARED ?= ../shared
DEMO_SRC := $(sort $(wildcard demo/*.cpp))
DEMO_OBJ := $(DEMO_SRC:%.cpp=$(BUILD)/obj/%.o)
DEMO_BIN := $(BUILD)/smg-demo
DEMO_PNGCHECK := $(BUILD)/smg-demo-pngcheck
DEMO_BODYTEST := $(BUILD)/smg-demo-bodytest
DEMO_BODYGLTF := $(BUILD)/smg-body-gltf
DEMO_BODY_OBJ := $(BUILD)/obj/demo/body.o $(BUILD)/obj/demo/body_graph.o
DEMO_DEFAULT_BLOB := $(BUILD)/default.smg
DEMO_CMU_BLOB := $(BUILD)/cmu.smg
DEMO_CMU_MANIFEST := data/cmu.manifest
# Real data `make demo` prefers: the manifest and the folder its clips are
# read from (--data-dir). Baked blobs stay in build/ (the Bandai Namco
# licence forbids committing anything derived from the clips).
DEMO_REAL_MANIFEST ?= data/bandai.manifest
DEMO_REAL_DATA ?= $(SMG_SHARED)/mocap/bandai-namco
DEMO_REAL_BLOB ?= $(BUILD)/$(basename $(notdir $(DEMO_REAL_MANIFEST))).smg
# The library the demo links; a static libsmg.a keeps the binary relocatable.
DEMO_LIBSMG ?= $(LIBSMG_A)
DEMO_ARGS ?=

ALL_TARGETS += $(DEMO_BIN) $(DEMO_PNGCHECK) $(DEMO_BODYTEST) $(DEMO_BODYGLTF)

# Third-party headers are -isystem so -Werror applies to our code only.
DEMO_IMGUI_INC := $(shell pkg-config --variable=includedir imgui 2>/dev/null || echo /usr/include/imgui)
DEMO_SDL_CFLAGS := $(patsubst -I%,-isystem %,$(shell pkg-config --cflags sdl2 2>/dev/null || echo -I/usr/include/SDL2 -D_REENTRANT))
DEMO_SDL_LIBS := $(shell pkg-config --libs sdl2 2>/dev/null || echo -lSDL2)
DEMO_CXXFLAGS := -std=c++17 -Wall -Wextra -Werror $(OPT) -Iinclude $(DEMO_SDL_CFLAGS) \
  -isystem $(DEMO_IMGUI_INC) -isystem $(DEMO_IMGUI_INC)/backends -isystem /usr/include/stb \
  -DSMG_DEMO_DEFAULT_GRAPH='"$(notdir $(DEMO_DEFAULT_BLOB))"'
DEMO_LDLIBS := -limgui -lstb $(DEMO_SDL_LIBS) -ldl -lm

# Xvfb with Mesa's software rasteriser: deterministic pictures, no GPU.
DEMO_XVFB := xvfb-run -a -s "-screen 0 1280x720x24"
DEMO_HEADLESS_ENV := LIBGL_ALWAYS_SOFTWARE=1

$(BUILD)/obj/demo/%.o: demo/%.cpp $(wildcard demo/*.h) include/smg.h
	@mkdir -p $(dir $@)
	$(CXX) $(DEMO_CXXFLAGS) -c $< -o $@

$(DEMO_BIN): $(DEMO_OBJ) $(DEMO_LIBSMG)
	@mkdir -p $(dir $@)
	$(CXX) -o $@ $(DEMO_OBJ) $(DEMO_LIBSMG) $(DEMO_LDLIBS)

$(DEMO_PNGCHECK): demo/tools/png_check.cpp
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 -Wall -Wextra -Werror $(OPT) -isystem /usr/include/stb $< -o $@ -lstb -lm

# The generated body's unit test: the demo's body code and libsmg, no GL.
$(DEMO_BODYTEST): demo/tools/body_test.cpp $(DEMO_BODY_OBJ) $(DEMO_LIBSMG) demo/body.h demo/body_graph.h
	@mkdir -p $(dir $@)
	$(CXX) $(DEMO_CXXFLAGS) $< $(DEMO_BODY_OBJ) $(DEMO_LIBSMG) -o $@ -lm

# The generated body as a glTF file for engines (the Godot demo loads it),
# through the export tools' glTF writer (mk/gltf.mk, named by path: that
# fragment is read after this one).
$(DEMO_BODYGLTF): demo/tools/body_gltf.cpp $(BUILD)/libsmg_gltf.a $(DEMO_LIBSMG) $(wildcard tools/gltf/*.h)
	@mkdir -p $(dir $@)
	$(CXX) $(DEMO_CXXFLAGS) -Itools/gltf $< $(BUILD)/libsmg_gltf.a $(DEMO_LIBSMG) -o $@ -lm

.PHONY: demo demo-cmu test-demo demo-pictures demo-build
demo-build: $(DEMO_BIN) $(DEMO_PNGCHECK) $(DEMO_BODYTEST) $(DEMO_BODYGLTF)

# Real clips when they are there (baked when missing or older than the
# manifest or the baker); the synthetic default otherwise, or when that
# bake fails, so `make demo` works on a bare machine.
demo: $(DEMO_BIN) $(DEMO_DEFAULT_BLOB) $(BUILD)/smg-bake
	@graph=$(DEMO_DEFAULT_BLOB); \
	if [ -d "$(DEMO_REAL_DATA)" ] && [ -f "$(DEMO_REAL_MANIFEST)" ]; then \
	  if [ ! -f "$(DEMO_REAL_BLOB)" ] || [ "$(DEMO_REAL_MANIFEST)" -nt "$(DEMO_REAL_BLOB)" ] || \
	      [ "$(BUILD)/smg-bake" -nt "$(DEMO_REAL_BLOB)" ]; then \
	    echo "demo: baking $(DEMO_REAL_BLOB) from $(DEMO_REAL_MANIFEST)"; \
	    $(BUILD)/smg-bake -m $(DEMO_REAL_MANIFEST) --data-dir $(DEMO_REAL_DATA) -o $(DEMO_REAL_BLOB) || \
	      rm -f $(DEMO_REAL_BLOB); fi; \
	  if [ -f "$(DEMO_REAL_BLOB)" ]; then graph=$(DEMO_REAL_BLOB); fi; \
	else echo "demo: no clips at $(DEMO_REAL_DATA) (set SMG_SHARED): using the synthetic default graph"; fi; \
	echo "demo: running on $$graph"; \
	$(DEMO_BIN) --graph $$graph $(DEMO_ARGS)

# Bakes the CMU blob when missing or older than the manifest or the baker.
define demo_bake_cmu
	@if [ ! -d "$(SMG_SHARED)/mocap/cmu" ]; then \
	  echo "demo-cmu: the CMU clips are not at $(SMG_SHARED)/mocap/cmu (set SMG_SHARED=/path/to/shared)"; exit 1; fi
	@if [ ! -f "$(DEMO_CMU_MANIFEST)" ]; then echo "demo-cmu: $(DEMO_CMU_MANIFEST) is missing"; exit 1; fi
	@if [ ! -f "$(DEMO_CMU_BLOB)" ] || [ "$(DEMO_CMU_MANIFEST)" -nt "$(DEMO_CMU_BLOB)" ] || \
	    [ "$(BUILD)/smg-bake" -nt "$(DEMO_CMU_BLOB)" ]; then \
	  echo "demo-cmu: baking $(DEMO_CMU_BLOB) from $(DEMO_CMU_MANIFEST)"; \
	  $(BUILD)/smg-bake -m $(DEMO_CMU_MANIFEST) --data-dir $(SMG_SHARED)/mocap/cmu -o $(DEMO_CMU_BLOB) || exit 1; fi
endef

demo-cmu: $(DEMO_BIN) $(BUILD)/smg-bake
	$(demo_bake_cmu)
	$(DEMO_BIN) --graph $(DEMO_CMU_BLOB) $(DEMO_ARGS)

# Smoke test (demo/tools/test_demo.sh, details in docs/demo.md): scripted
# drawings rendered headless on a private Xvfb with Mesa's software GL; the
# checker verifies size, non-blank, path and character pixels; a second run
# must be byte-identical (fixed dt); the HUD must render; mouse.txt draws,
# clicks, drags and deletes through the real input handler; robustness.sh
# feeds bad graphs, sizes, scripts and a GL 3.0-only context.
DEMO_TEST_DIR := $(BUILD)/tests/demo
test-demo: $(DEMO_BIN) $(DEMO_PNGCHECK) $(DEMO_BODYTEST) $(DEMO_BODYGLTF) $(DEMO_DEFAULT_BLOB)
	@sh demo/tools/test_demo.sh $(DEMO_BIN) $(DEMO_PNGCHECK) $(DEMO_DEFAULT_BLOB) $(DEMO_TEST_DIR) $(DEMO_BODYTEST) \
	  $(DEMO_BODYGLTF)

TEST_TARGETS += test-demo

# Pictures for docs/: the CMU set, rendered headless.
demo-pictures: $(DEMO_BIN) $(BUILD)/smg-bake
	$(demo_bake_cmu)
	$(DEMO_HEADLESS_ENV) $(DEMO_XVFB) $(DEMO_BIN) --graph $(DEMO_CMU_BLOB) --script demo/scripts/walk-run-punch.txt \
	  --frames 515 --width 1280 --height 720 --screenshot docs/img/demo-walk-run-punch.png
	$(DEMO_HEADLESS_ENV) $(DEMO_XVFB) $(DEMO_BIN) --graph $(DEMO_CMU_BLOB) --script demo/scripts/s-curve.txt \
	  --frames 960 --width 1280 --height 720 --screenshot docs/img/demo-s-curve.png
	$(DEMO_HEADLESS_ENV) $(DEMO_XVFB) $(DEMO_BIN) --graph $(DEMO_CMU_BLOB) --script demo/scripts/closeup.txt \
	  --frames 515 --width 1280 --height 540 --screenshot docs/img/demo-skinned.png
	$(DEMO_HEADLESS_ENV) $(DEMO_XVFB) $(DEMO_BIN) --graph $(DEMO_CMU_BLOB) --script demo/scripts/crowd.txt \
	  --characters 100 --frames 600 --width 1280 --height 720 --screenshot docs/img/demo-crowd.png
