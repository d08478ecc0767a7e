#!/usr/bin/env python3
"""Every option is read through dmhs's checked readers, and PETSc's are left as they are.

    option_readers.py REPO

include/dmhs/options.h gives options_read_real, ... (inside PetscOptionsBegin/End) and
options_get_real, ... (outside it): each refuses a bad value by name before PETSc reads it
and records it for -help and the checkpoint. A module that calls PETSc's reader of the same
kind (PetscOptionsReal, PetscOptionsGetInt, ...) skips both, and a header that #defines or
#undefs one of PETSc's names changes PETSc for every file that includes it. Every file of
src/, include/ and test/unit/ is read; src/core/options.c, which wraps PETSc's readers, is
the one place allowed to call them. Prints one line per problem and exits 1 if there is any.
"""
import glob
import os
import re
import sys

KINDS = r"(?:Real|Int|RangeInt|BoundedInt|Bool|String|Enum|RealArray|IntArray|StringArray|" \
        r"BoolArray|EnumArray|Scalar|Ellipsis|List)"
CALL = re.compile(r"\bPetscOptions(?:Get)?" + KINDS + r"\s*\(")
REDEFINE = re.compile(r"^\s*#\s*(?:define|undef)\s+PetscOptions\w*", re.M)
WRAPPER = os.path.join("src", "core", "options.c")


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def main():
    repo = sys.argv[1]
    problems = []
    files = []
    for pattern in ("src/**/*.[ch]", "include/**/*.h", "test/unit/*.[ch]"):
        files += glob.glob(os.path.join(repo, pattern), recursive=True)
    if not files:
        problems.append(f"no source files under {repo}")
    for path in sorted(files):
        rel = os.path.relpath(path, repo)
        with open(path, encoding="utf-8") as f:
            text = strip_comments(f.read())
        for m in REDEFINE.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            problems.append(f"{rel}:{line}: redefines PETSc's {m.group(0).split()[-1]}")
        if rel == WRAPPER:
            continue
        for m in CALL.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            name = m.group(0).rstrip("( ")
            problems.append(f"{rel}:{line}: calls {name} directly; read it with the checked "
                            f"reader of include/dmhs/options.h")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
