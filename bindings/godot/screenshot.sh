#!/bin/sh
# screenshot.sh DEMO_DIR OUT.png - render the demo scene under Xvfb with
# Godot's OpenGL (Compatibility) renderer on Mesa and save one frame.
# The demo script draws a fixed path, lets the character walk it for 5 s
# (--fixed-fps 30), saves the viewport and quits. In --headless mode no
# image can be read back, hence a virtual X display.
set -eu
DEMO=$1
OUT=$2
HERE=$(cd "$(dirname "$0")" && pwd)
command -v Xvfb >/dev/null 2>&1 || { echo "screenshot.sh: Xvfb missing (apt-get install xvfb)" >&2; exit 1; }
# A display number nobody uses.
d=90
while [ -e /tmp/.X11-unix/X$d ] || [ -e /tmp/.X$d-lock ]; do d=$((d + 1)); done
Xvfb :$d -screen 0 1280x720x24 -nolisten tcp >/dev/null 2>&1 &
XPID=$!
trap 'kill $XPID 2>/dev/null || true' EXIT INT TERM
i=0
while [ ! -e /tmp/.X11-unix/X$d ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
OUTDIR=$(cd "$(dirname "$OUT")" && pwd)
rm -f "$OUT"
cd "$DEMO"
DISPLAY=:$d SMG_GODOT_BIND="$OUTDIR${SMG_GODOT_BIND:+:$SMG_GODOT_BIND}" timeout 240 "$HERE/gd" \
	--path . --audio-driver Dummy --rendering-driver opengl3 --fixed-fps 30 --resolution 1280x720 \
	-- --screenshot="$OUTDIR/$(basename "$OUT")" 2>&1 | grep -v '^$' | tail -20 || true
[ -s "$OUT" ] || { echo "screenshot.sh: no image written to $OUT" >&2; exit 1; }
echo "screenshot.sh: wrote $OUT"
