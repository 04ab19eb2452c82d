#!/bin/sh
# check_dll.sh OBJDUMP LIBSMG.DLL HEADER
# The Windows twin of tests/abi/check_symbols.sh: libsmg.dll exports only
# smg_* names and every function smg.h declares; it imports nothing but
# Windows' own system DLLs (users ship libsmg.dll alone). (MinGW links its
# math functions into the DLL, so the "no inexact libm" check stays with
# the Linux library, built from the same sources.)
set -eu
objdump=$1
dll=$2
hdr=$3
dump=$("$objdump" -p "$dll")
# the export name table: "[ordinal] name" lines after its heading
exported=$(printf '%s\n' "$dump" |
  sed -n '/\[Ordinal\/Name Pointer\] Table/,/^$/p' |
  sed -n 's/^[[:space:]]*\[[[:space:]]*[0-9]*\][[:space:]]*\([A-Za-z_][A-Za-z0-9_]*\)$/\1/p' | sort -u)
count=$(printf '%s\n' "$exported" | grep -c . || true)
if [ "$count" = 0 ]; then
  echo "test-windows: FAILED: no export table read from $dll" >&2
  exit 1
fi
bad=$(printf '%s\n' "$exported" | grep -v '^smg_' | grep . || true)
if [ -n "$bad" ]; then
  echo "test-windows: FAILED: $dll exports names without the smg_ prefix:" >&2
  printf '  %s\n' $bad >&2
  exit 1
fi
declared=$(sed -n 's/^SMG_API[^(]*[ *]\(smg_[a-z0-9_]*\)(.*/\1/p' "$hdr" | sort -u)
missing=""
for f in $declared; do
  printf '%s\n' "$exported" | grep -qx "$f" || missing="$missing $f"
done
if [ -n "$missing" ]; then
  echo "test-windows: FAILED: declared in $hdr but not exported by $dll:" >&2
  printf '  %s\n' $missing >&2
  exit 1
fi
dlls=$(printf '%s\n' "$dump" | sed -n 's/^[[:space:]]*DLL Name: //p' | tr 'A-Z' 'a-z' | sort -u)
foreign=$(printf '%s\n' "$dlls" | grep -v -E '^(kernel32|msvcrt|user32|advapi32|ucrtbase|api-ms-win-.*)\.dll$' || true)
if [ -n "$foreign" ]; then
  echo "test-windows: FAILED: $dll needs DLLs that Windows does not have:" >&2
  printf '  %s\n' $foreign >&2
  exit 1
fi
ndecl=$(printf '%s\n' "$declared" | grep -c . || true)
echo "test-windows: libsmg.dll ok ($count exports, all smg_*; all $ndecl declared functions; imports only" $dlls")"
