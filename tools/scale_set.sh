#!/bin/sh
# The Bandai Namco scale set (../shared/mocap/bandai-namco-2/clips.tar.xz:
# 2,588 clips of six performer styles) unpacked under the build folder, for
# the benchmarks and evaluations that read it (make bench-bake-scale,
# bench-big-graph, eval-styles). Unpacks once; prints the folder's absolute
# path on stdout, or nothing (with the reason on stderr) when the set is
# absent. The clips are CC BY-NC-ND: they stay under the build folder and
# nothing made from them is committed.
#
# usage: scale_set.sh SHARED_DIR BUILD_DIR
set -eu
TAR=$1/mocap/bandai-namco-2/clips.tar.xz
DATA=$2/bandai-namco-2
PROBE=dataset-2_walk_normal_001.bvh
if [ ! -f "$DATA/$PROBE" ]; then
  if [ ! -f "$TAR" ]; then
    echo "scale set: $TAR not found" >&2
    exit 0
  fi
  mkdir -p "$DATA"
  tar -xJf "$TAR" -C "$DATA"
fi
cd "$DATA" && pwd
