#!/usr/bin/python3
"""scripts/post/particle_spacing.py on a made-up snapshot whose pairs are known.

A periodic-in-x lattice of liquid particles at spacing dx, with three pairs
moved together: one to 0.2 dx, one to 0.25 dx, and one to 0.4 dx across the
periodic boundary. A wall particle sits 0.1 dx from a liquid particle and must
not count. Expected: 6 liquid particles below 0.5 dx, 4 below 0.3 dx, and a
smallest distance of 0.2 dx. Bad --below values and a directory without
snapshots must fail with a message.
  particle_spacing_check.py SCRIPTS_POST_DIR WORK_DIR
"""
import csv
import os
import subprocess
import sys

import h5py
import numpy as np

post, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
script = os.path.join(post, "particle_spacing.py")
dx, nx, ny = 1e-3, 20, 10
xs = [((i + 0.5) * dx, (j + 0.5) * dx) for j in range(ny) for i in range(nx)]
x = np.array(xs)


def move_next_to(a, b, frac, wrap=0.0):
    """Puts particle b at frac dx from particle a along x (wrap: a periodic shift)."""
    x[b] = x[a] + np.array([frac * dx + wrap, 0.0])


move_next_to(2 * nx + 3, 2 * nx + 4, 0.2)
move_next_to(5 * nx + 10, 5 * nx + 11, 0.25)
move_next_to(8 * nx + nx - 1, 8 * nx + 0, 0.4, wrap=-nx * dx)  # across x = nx dx
typ = np.zeros(len(x), dtype=np.int32)
wall = np.array([[x[0, 0], x[0, 1] - 0.1 * dx]])
x = np.vstack([x, wall])
typ = np.append(typ, 1)
x3 = np.hstack([x, np.zeros((len(x), 1))])

run = os.path.join(work, "run")
os.makedirs(run, exist_ok=True)
with h5py.File(os.path.join(run, "snap_000000.h5"), "w") as f:
    f.attrs["time"] = np.array([0.5])
    f.attrs["dx"] = np.array([dx])
    f.attrs["box_lo"] = np.array([0.0, -dx])
    f.attrs["box_hi"] = np.array([nx * dx, (ny + 1) * dx])
    f.attrs["periodic"] = np.array([1, 0])
    f.create_dataset("particles/x", data=x3)
    f.create_dataset("particles/type", data=typ)

out_csv = os.path.join(work, "spacing.csv")
r = subprocess.run([sys.executable, script, run, "--csv", out_csv], capture_output=True, text=True)
assert r.returncode == 0, r.stderr
with open(out_csv) as f:
    rows = list(csv.DictReader(f))
assert len(rows) == 1, rows
row = rows[0]
assert int(row["n_liquid"]) == nx * ny, row
assert int(row["n_below_0.5dx"]) == 6, row
assert int(row["n_below_0.3dx"]) == 4, row
assert abs(float(row["min_nn_over_dx"]) - 0.2) < 1e-4, row

for bad, why in (("2", "(0, 1]"), ("a,b", "separated by commas")):
    r = subprocess.run([sys.executable, script, run, "--below", bad], capture_output=True, text=True)
    assert r.returncode == 1 and why in r.stderr, (bad, r.returncode, r.stderr)
empty = os.path.join(work, "empty")
os.makedirs(empty, exist_ok=True)
r = subprocess.run([sys.executable, script, empty], capture_output=True, text=True)
assert r.returncode == 1 and "no snapshot" in r.stderr, r.stderr
print("particle_spacing_check: ok")
