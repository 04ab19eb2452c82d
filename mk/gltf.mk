# The glTF writer the export tools share (tools/gltf/): a character's
# skeleton, skinned mesh and sampled animation as .glb or .gltf, written
# atomically (C), and the demo's generated body (demo/body.h, C++ with GLM)
# as that writer's skeleton and mesh. smg-synth (--glb) and smg-body-gltf
# link it, so they are linked as C++; it uses libsmg only through smg.h.
#
#   build/libsmg_gltf.a

GLTF_SRC := $(sort $(wildcard tools/gltf/*.c))
GLTF_HDR := $(wildcard tools/gltf/*.h)
LIBSMG_GLTF_A := $(BUILD)/libsmg_gltf.a
# the body generator is the demo's (demo.mk builds its objects)
GLTF_OBJ := $(GLTF_SRC:%.c=$(BUILD)/obj/%.o) $(BUILD)/obj/tools/gltf/gltf_body.o $(DEMO_BODY_OBJ)
GLTF_LDLIBS := -lm

ALL_TARGETS += $(LIBSMG_GLTF_A)

$(BUILD)/obj/tools/gltf/%.o: tools/gltf/%.c $(GLTF_HDR) include/smg.h
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -Itools/gltf -c $< -o $@

$(BUILD)/obj/tools/gltf/gltf_body.o: tools/gltf/gltf_body.cpp $(GLTF_HDR) demo/body.h demo/body_graph.h include/smg.h
	@mkdir -p $(dir $@)
	$(CXX) $(DEMO_CXXFLAGS) -Itools/gltf -c $< -o $@

$(LIBSMG_GLTF_A): $(GLTF_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@ && ar rcs $@ $^

# Its test links the writer, so it is linked as C++ (this explicit rule
# takes precedence over the tests' pattern rule in mk/tests.mk).
$(BUILD)/tests/export/test_gltf_export: tests/export/test_gltf_export.c $(LIBSMG_GLTF_A) $(LIBSMG_A) $(GLTF_HDR) $(LIB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TOOL) -Itests -Itools/gltf -DSMG_SHARED_DIR='"$(SMG_SHARED)"' -DSMG_BUILD_DIR='"$(BUILD)"' -c $< -o $@.o
	$(CXX) $(OPT) $@.o -o $@ $(LIBSMG_GLTF_A) $(LIBSMG_A) -lcmocka $(BAKE_LDLIBS) -lm
