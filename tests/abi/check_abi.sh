#!/bin/sh
# check_abi.sh BASELINE.abi LIB.so HEADERS_DIR - the ABI gate (make test-abi).
#
# Compares LIB.so (built with -g) against the committed baseline with
# abidiff (Debian abigail-tools). Fails on any incompatible change: a
# removed or changed function, a changed struct layout, a changed enum
# value. One kind of struct change is compatible and allowed: fields
# appended at the END of a public struct whose first member is struct_size
# (callers built against the older, smaller struct keep working: abi.h's
# rule). Added functions are compatible: they are listed, and pass.
# A new soname major (libsmg.so.N) allows anything: the baseline is then
# stale and `make abi-baseline` renews it (docs/abi.md).
set -eu
baseline=$1
lib=$2
headers=$3

command -v abidiff >/dev/null 2>&1 || {
  echo "test-abi: FAILED: abidiff not found (Debian abigail-tools: make deps)" >&2
  exit 1
}
readelf -S "$lib" | grep -q '\.debug_info' || {
  echo "test-abi: FAILED: $lib has no debug info (build with -g)" >&2
  exit 1
}
old_soname=$(sed -n "s/^<abi-corpus [^>]*soname='\([^']*\)'.*/\1/p" "$baseline" | head -n 1)
new_soname=$(readelf -d "$lib" | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p')

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Every public struct that starts with struct_size may grow at its end.
sed -n '/^typedef struct [a-z0-9_]* {$/{N;s/^typedef struct \([a-z0-9_]*\) {\n  uint32_t struct_size;.*/\1/p}' \
  "$headers"/*.h | sort -u > "$tmp/versioned"
: > "$tmp/supp"
while read -r name; do
  printf '[suppress_type]\n  type_kind = struct\n  name = %s\n  has_data_member_inserted_at = end\n\n' \
    "$name" >> "$tmp/supp"
done < "$tmp/versioned"

if [ "$old_soname" != "$new_soname" ]; then
  echo "test-abi: soname $old_soname -> $new_soname: a new major version may break the ABI;"
  echo "test-abi: the baseline is stale, renew it with 'make abi-baseline'. Changes:"
  abidiff --headers-dir2 "$headers" "$baseline" "$lib" || true
  exit 0
fi

# 1. Without additions: anything left is incompatible.
rc=0
abidiff --no-added-syms --headers-dir2 "$headers" --suppressions "$tmp/supp" \
  "$baseline" "$lib" > "$tmp/incompatible" 2>&1 || rc=$?
if [ $((rc & 3)) -ne 0 ]; then
  cat "$tmp/incompatible" >&2
  echo "test-abi: FAILED: abidiff could not compare (exit $rc)" >&2
  exit 1
fi
if [ "$rc" -ne 0 ]; then
  cat "$tmp/incompatible" >&2
  echo "test-abi: FAILED: incompatible ABI change against $baseline (soname $new_soname)." >&2
  echo "  Keep the ABI (new struct fields go at the END of struct_size structs;" >&2
  echo "  never remove or change a function, an enum value or another struct)," >&2
  echo "  or bump SONAME_MAJOR in mk/lib.mk and renew the baseline (docs/abi.md)." >&2
  exit 1
fi
# 2. The suppression above accepts any change to those structs that comes
#    with an insertion at the end, and abidiff even lets two swapped fields
#    through it: every field they had must keep its offset and type.
abidiff --no-added-syms --headers-dir2 "$headers" "$baseline" "$lib" \
  > "$tmp/structs" 2>&1 || true
if grep -Eq "data members? (change|deletion)|offset changed" "$tmp/structs"; then
  cat "$tmp/structs" >&2
  echo "test-abi: FAILED: a field of a struct_size struct moved, changed or" >&2
  echo "  went away (only appending at the end is compatible)." >&2
  exit 1
fi
# 3. Compatible changes: report them.
abidiff --headers-dir2 "$headers" --suppressions "$tmp/supp" "$baseline" "$lib" \
  > "$tmp/all" 2>&1 || true
added=$(grep -c "^  \[A\]" "$tmp/all" || true)
if [ "$added" -gt 0 ]; then
  echo "test-abi: compatible additions against $baseline:"
  grep "^  \[A\]" "$tmp/all"
fi
grown=$(sed -n "s/.*underlying type 'struct \([a-z0-9_]*\)'.*/\1/p" "$tmp/structs" |
  sort -u | tr '\n' ' ')
[ -z "$grown" ] || echo "test-abi: structs grown at their end (struct_size rule): $grown"
echo "test-abi: ok (no incompatible change against the baseline, soname $new_soname; $(wc -l < "$tmp/versioned") struct_size structs may grow at their end)"
