#!/bin/sh
# check_symbols.sh LIB.so HEADER
# Every symbol libsmg.so exports must start with smg_ (internal code uses
# smgi_/smgb_ and -fvisibility=hidden), and every function smg.h declares
# must be exported (a missing one would be a link error for users). And
# it imports no libm function whose last bit differs between C libraries
# (sin, atan2, exp, ...: libsmg/runtime/dmath.h says why); only the exact
# ones (floor, fmod, fmin, sqrt, ...) are allowed.
set -eu
so=$1
hdr=$2
exported=$(nm -D --defined-only "$so" | awk '$2 ~ /^[TDBRVWGSi]$/ {print $3}' | sort -u)
count=$(printf '%s\n' "$exported" | grep -c . || true)
bad=$(printf '%s\n' "$exported" | grep -v '^smg_' | grep . || true)
if [ -n "$bad" ]; then
  echo "test-symbols: FAILED: exported symbols without the smg_ prefix:" >&2
  printf '  %s\n' $bad >&2
  exit 1
fi
declared=$(sed -n 's/^SMG_API[^(]*[ *]\(smg_[a-z0-9_]*\)(.*/\1/p' "$hdr" | sort -u)
missing=""
for f in $declared; do
  printf '%s\n' "$exported" | grep -qx "$f" || missing="$missing $f"
done
if [ -n "$missing" ]; then
  echo "test-symbols: FAILED: declared in $hdr but not exported by $so:" >&2
  printf '  %s\n' $missing >&2
  exit 1
fi
inexact=$(nm -D --undefined-only "$so" | awk '{print $2}' | sed 's/@.*//' |
  grep -E '^(a?(sin|cos|tan)h?|atan2|exp(2|10|m1)?|log(2|10|1p)?|pow|cbrt|hypot|erfc?|[lt]gamma|sincos)[fl]?$' || true)
if [ -n "$inexact" ]; then
  echo "test-symbols: FAILED: $so calls libm functions whose results differ between C libraries:" >&2
  printf '  %s\n' $inexact >&2
  exit 1
fi
ndecl=$(printf '%s\n' "$declared" | grep -c . || true)
echo "test-symbols: ok ($count exported symbols, all smg_*; all $ndecl declared functions present; no inexact libm calls)"
