#!/bin/sh
# check_abi_gate.sh CC - proves the ABI gate (check_abi.sh) works both ways.
# A copy of the runtime is built as libsmg.so.0 (-O0 -g), its abidw output
# is the baseline, and modified copies are checked against it:
#   must pass: fields appended at the end of struct_size structs plus a new
#              function; the unchanged library; a removed function under a
#              new soname major
#   must fail: a field inserted in the middle of a struct_size struct,
#              two fields swapped, a removed function, a changed enum
#              value, a field appended to a struct without struct_size
set -eu
cc=${1:-cc}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"

# variant NAME [SONAME_MAJOR]: copy the sources into NAME/, the caller
# edits them, then build NAME/libsmg.so
variant() {
  mkdir -p "$1"
  cp -r "$root/include" "$root/libsmg" "$1/"
}
build() {
  (cd "$1" && $cc -std=c99 -O0 -g -fPIC -fvisibility=hidden -DSMG_BUILD_SHARED \
    -D_POSIX_C_SOURCE=200809L -Iinclude -Ilibsmg/common -Ilibsmg/runtime \
    -shared -Wl,-soname,libsmg.so.${2:-0} -o libsmg.so \
    libsmg/common/*.c libsmg/runtime/*.c -lm)
}
# edit FILE PATTERN REPLACEMENT: sed on the first line matching PATTERN
edit() {
  grep -q "$2" "$1" || { echo "check_abi_gate: '$2' not in $1" >&2; exit 1; }
  sed -i "0,/$2/s//$3/" "$1"
}
expect() { # expect pass|fail NAME
  if sh "$here/check_abi.sh" base.abi "$2/libsmg.so" "$2/include" > "$2.log" 2>&1; then
    got=pass
  else
    got=fail
  fi
  if [ "$got" != "$1" ]; then
    cat "$2.log"
    echo "test-abi: FAILED: the gate should $1 '$2' but did $got" >&2
    exit 1
  fi
  echo "  gate $got: $2"
}

variant base
build base
abidw --no-corpus-path --no-comp-dir-path --short-locs --headers-dir base/include \
  --drop-private-types --drop-undefined-syms --out-file base.abi base/libsmg.so

expect pass base

variant appended
edit appended/include/smg.h '^} smg_character_desc;' \
  '  float appended_a;\n  uint32_t appended_b;\n&'
edit appended/include/smg.h '^} smg_character_state;' '  float appended_c;\n&'
edit appended/include/smg.h '^SMG_API const char\* smg_result_string' \
  'SMG_API smg_result smg_abi_gate_added(uint32_t x);\n&'
printf '\nSMG_API smg_result smg_abi_gate_added(uint32_t x) { return x ? SMG_OK : SMG_ERROR_INVALID_ARGUMENT; }\n' \
  >> appended/libsmg/common/result.c
build appended
expect pass appended

variant inserted
edit inserted/include/smg.h '  float heading;             \/\* start heading' \
  '  float inserted;\n&'
build inserted
expect fail inserted

variant swapped
edit swapped/include/smg.h '  uint32_t initial_style; ' '  uint32_t initial_action_x;'
edit swapped/include/smg.h '  uint32_t initial_action; ' '  uint32_t initial_style;'
edit swapped/include/smg.h '  uint32_t initial_action_x;' '  uint32_t initial_action;'
build swapped
expect fail swapped

variant removed
edit removed/include/smg.h '^SMG_API smg_result smg_character_get_path_length(' \
  'smg_result smg_character_get_path_length_gone('
edit removed/libsmg/runtime/character.c '^SMG_API smg_result smg_character_get_path_length(' \
  'smg_result smg_character_get_path_length_gone('
build removed
expect fail removed

variant enum
edit enum/include/smg.h '  SMG_ERROR_IO = 3,' '  SMG_ERROR_IO = 30,'
build enum
expect fail enum

variant unversioned
edit unversioned/include/smg.h '  void\* user;' '&\n  uint32_t appended;'
build unversioned
expect fail unversioned

variant major
edit major/include/smg.h '^SMG_API smg_result smg_character_get_path_length(' \
  'smg_result smg_character_get_path_length_gone('
edit major/libsmg/runtime/character.c '^SMG_API smg_result smg_character_get_path_length(' \
  'smg_result smg_character_get_path_length_gone('
build major 1
expect pass major
echo "test-abi: the gate passes compatible changes and fails incompatible ones"
