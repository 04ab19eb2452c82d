# Release artifacts (docs/packaging.md), versioned from smg.h:
#
#   make dist   dist/libsmg-VERSION-linux-x86_64.tar.gz
#               dist/libsmg-VERSION-windows-x86_64.zip
#               dist/com.libsmg.smg-VERSION.tgz   (the Unity package)
#               dist/libsmg-godot-addon-VERSION.zip (mk/godot.mk's zip,
#                                                   when that part has it)
#   make test-unity-package  (part of `make test`) the Unity tarball holds
#               a .meta for every file and folder, both native plugins with
#               their platforms, and no reference to a missing asset
#
# The archives hold the headers, the libraries (static, shared, and the
# Windows import library), pkg-config files that work wherever the
# archive is unpacked (prefix from ${pcfiledir}), smg-bake and smg-synth,
# README, LICENSE and docs/. Archive members are sorted, owned by 0:0 and
# dated at the last commit, so the same tree packs the same bytes.

DIST_DIR := dist
SMG_VERSION_STR := $(shell sed -n 's/^\#define SMG_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)$$/\2/p' include/smg.h | paste -sd.)
DIST_STAGE := $(BUILD)/dist-stage
DIST_LINUX := libsmg-$(SMG_VERSION_STR)-linux-x86_64
DIST_WINDOWS := libsmg-$(SMG_VERSION_STR)-windows-x86_64
DIST_UNITY := com.libsmg.smg-$(SMG_VERSION_STR).tgz
DIST_DATE := $(shell git log -1 --format=%ct 2>/dev/null || echo 0)
DIST_TAR := tar --sort=name --owner=0 --group=0 --numeric-owner --mtime=@$(DIST_DATE)
DIST_DOCS := README.md LICENSE docs
# the Godot part's addon zip, when its fragment defines the target
DIST_GODOT := $(if $(shell grep -s -l '^godot-addon-zip:' mk/godot.mk),godot-addon-zip)
DIST_GODOT_ZIP := $(BUILD)/dist/libsmg-godot-addon-$(SMG_VERSION_STR).zip
# by path: these come from fragments included after this one
DIST_WIN_BUILD := $(BUILD)/windows
DIST_WIN_FILES := $(addprefix $(DIST_WIN_BUILD)/,libsmg.dll libsmg.a libsmg_bake.a smg-synth.exe smg-bake.exe)
DIST_UNITY_STAGE := $(BUILD)/unity/package

TEST_TARGETS += test-unity-package

.PHONY: dist dist-linux dist-windows dist-unity test-unity-package
dist: dist-linux dist-windows dist-unity $(DIST_GODOT)
	$(if $(DIST_GODOT),cp $(DIST_GODOT_ZIP) $(DIST_DIR)/)
	@cd $(DIST_DIR) && ls -l $(DIST_LINUX).tar.gz $(DIST_WINDOWS).zip $(DIST_UNITY) $(if $(DIST_GODOT),$(notdir $(DIST_GODOT_ZIP)))

# make install into a scratch prefix, then the pkg-config files made
# relocatable
dist-linux: $(LIBSMG_A) $(LIBSMG_SO) $(LIBSMG_BAKE_A) $(SMG_BAKE) $(SMG_SYNTH)
	@rm -rf $(DIST_STAGE)/linux && mkdir -p $(DIST_STAGE)/linux $(DIST_DIR)
	$(MAKE) --no-print-directory install PREFIX=/usr DESTDIR=$(abspath $(DIST_STAGE)/linux/root) >/dev/null
	@mv $(DIST_STAGE)/linux/root/usr $(DIST_STAGE)/linux/$(DIST_LINUX)
	@strip --strip-unneeded $(DIST_STAGE)/linux/$(DIST_LINUX)/lib/libsmg.so.$(LIB_VERSION) $(DIST_STAGE)/linux/$(DIST_LINUX)/bin/*
	@sed -i 's|^prefix=.*|prefix=$${pcfiledir}/../..|; s|^libdir=.*|libdir=$${prefix}/lib|; s|^includedir=.*|includedir=$${prefix}/include|' \
	  $(DIST_STAGE)/linux/$(DIST_LINUX)/lib/pkgconfig/*.pc
	@cp -r $(DIST_DOCS) $(DIST_STAGE)/linux/$(DIST_LINUX)/
	$(DIST_TAR) -C $(DIST_STAGE)/linux -cf - $(DIST_LINUX) | gzip -n9 > $(DIST_DIR)/$(DIST_LINUX).tar.gz

# MinGW users link the import library (-lsmg finds libsmg.dll.a) or
# libsmg.a; MSVC users make an import library from libsmg.def
# (docs/windows.md).
dist-windows: $(DIST_WIN_FILES)
	@rm -rf $(DIST_STAGE)/windows && mkdir -p $(DIST_STAGE)/windows/$(DIST_WINDOWS) $(DIST_DIR)
	@cd $(DIST_STAGE)/windows/$(DIST_WINDOWS) && mkdir -p bin lib/pkgconfig include
	cp $(DIST_WIN_BUILD)/libsmg.dll $(DIST_WIN_BUILD)/smg-synth.exe $(DIST_WIN_BUILD)/smg-bake.exe $(DIST_STAGE)/windows/$(DIST_WINDOWS)/bin/
	cp $(DIST_WIN_BUILD)/libsmg.dll.a $(DIST_WIN_BUILD)/libsmg.def $(DIST_WIN_BUILD)/libsmg.a $(DIST_WIN_BUILD)/libsmg_bake.a \
	  $(DIST_STAGE)/windows/$(DIST_WINDOWS)/lib/
	cp include/smg.h include/smg_bake.h $(DIST_STAGE)/windows/$(DIST_WINDOWS)/include/
	@printf '%s\n' 'prefix=$${pcfiledir}/../..' 'libdir=$${prefix}/lib' 'includedir=$${prefix}/include' '' \
	  'Name: smg' 'Description: Splicing Motion Graphs runtime (path-following characters from motion capture)' \
	  'Version: $(SMG_VERSION_STR)' 'Libs: -L$${libdir} -lsmg' 'Cflags: -I$${includedir}' \
	  > $(DIST_STAGE)/windows/$(DIST_WINDOWS)/lib/pkgconfig/smg.pc
	@cp -r $(DIST_DOCS) $(DIST_STAGE)/windows/$(DIST_WINDOWS)/
	@rm -f $(DIST_DIR)/$(DIST_WINDOWS).zip
	cd $(DIST_STAGE)/windows && find $(DIST_WINDOWS) -exec touch -h -d @$(DIST_DATE) {} + && \
	  find $(DIST_WINDOWS) | LC_ALL=C sort | zip -X -q -@ $(abspath $(DIST_DIR))/$(DIST_WINDOWS).zip

dist-unity: $(DIST_DIR)/$(DIST_UNITY)
$(DIST_DIR)/$(DIST_UNITY): $(DIST_UNITY_STAGE).stamp
	@mkdir -p $(DIST_DIR)
	$(DIST_TAR) -C $(dir $(DIST_UNITY_STAGE)) -cf - package | gzip -n9 > $@

# the tarball is checked as a user would get it, from a build of its own
test-unity-package: $(DIST_UNITY_STAGE).stamp
	@rm -rf $(DIST_STAGE)/unity-test && mkdir -p $(DIST_STAGE)/unity-test
	@$(DIST_TAR) -C $(dir $(DIST_UNITY_STAGE)) -cf - package | gzip -n9 > $(DIST_STAGE)/unity-test/$(DIST_UNITY)
	@python3 tests/dist/check_unity_tarball.py $(DIST_STAGE)/unity-test/$(DIST_UNITY) $(SMG_VERSION_STR)
