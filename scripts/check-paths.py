#!/usr/bin/env python3
"""Fails when a repository path named in the docs or in a comment does not exist.

Every tracked Markdown file, and the comments of every source, shader, script and CMake file, are searched for
paths that start at one of the
repository's top folders (src/, docs/, tests/, apps/, ...). A path is fine when it exists from the repository
root, or, in a Markdown link, from the Markdown file's folder; a module named without its extension
(src/scenes/testbed/TestbedRaytracer) when its .h or .cpp exists; "Color.h/.cpp" when Color.h exists. Paths
that are patterns (f%04d, *.exr, <name>, {a,b}, ####) and the folders programs make as they run (listed below,
each with the reason) are not checked. docs/bench/ is a log of past measurements and is not checked.

    scripts/check-paths.py        exit 0 when every path exists, else 1 listing FILE:LINE PATH

Run in a checkout it reads the files git tracks; in a copy of the tree without .git (the standalone test's), every
file below the current folder but build/ and out/.
"""

import os
import re
import subprocess
import sys

TOP = "src|docs|tests|apps|scripts|tools|include|data|examples|bench|fuzz|cmake"
PATH = re.compile(r"(?<![A-Za-z0-9_./-])((?:%s)/[A-Za-z0-9_./-]*[A-Za-z0-9_])" % TOP)
LINK = re.compile(r"\]\(([^)#\s]+)")
PATTERN_NEXT = set("%*<{#$[")

# Folders and files programs make as they run, named where the docs say where output goes.
MADE_AT_RUN_TIME = {
    "fuzz/corpus/cube": "the fuzzers write their new inputs there (fuzz/run.sh)",
    "tests/data/fuzz-repro": "the fuzzers write their reproducers there",
}


KEEP = (".md", ".h", ".cpp", ".glsl", ".sh", ".bash", ".py", ".cmake", ".txt")


def checked(name):
    if name.startswith("docs/bench/") or name.startswith("tests/data/"):
        return False
    return name.endswith(KEEP) or os.path.basename(name) in ("Makefile", "CMakeLists.txt")


def tracked_files(root, in_git):
    """The files git tracks; outside a checkout (a copy of the tree), every file but the build's."""
    if in_git:
        out = subprocess.run(["git", "ls-files"], cwd=root, capture_output=True, text=True, check=True).stdout
        names = out.splitlines()
    else:
        names = []
        for folder, dirs, files in os.walk(root):
            dirs[:] = [d for d in dirs if d not in (".git", "build", "out") and not d.startswith(".")]
            names += [os.path.relpath(os.path.join(folder, f), root) for f in files]
    return sorted(n for n in names if checked(n))


def commentOf(name, line):
    """The part of `line` that is prose: all of it in Markdown, the comment in code."""
    if name.endswith(".md"):
        return line
    if name.endswith((".h", ".cpp", ".glsl")):
        at = line.find("//")
        return line[at:] if at >= 0 else ""
    stripped = line.lstrip()
    if stripped.startswith("#"):
        return line
    at = line.find(" # ")
    return line[at:] if at >= 0 else ""


def exists(root, base, path):
    for folder in (root, base):
        full = os.path.join(folder, path)
        if os.path.exists(full):
            return True
        if os.path.exists(full + ".h") or os.path.exists(full + ".cpp"):
            return True
    return False


def main():
    # The checkout around the current folder; outside one (a copy of the tree), the current folder.
    top = subprocess.run(["git", "rev-parse", "--show-toplevel"], capture_output=True, text=True)
    in_git = top.returncode == 0
    root = top.stdout.strip() if in_git else os.getcwd()
    missing = []
    for name in tracked_files(root, in_git):
        base = os.path.dirname(os.path.join(root, name))
        with open(os.path.join(root, name), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                line = commentOf(name, line)
                candidates = [(m.group(1), m.end(1)) for m in PATH.finditer(line)]
                if name.endswith(".md"):
                    candidates += [(m.group(1), m.end(1)) for m in LINK.finditer(line)
                                   if not re.match(r"[a-z]+:", m.group(1))]
                for path, end in candidates:
                    if end < len(line) and line[end] in PATTERN_NEXT:
                        continue
                    path = path.rstrip(".")
                    if "/." in path:  # Color.h/.cpp
                        path = path.split("/.")[0]
                    if any(path == p or path.startswith(p + "/") for p in MADE_AT_RUN_TIME):
                        continue
                    if not exists(root, base, path):
                        missing.append("%s:%d %s" % (name, number, path))
    for entry in missing:
        print("missing: " + entry)
    if missing:
        print("check-paths: %d path(s) named in the docs or comments do not exist" % len(missing))
        return 1
    print("check-paths: every path named in the docs and comments exists")
    return 0


if __name__ == "__main__":
    sys.exit(main())
