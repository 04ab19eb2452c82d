# Unity package (bindings/unity): the C# interop layer tested outside Unity
# with Debian's mono (mcs, C# 7.2 with Span<T>), against the real
# libsmg.so in $(BUILD) (DllImport("smg") finds $(BUILD)/libsmg.so through
# LD_LIBRARY_PATH).
#
#   make test-csharp     (part of `make test`) struct layouts and constants
#                        vs the C compiler, every exported smg_ function
#                        declared, 10^4 frames bit for bit vs the C API on
#                        build/default.smg (and build/cmu.smg when ../shared
#                        has the CMU clips), error paths, handle lifetime
#                        under GC churn, threads, the left-handed frame
#                        conversion vs libsmg's matrices, no allocation per
#                        frame; the Unity layer and sample type-checked;
#                        the package's NUnit tests (Tests/Runtime: events,
#                        engine mover, uneven ground, humanoid mapping,
#                        blend weights, ...) run with nunit-console
#   make bench-csharp    (part of `make bench`) managed step + pose per
#                        character vs the same calls from C, medians, ratio
#   make unity-package   the installable package in build/unity/package
#                        (add it from disk; `make dist` packs it)

MCS ?= mcs
MONO ?= mono
# -unsafe only where the asmdef allows it (Smg.Interop) and for the tests
MCS_FLAGS := -langversion:7.2 -warnaserror -nologo
UNITY_DIR := bindings/unity
CSHARP_BUILD := $(BUILD)/csharp
CSHARP_INTEROP_SRC := $(sort $(wildcard $(UNITY_DIR)/Runtime/Interop/*.cs))
CSHARP_INTEROP_DLL := $(CSHARP_BUILD)/Smg.Interop.dll
CSHARP_TEST_EXE := $(CSHARP_BUILD)/smg-csharp-tests.exe
CSHARP_BENCH_EXE := $(CSHARP_BUILD)/bench-csharp.exe
CSHARP_LAYOUT := $(CSHARP_BUILD)/layout
CSHARP_REPLAY := $(CSHARP_BUILD)/c_replay
CSHARP_BENCH_C := $(CSHARP_BUILD)/bench_csharp_c
CSHARP_FRAMES ?= 10000
CSHARP_RUN := LD_LIBRARY_PATH=$(abspath $(BUILD)) MONO_PATH=$(abspath $(CSHARP_BUILD)) $(MONO) --debug
# the CMU blob joins the checks when ../shared has the clips (mk/tools.mk)
CSHARP_BLOBS := $(DEFAULT_BLOB) $(if $(wildcard $(SMG_SHARED)/mocap/cmu/09_12.bvh),$(CMU_BLOB))

TEST_TARGETS += test-csharp
BENCH_TARGETS += bench-csharp

$(CSHARP_INTEROP_DLL): $(CSHARP_INTEROP_SRC)
	@mkdir -p $(dir $@)
	$(MCS) $(MCS_FLAGS) -unsafe -target:library -out:$@ $(CSHARP_INTEROP_SRC)

# The Unity layer and the sample, type-checked against a declared surface
# of the UnityEngine members they use (tests/csharp/unity-surface: extern
# declarations with Unity's signatures, no behaviour; Unity is not here).
CSHARP_UNITY_SURFACE := $(CSHARP_BUILD)/unity-surface/UnityEngine.dll
CSHARP_UNITY_DLL := $(CSHARP_BUILD)/unity-surface/Smg.Unity.dll
CSHARP_SAMPLE_DLL := $(CSHARP_BUILD)/unity-surface/Smg.Samples.PathFollower.dll
UNITY_SAMPLE_SRC := $(sort $(wildcard $(UNITY_DIR)/Samples~/PathFollower/*.cs))

$(CSHARP_UNITY_SURFACE): tests/csharp/unity-surface/UnityEngineSurface.cs
	@mkdir -p $(dir $@)
	$(MCS) $(MCS_FLAGS) -nowarn:626,824 -target:library -out:$@ $<

$(CSHARP_UNITY_DLL): $(sort $(wildcard $(UNITY_DIR)/Runtime/Unity/*.cs)) $(CSHARP_INTEROP_DLL) $(CSHARP_UNITY_SURFACE)
	$(MCS) $(MCS_FLAGS) -target:library -r:$(CSHARP_INTEROP_DLL) -r:$(CSHARP_UNITY_SURFACE) -out:$@ $(filter %.cs,$^)

$(CSHARP_SAMPLE_DLL): $(UNITY_SAMPLE_SRC) $(CSHARP_UNITY_DLL)
	$(MCS) $(MCS_FLAGS) -target:library -r:$(CSHARP_INTEROP_DLL) -r:$(CSHARP_UNITY_SURFACE) -r:$(CSHARP_UNITY_DLL) \
	  -out:$@ $(UNITY_SAMPLE_SRC)

$(CSHARP_TEST_EXE): $(sort $(wildcard tests/csharp/*.cs)) $(CSHARP_INTEROP_DLL)
	$(MCS) $(MCS_FLAGS) -unsafe -r:$(CSHARP_INTEROP_DLL) -r:System.Core.dll -out:$@ $(filter %.cs,$^)

# The package's own tests (bindings/unity/Tests/Runtime, NUnit: Unity's
# Test Runner runs them in the editor) with Debian's NUnit 2.6 console
# runner, beside a copy of Smg.Interop.dll; they load $(DEFAULT_BLOB).
# A test that did not run (ignored: no blob, one application domain) fails
# the target here, where everything it needs is present.
NUNIT_FRAMEWORK := /usr/lib/cli/nunit.framework-2.6.3/nunit.framework.dll
NUNIT_CONSOLE ?= nunit-console
CSHARP_PKG_TEST_DIR := $(CSHARP_BUILD)/package-tests
CSHARP_PKG_TEST_DLL := $(CSHARP_PKG_TEST_DIR)/Smg.Tests.Runtime.dll
CSHARP_PKG_TEST_SRC := $(sort $(wildcard $(UNITY_DIR)/Tests/Runtime/*.cs))

$(CSHARP_PKG_TEST_DLL): $(CSHARP_PKG_TEST_SRC) $(CSHARP_INTEROP_DLL)
	@mkdir -p $(dir $@)
	cp $(CSHARP_INTEROP_DLL) $(CSHARP_PKG_TEST_DIR)/
	$(MCS) $(MCS_FLAGS) -target:library -r:$(CSHARP_PKG_TEST_DIR)/Smg.Interop.dll -r:$(NUNIT_FRAMEWORK) -out:$@ $(CSHARP_PKG_TEST_SRC)

$(CSHARP_BENCH_EXE): bench/BenchCsharp.cs $(CSHARP_INTEROP_DLL)
	$(MCS) $(MCS_FLAGS) -unsafe -r:$(CSHARP_INTEROP_DLL) -out:$@ $<

# smg.h as the C compiler lays it out (tests/csharp/gen_c_layout.py)
$(CSHARP_LAYOUT).c: include/smg.h tests/csharp/gen_c_layout.py
	@mkdir -p $(dir $@)
	python3 tests/csharp/gen_c_layout.py include/smg.h > $@

$(CSHARP_LAYOUT): $(CSHARP_LAYOUT).c include/smg.h
	$(CC) $(CSTD) $(WARN) -Iinclude $< -o $@

# the C helpers link the same shared library the C# code loads
$(CSHARP_REPLAY): tests/csharp/c_replay.c include/smg.h $(LIBSMG_SO)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) $(OPT) -Iinclude $< -o $@ $(LIBSMG_SO)

$(CSHARP_BENCH_C): bench/bench_csharp_c.c include/smg.h $(LIBSMG_SO)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) $(OPT) $(CPPFLAGS_COMMON) $< -o $@ $(LIBSMG_SO)

.PHONY: test-csharp bench-csharp unity-package
test-csharp: $(CSHARP_SAMPLE_DLL) $(CSHARP_TEST_EXE) $(CSHARP_PKG_TEST_DLL) $(CSHARP_LAYOUT) $(CSHARP_REPLAY) $(LIBSMG_SO) $(CSHARP_BLOBS)
	@$(if $(filter $(CMU_BLOB),$(CSHARP_BLOBS)),,echo "test-csharp: $(SMG_SHARED)/mocap/cmu absent: CMU replay skipped")
	@$(CSHARP_LAYOUT) > $(CSHARP_BUILD)/layout.txt
	@nm -D --defined-only $(LIBSMG_SO) | awk '$$2 == "T" {print $$3}' > $(CSHARP_BUILD)/exports.txt
	$(CSHARP_RUN) $(CSHARP_TEST_EXE) --layout $(CSHARP_BUILD)/layout.txt --exports $(CSHARP_BUILD)/exports.txt \
	  --replay $(CSHARP_REPLAY) --frames $(CSHARP_FRAMES) $(addprefix --blob ,$(CSHARP_BLOBS)) --library $(LIBSMG_SO)
	@cd $(CSHARP_PKG_TEST_DIR) && LD_LIBRARY_PATH=$(abspath $(BUILD)) SMG_TEST_BLOB=$(abspath $(DEFAULT_BLOB)) \
	  $(NUNIT_CONSOLE) -nologo -noshadow -labels -xml=package-tests.xml Smg.Tests.Runtime.dll > package-tests.log 2>&1 \
	  && grep -q 'Not run: 0,' package-tests.log && grep -E '^(\*\*\*\*\*|Tests run)' package-tests.log \
	  || { cat package-tests.log; echo "test-csharp: FAILED: package tests (bindings/unity/Tests/Runtime)"; exit 1; }

bench-csharp: $(CSHARP_BENCH_EXE) $(CSHARP_BENCH_C) $(LIBSMG_SO) $(DEFAULT_BLOB)
	$(CSHARP_RUN) $(CSHARP_BENCH_EXE) $(CSHARP_BENCH_C) 7 $(DEFAULT_BLOB) $(wildcard $(CMU_BLOB))

# The installable package, staged in $(UNITY_STAGE) (Unity's tarball root
# is a folder named "package"): the sources plus LICENSE.md, both native
# plugins, the sample's graph and scene and a .meta for every asset
# (tools/unity_package.py). The Windows DLL comes from mk/windows.mk,
# included after this file: named by path here.
UNITY_STAGE := $(BUILD)/unity/package
UNITY_SRC := $(shell find $(UNITY_DIR) -type f 2>/dev/null)
UNITY_WIN_DLL := $(BUILD)/windows/libsmg.dll

unity-package: $(UNITY_STAGE).stamp
$(UNITY_STAGE).stamp: $(UNITY_SRC) tools/unity_package.py LICENSE include/smg.h $(LIBSMG_SO) $(UNITY_WIN_DLL) $(DEFAULT_BLOB)
	python3 tools/unity_package.py --src $(UNITY_DIR) --out $(UNITY_STAGE) --header include/smg.h \
	  --license LICENSE --linux-so $(LIBSMG_SO) --windows-dll $(UNITY_WIN_DLL) --graph $(DEFAULT_BLOB)
	@touch $@
