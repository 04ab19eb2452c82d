#!/bin/sh
# run_test.sh EXT.so GRAPH.smg PROJECT_DIR LOG [EDITOR_LOG]
#
# Builds a throw-away copy of the test project in PROJECT_DIR (Godot writes
# .godot/ into it) with the addon (EXT as its Linux library) and the graph, runs test_smg.gd
# headless at a fixed 30 fps and lets check_log.sh decide (Godot exits 0
# even after script errors). With EDITOR_LOG it then opens the test scene in
# the headless editor and fails on a crash or if the scene did not open, and
# drives a copy of the demo project with synthetic input (demo_input.gd).
#
# Environment: GODOT_GD (the command running Godot, default ../gd),
# GODOT_TIMEOUT (seconds per Godot run, default 300), GODOT_PRELOAD
# (LD_PRELOAD for Godot, used by the AddressSanitizer run), GODOT_BODY and
# GODOT_BVH (the generated body glTF of GRAPH and smg-synth's BVH of it
# along skinned_path.txt at 30 fps: with both, test_skinned.gd checks the
# skinned character against them).
set -eu
EXT=$1
GRAPH=$2
PROJ=$3
LOG=$4
EDITOR_LOG=${5:-}
HERE=$(cd "$(dirname "$0")" && pwd)
GD=${GODOT_GD:-$HERE/../gd}
TMO=${GODOT_TIMEOUT:-300}
abs() { (cd "$(dirname "$1")" && printf '%s/%s\n' "$(pwd)" "$(basename "$1")"); }
GRAPH_ABS=$(abs "$GRAPH")
LOG_ABS=$(abs "$LOG")

# The addon as users install it (addons/libsmg/, ../addon) with EXT as its
# Linux library, listed in .godot/extension_list.cfg: written here because
# `godot --import` would crash (Godot issue #111048).
install_addon() {
	mkdir -p "$1/addons/libsmg/bin" "$1/.godot"
	cp -R "$HERE/../addon/." "$1/addons/libsmg/"
	cp "$EXT" "$1/addons/libsmg/bin/libsmg_godot.linux.x86_64.so"
	echo 'res://addons/libsmg/smg.gdextension' > "$1/.godot/extension_list.cfg"
}

rm -rf "$PROJ"
mkdir -p "$PROJ"
cp "$HERE/project.godot" "$HERE"/*.gd "$HERE"/*.tscn "$PROJ/"
install_addon "$PROJ"
cp "$GRAPH" "$PROJ/default.smg"

echo "== godot headless test ($LOG)"
set +e
(cd "$PROJ" && env SMG_TEST_GRAPH_ABS="$GRAPH_ABS" ${GODOT_PRELOAD:+LD_PRELOAD=$GODOT_PRELOAD} \
	timeout "$TMO" $GD --headless --fixed-fps 30 --audio-driver Dummy --path . --script res://test_smg.gd \
	> "$LOG_ABS" 2>&1)
echo "godot exit code $? (not trusted; checking the pass line)"
set -e
grep -E '^(PASS|FAIL|godot:)' "$LOG_ABS" || true
sh "$HERE/check_log.sh" "$LOG_ABS"

# A graph retargeted onto a rig that is not the capture skeleton, driven
# into a Skeleton3D with its own bone axes and compared with smg-synth
# (test_rig.gd). SMG_RIG_GRAPH / SMG_RIG_REF: the graph and the reference
# positions (bvh_positions.py output); skipped when not given.
SCENE_LOG=$(echo "$LOG_ABS" | sed 's/\.log$//')-scene.log
echo "== godot game scene test ($SCENE_LOG)"
set +e
(cd "$PROJ" && env ${GODOT_PRELOAD:+LD_PRELOAD=$GODOT_PRELOAD} timeout "$TMO" $GD --headless --fixed-fps 30 \
	--audio-driver Dummy --path . --script res://test_scene.gd > "$SCENE_LOG" 2>&1)
set -e
grep -E '^(PASS|FAIL|scene:)' "$SCENE_LOG" || true
planned=$(sed -n 's/^const PLANNED := \([0-9]*\).*/\1/p' "$HERE/test_scene.gd")
if ! grep -qx "scene: $planned passed, 0 failed" "$SCENE_LOG" || grep -qE 'SCRIPT ERROR|Program crashed|AddressSanitizer' "$SCENE_LOG"; then
	echo "test-godot: game scene test failed, see $SCENE_LOG" >&2
	grep -E -A3 'SCRIPT ERROR|Program crashed|AddressSanitizer' "$SCENE_LOG" | head -20 >&2
	exit 1
fi

if [ -n "${SMG_RIG_GRAPH:-}" ]; then
	RIG_LOG=$(echo "$LOG_ABS" | sed 's/\.log$//')-rig.log
	cp "$SMG_RIG_GRAPH" "$PROJ/rig.smg"
	cp "$SMG_RIG_REF" "$PROJ/rig_ref.csv"
	echo "== godot retargeted rig test ($RIG_LOG)"
	set +e
	(cd "$PROJ" && env ${GODOT_PRELOAD:+LD_PRELOAD=$GODOT_PRELOAD} timeout "$TMO" $GD --headless --fixed-fps 30 \
		--audio-driver Dummy --path . --script res://test_rig.gd > "$RIG_LOG" 2>&1)
	set -e
	grep -E '^(PASS|FAIL|rig:)' "$RIG_LOG" || true
	planned=$(sed -n 's/^const PLANNED := \([0-9]*\).*/\1/p' "$HERE/test_rig.gd")
	if ! grep -qx "rig: $planned passed, 0 failed" "$RIG_LOG" || grep -qE 'SCRIPT ERROR|Program crashed|AddressSanitizer' "$RIG_LOG"; then
		echo "test-godot: retargeted rig test failed, see $RIG_LOG" >&2
		grep -E -A3 'SCRIPT ERROR|Program crashed|AddressSanitizer' "$RIG_LOG" | head -20 >&2
		exit 1
	fi
fi

if [ -n "${GODOT_BODY:-}" ] && [ -n "${GODOT_BVH:-}" ]; then
	cp "$GODOT_BODY" "$PROJ/body.gltf"
	cp "$GODOT_BVH" "$PROJ/skinned.bvh"
	cp "$HERE/skinned_path.txt" "$PROJ/"
	SKIN_LOG=$(echo "$LOG_ABS" | sed 's/\.log$//')-skinned.log
	echo "== godot skinned character test ($SKIN_LOG)"
	set +e
	(cd "$PROJ" && env ${GODOT_PRELOAD:+LD_PRELOAD=$GODOT_PRELOAD} timeout "$TMO" $GD --headless --fixed-fps 30 \
		--audio-driver Dummy --path . --script res://test_skinned.gd > "$SKIN_LOG" 2>&1)
	set -e
	grep -E '^(PASS|FAIL|skinned:|bones vs|skinned mesh:)' "$SKIN_LOG" || true
	planned=$(sed -n 's/^const PLANNED := \([0-9]*\).*/\1/p' "$HERE/test_skinned.gd")
	if ! grep -qx "skinned: $planned passed, 0 failed" "$SKIN_LOG" || grep -qE 'SCRIPT ERROR|Program crashed' "$SKIN_LOG"; then
		echo "test-godot: skinned character test failed, see $SKIN_LOG" >&2
		grep -E -A3 'SCRIPT ERROR|Program crashed' "$SKIN_LOG" | head -20 >&2
		exit 1
	fi
fi

[ -n "$EDITOR_LOG" ] || exit 0

# The demo project driven by synthetic input (drag, keys, right click).
DEMO_PROJ=$PROJ-demo
DEMO_LOG=$(abs "$EDITOR_LOG" | sed 's/-editor\.log$//; s/\.log$//')-demo.log
rm -rf "$DEMO_PROJ"
mkdir -p "$DEMO_PROJ"
cp "$HERE/../demo/project.godot" "$HERE/../demo"/*.gd "$HERE/../demo"/*.tscn "$HERE/demo_input.gd" "$DEMO_PROJ/"
install_addon "$DEMO_PROJ"
cp "$GRAPH" "$DEMO_PROJ/default.smg"
# The demo draws the generated body when it is there (capsules otherwise).
[ -z "${GODOT_BODY:-}" ] || cp "$GODOT_BODY" "$DEMO_PROJ/body.gltf"
echo "== godot demo input test ($DEMO_LOG)"
set +e
(cd "$DEMO_PROJ" && env ${GODOT_PRELOAD:+LD_PRELOAD=$GODOT_PRELOAD} timeout "$TMO" $GD --headless --fixed-fps 30 \
	--audio-driver Dummy --path . --script res://demo_input.gd > "$DEMO_LOG" 2>&1)
set -e
grep -E '^(PASS|FAIL|demo:)' "$DEMO_LOG" || true
planned=$(sed -n 's/^const PLANNED := \([0-9]*\).*/\1/p' "$HERE/demo_input.gd")
if ! grep -qx "demo: $planned passed, 0 failed" "$DEMO_LOG" || grep -qE 'SCRIPT ERROR|Program crashed|AddressSanitizer' "$DEMO_LOG"; then
	echo "test-godot: demo input test failed, see $DEMO_LOG" >&2
	grep -E -A3 'SCRIPT ERROR|Program crashed|AddressSanitizer' "$DEMO_LOG" | head -20 >&2
	exit 1
fi
ED_ABS=$(abs "$EDITOR_LOG")
echo "== godot editor smoke test: open character.tscn in the headless editor ($EDITOR_LOG)"
set +e
(cd "$PROJ" && env ${GODOT_PRELOAD:+LD_PRELOAD=$GODOT_PRELOAD} timeout "$TMO" $GD --headless --editor \
	--audio-driver Dummy --path . --quit-after 120 character.tscn > "$ED_ABS" 2>&1)
rc=$?
set -e
if [ $rc -ne 0 ] || grep -qE 'Program crashed|handle_crash|Segmentation fault|AddressSanitizer|SmgGraph: .*(not found|not a valid)' "$ED_ABS"; then
	echo "test-godot: editor run failed (exit $rc), see $EDITOR_LOG" >&2
	tail -20 "$ED_ABS" >&2
	exit 1
fi
if ! grep -q 'open_scenes=PackedStringArray("res://character.tscn")' "$PROJ/.godot/editor/editor_layout.cfg"; then
	echo "test-godot: the editor did not open character.tscn" >&2
	exit 1
fi
echo "test-godot: editor opened the scene with the extension loaded and exited cleanly"
