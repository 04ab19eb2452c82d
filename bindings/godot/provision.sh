#!/bin/sh
# provision.sh - make a Godot 4 available for building and testing the
# libsmg GDExtension, on a Debian 12 (bookworm) machine.
#
# Why a root filesystem: Godot 4 is packaged only in Debian sid, whose glibc
# is newer than bookworm's, so it cannot be installed on the host. We build a
# small sid root with mmdebstrap (godot + Mesa for screenshots) and run Godot
# inside it with chroot in a private mount namespace (see bindings/godot/gd).
#
# The root is cached (default /var/cache/smg-godot/root, override with
# SMG_GODOT_ROOT) and rebuilt only when missing or when PACKAGES below
# change. A cold run takes about a minute and ~200 MB of downloads; a cached
# run returns at once. The new root is built beside the old one and renamed
# into place, so an interrupted run never leaves a half-built cache.
#
# Needs root (mmdebstrap, chroot, mount). Installs mmdebstrap on the host if
# it is missing (apt-get).
set -eu

ROOT=${SMG_GODOT_ROOT:-/var/cache/smg-godot/root}
# godot: the engine (4.6 in sid); ca-certificates silences a TLS warning;
# the Mesa GL/EGL drivers (llvmpipe) let Godot render with its OpenGL
# renderer under Xvfb (screenshots); no Vulkan drivers (137 MB) are needed.
PACKAGES="godot,ca-certificates,libgl1,libglx-mesa0,libegl1,libegl-mesa0,libgl1-mesa-dri"
STAMP="$ROOT/.smg-godot-stamp"

cached() { [ -x "$ROOT/usr/bin/godot" ] && [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$PACKAGES" ]; }
cached && exit 0

if [ "$(id -u)" != 0 ]; then
	echo "provision.sh: building the Godot root at $ROOT needs root (mmdebstrap, chroot)." >&2
	echo "  run: sudo sh $0   (or set SMG_GODOT_ROOT to an existing root)" >&2
	exit 1
fi

if ! command -v mmdebstrap >/dev/null 2>&1; then
	echo "provision.sh: installing mmdebstrap on the host" >&2
	export DEBIAN_FRONTEND=noninteractive
	apt-get update -qq
	apt-get install -y -qq --no-install-recommends mmdebstrap >/dev/null
fi

mkdir -p "$(dirname "$ROOT")"
# One builder at a time (parallel make runs, several checkouts): the others
# wait and then find the cache ready.
exec 9>"$ROOT.lock"
flock 9
cached && exit 0
start=$(date +%s)
NEW="$ROOT.new.$$"
trap 'rm -rf "$NEW"' EXIT INT TERM
echo "provision.sh: building a Debian sid root with Godot in $ROOT (about a minute, ~200 MB download)" >&2
# The sid index served by the mirror can be past its Valid-Until date, hence
# Check-Valid-Until false. Docs, man pages and locales are not needed.
mmdebstrap --quiet --variant=apt \
	--aptopt='Acquire::Check-Valid-Until "false"' \
	--dpkgopt='path-exclude=/usr/share/doc/*' \
	--dpkgopt='path-exclude=/usr/share/man/*' \
	--dpkgopt='path-exclude=/usr/share/locale/*' \
	--include="$PACKAGES" \
	sid "$NEW" >&2
[ -x "$NEW/usr/bin/godot" ] || { echo "provision.sh: godot missing from the new root" >&2; exit 1; }
printf '%s\n' "$PACKAGES" > "$NEW/.smg-godot-stamp"
rm -rf "$ROOT"
mv "$NEW" "$ROOT"
trap - EXIT INT TERM
echo "provision.sh: Godot root ready in $(( $(date +%s) - start )) s: $ROOT" >&2
