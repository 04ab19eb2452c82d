#!/bin/sh
# robustness.sh - the demo must fail cleanly (clear message, non-zero exit,
# never a crash) on a missing or corrupt graph, a zero-size window, no
# OpenGL 3.3, and bad scripts. Part of `make test-demo` (test_demo.sh runs
# it with DISPLAY set to its Xvfb server).
# usage: robustness.sh SMG_DEMO GOOD_BLOB SCRATCH_DIR
set -u
demo=$1
blob=$2
dir=$3
failures=0

# expect NAME EXIT_CODE PATTERN COMMAND...: runs COMMAND, checks the exit
# code and that stderr contains PATTERN.
expect() {
  name=$1 want=$2 pattern=$3
  shift 3
  "$@" >"$dir/robust.out" 2>"$dir/robust.err"
  rc=$?
  if [ "$rc" -ne "$want" ] || ! grep -q -- "$pattern" "$dir/robust.err"; then
    echo "robustness: FAIL $name: exit $rc (want $want), stderr:"
    sed 's/^/  | /' "$dir/robust.err"
    failures=$((failures + 1))
  else
    echo "robustness: ok   $name: exit $rc, \"$(grep -m1 -- "$pattern" "$dir/robust.err")\""
  fi
}

head -c 4096 /dev/urandom >"$dir/garbage.smg"
head -c 100 "$blob" >"$dir/truncated.smg"
printf 'frame 0 path 0 0 1\n' >"$dir/bad-syntax.txt"
printf 'frame 0 path 0 0 0 5\nframe 1 transition 1.0 no-such-style\n' >"$dir/bad-style.txt"

shot="--script demo/scripts/smoke.txt --frames 2 --screenshot $dir/robust.png"
export LIBGL_ALWAYS_SOFTWARE=1
expect "missing graph" 1 "cannot load graph" "$demo" --graph "$dir/no-such-file.smg" $shot
expect "garbage graph" 1 "cannot load graph" "$demo" --graph "$dir/garbage.smg" $shot
expect "truncated graph" 1 "cannot load graph" "$demo" --graph "$dir/truncated.smg" $shot
expect "zero width" 2 "width must be" "$demo" --graph "$blob" --width 0 $shot
expect "zero height" 2 "height must be" "$demo" --graph "$blob" --height 0 $shot
expect "bad script" 2 "bad-syntax.txt:1:" "$demo" --graph "$blob" --script "$dir/bad-syntax.txt"
expect "unknown style" 1 "unknown style 'no-such-style'" \
  "$demo" --graph "$blob" --script "$dir/bad-style.txt" --frames 3 --screenshot "$dir/robust.png"
expect "no OpenGL 3.3" 1 "OpenGL 3.3" env MESA_GL_VERSION_OVERRIDE=3.0 "$demo" --graph "$blob" $shot
rm -f "$dir/garbage.smg" "$dir/truncated.smg" "$dir/bad-syntax.txt" "$dir/bad-style.txt" "$dir/robust.out" \
  "$dir/robust.err" "$dir/robust.png"
[ "$failures" -eq 0 ] || { echo "robustness: $failures failure(s)"; exit 1; }
