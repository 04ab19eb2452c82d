# SDL2 + OpenGL 3.3 demo (demo/): build/smg-demo links libsmg only through
# include/smg.h, like any engine. C++17 with GLM and Dear ImGui (Debian's
# libimgui-dev ships imgui plus its SDL2/OpenGL3 backends in libimgui.a).
#
#   make demo              run on the embedded default graph (build/default.smg)
#   make demo DEMO_ARGS="--characters 50"
#   make demo-cmu          bake the CMU set from $(SMG_SHARED) and run on it
#   make test-demo         headless smoke test (part of `make test`)
#   make demo-pictures     regenerate docs/img/demo-*.png from the CMU set

SMG_SHARED ?= ../shared
DEMO_SRC := $(sort $(wildcard demo/*.cpp))
DEMO_OBJ := $(DEMO_SRC:%.cpp=$(BUILD)/obj/%.o)
DEMO_BIN := $(BUILD)/smg-demo
DEMO_PNGCHECK := $(BUILD)/smg-demo-pngcheck
DEMO_DEFAULT_BLOB := $(BUILD)/default.smg
DEMO_CMU_BLOB := $(BUILD)/cmu.smg
DEMO_CMU_MANIFEST := data/cmu.manifest
# The library the demo links; a static libsmg.a keeps the binary relocatable.
DEMO_LIBSMG ?= $(LIBSMG_A)
DEMO_ARGS ?=

ALL_TARGETS += $(DEMO_BIN) $(DEMO_PNGCHECK)

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

.PHONY: demo demo-cmu test-demo demo-pictures demo-build
demo-build: $(DEMO_BIN) $(DEMO_PNGCHECK)

demo: $(DEMO_BIN) $(DEMO_DEFAULT_BLOB)
	$(DEMO_BIN) --graph $(DEMO_DEFAULT_BLOB) $(DEMO_ARGS)

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
test-demo: $(DEMO_BIN) $(DEMO_PNGCHECK) $(DEMO_DEFAULT_BLOB)
	@sh demo/tools/test_demo.sh $(DEMO_BIN) $(DEMO_PNGCHECK) $(DEMO_DEFAULT_BLOB) $(DEMO_TEST_DIR)

TEST_TARGETS += test-demo

# Pictures for docs/: the CMU set, rendered headless.
demo-pictures: $(DEMO_BIN) $(BUILD)/smg-bake
	$(demo_bake_cmu)
	$(DEMO_HEADLESS_ENV) $(DEMO_XVFB) $(DEMO_BIN) --graph $(DEMO_CMU_BLOB) --script demo/scripts/walk-run-punch.txt \
	  --frames 515 --width 1280 --height 720 --screenshot docs/img/demo-walk-run-punch.png
	$(DEMO_HEADLESS_ENV) $(DEMO_XVFB) $(DEMO_BIN) --graph $(DEMO_CMU_BLOB) --script demo/scripts/s-curve.txt \
	  --frames 960 --width 1280 --height 720 --screenshot docs/img/demo-s-curve.png
	$(DEMO_HEADLESS_ENV) $(DEMO_XVFB) $(DEMO_BIN) --graph $(DEMO_CMU_BLOB) --script demo/scripts/crowd.txt \
	  --characters 100 --frames 600 --width 1280 --height 720 --screenshot docs/img/demo-crowd.png
