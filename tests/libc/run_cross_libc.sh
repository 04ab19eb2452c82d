#!/bin/sh
# run_cross_libc.sh - the baker and the runtime give the same bits under
# another C library.
#
# Why: users bake on one machine and run on many (a build farm on one
# distribution, players on others, Godot's own newer C library). Since
# glibc 2.41 several float math functions are correctly rounded, so a
# program that calls them gives other bits on a newer system; libsmg's
# runtime computes its trigonometry itself (libsmg/runtime/dmath.h) and the
# baker's double-precision libm calls must not move a blob's bytes either.
# This runs the host's smg-bake and smg-synth a second time with the C
# library of the Debian sid root that the Godot tests use (its own loader,
# no chroot) and requires byte-identical blobs and BVH output.
#
# usage: run_cross_libc.sh ROOT BUILD   (ROOT: the sid root; BUILD: build dir)
set -eu

ROOT=$1
BUILD=$2
OUT=$BUILD/cross-libc
LOADER=$ROOT/lib64/ld-linux-x86-64.so.2
# sid's libc and libm first; the host's other libraries (assimp) after them
LIBPATH=$ROOT/lib/x86_64-linux-gnu:$ROOT/usr/lib/x86_64-linux-gnu:/usr/lib/x86_64-linux-gnu

[ -x "$LOADER" ] || { echo "cross-libc: no loader at $LOADER" >&2; exit 1; }
other() { "$LOADER" --library-path "$LIBPATH" "$@"; }

host_libc=$(getconf GNU_LIBC_VERSION)
other_libc=$(other "$ROOT/usr/bin/getconf" GNU_LIBC_VERSION)
echo "cross-libc: host $host_libc, other $other_libc"
if [ "$host_libc" = "$other_libc" ]; then
	echo "cross-libc: FAILED: the other root has the host's C library; nothing would be compared" >&2
	exit 1
fi

rm -rf "$OUT" && mkdir -p "$OUT"
failed=0
same() { # same NAME FILE_A FILE_B
	if cmp -s "$2" "$3"; then
		echo "cross-libc: $1: identical ($(wc -c <"$2") bytes)"
	else
		echo "cross-libc: FAILED: $1 differs: $(cmp "$2" "$3" | head -1)" >&2
		failed=1
	fi
}
# both NAME PROGRAM ARGS... : run under each C library, output to -o $OUT/NAME.{host,other}
both() {
	name=$1 prog=$2
	shift 2
	"$prog" "$@" -o "$OUT/$name.host" >"$OUT/$name.host.log" 2>&1 ||
		{ echo "cross-libc: FAILED: $name (host) exited non-zero, see $OUT/$name.host.log" >&2; exit 1; }
	other "$prog" "$@" -o "$OUT/$name.other" >"$OUT/$name.other.log" 2>&1 ||
		{ echo "cross-libc: FAILED: $name (other) exited non-zero, see $OUT/$name.other.log" >&2; exit 1; }
	same "$name" "$OUT/$name.host" "$OUT/$name.other"
}

SYN=$BUILD/synthetic
both synthetic.smg "$BUILD/smg-bake" -q -m data/synthetic.manifest --data-dir "$SYN"
both synthetic-on-rig.smg "$BUILD/smg-bake" -q -m data/synthetic.manifest --data-dir "$SYN" \
	--target "$SYN/rig_mixamo_apose.bvh" --target-unit 1
both synthetic-scribble.bvh "$BUILD/smg-synth" -g "$OUT/synthetic.smg.host" \
	-p data/paths/scribble.txt --seconds 20
both rig-corner.bvh "$BUILD/smg-synth" -g "$OUT/synthetic-on-rig.smg.host" \
	-p data/paths/corner-left.txt --seconds 12

CMU=../shared/mocap/cmu
if [ -d "$CMU" ]; then
	both cmu.smg "$BUILD/smg-bake" -q -m data/cmu.manifest --data-dir "$CMU"
	both cmu-u-turn.bvh "$BUILD/smg-synth" -g "$OUT/cmu.smg.host" -p data/paths/u-turn.txt --seconds 24
else
	echo "cross-libc: $CMU not found: the CMU bake and run are skipped"
fi

[ "$failed" = 0 ] || exit 1
echo "cross-libc: passed"
