#!/usr/bin/python3
"""Compares two snapshots or checkpoints particle by particle (matched by
gid, whatever the row order the rank count gave): prints the largest relative
difference of every particle dataset and exits 1 when any exceeds --tol
(default 0: bitwise), or when the files' step or time differ. Datasets that are
not one row per particle (a checkpoint's rank_counts) are skipped.

  compare_by_gid.py A.h5 B.h5 [--tol T]
"""
import sys, h5py, numpy as np
tol = float(sys.argv[sys.argv.index("--tol") + 1]) if "--tol" in sys.argv else 0.0
a, b = (h5py.File(p, "r") for p in sys.argv[1:3])
ia, ib = np.argsort(a["particles/gid"][()]), np.argsort(b["particles/gid"][()])
worst = 0
for k in a["particles"]:
    if a["particles"][k].shape[:1] != ia.shape or k not in b["particles"]:
        print(f"{k:6s} skipped (not one row per particle, or only in {sys.argv[1]})")
        continue
    x, y = a["particles"][k][()][ia], b["particles"][k][()][ib]
    d = np.max(np.abs(x.astype(float) - y.astype(float))) if x.size else 0
    if tol == 0 and x.tobytes() != y.tobytes():
        d = max(d, np.finfo(float).tiny)  # e.g. -0.0 against 0.0
    scale = np.max(np.abs(x.astype(float))) or 1
    worst = max(worst, d / scale)
    print(f"{k:6s} max rel diff {d/scale:.3e}")
for key in ("step", "t", "time"):
    if key in a.attrs and key in b.attrs and a.attrs[key][0] != b.attrs[key][0]:
        print(f"attribute {key}: {a.attrs[key][0]} != {b.attrs[key][0]}")
        worst = float("inf")
print(f"{sys.argv[1]} vs {sys.argv[2]}: worst relative difference {worst:.3e} (tolerance {tol:g})")
sys.exit(0 if worst <= tol else 1)
