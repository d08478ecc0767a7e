#!/usr/bin/env python3
"""Checks <output_dir>/dt.csv of a run with the automatic time step (-dt 0).

  dt_csv.py DIR [--min-changes N] [--limit NAME]... [--growth G] [--substeps N] [--same DIR2]...

Fails (exit 1) unless: the header is step,t,dt,limit; the first row is step 0;
steps increase; every dt is finite and > 0; each row's t is the previous row's
t plus the steps between them times the previous dt (t advances from the last
change); no dt grows by more than G (default 1.05) per step; at least N rows
after the first (dt changed N times); every --limit NAME binds in some row;
each --same DIR2 holds a byte-identical dt.csv (rank counts, restarts); with
--substeps N the file has the column substeps (-solid_substeps), every value
is an integer >= 1 and N is one of them.
"""
import argparse
import math
import os
import sys


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("--min-changes", type=int, default=0)
    ap.add_argument("--limit", action="append", default=[])
    ap.add_argument("--growth", type=float, default=1.05)
    ap.add_argument("--same", action="append", default=[])
    ap.add_argument("--substeps", type=int, default=0)
    a = ap.parse_args()
    path = os.path.join(a.dir, "dt.csv")
    if not os.path.isfile(path):
        fail(f"{path} is missing")
    with open(path, "rb") as f:
        raw = f.read()
    lines = raw.decode().splitlines()
    header = "step,t,dt,limit,substeps" if a.substeps else "step,t,dt,limit"
    if not lines or lines[0] != header:
        fail(f"{path}: header {lines[:1]} is not {header}")
    rows, subs = [], set()
    for n, line in enumerate(lines[1:], start=2):
        parts = line.split(",")
        if len(parts) != header.count(",") + 1 or not parts[3]:
            fail(f"{path}:{n}: '{line}' is not {header}")
        if a.substeps:
            if not parts[4].isdigit() or int(parts[4]) < 1:
                fail(f"{path}:{n}: substeps '{parts[4]}' is not an integer >= 1")
            subs.add(int(parts[4]))
        step, t, dt = int(parts[0]), float(parts[1]), float(parts[2])
        if not (math.isfinite(t) and math.isfinite(dt) and dt > 0):
            fail(f"{path}:{n}: t = {t}, dt = {dt}")
        rows.append((step, t, dt, parts[3]))
    if not rows or rows[0][0] != 0 or rows[0][1] != 0.0:
        fail(f"{path}: the first row is not step 0 at t = 0")
    for (s0, t0, d0, _), (s1, t1, d1, _) in zip(rows, rows[1:]):
        if s1 <= s0:
            fail(f"{path}: step {s1} after step {s0}")
        if d1 == d0:  # a change of the sub-steps only
            continue
        expect = t0 + (s1 - s0) * d0
        if abs(t1 - expect) > 1e-9 * max(abs(expect), 1e-30):
            fail(f"{path}: step {s1}: t = {t1!r}, expected {expect!r} from the previous dt")
        if d1 > a.growth * d0 * (1 + 1e-12):
            fail(f"{path}: step {s1}: dt grew {d1 / d0:.4f}x in one step (bound {a.growth})")
    changes = len(rows) - 1
    if changes < a.min_changes:
        fail(f"{path}: dt changed {changes} times, expected at least {a.min_changes}")
    if a.substeps and a.substeps not in subs:
        fail(f"{path}: no row with {a.substeps} sub-steps (seen: {sorted(subs)})")
    names = {r[3] for r in rows}
    for name in a.limit:
        if name not in names:
            fail(f"{path}: no row bound by '{name}' (limits seen: {sorted(names)})")
    for other in a.same:
        op = os.path.join(other, "dt.csv")
        if not os.path.isfile(op):
            fail(f"{op} is missing")
        with open(op, "rb") as f:
            if f.read() != raw:
                fail(f"{op} differs from {path}")
    print(f"OK: {path}: {changes} changes, limits {sorted(names)}, dt {min(r[2] for r in rows):.4g}.."
          f"{max(r[2] for r in rows):.4g} s" + (f", identical to {a.same}" if a.same else ""))


if __name__ == "__main__":
    main()
