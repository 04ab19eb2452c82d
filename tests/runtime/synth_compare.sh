#!/bin/sh
# synth_compare.sh BASE MAKE BUILD - smg-synth's output from this tree
# against the one built from git revision BASE, byte for byte: BVH and CSV
# of the runs below, on BUILD/default.smg and, when it exists,
# BUILD/cmu.smg (the blobs of this tree for both, so only the runtime is
# compared). For a change that must not alter behaviour. Writes under
# BUILD/synth-compare; nothing is committed.
#
# Runs per graph: five paths (corner-left, corner-right, circle-r5,
# scribble, u-turn) x foot IK on/off x {no constraints, a transition to
# style 1 at 4 m, a splice of action 1 at 2 m, both and a transition back
# to style 0 at 9 m}; and once each with steering off and with swing
# clearance off.
set -e
base=$1
make=$2
build=$3
if [ -z "$base" ] || [ -z "$make" ] || [ -z "$build" ]; then
  echo "usage: synth_compare.sh BASE MAKE BUILD" >&2
  exit 2
fi
dir=$build/synth-compare
rm -rf "$dir"
mkdir -p "$dir/src" "$dir/base" "$dir/new"
git archive "$base" | tar -x -C "$dir/src"
(cd "$dir/src" && $make --no-print-directory -j2 build/smg-synth > ../build.log 2>&1) || {
  echo "synth-compare: could not build smg-synth at $base (see $dir/build.log)" >&2
  exit 1
}

run() { # out-dir synth graph name args...
  out=$1 synth=$2 graph=$3 name=$4
  shift 4
  "$synth" -g "$graph" --seconds 12 "$@" --csv "$out/$name.csv" \
    -o "$out/$name.bvh" > /dev/null
}

graphs=$build/default.smg
[ -f "$build/cmu.smg" ] && graphs="$graphs $build/cmu.smg"
runs=0
for graph in $graphs; do
  g=$(basename "$graph" .smg)
  for p in corner-left corner-right circle-r5 scribble u-turn; do
    for ik in on off; do
      for v in plain trans splice both; do
        set -- -p "data/paths/$p.txt"
        case $v in
          trans) set -- "$@" --transition 4:1 ;;
          splice) set -- "$@" --splice 2:1 ;;
          both) set -- "$@" --transition 4:1 --splice 2:1 --transition 9:0 ;;
        esac
        [ $ik = off ] && set -- "$@" --no-ik
        for side in base new; do
          synth=$build/smg-synth
          [ $side = base ] && synth=$dir/src/build/smg-synth
          run "$dir/$side" "$synth" "$graph" "$g-$p-ik$ik-$v" "$@"
        done
        runs=$((runs + 1))
      done
    done
  done
  for side in base new; do
    synth=$build/smg-synth
    [ $side = base ] && synth=$dir/src/build/smg-synth
    run "$dir/$side" "$synth" "$graph" "$g-nosteer" -p data/paths/scribble.txt --no-steering --splice 1:1
    run "$dir/$side" "$synth" "$graph" "$g-noswing" -p data/paths/corner-left.txt --no-swing-clearance --seed 7
  done
  runs=$((runs + 2))
done

differ=0
for f in "$dir"/base/*; do
  n=$(basename "$f")
  if ! cmp -s "$f" "$dir/new/$n"; then
    echo "synth-compare: $n differs"
    differ=$((differ + 1))
  fi
done
files=$(ls "$dir/base" | wc -l)
if [ $differ -ne 0 ]; then
  echo "synth-compare: $differ of $files files differ from $base ($runs runs)"
  exit 1
fi
echo "synth-compare: $runs runs, $files files byte-identical to $base"
