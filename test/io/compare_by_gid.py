#!/usr/bin/python3
"""Compares two snapshots particle by particle (matched by gid, whatever the
row order the rank count gave): prints the largest relative difference of
every dataset and exits 1 when any exceeds --tol (default 0: bitwise).

  compare_by_gid.py A.h5 B.h5 [--tol T]
"""
import sys, h5py, numpy as np
tol = float(sys.argv[sys.argv.index("--tol") + 1]) if "--tol" in sys.argv else 0.0
a, b = (h5py.File(p, "r") for p in sys.argv[1:3])
ia, ib = np.argsort(a["particles/gid"][()]), np.argsort(b["particles/gid"][()])
worst = 0
for k in a["particles"]:
    x, y = a["particles"][k][()][ia], b["particles"][k][()][ib]
    d = np.max(np.abs(x.astype(float) - y.astype(float))) if x.size else 0
    scale = np.max(np.abs(x.astype(float))) or 1
    worst = max(worst, d / scale)
    print(f"{k:6s} max rel diff {d/scale:.3e}")
print(f"{sys.argv[1]} vs {sys.argv[2]}: worst relative difference {worst:.3e} (tolerance {tol:g})")
sys.exit(0 if worst <= tol else 1)
