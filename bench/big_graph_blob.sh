#!/bin/sh
# The big graph of the runtime benchmarks (make bench-big-graph, and
# make bench-runtime when the data is there): all of the Bandai Namco
# scale set (2,588 clips, 181 minutes; six performer styles of walks,
# turning walks and runs, plus standing waves and hand raises), baked once
# into the build folder and re-baked when smg-bake is newer than it.
#
# Prints the blob's path on stdout, or nothing (with the reason on
# stderr) when the scale set is not in SHARED_DIR. The clips are CC
# BY-NC-ND: they are unpacked under the build folder, and the blob stays
# there (never in the repository).
#
# usage: big_graph_blob.sh SMG_BAKE SHARED_DIR BUILD_DIR
set -eu
BAKE=$1
SHARED=$2
BUILD=$3
OUT=$BUILD/big-graph
BLOB=$OUT/graph.smg

DATA_ABS=$(sh "$(dirname "$0")/../tools/scale_set.sh" "$SHARED" "$BUILD")
if [ -z "$DATA_ABS" ]; then
  echo "big graph: skipped (no scale set)" >&2
  exit 0
fi
mkdir -p "$OUT"
if [ ! -f "$BLOB" ] || [ "$BAKE" -nt "$BLOB" ]; then
  # the scale benchmark's manifest (bench/bake_scale.sh) for all clips
  cat > "$OUT/graph.manifest" <<EOM
# all of the scale set (bench/big_graph_blob.sh)
frame_rate 30
root $DATA_ABS
unit 0.01
mirror 1
lower walk:{2} "dataset-2_walk*_*_*.bvh"
lower run:{1} "dataset-2_run_*_*.bvh"
upper wave "dataset-2_wave-*.bvh"
upper raise "dataset-2_raise-up-*.bvh"
EOM
  echo "big graph: baking all of the scale set into $BLOB (about a minute, 2 GB)" >&2
  if ! "$BAKE" -m "$OUT/graph.manifest" -o "$BLOB" > "$OUT/bake.log" 2>&1; then
    echo "big graph: bake failed (see $OUT/bake.log)" >&2
    rm -f "$BLOB"
    exit 1
  fi
fi
echo "$BLOB"
