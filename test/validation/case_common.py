"""Helpers shared by the scene checkers (vein.py, clots.py): run dmhs, read a
scene CSV strictly, read an option from an options file, compare outputs."""
import math
import os
import subprocess
import sys


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def run(args, outdir, extra, ranks, tail=2500):
    """dmhs -options_file args.opts into outdir (on `ranks` ranks with args.mpirun); fails on a non-zero exit."""
    os.makedirs(outdir, exist_ok=True)
    cmd = [args.exe, "-options_file", args.opts, "-output_dir", outdir, "-quiet"] + extra
    if ranks > 1:
        cmd = args.mpirun.split() + ["-n", str(ranks)] + cmd
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(p.stdout[-tail:])
    if p.returncode != 0:
        fail(f"dmhs exited with {p.returncode}: {' '.join(cmd)}")


def read_csv(path):
    """(names, rows): '#' lines skipped, an empty cell is None ('not defined yet',
    never a value); a missing or empty file, no data rows, a short row, a cell
    that is not a number or a non-finite value fail."""
    if not os.path.isfile(path) or os.path.getsize(path) == 0:
        fail(f"{path} is missing or empty")
    with open(path) as f:
        lines = [ln.rstrip("\n") for ln in f if not ln.startswith("#")]
    names = lines[0].split(",")
    rows = []
    for n, ln in enumerate(lines[1:], 2):
        cells = ln.split(",")
        if len(cells) != len(names):
            fail(f"{path}:{n}: {len(cells)} cells, header has {len(names)}")
        row = []
        for c in cells:
            if c == "":
                row.append(None)
                continue
            try:
                v = float(c)
            except ValueError:
                fail(f"{path}:{n}: '{c}' is not a number")
            if not math.isfinite(v):
                fail(f"{path}:{n}: non-finite value {c}")
            row.append(v)
        rows.append(row)
    if not rows:
        fail(f"{path} has no rows")
    return names, rows


def opt_value(path, name):
    """The last value of an option in an options file and the files it includes
    (-options_file paths as given, else relative to the repository root)."""
    value = None
    for line in open(path):
        w = line.split("#")[0].split()
        if len(w) >= 2 and w[0] == "-options_file":
            inner = w[1]
            if not os.path.isfile(inner):
                inner = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(path))), w[1])
            v = opt_value(inner, name)
            value = v if v is not None else value
        elif w and w[0] == name:
            value = w[1] if len(w) > 1 else ""
    return value


def compare(a, b, files):
    """Each of `files` byte for byte the same in directories a and b."""
    for c in files:
        pa, pb = os.path.join(a, c), os.path.join(b, c)
        for p in (pa, pb):
            if not os.path.isfile(p):
                fail(f"{p} is missing")
        if open(pa, "rb").read() != open(pb, "rb").read():
            fail(f"{pa} differs from {pb}")
        print(f"  {c}: identical to {pb}")
