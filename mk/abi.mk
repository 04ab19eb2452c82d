# ABI gate (docs/abi.md): libsmg.so against the committed baseline of the
# released ABI, tests/abi/libsmg.abi (abidw output, Debian abigail-tools).
#
#   make test-abi      (part of `make test`) fails on any incompatible change
#                      unless the soname major changed; lists compatible
#                      additions; then proves the gate both ways on modified
#                      copies of the library (tests/abi/check_abi_gate.sh)
#   make abi-baseline  renew the baseline from this tree (at a release)

ABI_BASELINE := tests/abi/libsmg.abi
ABI_SO := $(BUILD)/libsmg.so.$(SONAME_MAJOR)
ABIDW_FLAGS := --no-corpus-path --no-comp-dir-path --short-locs --headers-dir include \
  --drop-private-types --drop-undefined-syms

TEST_TARGETS += test-abi

.PHONY: test-abi abi-baseline
test-abi: $(LIBSMG_SO)
	@sh tests/abi/check_abi.sh $(ABI_BASELINE) $(ABI_SO) include
	@sh tests/abi/check_abi_gate.sh "$(CC)"

abi-baseline: $(LIBSMG_SO)
	abidw $(ABIDW_FLAGS) --out-file $(ABI_BASELINE) $(ABI_SO)
	@echo "abi-baseline: wrote $(ABI_BASELINE) from $(ABI_SO); commit it"
