#!/bin/sh
# check_symbols.sh LIB.so HEADER
# Every symbol libsmg.so exports must start with smg_ (internal code uses
# smgi_/smgb_ and -fvisibility=hidden), and every function smg.h declares
# must be exported (a missing one would be a link error for users).
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
ndecl=$(printf '%s\n' "$declared" | grep -c . || true)
echo "test-symbols: ok ($count exported symbols, all smg_*; all $ndecl declared functions present)"
