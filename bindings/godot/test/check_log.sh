#!/bin/sh
# check_log.sh LOG - decide the Godot test's result from its output, since
# Godot exits 0 even after script errors: require the exact pass line with
# the planned number of checks, the Godot error messages that bad input must
# produce, and no script error or crash.
set -u
LOG=$1
planned=$(sed -n 's/^const PLANNED := \([0-9]*\).*/\1/p' "$(dirname "$0")/test_smg.gd")
fail=0
if ! grep -qx "godot: $planned passed, 0 failed" "$LOG"; then
	echo "test-godot: no 'godot: $planned passed, 0 failed' line in $LOG" >&2
	fail=1
fi
for msg in \
	"ERROR: SmgGraph: graph file 'res://missing.smg' not found" \
	"ERROR: SmgGraph: 'user://garbage.smg' is not a valid libsmg graph" \
	"ERROR: SmgCharacter.set_path: no graph set" \
	"ERROR: SmgCharacter.set_path: empty path" \
	"ERROR: SmgCharacter.graph: expected an SmgGraph" \
	"WARNING: SmgCharacter: " ; do
	if ! grep -qF "$msg" "$LOG"; then
		echo "test-godot: expected Godot message missing: $msg" >&2
		fail=1
	fi
done
if grep -qE 'SCRIPT ERROR|Program crashed|handle_crash|Segmentation fault|AddressSanitizer' "$LOG"; then
	echo "test-godot: script error or crash in $LOG:" >&2
	grep -E -A3 'SCRIPT ERROR|Program crashed|handle_crash|Segmentation fault|AddressSanitizer' "$LOG" | head -20 >&2
	fail=1
fi
[ $fail = 0 ] && echo "test-godot: passed ($planned checks)"
exit $fail
