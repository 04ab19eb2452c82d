#!/usr/bin/env python3
"""unity_package.py - stage the Unity package (`make unity-package`).

    unity_package.py --src bindings/unity --out DIR --header include/smg.h
                     --license LICENSE --linux-so SO --windows-dll DLL
                     --graph BLOB

Copies the package sources to DIR and adds what is built, never committed:
LICENSE.md (the repository's LICENSE), the native plugins for Linux and
Windows x86_64, the sample's graph (the synthetic default graph), the
sample scene (rendered from its .unity.in template) and a .meta file for
every file and folder.

Every .meta GUID is the MD5 of the package name and the asset's path in
the package, so the same path always gets the same GUID: references
between assets (the scene's scripts and graph) stay valid from release to
release, and the templates name assets by path ({{guid:PATH}}). Folders
whose names end in '~' are hidden from Unity and need no .meta, but the
sample's contents get them: Unity copies them into the project with the
sample, and the scene refers to them by GUID. Documentation~ has none.
"""
import argparse
import hashlib
import json
import os
import re
import shutil
import sys

PACKAGE = "com.libsmg.smg"

# What Unity's plugin importer is told for each native library: the
# editor OS it loads in and the standalone player it ships with.
PLUGINS = {
    "Plugins/Linux/x86_64/libsmg.so": ("Linux", "Linux64"),
    "Plugins/Windows/x86_64/smg.dll": ("Windows", "Win64"),
}
STANDALONES = ["Linux64", "OSXUniversal", "Win", "Win64"]


def guid(rel):
    return hashlib.md5((PACKAGE + "/" + rel).encode("utf-8")).hexdigest()


def header_version(path):
    text = open(path, encoding="utf-8").read()
    parts = []
    for name in ("MAJOR", "MINOR", "PATCH"):
        m = re.search(r"^#define SMG_VERSION_%s (\d+)$" % name, text, re.M)
        if not m:
            sys.exit("unity_package: %s has no SMG_VERSION_%s" % (path, name))
        parts.append(m.group(1))
    return ".".join(parts)


def importer_yaml(rel, is_dir):
    tail = "  userData: \n  assetBundleName: \n  assetBundleVariant: \n"
    if is_dir:
        return "folderAsset: yes\nDefaultImporter:\n  externalObjects: {}\n" + tail
    if rel in PLUGINS:
        return plugin_yaml(*PLUGINS[rel]) + tail
    name = os.path.basename(rel)
    ext = os.path.splitext(name)[1]
    if ext == ".cs":
        return ("MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n"
                "  defaultReferences: []\n  executionOrder: 0\n"
                "  icon: {instanceID: 0}\n" + tail)
    if ext == ".asmdef":
        return "AssemblyDefinitionImporter:\n  externalObjects: {}\n" + tail
    if name == "package.json":
        return "PackageManifestImporter:\n  externalObjects: {}\n" + tail
    if ext in (".md", ".txt", ".json", ".bytes"):
        return "TextScriptImporter:\n  externalObjects: {}\n" + tail
    return "DefaultImporter:\n  externalObjects: {}\n" + tail


def plugin_yaml(editor_os, standalone):
    lines = [
        "PluginImporter:", "  externalObjects: {}", "  serializedVersion: 2",
        "  iconMap: {}", "  executionOrder: {}", "  defineConstraints: []",
        "  isPreloaded: 0", "  isOverridable: 0",
        "  isExplicitlyReferenced: 0", "  validateReferences: 1",
        "  platformData:", "  - first:", "      : Any", "    second:",
        "      enabled: 0", "      settings:", "        Exclude Editor: 0",
    ]
    for s in STANDALONES:
        lines.append("        Exclude %s: %d" % (s, 0 if s == standalone else 1))
    lines += ["  - first:", "      Any: ", "    second:", "      enabled: 0",
              "      settings: {}",
              "  - first:", "      Editor: Editor", "    second:",
              "      enabled: 1", "      settings:", "        CPU: x86_64",
              "        DefaultValueInitialized: true",
              "        OS: %s" % editor_os]
    for s in STANDALONES:
        on = s == standalone
        lines += ["  - first:", "      Standalone: %s" % s, "    second:",
                  "      enabled: %d" % (1 if on else 0), "      settings:",
                  "        CPU: %s" % ("x86_64" if on else "None")]
    return "\n".join(lines) + "\n"


def needs_meta(rel):
    parts = rel.split("/")
    if parts[0] == "Documentation~":
        return False
    return not parts[-1].endswith("~")


def render(template, out_root):
    def sub(m):
        rel = m.group(1)
        if not os.path.exists(os.path.join(out_root, rel)):
            sys.exit("unity_package: %s refers to %s, which the package does not have"
                     % (template, rel))
        return guid(rel)
    return re.sub(r"\{\{guid:([^}]+)\}\}", sub, open(template, encoding="utf-8").read())


def main():
    ap = argparse.ArgumentParser()
    for opt in ("src", "out", "header", "license", "linux-so", "windows-dll", "graph"):
        ap.add_argument("--" + opt, required=True)
    a = ap.parse_args()

    version = header_version(a.header)
    manifest = json.load(open(os.path.join(a.src, "package.json"), encoding="utf-8"))
    if manifest.get("name") != PACKAGE or manifest.get("version") != version:
        sys.exit("unity_package: package.json is %s %s; smg.h says %s %s"
                 % (manifest.get("name"), manifest.get("version"), PACKAGE, version))

    if os.path.exists(a.out):
        shutil.rmtree(a.out)
    templates = []

    def keep(directory, names):
        rel_dir = os.path.relpath(directory, a.src).replace(os.sep, "/")
        dropped = set()
        for n in names:
            rel = n if rel_dir == "." else rel_dir + "/" + n
            if n == ".gitignore" or n.endswith(".meta") or rel == "Plugins":
                dropped.add(n)  # plugins and metas are made here
            elif n.endswith(".in"):
                templates.append(rel)
                dropped.add(n)
        return dropped

    shutil.copytree(a.src, a.out, ignore=keep)
    shutil.copyfile(a.license, os.path.join(a.out, "LICENSE.md"))
    for rel, built in (("Plugins/Linux/x86_64/libsmg.so", a.linux_so),
                       ("Plugins/Windows/x86_64/smg.dll", a.windows_dll),
                       ("Samples~/PathFollower/Graph/default.smg.bytes", a.graph)):
        dst = os.path.join(a.out, rel)
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        shutil.copyfile(built, dst)
    for rel in templates:
        with open(os.path.join(a.out, rel[:-3]), "w", encoding="utf-8") as f:
            f.write(render(os.path.join(a.src, rel), a.out))

    assets = []
    for root, dirs, files in os.walk(a.out):
        dirs.sort()
        for n in dirs + sorted(files):
            path = os.path.join(root, n)
            rel = os.path.relpath(path, a.out).replace(os.sep, "/")
            if needs_meta(rel):
                assets.append((rel, os.path.isdir(path)))
    for rel, is_dir in assets:
        with open(os.path.join(a.out, rel + ".meta"), "w", encoding="utf-8") as f:
            f.write("fileFormatVersion: 2\nguid: %s\n" % guid(rel))
            f.write(importer_yaml(rel, is_dir))
    print("unity_package: %s %s in %s (%d assets with .meta)" % (PACKAGE, version, a.out, len(assets)))


if __name__ == "__main__":
    main()
