#!/usr/bin/env python3
"""scripts/post/sph_grid.py on synthetic lattices (no run needed):
  * each kernel (lucy, cubic, wendland) integrates to 1 over its support;
  * in a box periodic in x and y, a square lattice's kernel sum S is 1 within
    1 % everywhere (2 % with Wendland's), at the boundaries too, and a constant
    field is exact;
  * a field sin(2 pi x / L) cos(2 pi y / L) is interpolated within 2 % of its
    amplitude everywhere, and points at x and x + L (or y + L) get the same value;
  * shifting particles and points by half the period (wrapped) changes nothing;
  * periods of 2 and 3 cells (the smallest a run allows: more than 2 h) count
    no neighbour twice (S stays 1), also with the box's origin off 0;
  * bounded directions: S falls to about 0.5 at a free edge and 0 beyond h.
Usage: sph_grid_selftest.py SCRIPTS_POST_DIR"""
import math
import sys

import numpy as np

sys.path.insert(0, sys.argv[1])
import sph_grid as sg  # noqa: E402

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def lattice(n, dx, lo=(0.0, 0.0)):
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    return lo[0] + (i.ravel() + 0.5) * dx, lo[1] + (j.ravel() + 0.5) * dx


for kind in sg.KERNELS:  # the integral of W over the disc of radius h, by a fine radial sum
    h = 1.0
    r = (np.arange(200000) + 0.5) * h / 200000
    integral = float(np.sum(sg.kernel_w(kind, r / h, h) * 2 * math.pi * r) * h / 200000)
    check(abs(integral - 1) < 1e-6, f"{kind}: the integral of W is {integral:.8f}")

n, dx = 40, 1e-3
L, h = n * dx, 2.5 * dx
px, py = lattice(n, dx)
vol = np.full(px.size, dx * dx)
rng = np.random.default_rng(1)
qx, qy = rng.uniform(-0.2 * L, 1.2 * L, 4000), rng.uniform(-0.2 * L, 1.2 * L, 4000)
for kind in sg.KERNELS:
    f, S = sg.interpolate(px, py, vol, np.ones(px.size), qx, qy, h, period=(L, L), kernel=kind)
    tol = 0.02 if kind == "wendland" else 0.01  # Wendland's sum at h = 2.5 dx is the roughest
    check(np.abs(S - 1).max() < tol and np.abs(f[:, 0] - 1).max() < 1e-12,
          f"{kind}, periodic x and y: S in [{S.min():.4f}, {S.max():.4f}], a constant field exact")

value = np.sin(2 * math.pi * px / L) * np.cos(2 * math.pi * py / L)
f, S = sg.interpolate(px, py, vol, value, qx, qy, h, period=(L, L))
exact = np.sin(2 * math.pi * qx / L) * np.cos(2 * math.pi * qy / L)
check(np.abs(f[:, 0] - exact).max() < 0.02, f"a periodic wave: largest error {np.abs(f[:, 0] - exact).max():.4f}")
a, _ = sg.interpolate(px, py, vol, value, qx, qy, h, period=(L, L))
b, _ = sg.interpolate(px, py, vol, value, qx + L, qy - L, h, period=(L, L))
check(np.abs(a - b).max() < 1e-12, "points one period apart get the same value")
sx, sy = np.mod(px + 0.5 * L, L), np.mod(py + 0.5 * L, L)
c, _ = sg.interpolate(sx, sy, vol, value, qx + 0.5 * L, qy + 0.5 * L, h, period=(L, L))
check(np.abs(a - c).max() < 1e-12, f"shifted by half the period: largest change {np.abs(a - c).max():.2e}")

for cells in (2, 3):  # a period of 2 or 3 cells of width >= h
    m = int(round(cells * h / dx)) + 1  # just over cells * h
    Lp = m * dx
    lo = (-0.37 * Lp, 0.0)
    i, j = np.meshgrid(np.arange(m), np.arange(n), indexing="ij")  # y bounded: n rows
    px2, py2 = lo[0] + (i.ravel() + 0.5) * dx, (j.ravel() + 0.5) * dx
    vol2 = np.full(px2.size, dx * dx)
    q = rng.uniform(lo[0] - Lp, lo[0] + 2 * Lp, 500)
    f2, S2 = sg.interpolate(px2, py2, vol2, np.ones(px2.size), q, np.full(q.size, 0.5 * L), h,
                            period=(Lp, None), origin=lo)
    check(np.abs(S2 - 1).max() < 0.01, f"a period of {cells} cells (L = {Lp / h:.2f} h, origin "
          f"{lo[0] / dx:.1f} dx): S in [{S2.min():.4f}, {S2.max():.4f}]")

# bounded: the free edge of the lattice at x = 0 (y periodic)
edge = np.array([0.0, -0.5 * h, -1.01 * h])
_, S3 = sg.interpolate(px, py, vol, np.ones(px.size), edge, np.full(3, 0.5 * L), h, period=(None, L))
check(0.4 < S3[0] < 0.6 and S3[2] == 0, f"a free edge: S = {S3[0]:.3f} on it, {S3[2]:g} beyond h")

if failures:
    print(f"sph_grid self-test: {len(failures)} failure(s)")
    sys.exit(1)
print("sph_grid self-test: OK")
