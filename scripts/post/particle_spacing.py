#!/usr/bin/python3
"""How close the liquid's particles come to each other, snapshot by snapshot.

  scripts/post/particle_spacing.py RUNDIR [--below F,F,...] [--csv PATH]

A liquid particle whose nearest liquid neighbour sits much closer than the
spacing dx has paired up with it (the tensile instability, doc/theory.md,
"Artificial pressure"): a pair acts as one particle of twice the mass, and the
fields it carries are noise. For every snapshot RUNDIR/snap_*.h5 this prints
and writes, per row: the time, the number of liquid particles, the smallest
nearest-neighbour distance over dx, and how many liquid particles have a
liquid neighbour closer than each fraction of --below (default 0.5,0.3) of dx.
dx is the snapshot's own (its 'dx' attribute); periodic directions are taken
from its 'periodic' and box attributes.

  --below F,...  fractions of dx to count pairs below (each in (0, 1])
  --csv PATH     the table as CSV (default: RUNDIR/particle_spacing.csv)

Exits with status 1 and a one-line message naming the file when a snapshot is
missing or lacks what it needs.
"""
import argparse
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from snapshot_files import snapshot_files  # noqa: E402

PROG = os.path.basename(sys.argv[0])
FLUID = 0


def fail(msg):
    sys.exit(f"{PROG}: {msg}")


def nearest_distances(x, reach, box_lo, box_hi, periodic):
    """Distance from each point of x (n x 2) to its nearest other point, capped at
    `reach` (points with none closer get reach). Cells of side `reach`: a point
    meets the points of its own and the 8 neighbouring cells."""
    n = len(x)
    best = np.full(n, reach)
    if n < 2:
        return best
    lo = np.asarray(box_lo, float)
    span = np.asarray(box_hi, float) - lo
    ncell = np.maximum((span // reach).astype(np.int64), 1)
    c = np.minimum(((x - lo) // (span / ncell)).astype(np.int64), ncell - 1)
    c = np.maximum(c, 0)
    key = c[:, 0] * ncell[1] + c[:, 1]
    order = np.argsort(key, kind="stable")
    skey = key[order]
    for ox in (-1, 0, 1):
        for oy in (-1, 0, 1):
            cx, cy = c[:, 0] + ox, c[:, 1] + oy
            shift = np.zeros((n, 2))
            ok = np.ones(n, bool)
            for d, cd in ((0, cx), (1, cy)):
                if periodic[d]:
                    wrap_lo, wrap_hi = cd < 0, cd >= ncell[d]
                    shift[wrap_lo, d] = -span[d]
                    shift[wrap_hi, d] = span[d]
                    cd %= ncell[d]
                else:
                    ok &= (cd >= 0) & (cd < ncell[d])
            nkey = np.where(ok, cx * ncell[1] + cy, -1)
            first = np.searchsorted(skey, nkey, "left")
            last = np.searchsorted(skey, nkey, "right")
            count = np.where(ok, last - first, 0)
            for k in range(int(count.max())):
                has = count > k
                i = np.nonzero(has)[0]
                j = order[first[i] + k]
                d = np.hypot(*(x[j] + shift[i] - x[i]).T)
                d[j == i] = np.inf
                np.minimum.at(best, i, d)
    return best


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("rundir")
    ap.add_argument("--below", default="0.5,0.3")
    ap.add_argument("--csv", default=None)
    a = ap.parse_args()
    try:
        below = [float(v) for v in a.below.split(",")]
    except ValueError:
        fail(f"--below '{a.below}': give fractions of dx separated by commas, e.g. 0.5,0.3")
    if not below or any(not (0 < f <= 1) for f in below):
        fail(f"--below '{a.below}': every fraction must lie in (0, 1]")
    import h5py

    rows = []
    for t, path in snapshot_files(a.rundir, fail):
        try:
            with h5py.File(path, "r") as f:
                dx = float(np.ravel(f.attrs["dx"])[0])
                lo, hi = np.ravel(f.attrs["box_lo"])[:2], np.ravel(f.attrs["box_hi"])[:2]
                per = [bool(v) for v in np.ravel(f.attrs["periodic"])[:2]]
                x = f["particles/x"][()][:, :2]
                typ = f["particles/type"][()]
        except (OSError, KeyError) as e:
            fail(f"{path}: unreadable or missing dx, box_lo, box_hi, periodic, particles/x or particles/type ({e})")
        if not dx > 0:
            fail(f"{path}: dx attribute {dx} is not positive")
        xl = x[typ == FLUID]
        nn = nearest_distances(xl, dx, lo, hi, per) / dx
        rows.append([t, len(xl), float(nn.min()) if len(xl) else float("nan")]
                    + [int((nn < f).sum()) for f in below])
    head = ["t", "n_liquid", "min_nn_over_dx"] + [f"n_below_{f:g}dx" for f in below]
    out = a.csv or os.path.join(a.rundir, "particle_spacing.csv")
    tmp = out + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(head)
        for r in rows:
            w.writerow([f"{r[0]:.6g}", r[1], f"{r[2]:.4f}"] + r[3:])
    os.replace(tmp, out)
    print("  ".join(f"{h:>14}" for h in head))
    for r in rows:
        print("  ".join(f"{v:>14.6g}" if isinstance(v, float) else f"{v:>14}" for v in r))
    print(f"{PROG}: wrote {out}")


if __name__ == "__main__":
    main()
