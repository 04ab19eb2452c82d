#!/bin/sh
# tools/deps.sh - install every Debian package libsmg needs (`make deps`).
#
# Installs whatever is missing (apt-get update + install; quiet, idempotent:
# nothing is downloaded when everything is already there): directly as root
# (a fresh container has no sudo), through sudo otherwise. Not root and no
# sudo: print the exact command to run and exit 1.
#
# THE package list: add a line here when a part of the project needs a new
# package (and say which part, after the #).
PACKAGES='
build-essential   # cc, make, ar: everything
pkg-config        # smg.pc and make test-install
ca-certificates   # fetching over https (CI bootstrap)
libcglm-dev       # C math used by runtime and baker (header-only)
libassimp-dev     # baker: glTF/FBX import (offline only, never the runtime)
libcmocka-dev     # unit tests
valgrind          # make test-valgrind, fuzz smoke under valgrind; make soak counts with callgrind (and tests/soak includes its header)
abigail-tools     # make test-abi: abidw/abidiff against tests/abi/libsmg.abi
libsdl2-dev       # demo: window, input, GL context
libglm-dev        # demo (C++ side)
libimgui-dev      # demo UI
libstb-dev        # demo/eval: image writing
libgl-dev         # demo: OpenGL headers
libgl1-mesa-dri   # software OpenGL (llvmpipe) for headless demo tests
libglx-mesa0      # GLX for the above
xvfb              # headless X server for demo/Godot tests
xauth             # xvfb-run
mmdebstrap        # Godot binding: builds the cached Debian sid root with Godot 4.6
python3           # Godot binding: method-bind hashes; C# test: smg.h layout generator
assimp-testmodels # baker tests: real FBX/glTF files (tests skip without it)
mono-mcs          # Unity binding: C# compiler for make test-csharp / bench-csharp
mono-runtime      # Unity binding: runs the C# tests against libsmg.so
libnunit-cil-dev  # Unity binding: NUnit for the tests inside the package (make test-csharp)
nunit-console     # Unity binding: runs them under mono
gcc-mingw-w64-x86-64 # Windows builds: the MinGW-w64 cross compiler (mk/windows.mk)
g++-mingw-w64-x86-64 # Windows builds: the glTF body generator of smg-synth.exe (C++)
wine              # Windows builds: runs the Windows tests (make test-windows)
wine64            # Windows builds: 64-bit Wine for the x86_64 programs
'

set -eu

list=$(printf '%s\n' "$PACKAGES" | sed 's/#.*//' | tr -s ' \t' '\n' | grep -v '^$')
missing=""
for p in $list; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing="$missing $p"
done

if [ -z "$missing" ]; then
  echo "deps: all $(printf '%s\n' $list | wc -l) packages present"
  exit 0
fi

as_root=""
if [ "$(id -u)" != 0 ]; then
  if ! command -v sudo >/dev/null 2>&1; then
    echo "deps: missing:$missing" >&2
    echo "deps: not root and no sudo; as root, run:" >&2
    echo "  apt-get install -y --no-install-recommends$missing" >&2
    exit 1
  fi
  as_root=sudo
fi

echo "deps: installing:$missing${as_root:+ (through sudo)}"
# shellcheck disable=SC2086
$as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
# shellcheck disable=SC2086
$as_root env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -qq --no-install-recommends $missing >/dev/null
echo "deps: done"
