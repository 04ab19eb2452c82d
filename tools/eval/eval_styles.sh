#!/bin/sh
# make eval-styles: the behaviour checks of issue 24 (smg-eval --only
# behaviour) on graphs of performers the project was not tuned on - one
# graph per performer style of the Bandai Namco scale set, built like
# data/bandai.manifest: the style's straight and turning walks (`walk`),
# its runs (`run`), another performer's walks (`other`, a second style
# joined by transition points) and the style's standing waves and hand
# raises. Other takes than data/bandai.manifest's (the 5th to 7th of each
# motion, sorted by name; the 5th to 8th run). The CMU and sparse graphs
# are checked too, as in make eval.
#
# Prints one table: per check, the Bandai Namco graph's figure for each
# style (FAIL marked), and writes it with the logs under BUILD/eval-styles.
# Skips with a message when the scale set is absent. Figures only; the
# exit status is 0 unless a bake or run fails. The clips are CC BY-NC-ND:
# the manifests name them, nothing made from them leaves the build folder.
#
# usage: eval_styles.sh SMG_EVAL SHARED_DIR BUILD_DIR
set -eu
EVAL=$1
SHARED=$2
BUILD=$3
DATA=$(sh "$(dirname "$0")/../scale_set.sh" "$SHARED" "$BUILD")
if [ -z "$DATA" ]; then
  echo "eval-styles: skipped (no scale set)"
  exit 0
fi
OUT=$BUILD/eval-styles
rm -rf "$OUT"
mkdir -p "$OUT"

# the styles the set has, from its runs' file names (dataset-2_run_STYLE_N)
STYLES=$(cd "$DATA" && ls dataset-2_run_*_*.bvh | sed -E 's/^dataset-2_run_(.*)_[0-9]+\.bvh$/\1/' | sort -u)
# takes FROM..TO (by name) of one motion of one style, as manifest lines
takes() { # label motion style from to
  (cd "$DATA" && ls "dataset-2_$2_$3_"*.bvh) | sed -n "$4,$5p" | sed "s/^/lower $1 /"
}

first=""; prev=""
for s in $STYLES; do [ -z "$first" ] && first=$s; done
for s in $STYLES; do
  # the other performer: the next style in the list (the first after the last)
  other=""; seen=0
  for t in $STYLES; do
    [ $seen = 1 ] && { other=$t; break; }
    [ "$t" = "$s" ] && seen=1
  done
  [ -z "$other" ] && other=$first
  M=$OUT/$s.manifest
  {
    echo "# $s: the behaviour checks' graph (tools/eval/eval_styles.sh)"
    echo "frame_rate 30"
    echo "unit 0.01"
    echo "skip_first_frame 0"
    echo "mirror 1"
    takes walk walk "$s" 5 7
    takes walk walk-turn-left "$s" 5 7
    takes walk walk-turn-right "$s" 5 7
    takes run run "$s" 5 8
    takes other walk "$other" 5 6
    takes other walk-turn-left "$other" 5 5
    takes other walk-turn-right "$other" 5 5
    (cd "$DATA" && ls "dataset-2_wave-right-hand_${s}_"*.bvh dataset-2_wave-both-hands_"${s}"_*.bvh) |
      awk -F_ '{ k = $2 } !(k in seen) && ++n[k] == 5 { seen[k] = 1; print "upper wave " $0 }'
    (cd "$DATA" && ls "dataset-2_raise-up-right-hand_${s}_"*.bvh dataset-2_raise-up-both-hands_"${s}"_*.bvh) |
      awk -F_ '{ k = $2 } !(k in seen) && ++n[k] == 5 { seen[k] = 1; print "upper raise " $0 }'
  } > "$M"
  echo "eval-styles: $s (other performer: $other)"
  if ! "$EVAL" --only behaviour --shared "$SHARED" --bandai-dir "$DATA" \
      --bandai-manifest "$M" --img "$OUT/img-$s" --out "$OUT/$s.md" > "$OUT/$s.log" 2>&1; then
    echo "eval-styles: smg-eval failed for $s (see $OUT/$s.log)" >&2
    exit 1
  fi
done

# one row per Bandai Namco check, one column per style
{
  printf '| check (bound) |'
  for s in $STYLES; do printf ' %s |' "$s"; done
  printf '\n|---|'
  for s in $STYLES; do printf -- '---:|'; done
  printf '\n'
  for s in $STYLES; do
    grep -E '^(PASS|FAIL) behaviour, Bandai Namco graph: ' "$OUT/$s.log" |
      sed -E 's/^(PASS|FAIL) behaviour, Bandai Namco graph: (.*): ([-0-9.]+) \(bound (.*)\)$/\2 (\4)\t\1 \3/' |
      sed "s/^/$s\t/"
  done | awk -F'\t' -v styles="$STYLES" '
    BEGIN { ns = split(styles, st, " ") }
    { if (!($2 in row)) { order[++n] = $2; row[$2] = 1 }
      split($3, v, " "); cell[$2, $1] = (v[1] == "FAIL" ? "**" v[2] " FAIL**" : v[2]) }
    END { for (i = 1; i <= n; ++i) { printf "| %s |", order[i]
            for (j = 1; j <= ns; ++j) printf " %s |", ((order[i], st[j]) in cell) ? cell[order[i], st[j]] : "-"
            printf "\n" } }'
} > "$OUT/summary.md"
cat "$OUT/summary.md"
fails=$(grep -c 'FAIL' "$OUT/summary.md" || true)
echo "eval-styles: $fails check(s) with a FAIL; logs and manifests in $OUT"
