#!/usr/bin/env python3
"""check_unity_tarball.py TARBALL VERSION - the Unity package as shipped.

Fails (exit 1, one line per problem) unless the tarball:
  - has every entry under package/, and package.json names com.libsmg.smg
    at VERSION, with samples that exist;
  - has a .meta for every file and folder Unity imports (everything but
    Documentation~ and folder names ending in '~'; a sample's contents
    are imported with the sample, so they have them too), no .meta without
    its asset, and distinct, well-formed GUIDs;
  - carries both native plugins, for the right machine, with importer
    settings that enable each on its own platform only;
  - has LICENSE.md, CHANGELOG.md with a section for VERSION, the
    documentation, the tests with their assembly definition, and a sample
    with a scene and its graph;
  - has no scene referring to a GUID the package does not define (Unity's
    built-in assets aside).
"""
import json
import re
import struct
import sys
import tarfile

BUILTIN_GUIDS = {"0000000000000000e000000000000000", "0000000000000000f000000000000000"}
problems = []


def fail(msg):
    problems.append(msg)


def needs_meta(rel):
    parts = rel.split("/")
    return parts[0] != "Documentation~" and not parts[-1].endswith("~")


def main():
    path, version = sys.argv[1], sys.argv[2]
    with tarfile.open(path, "r:gz") as tar:
        members = tar.getmembers()
        data = {m.name: tar.extractfile(m).read() for m in members if m.isfile()}
    files, dirs = set(), set()
    for m in members:
        name = m.name.rstrip("/")
        if name == "package":
            continue
        if not name.startswith("package/"):
            fail("entry outside package/: " + name)
            continue
        rel = name[len("package/"):]
        (dirs if m.isdir() else files).add(rel)
    for rel in list(files | dirs):  # folders implied by the paths
        parts = rel.split("/")
        for i in range(1, len(parts)):
            dirs.add("/".join(parts[:i]))

    metas = {f for f in files if f.endswith(".meta")}
    assets = (files - metas) | dirs
    guids = {}
    for rel in sorted(assets):
        if not needs_meta(rel):
            continue
        meta = rel + ".meta"
        if meta not in metas:
            fail("no .meta for " + rel + ("/" if rel in dirs else ""))
            continue
        text = data["package/" + meta].decode("utf-8")
        m = re.search(r"^guid: ([0-9a-f]{32})$", text, re.M)
        if not m or not text.startswith("fileFormatVersion: 2\n"):
            fail(meta + ": not a Unity .meta with a 32-digit GUID")
            continue
        if m.group(1) in guids:
            fail(meta + ": GUID also used by " + guids[m.group(1)])
        guids[m.group(1)] = rel
        if rel in dirs and "folderAsset: yes" not in text:
            fail(meta + ": a folder's .meta without folderAsset")
    for meta in sorted(metas):
        if meta[:-5] not in assets:
            fail(meta + " without its asset")

    try:
        manifest = json.loads(data["package/package.json"])
    except (KeyError, ValueError) as e:
        fail("package.json unreadable: %s" % e)
        manifest = {}
    if manifest.get("name") != "com.libsmg.smg" or manifest.get("version") != version:
        fail("package.json is %s %s, expected com.libsmg.smg %s"
             % (manifest.get("name"), manifest.get("version"), version))
    for sample in manifest.get("samples", []):
        if sample.get("path") not in dirs:
            fail("package.json sample path %s is not in the package" % sample.get("path"))

    plugins = {
        "Plugins/Linux/x86_64/libsmg.so": ("Linux64", "Linux", elf_x86_64),
        "Plugins/Windows/x86_64/smg.dll": ("Win64", "Windows", pe_x86_64),
    }
    for rel, (standalone, editor_os, machine_ok) in plugins.items():
        blob = data.get("package/" + rel)
        if blob is None:
            fail("native plugin missing: " + rel)
            continue
        if not machine_ok(blob):
            fail(rel + ": not an x86_64 library of its platform")
        meta = data.get("package/" + rel + ".meta", b"").decode("utf-8")
        if "PluginImporter:" not in meta:
            fail(rel + ".meta: no PluginImporter")
            continue
        enabled = dict(re.findall(r"Standalone: (\w+)\n    second:\n      enabled: (\d)", meta))
        if enabled.get(standalone) != "1" or any(v != "0" for k, v in enabled.items() if k != standalone):
            fail(rel + ".meta: standalone players enabled %s, expected only %s" % (enabled, standalone))
        if not re.search(r"Editor: Editor\n    second:\n      enabled: 1\n.*?OS: %s\n" % editor_os, meta, re.S):
            fail(rel + ".meta: not enabled in the %s editor" % editor_os)

    required = ["LICENSE.md", "CHANGELOG.md", "README.md", "Tests/Runtime/Smg.Tests.Runtime.asmdef",
                "Samples~/PathFollower/PathFollower.unity", "Samples~/PathFollower/Graph/default.smg.bytes"]
    for rel in required:
        if rel not in files:
            fail("missing " + rel)
    if not any(f.startswith("Documentation~/") and f.endswith(".md") for f in files):
        fail("no Documentation~/*.md")
    if not any(f.startswith("Tests/Runtime/") and f.endswith(".cs") for f in files):
        fail("no tests in Tests/Runtime")
    changelog = data.get("package/CHANGELOG.md", b"").decode("utf-8")
    if not re.search(r"^## \[%s\]" % re.escape(version), changelog, re.M):
        fail("CHANGELOG.md has no section for " + version)
    if not data.get("package/LICENSE.md", b"").startswith(b"MIT License"):
        fail("LICENSE.md is not the MIT licence")
    graph = data.get("package/Samples~/PathFollower/Graph/default.smg.bytes", b"")
    if not graph.startswith(b"SMGGRAPH"):
        fail("the sample's graph is not a libsmg blob")

    for rel in sorted(files):
        if rel.endswith((".unity", ".prefab", ".asset", ".mat")):
            for g in re.findall(r"guid: ([0-9a-f]{32})", data["package/" + rel].decode("utf-8")):
                if g not in guids and g not in BUILTIN_GUIDS:
                    fail("%s refers to GUID %s, which the package does not define" % (rel, g))

    for p in problems:
        print("test-unity-package: FAILED: " + p)
    if problems:
        return 1
    print("test-unity-package: %s ok (%d assets with .meta, Linux and Windows plugins, sample scene and graph)"
          % (path.split("/")[-1], len(guids)))
    return 0


def elf_x86_64(blob):
    return blob[:4] == b"\x7fELF" and blob[4] == 2 and struct.unpack_from("<H", blob, 18)[0] == 0x3E


def pe_x86_64(blob):
    if blob[:2] != b"MZ" or len(blob) < 0x40:
        return False
    pe = struct.unpack_from("<I", blob, 0x3C)[0]
    return blob[pe:pe + 4] == b"PE\0\0" and struct.unpack_from("<H", blob, pe + 4)[0] == 0x8664


if __name__ == "__main__":
    sys.exit(main())
