#!/bin/sh
# addon_test.sh ZIP GRAPH.smg PROJECT_DIR [LICENSE] - the addon zip installed
# as a user would: unpacked at the root of a fresh project (addon/project.godot,
# walk.tscn, walk.gd, the editor check plugin and GRAPH as res://default.smg).
#
#  1. the headless editor opens the project: it must find and load the
#     extension by itself (it writes .godot/extension_list.cfg) and
#     addon/check_editor must pass (plugin enables, class reference shown);
#  2. walk.tscn runs headless at 30 fps: a character on a Path3D's curve
#     must walk along it (addon/walk.gd);
#  3. the class reference in the zip describes exactly the registered API
#     (Godot's --doctool --gdextension-docs changes nothing, nothing empty);
#  4. the Windows DLL in the zip must be a PE32+ x86-64 DLL exporting exactly
#     the entry symbol and importing only Windows' own DLLs (objdump -p), and
#     load under Wine as Godot loads it (GODOT_DLL_LOADER, test/dll_load.c);
#  5. the zip's LICENSE must be the repository's, when one is given.
# Every Godot run is wrapped in `timeout` and judged by its exact pass line
# (Godot exits 0 even after a script error).
#
# Environment: GODOT_GD (default ../gd), GODOT_TIMEOUT (seconds per run,
# default 300), WIN_OBJDUMP (default x86_64-w64-mingw32-objdump),
# GODOT_DLL_LOADER (dll_load.exe) and GODOT_WINE (the command running it).
set -eu
ZIP=$1
GRAPH=$2
PROJ=$3
LICENSE=${4:-}
HERE=$(cd "$(dirname "$0")" && pwd)
GD=${GODOT_GD:-$HERE/../gd}
TMO=${GODOT_TIMEOUT:-300}
OBJDUMP=${WIN_OBJDUMP:-x86_64-w64-mingw32-objdump}
GODOT_WINE=${GODOT_WINE:-wine}
GODOT_DLL_LOADER=${GODOT_DLL_LOADER:?GODOT_DLL_LOADER: the dll_load.exe to run under Wine}
abs() { (cd "$(dirname "$1")" && printf '%s/%s\n' "$(pwd)" "$(basename "$1")"); }
fail() { echo "test-godot-addon: $*" >&2; exit 1; }
planned() { sed -n 's/^const PLANNED := \([0-9]*\).*/\1/p' "$1"; }
crashed() { grep -qE 'SCRIPT ERROR|Program crashed|handle_crash|Segmentation fault' "$1"; }

ZIP_ABS=$(abs "$ZIP")
rm -rf "$PROJ"
mkdir -p "$PROJ"
PROJ=$(cd "$PROJ" && pwd)
(cd "$PROJ" && unzip -q "$ZIP_ABS")
cp "$HERE/addon/project.godot" "$HERE/addon/walk.tscn" "$HERE/addon/walk.gd" "$PROJ/"
cp -R "$HERE/addon/check_editor" "$PROJ/addons/"
cp "$GRAPH" "$PROJ/default.smg"
[ ! -e "$PROJ/.godot" ] || fail "the zip must not carry a .godot folder"

echo "== the fresh project opened in the headless editor ($PROJ/editor.log)"
set +e
(cd "$PROJ" && timeout "$TMO" $GD --headless --editor --audio-driver Dummy --path . > editor.log 2>&1)
rc=$?
set -e
grep -E '^(PASS|FAIL|editor:|  help page)' "$PROJ/editor.log" || true
n=$(planned "$HERE/addon/check_editor/check_editor.gd")
if [ $rc -ne 0 ] || ! grep -qx "editor: $n passed, 0 failed" "$PROJ/editor.log" || crashed "$PROJ/editor.log"; then
	tail -20 "$PROJ/editor.log" >&2
	fail "editor check failed (exit $rc)"
fi
grep -qx 'res://addons/libsmg/smg.gdextension' "$PROJ/.godot/extension_list.cfg" 2>/dev/null ||
	fail "the editor did not register addons/libsmg/smg.gdextension in .godot/extension_list.cfg"

echo "== walk.tscn run headless ($PROJ/run.log)"
set +e
(cd "$PROJ" && timeout "$TMO" $GD --headless --fixed-fps 30 --audio-driver Dummy --path . > run.log 2>&1)
set -e
grep -E '^(PASS|FAIL|addon:|after)' "$PROJ/run.log" || true
n=$(planned "$HERE/addon/walk.gd")
if ! grep -qx "addon: $n passed, 0 failed" "$PROJ/run.log" || crashed "$PROJ/run.log"; then
	grep -E -A3 'SCRIPT ERROR|Program crashed' "$PROJ/run.log" | head -20 >&2
	fail "walk.tscn failed"
fi

# The class reference must describe exactly the API the extension registers:
# Godot's doc tool merges the zip's doc_classes with the registered classes
# and must change nothing, and no description may be empty.
echo "== the class reference against the registered API (godot --doctool --gdextension-docs)"
DOCS=$PROJ/addons/libsmg/doc_classes
rm -rf "$PROJ/doctool" && mkdir -p "$PROJ/doctool" && cp -R "$DOCS" "$PROJ/doctool/"
(cd "$PROJ" && timeout "$TMO" $GD --headless --path . --doctool doctool --gdextension-docs > doctool.log 2>&1) ||
	fail "godot --doctool failed, see $PROJ/doctool.log"
diff -r "$DOCS" "$PROJ/doctool/doc_classes" >&2 ||
	fail "doc_classes/ does not match the registered classes (Godot's version: $PROJ/doctool/doc_classes)"
python3 - "$DOCS"/*.xml <<'PY' || fail "doc_classes/ has members without a description"
import sys
import xml.etree.ElementTree as ET
empty = []
for path in sys.argv[1:]:
    cls = ET.parse(path).getroot()
    for el in [cls] + cls.findall("./methods/method") + cls.findall("./signals/signal") + cls.findall("./members/member"):
        text = el.text if el.tag == "member" else el.findtext("description")
        if not (text or "").strip():
            empty.append("%s.%s" % (cls.get("name"), el.get("name", "")))
        if el is cls and not (cls.findtext("brief_description") or "").strip():
            empty.append(cls.get("name") + " (brief)")
if empty:
    sys.exit("no description: " + ", ".join(empty))
print("every class, method, property and signal is described (%d files)" % (len(sys.argv) - 1))
PY

echo "== the Windows DLL ($OBJDUMP -p)"
DLL=$PROJ/addons/libsmg/bin/libsmg_godot.windows.x86_64.dll
"$OBJDUMP" -p "$DLL" > "$PROJ/dll.txt"
grep -q 'file format pei-x86-64' "$PROJ/dll.txt" || fail "$DLL is not a PE32+ x86-64 file"
exports=$(sed -n '/^\[Ordinal\/Name Pointer\] Table/,/^$/p' "$PROJ/dll.txt" | sed -n 's/^\s*\[ *[0-9]*\] //p')
[ "$exports" = smg_godot_init ] || fail "the DLL must export exactly smg_godot_init, exports: $exports"
imports=$(sed -n 's/^\s*DLL Name: //p' "$PROJ/dll.txt" | sort | tr '\n' ' ')
for d in $imports; do
	case $(echo "$d" | tr 'A-Z' 'a-z') in
	kernel32.dll | msvcrt.dll | ucrtbase.dll | api-ms-win-*) ;;
	*) fail "the DLL needs $d, which Windows does not have (imports: $imports)" ;;
	esac
done
echo "exports: $exports; imports: $imports"

echo "== the Windows DLL loaded under Wine (test/dll_load.c)"
W=$(printf 'Z:%s' "$DLL" | tr / '\\')
set +e
$GODOT_WINE "$GODOT_DLL_LOADER" "$W" 2>"$PROJ/dll_load.err" | tr -d '\r' > "$PROJ/dll_load.log"
set -e
cat "$PROJ/dll_load.log"
grep -qx "dll: 5 passed, 0 failed" "$PROJ/dll_load.log" || fail "the DLL did not load and answer as Godot expects under Wine"

if [ -n "$LICENSE" ]; then
	cmp -s "$LICENSE" "$PROJ/addons/libsmg/LICENSE" || fail "addons/libsmg/LICENSE is not the repository's $LICENSE"
	echo "LICENSE: the repository's"
else
	echo "LICENSE: the repository has none yet; not checked"
fi
echo "test-godot-addon: passed"
