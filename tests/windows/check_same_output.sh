#!/bin/sh
# check_same_output.sh "WINE_RUN" BUILD WIN_BUILD SHARED
# The Windows programs under Wine write the same bytes as the Linux ones:
#   smg-synth.exe vs smg-synth: BVH and CSV for three paths with transition
#   and splice points, on the CMU graph when SHARED has the clips (else on
#   the synthetic default graph);
#   smg-bake.exe vs smg-bake: the default graph from the synthetic clips,
#   and the CMU graph when SHARED has the clips.
set -eu
wine_run=$1
build=$2
wbuild=$3
shared=$4
out=$wbuild/same-output
rm -rf "$out"
mkdir -p "$out"

if [ -f "$shared/mocap/cmu/09_12.bvh" ] && [ -f "$build/cmu.smg" ]; then
  blob=$build/cmu.smg
  actions="punch"
else
  echo "test-windows: $shared/mocap/cmu absent: smg-synth compared on the default graph"
  blob=$build/default.smg
  actions="wave punch"
fi
first_action=${actions%% *}
last_action=${actions##* }

# three paths: straight, a winding S, a tight turn back
printf '0 0\n0 12\n' > "$out/straight.txt"
printf '0 0\n0 3\n2 6\n0 9\n-2 12\n0 15\n' > "$out/winding.txt"
printf '0 0\n0 5\n1.5 6.5\n3 5\n3 0\n' > "$out/turn.txt"
set -- \
  "straight --splice 2:$first_action --transition 6:run" \
  "winding --transition 3:run --splice 5:$last_action --transition 9:walk" \
  "turn --splice 1:$last_action --transition 4:run --splice 7:$first_action"

for job in "$@"; do
  name=${job%% *}
  args=${job#* }
  # shellcheck disable=SC2086
  "$build/smg-synth" -g "$blob" -p "$out/$name.txt" $args --seconds 12 \
    --csv "$out/$name-linux.csv" --glb "$out/$name-linux.glb" -o "$out/$name-linux.bvh" >> "$out/log.txt" 2>&1
  # shellcheck disable=SC2086
  $wine_run "$wbuild/smg-synth.exe" -g "$blob" -p "$out/$name.txt" $args \
    --seconds 12 --csv "$out/$name-windows.csv" --glb "$out/$name-windows.glb" \
    -o "$out/$name-windows.bvh" \
    >> "$out/log.txt" 2>&1
  for ext in bvh csv glb; do
    if ! cmp -s "$out/$name-linux.$ext" "$out/$name-windows.$ext"; then
      echo "test-windows: FAILED: smg-synth.exe and smg-synth differ on $name.$ext ($blob):" >&2
      cmp "$out/$name-linux.$ext" "$out/$name-windows.$ext" >&2 || true
      exit 1
    fi
  done
  echo "test-windows: smg-synth.exe = smg-synth on $(basename "$blob"), path $name ($args): $(wc -c < "$out/$name-linux.bvh") + $(wc -c < "$out/$name-linux.csv") + $(wc -c < "$out/$name-linux.glb") bytes (BVH, CSV, glTF)"
done

# same_bake NAME MANIFEST DATA_DIR LINUX_BLOB
same_bake() {
  $wine_run "$wbuild/smg-bake.exe" -q -m "$2" --data-dir "$3" \
    -o "$out/$1-windows.smg"
  if ! cmp -s "$4" "$out/$1-windows.smg"; then
    echo "test-windows: FAILED: smg-bake.exe and smg-bake bake different $1 graphs:" >&2
    cmp "$4" "$out/$1-windows.smg" >&2 || true
    exit 1
  fi
  echo "test-windows: smg-bake.exe = smg-bake on the $1 graph ($(wc -c < "$4") bytes)"
}
same_bake default data/synthetic.manifest "$build/synthetic" "$build/default.smg"
if [ "$blob" = "$build/cmu.smg" ]; then
  same_bake CMU data/cmu.manifest "$shared/mocap/cmu" "$build/cmu.smg"
fi
