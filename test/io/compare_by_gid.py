#!/usr/bin/python3
"""Compares two snapshots or checkpoints particle by particle (matched by
gid, whatever the row order the rank count gave): prints the largest relative
difference of every particle dataset and exits 1 when any exceeds --tol
(default 0: bitwise), when the files hold different gid sets, when a dataset
or a step/time attribute is in one file only, when a value is NaN in one file
and not in the other, or when the files' step or time differ. Datasets that
are not one row per particle in either file (a checkpoint's rank_counts) are
skipped.

  compare_by_gid.py A.h5 B.h5 [--tol T]
"""
import sys, h5py, numpy as np
tol = float(sys.argv[sys.argv.index("--tol") + 1]) if "--tol" in sys.argv else 0.0
a, b = (h5py.File(p, "r") for p in sys.argv[1:3])
worst = 0.0


def bad(msg):
    global worst
    print(msg)
    worst = float("inf")


ga, gb = a["particles/gid"][()], b["particles/gid"][()]
ia, ib = np.argsort(ga, kind="stable"), np.argsort(gb, kind="stable")
if len(np.unique(ga)) != len(ga) or len(np.unique(gb)) != len(gb):
    bad("a gid appears twice in one file")
if ga.shape != gb.shape or not np.array_equal(ga[ia], gb[ib]):
    bad(f"different particles: {len(ga)} gids in {sys.argv[1]}, {len(gb)} in {sys.argv[2]}")
else:
    for k in sorted(set(a["particles"]) | set(b["particles"])):
        if k not in a["particles"] or k not in b["particles"]:
            bad(f"{k:6s} only in {sys.argv[1] if k in a['particles'] else sys.argv[2]}")
            continue
        if a["particles"][k].shape[:1] != ia.shape or b["particles"][k].shape[:1] != ib.shape:
            print(f"{k:6s} skipped (not one row per particle)")
            continue
        x, y = a["particles"][k][()][ia], b["particles"][k][()][ib]
        if x.shape != y.shape:
            bad(f"{k:6s} shapes {x.shape} and {y.shape}")
            continue
        xf, yf = x.astype(float), y.astype(float)
        # equal values and NaN against NaN count as the same; NaN against a number, or inf - inf, as infinitely apart
        same = (xf == yf) | (np.isnan(xf) & np.isnan(yf))
        diff = np.where(same, 0.0, np.abs(xf - yf))
        diff[np.isnan(diff)] = np.inf
        d = float(diff.max()) if diff.size else 0.0
        if tol == 0 and x.tobytes() != y.tobytes():
            d = max(d, np.finfo(float).tiny)  # e.g. -0.0 against 0.0
        finite = np.abs(xf[np.isfinite(xf)])
        scale = float(finite.max()) if finite.size and finite.max() > 0 else 1.0
        worst = max(worst, d / scale)
        print(f"{k:6s} max rel diff {d/scale:.3e}")
for key in ("step", "t", "time"):
    if (key in a.attrs) != (key in b.attrs):
        bad(f"attribute {key} only in {sys.argv[1] if key in a.attrs else sys.argv[2]}")
    elif key in a.attrs and not a.attrs[key][0] == b.attrs[key][0]:
        bad(f"attribute {key}: {a.attrs[key][0]} != {b.attrs[key][0]}")
print(f"{sys.argv[1]} vs {sys.argv[2]}: worst relative difference {worst:.3e} (tolerance {tol:g})")
sys.exit(0 if worst <= tol else 1)
