#!/bin/sh
# test_demo.sh - the demo's smoke test (make test-demo): scripted drawings
# rendered headless on one private Xvfb server with Mesa's software GL,
# checked by smg-demo-pngcheck; then robustness.sh. See docs/demo.md.
# usage: test_demo.sh SMG_DEMO PNGCHECK GOOD_BLOB SCRATCH_DIR BODYTEST BODYGLTF
set -eu
demo=$1
check=$2
blob=$3
dir=$4
bodytest=$5
bodygltf=$6
mkdir -p "$dir"
rm -f "$dir"/*.png "$dir"/*.log

command -v Xvfb >/dev/null || { echo "test-demo: Xvfb is missing (make deps installs xvfb)"; exit 1; }
# One server for every run; -displayfd picks a free display and reports it
# when the server is ready (no lock-file races with other tests).
Xvfb -displayfd 3 -screen 0 1280x720x24 -nolisten tcp 3>"$dir/xvfb.display" 2>"$dir/xvfb.log" &
xvfb_pid=$!
trap 'kill $xvfb_pid 2>/dev/null || :' EXIT
i=0
while [ ! -s "$dir/xvfb.display" ]; do
  i=$((i + 1))
  if [ $i -gt 100 ] || ! kill -0 $xvfb_pid 2>/dev/null; then
    echo "test-demo: Xvfb did not start:"; cat "$dir/xvfb.log"; exit 1
  fi
  sleep 0.1
done
DISPLAY=:$(cat "$dir/xvfb.display")
LIBGL_ALWAYS_SOFTWARE=1
export DISPLAY LIBGL_ALWAYS_SOFTWARE
echo "== demo smoke test (headless, Xvfb $DISPLAY + Mesa llvmpipe)"

run() { echo "+ $*"; "$@"; }
small="--no-hud --width 640 --height 360"

# 0. The generated body: mesh, bind pose, skinning matrices vs own FK + LBS;
# the glTF writer writes it, and refuses a bad blob or an unwritable file.
run "$bodytest" "$blob"
run "$bodygltf" "$blob" "$dir/body.gltf"
head -c 2048 /dev/urandom >"$dir/garbage.smg"
for bad in "$dir/garbage.smg $dir/garbage.gltf" "$blob $dir/no-such-dir/body.gltf"; do
  set +e
  "$bodygltf" $bad 2>"$dir/gltf.err"
  rc=$?
  set -e
  [ $rc -eq 1 ] && grep -q "smg-body-gltf: " "$dir/gltf.err" ||
    { echo "test-demo: FAIL: smg-body-gltf $bad: exit $rc"; cat "$dir/gltf.err"; exit 1; }
  echo "test-demo: ok   smg-body-gltf $bad: exit 1, \"$(head -1 "$dir/gltf.err")\""
done
rm -f "$dir/garbage.smg" "$dir/gltf.err"
# 1. A drawn path and the walking skinned character are visible, its head
# and hands where its skeleton projects.
run "$demo" --graph "$blob" --script demo/scripts/smoke.txt --frames 150 $small --screenshot "$dir/smoke.png" \
  >"$dir/smoke.log"
cat "$dir/smoke.log"
box=$(sed -n 's/^smg-demo: character 0 skeleton box //p' "$dir/smoke.log")
[ -n "$box" ] || { echo "test-demo: FAIL: the demo did not print the skeleton's box"; exit 1; }
run "$check" "$dir/smoke.png" --size 640 360 --path 300 --character 150 --inside $box 100
# The capsule skeleton view (the toggle) draws the character too.
printf 'frame 0 skeleton on\n' | cat demo/scripts/smoke.txt - >"$dir/skeleton.txt"
run "$demo" --graph "$blob" --script "$dir/skeleton.txt" --frames 150 $small --screenshot "$dir/skeleton.png" >/dev/null
run "$check" "$dir/skeleton.png" --size 640 360 --path 300 --character 150
# 2. Fixed dt: the same run gives the same picture, byte for byte.
run "$demo" --graph "$blob" --script demo/scripts/smoke.txt --frames 150 $small --screenshot "$dir/smoke2.png"
run cmp "$dir/smoke.png" "$dir/smoke2.png"
# 3. Several characters and the ImGui HUD (its panel region must be dark).
run "$demo" --graph "$blob" --script demo/scripts/smoke.txt --frames 30 --characters 4 --width 800 --height 600 \
  --screenshot "$dir/hud.png"
run "$check" "$dir/hud.png" --size 800 600 --dark 16 30 300 90 90
# 4. Drawing by (synthetic) mouse through the real input handler.
run "$demo" --graph "$blob" --script demo/scripts/mouse.txt --frames 40 $small --screenshot "$dir/mouse.png" \
  >"$dir/mouse.log"
cat "$dir/mouse.log"
grep -q "markers: #1 transition run @[0-9.]* #2 splice [a-z]* @[0-9.]*$" "$dir/mouse.log" ||
  { echo "test-demo: FAIL: clicking did not place a transition and a splice"; exit 1; }
run "$demo" --graph "$blob" --script demo/scripts/mouse.txt --frames 120 $small --screenshot "$dir/mouse.png" \
  >"$dir/mouse.log"
cat "$dir/mouse.log"
grep -q "markers: #1 transition run @4\.[0-9]*$" "$dir/mouse.log" ||
  { echo "test-demo: FAIL: the splice was not deleted or the transition not dragged to ~4.9 m"; exit 1; }
awk '/markers:/ { if ($3 + 0 <= 15 || $5 + 0 <= 8.0) { print "test-demo: FAIL: the path was not extended"; exit 1 } }' \
  "$dir/mouse.log"
run "$check" "$dir/mouse.png" --size 640 360 --character 50 --colour 41 107 230 300 --colour 224 41 36 300
# 5. Bad input fails cleanly.
sh demo/tools/robustness.sh "$demo" "$blob" "$dir"
echo "test-demo: passed"
