#!/usr/bin/env python3
"""No file in a lower layer includes a header of a higher one.

    layers.py REPO

The layers, low to high, as doc/architecture.md draws them (calls point down):
core < io < physics < diag < scenes < driver, with src/main.c above them all.
A file under src/<layer>/ is in that layer; a public header include/dmhs/X.h
is in the layer of src/<layer>/X.c, its implementation, or in the one
HEADER_LAYERS gives when it has none. Every `#include "..."` of src/ and
include/ is read (the file's own directory first, then include/ and src/, as
the compiler looks), and one from a lower layer to a higher one fails, unless it
is in KNOWN_VIOLATIONS. A known violation that no longer exists fails too,
so that the list only shrinks and stays true: take an entry out in the commit
that removes its include. A directory of src/ that is not a layer, a header
with no layer and an include that names no file fail as well. Prints one line
per problem and exits 1 if there is any; with -v, every upward include.
"""
import glob
import os
import re
import sys

LAYERS = ["core", "io", "physics", "diag", "scenes", "driver"]  # low to high
TOP = "main"  # src/main.c

# Public headers without a src/<layer>/<stem>.c of their own.
HEADER_LAYERS = {
    "build_info.h": "core",  # dmhs_commit[], generated at build time (cmake/DmhsCommit.cmake)
    "module.h": "core",  # the module interface: core's force evaluation calls it (sim.c)
    "diagnostic.h": "core",  # the diagnostic interface: io's checkpoint calls its hooks
    "scene.h": "scenes",  # the scene interface
    "scenes.h": "scenes",  # the scenes' constructors
}

# The includes that run upward today; none. Take an entry out in the commit that removes its
# include, and add none: a lower layer reads an upper one's state through an interface of
# its own layer (module.h, diagnostic.h) or a forward-declared struct it does not open.
KNOWN_VIOLATIONS = set()

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def rank(layer):
    return len(LAYERS) if layer == TOP else LAYERS.index(layer)


def layer_of(repo, rel, problems):
    """The layer of a file of src/ or include/, or None (with a problem) when it has none."""
    parts = rel.split("/")
    if rel == "src/main.c":
        return TOP
    if parts[0] == "src":
        if len(parts) < 3 or parts[1] not in LAYERS:
            problems.append(f"{rel}: not in a layer's directory (src/<{'|'.join(LAYERS)}>/)")
            return None
        return parts[1]
    name = parts[-1]
    if name in HEADER_LAYERS:
        return HEADER_LAYERS[name]
    stem = os.path.splitext(name)[0]
    impl = sorted(glob.glob(os.path.join(repo, "src", "*", stem + ".c")))
    if len(impl) == 1:
        return impl[0].split(os.sep)[-2]
    problems.append(f"{rel}: no layer ({len(impl)} src/*/{stem}.c; give it in HEADER_LAYERS "
                    "of test/doc/layers.py)")
    return None


def resolve(repo, rel, name):
    """The repository path a quoted include names, as the compiler finds it, or None."""
    for base in (os.path.dirname(rel), "include", "src"):
        path = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(os.path.join(repo, path)):
            return path
    return None


def check(repo, verbose=False):
    problems, upward = [], set()
    files = sorted(
        os.path.relpath(p, repo)
        for pattern in ("src/**/*.c", "src/**/*.h", "include/**/*.h")
        for p in glob.glob(os.path.join(repo, pattern), recursive=True))
    layers = {}
    for rel in files:
        layers[rel] = layer_of(repo, rel, problems)
    for rel in files:
        with open(os.path.join(repo, rel), encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = resolve(repo, rel, m.group(1))
                if target is None:
                    problems.append(f"{rel}:{number}: #include \"{m.group(1)}\" names no file "
                                    "of src/ or include/")
                    continue
                mine, theirs = layers[rel], layers.get(target)
                if mine is None or theirs is None or rank(theirs) <= rank(mine):
                    continue
                upward.add((rel, target))
                known = (rel, target) in KNOWN_VIOLATIONS
                if verbose:
                    print(f"{rel}:{number}: {mine} includes {target} ({theirs})"
                          + (" [known]" if known else ""))
                if not known:
                    problems.append(f"{rel}:{number}: {mine} includes {target} of the higher "
                                    f"layer {theirs}")
    for rel, target in sorted(KNOWN_VIOLATIONS - upward):
        problems.append(f"{rel} no longer includes {target}: take the entry out of "
                        "KNOWN_VIOLATIONS in test/doc/layers.py")
    return problems


def main():
    args = [a for a in sys.argv[1:] if a != "-v"]
    if len(args) != 1 or not os.path.isdir(args[0]):
        sys.exit("usage: layers.py [-v] REPO")
    problems = check(os.path.abspath(args[0]), "-v" in sys.argv)
    for line in problems:
        print(line)
    if problems:
        print(f"layers: {len(problems)} problem(s) with the layers' includes")
        sys.exit(1)
    print(f"layers: no include runs from a lower layer to a higher one "
          f"({len(KNOWN_VIOLATIONS)} known, listed in test/doc/layers.py)")


if __name__ == "__main__":
    main()
