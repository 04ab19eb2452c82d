#!/bin/sh
# Baker scale benchmark (make bench-bake-scale; not part of make test).
#
# Bakes 1/8, 1/4, 1/2 and all of the Bandai Namco scale set (2,588 clips,
# 181 minutes: walks, turning walks and runs of six performer styles, and
# standing waves and hand raises) through one manifest of folder patterns
# (every=N), and prints per size the wall and CPU time, the peak memory,
# the graphs' node/edge counts and the blob size, then the growth exponent
# of time, graph nodes and blob size against the data's frames (least
# squares over the sizes, log-log).
#
# The clips are CC BY-NC-ND: they are unpacked under the build folder and
# read from there; nothing baked from them is kept (the blobs go to the
# build folder and are removed).
#
# usage: bake_scale.sh SMG_BAKE SHARED_DIR BUILD_DIR [FRACTIONS]
set -eu
BAKE=$1
SHARED=$2
BUILD=$3
FRACTIONS=${4:-"8 4 2 1"}
OUT=$BUILD/bench-bake-scale

DATA_ABS=$(sh "$(dirname "$0")/../tools/scale_set.sh" "$SHARED" "$BUILD")
if [ -z "$DATA_ABS" ]; then
  echo "bench-bake-scale: skipped (no scale set)"
  exit 0
fi
mkdir -p "$OUT"

echo "bench-bake-scale: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at the start"
printf '%-6s %8s %9s %9s %9s %8s %8s %8s %8s %9s\n' size frames "wall s" "cpu s" "peak MB" \
  "lower n" "lower e" "upper n" "upper e" "blob MB"
for N in $FRACTIONS; do
  M=$OUT/scale_$N.manifest
  cat > "$M" <<EOF
# every $N-th clip of each pattern (bench/bake_scale.sh)
frame_rate 30
root $DATA_ABS
unit 0.01
mirror 1
lower walk:{2} "dataset-2_walk*_*_*.bvh" every=$N
lower run:{1} "dataset-2_run_*_*.bvh" every=$N
upper wave "dataset-2_wave-*.bvh" every=$N
upper raise "dataset-2_raise-up-*.bvh" every=$N
EOF
  LOG=$OUT/scale_$N.log
  if ! "$BAKE" -m "$M" -o "$OUT/scale_$N.smg" > "$LOG" 2>&1; then
    echo "1/$N: bake failed:"
    tail -5 "$LOG"
    exit 1
  fi
  # smg-bake's summary: timing table total, clip/frame line (frames kept
  # plus the covered ones: the data's size), graph lines
  awk -v n="1/$N" '
    /^  total / { wall = $2; cpu = $3; peak = $4 }
    /^  clips / { c = $4; gsub(/,/, "", c); f += c }
    /^  covered / { c = $4; gsub(/[(]/, "", c); f += c }
    /^  lower graph: / { for (i = 1; i <= NF; ++i) if ($i == "after") { ln = $(i-3); le = $(i-1) } }
    /^  upper graph: / { for (i = 1; i <= NF; ++i) if ($i == "after") { un = $(i-3); ue = $(i-1) } }
    /^  wrote / { b = $(NF-1); gsub(/[()]/, "", b); blob = b / 1048576 }
    END { printf "%-6s %8d %9.2f %9.2f %9.1f %8d %8d %8d %8d %9.1f\n", n, f, wall, cpu, peak, ln, le, un, ue, blob }
  ' "$LOG" | tee -a "$OUT/table.txt.$$"
  SKIPPED=$(grep -c "skipped, it cannot be used" "$LOG" || true)
  [ "$SKIPPED" -gt 0 ] && echo "       ($SKIPPED unusable clips skipped, named in $LOG)"
  COVERED=$(awk '/^  covered / { print $2 }' "$LOG")
  [ -n "$COVERED" ] && echo "       ($COVERED clips covered by kept ones: not in the graphs or the blob)"
  rm -f "$OUT/scale_$N.smg"
done
# growth exponents: slope of log(y) against log(frames)
awk '
  { x = log($2); n++; sx += x; sxx += x * x
    yw = log($3); yc = log($4); yb = log($10); yn = log($6 + $8)
    sw += yw; sxw += x * yw; sc += yc; sxc += x * yc; sb += yb; sxb += x * yb
    sn += yn; sxn += x * yn }
  END {
    if (n < 2) exit
    d = n * sxx - sx * sx
    printf "growth exponent over %d sizes: wall %.2f, cpu %.2f, nodes %.2f, blob %.2f\n", n,
      (n * sxw - sx * sw) / d, (n * sxc - sx * sc) / d, (n * sxn - sx * sn) / d,
      (n * sxb - sx * sb) / d
  }' "$OUT/table.txt.$$"
rm -f "$OUT/table.txt.$$"
echo "bench-bake-scale: load average $(cut -d' ' -f1-3 /proc/loadavg) at the end"
