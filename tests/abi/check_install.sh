#!/bin/sh
# check_install.sh MAKE BUILD CC
# Installs libsmg into a temporary prefix, builds tests/abi/consumer.c
# against the installed copy through pkg-config (shared and static) and
# runs it; builds tests/abi/bake_consumer.c through smg-bake.pc and bakes
# a synthetic clip with it (and with the installed smg-bake); then checks a
# DESTDIR staged install lays out the same files with the final prefix
# inside both .pc files, and that install-runtime leaves the baker out.
set -eu
make_cmd=$1
build=$2
cc=$3
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/smg-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM

fail() { echo "test-install: FAILED: $*" >&2; exit 1; }

$make_cmd --no-print-directory -s BUILD="$build" install PREFIX="$tmp/usr" >/dev/null
lib=$tmp/usr/lib
for f in "$tmp/usr/include/smg.h" "$lib/libsmg.a" "$lib/libsmg.so.0.1.0" \
         "$lib/pkgconfig/smg.pc"; do
  [ -f "$f" ] || fail "missing $f"
done
[ "$(readlink "$lib/libsmg.so.0")" = libsmg.so.0.1.0 ] || fail "libsmg.so.0 link"
[ "$(readlink "$lib/libsmg.so")" = libsmg.so.0 ] || fail "libsmg.so link"
readelf -d "$lib/libsmg.so.0.1.0" | grep -q 'SONAME.*\[libsmg\.so\.0\]' ||
  fail "soname is not libsmg.so.0"

export PKG_CONFIG_PATH="$lib/pkgconfig"
flags=$(pkg-config --cflags --libs smg) || fail "pkg-config cannot find smg"
# shellcheck disable=SC2086
$cc -std=c99 -Wall -Wextra -Wpedantic -Werror "$here/consumer.c" $flags \
  -o "$tmp/consumer" || fail "consumer does not build against the install"
readelf -d "$tmp/consumer" | grep -q 'NEEDED.*\[libsmg\.so\.0\]' ||
  fail "consumer is not linked against libsmg.so.0"
LD_LIBRARY_PATH="$lib" "$tmp/consumer" || fail "consumer (shared) failed"
# the resolved library is the installed one, not build/
LD_LIBRARY_PATH="$lib" ldd "$tmp/consumer" | grep -q "$lib/libsmg.so.0" ||
  fail "consumer does not resolve to the installed libsmg.so.0"

# static: the archive plus Libs.private from pkg-config --static
static_libs=$(pkg-config --static --libs-only-l smg | sed 's/-lsmg//')
# shellcheck disable=SC2086
$cc -std=c99 -Wall -Wextra -Wpedantic -Werror "$here/consumer.c" \
  $(pkg-config --cflags smg) "$lib/libsmg.a" $static_libs -o "$tmp/consumer-static" ||
  fail "consumer does not link statically"
"$tmp/consumer-static" >/dev/null || fail "consumer (static) failed"

# the offline side: header, archive, smg-bake.pc and the command lines; a
# tools program bakes a clip and steps the result through the runtime
for f in "$tmp/usr/include/smg_bake.h" "$lib/libsmg_bake.a" \
         "$lib/pkgconfig/smg-bake.pc" "$tmp/usr/bin/smg-bake" \
         "$tmp/usr/bin/smg-synth"; do
  [ -f "$f" ] || fail "missing $f"
done
bflags=$(pkg-config --cflags --libs smg-bake) || fail "pkg-config cannot find smg-bake"
# shellcheck disable=SC2086
$cc -std=c99 -Wall -Wextra -Wpedantic -Werror "$here/bake_consumer.c" $bflags \
  -o "$tmp/bake_consumer" || fail "bake consumer does not build against the install"
"$tmp/bake_consumer" "$build/synthetic/synthetic_walk_straight.bvh" ||
  fail "bake consumer failed"
"$tmp/usr/bin/smg-bake" -q --lower walk "$build/synthetic/synthetic_walk_straight.bvh" \
  -o "$tmp/walk.smg" >/dev/null || fail "installed smg-bake cannot bake"
"$tmp/usr/bin/smg-bake" --info "$tmp/walk.smg" >/dev/null ||
  fail "installed smg-bake cannot read its blob"

# DESTDIR staging keeps the real prefix in smg.pc
$make_cmd --no-print-directory -s BUILD="$build" install PREFIX=/opt/smg DESTDIR="$tmp/stage" >/dev/null
[ -f "$tmp/stage/opt/smg/include/smg.h" ] || fail "DESTDIR install missing header"
[ -f "$tmp/stage/opt/smg/lib/libsmg.a" ] || fail "DESTDIR install missing libsmg.a"
[ -f "$tmp/stage/opt/smg/bin/smg-bake" ] || fail "DESTDIR install missing smg-bake"
grep -qx 'prefix=/opt/smg' "$tmp/stage/opt/smg/lib/pkgconfig/smg.pc" ||
  fail "smg.pc under DESTDIR does not say prefix=/opt/smg"
grep -qx 'prefix=/opt/smg' "$tmp/stage/opt/smg/lib/pkgconfig/smg-bake.pc" ||
  fail "smg-bake.pc under DESTDIR does not say prefix=/opt/smg"

# the runtime alone, for engines that only load blobs
$make_cmd --no-print-directory -s BUILD="$build" install-runtime PREFIX="$tmp/rt" >/dev/null
[ -f "$tmp/rt/lib/libsmg.so.0.1.0" ] || fail "install-runtime missing libsmg.so"
[ ! -e "$tmp/rt/include/smg_bake.h" ] || fail "install-runtime installed the baker"
echo "test-install: ok (install, pkg-config, shared + static consumer, baker + bake round trip, runtime-only install, DESTDIR)"
