# libsmg top-level Makefile.
#
# Each part of the project owns one fragment in mk/ and adds its outputs to
# the shared lists below, so parts can grow without editing each other:
#   ALL_TARGETS    built by `make`
#   TEST_TARGETS   run by `make test` (each must fail the build on failure)
#   BENCH_TARGETS  run by `make bench` (print figures; never pass/fail on time)
# Layout: include/ (public headers), libsmg/common (blob container, shared by
# runtime and baker), libsmg/runtime (libsmg.a/.so), libsmg/bake (offline,
# libsmg_bake.a, links assimp), tools/ (CLIs), tests/, demo/, bindings/.

PREFIX ?= /usr/local
DESTDIR ?=
BUILD ?= build

CC ?= cc
CXX ?= c++
OPT ?= -O2 -g
WARN := -Wall -Wextra -Wpedantic -Werror
CSTD := -std=c99
CPPFLAGS_COMMON := -Iinclude -Ilibsmg/common -D_POSIX_C_SOURCE=200809L
# The library never reads errno after a math call, so sqrtf compiles to
# the bare instruction (no NaN check with a libm call behind it); results
# are the same bits.
MATHFLAGS := -fno-math-errno -ffp-contract=off
CFLAGS_LIB := $(CSTD) $(WARN) $(OPT) $(MATHFLAGS) -fPIC -fvisibility=hidden $(CPPFLAGS_COMMON)
CFLAGS_TOOL := $(CSTD) $(WARN) $(OPT) $(CPPFLAGS_COMMON) -Ilibsmg/bake -Ilibsmg/runtime
LDLIBS_M := -lm

ALL_TARGETS :=
TEST_TARGETS :=
BENCH_TARGETS :=

.DEFAULT_GOAL := all

# lib.mk and bake.mk define the libraries others link; every other fragment
# (tools, tests, demo, godot, eval, ...) is picked up automatically.
include mk/lib.mk
include mk/bake.mk
include $(filter-out mk/lib.mk mk/bake.mk,$(sort $(wildcard mk/*.mk)))

.PHONY: all test bench clean deps
all: $(ALL_TARGETS)

# The core suites run first, then every other part's target. Every target
# runs even when an earlier one failed, so one red part does not hide the
# state of the others; the run fails if any target failed.
TEST_FIRST := test-unit test-valgrind
TEST_ORDER := $(filter $(TEST_FIRST),$(TEST_TARGETS)) $(filter-out $(TEST_FIRST),$(TEST_TARGETS))
test: all
	@failed=""; for t in $(TEST_ORDER); do \
	  echo "######## $$t"; \
	  $(MAKE) --no-print-directory $$t || failed="$$failed $$t"; \
	done; \
	if [ -n "$$failed" ]; then echo "make test: FAILED:$$failed"; exit 1; fi; \
	echo "make test: all test targets passed ($(TEST_ORDER))"

bench: all
	@set -e; for t in $(BENCH_TARGETS); do $(MAKE) --no-print-directory $$t; done

clean:
	rm -rf $(BUILD)

# Installs every Debian package the project needs (as root, or through sudo
# when not root), else prints the exact command and fails.
deps:
	@sh tools/deps.sh
