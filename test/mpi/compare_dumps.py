#!/usr/bin/env python3
"""Compare -dump_final CSV files (gid,type,x,y,vx,vy,rho, gid-sorted) against a reference.

usage: compare_dumps.py [--tol 1e-10] reference.csv other.csv [other.csv ...]

Both files must list the same gids in the same order (nothing lost or
duplicated). For each column the difference is measured relative to the
column's largest magnitude in the reference (velocities cross zero, so a
pointwise relative difference is meaningless there):
    rel = max_i |a_i - b_i| / max_i |a_i|
Prints the largest rel per file and column; exits 1 when any exceeds --tol.
"""
import csv
import sys


def load(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    cols = {name: [] for name in header}
    for r in body:
        for name, v in zip(header, r):
            cols[name].append(float(v))
    return header, cols


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
            scale = max(abs(v) for v in a) or 1.0
            rel = max(abs(x - y) for x, y in zip(a, b)) / scale
            worst = max(worst, rel)
            parts.append(f"{name} {rel:.3e}")
            if not rel <= tol:
                ok = False
        print(f"{path} vs {ref_path}: {len(ref['gid'])} particles, max rel diff: " + ", ".join(parts))
    print(f"worst max relative difference: {worst:.3e} (tolerance {tol:g}): {'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
