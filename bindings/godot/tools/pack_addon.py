#!/usr/bin/env python3
"""pack_addon.py OUT.zip ADDON_DIR LINUX_SO WINDOWS_DLL DOCS_DIR [LICENSE]

Writes the installable Godot addon: everything in ADDON_DIR (plugin.cfg,
smg.gdextension, plugin.gd, icons) under addons/libsmg/, the two extension
libraries under addons/libsmg/bin/ with the names smg.gdextension lists, the
class reference under addons/libsmg/doc_classes/ and LICENSE. Entries are
sorted and carry a fixed date, so the same inputs give the same bytes; the
file appears only when complete.
"""
import os
import sys
import zipfile

ROOT = "addons/libsmg/"
DATE = (1980, 1, 1, 0, 0, 0)


def add(z, name, path, mode):
    info = zipfile.ZipInfo(ROOT + name, DATE)
    info.compress_type = zipfile.ZIP_DEFLATED
    info.external_attr = (0o100000 | mode) << 16
    info.create_system = 3  # unix, so the permissions above are read
    with open(path, "rb") as f:
        z.writestr(info, f.read())


def files_under(top):
    for d, _, names in os.walk(top):
        for n in names:
            p = os.path.join(d, n)
            yield os.path.relpath(p, top).replace(os.sep, "/"), p


def main(argv):
    if len(argv) not in (6, 7):
        sys.exit(__doc__)
    out, addon, so, dll, docs = argv[1:6]
    entries = dict(files_under(addon))
    entries["bin/libsmg_godot.linux.x86_64.so"] = so
    entries["bin/libsmg_godot.windows.x86_64.dll"] = dll
    for name, p in files_under(docs):
        if name.endswith(".xml"):
            entries["doc_classes/" + name] = p
    if len(argv) == 7:
        entries["LICENSE"] = argv[6]
    tmp = out + ".tmp"
    with zipfile.ZipFile(tmp, "w") as z:
        for name in sorted(entries):
            add(z, name, entries[name], 0o755 if name.startswith("bin/") else 0o644)
    os.replace(tmp, out)
    print("%s: %d files" % (out, len(entries)))


if __name__ == "__main__":
    main(sys.argv)
