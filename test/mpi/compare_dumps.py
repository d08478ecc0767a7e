#!/usr/bin/env python3
"""Compare -dump_final CSV files (gid,type,x,y,vx,vy,rho, gid-sorted) against a reference.

usage: compare_dumps.py [--tol 1e-10] reference.csv other.csv [other.csv ...]

Both files must list the same gids in the same order (nothing lost or
duplicated). For each column the difference is measured relative to the
column's largest magnitude in the reference (velocities cross zero, so a
pointwise relative difference is meaningless there):
    rel = max_i |a_i - b_i| / max_i |a_i|
A non-finite value in the reference fails, a NaN in another file counts as an
infinite difference, and a file without rows or with a short row fails.
Prints the largest rel per file and column; exits 1 when any exceeds --tol.
"""
import csv
import math
import sys


def load(path):
    """(header, columns); a file without rows, or a row whose cell count differs
    from the header's, is an error (zip would drop the missing cells)."""
    with open(path) as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        raise SystemExit(f"FAIL: {path} has no particle rows")
    header, body = rows[0], rows[1:]
    cols = {name: [] for name in header}
    for n, r in enumerate(body, start=2):
        if len(r) != len(header):
            raise SystemExit(f"FAIL: {path}:{n}: {len(r)} cells, the header has {len(header)}")
        for name, v in zip(header, r):
            cols[name].append(float(v))
    return header, cols


def max_abs_diff(a, b):
    """max |a_i - b_i|, NaN against NaN equal; NaN against a number (or inf - inf) infinite.
    (Python's max() skips a NaN after the first element: max(0, nan) is 0.)"""
    worst = 0.0
    for x, y in zip(a, b):
        if x == y or (math.isnan(x) and math.isnan(y)):
            continue
        d = abs(x - y)
        worst = max(worst, d if not math.isnan(d) else math.inf)
    return worst


def main(argv):
    tol = 1e-10
    if len(argv) > 1 and argv[1] == "--tol":
        tol = float(argv[2])
        argv = argv[:1] + argv[3:]
    if len(argv) < 3:
        print(__doc__)
        return 2
    ref_path, others = argv[1], argv[2:]
    header, ref = load(ref_path)
    for name, values in ref.items():
        if not all(math.isfinite(v) for v in values):
            print(f"{ref_path}: column {name} holds a non-finite value: FAIL")
            return 1
    worst = 0.0
    ok = True
    for path in others:
        h, cols = load(path)
        if h != header:
            print(f"{path}: header {h} differs from {header}")
            ok = False
            continue
        if cols["gid"] != ref["gid"]:
            print(f"{path}: gid sets differ ({len(cols['gid'])} vs {len(ref['gid'])} particles): "
                  "particles lost or duplicated")
            ok = False
            continue
        if cols["type"] != ref["type"]:
            print(f"{path}: particle types differ")
            ok = False
            continue
        parts = []
        for name in header[2:]:
            a, b = ref[name], cols[name]
            scale = max((abs(v) for v in a if math.isfinite(v)), default=0.0) or 1.0
            rel = max_abs_diff(a, b) / scale
            worst = max(worst, rel)
            parts.append(f"{name} {rel:.3e}")
            if not rel <= tol:
                ok = False
        print(f"{path} vs {ref_path}: {len(ref['gid'])} particles, max rel diff: " + ", ".join(parts))
    print(f"worst max relative difference: {worst:.3e} (tolerance {tol:g}): {'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
