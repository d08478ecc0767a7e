#!/usr/bin/python3
"""Compares LAMMPS' tables of bench/lammps/potentials.in with dmhs's formulas
(doc/theory.md, "Bonds, angles and repulsion"):

  repulsion  U = K[(s^p1 - 1)/p1 - (s^p2 - 1)/p2], |F| = K (s^p1 - s^p2)/r, s = r*/r < 1
  nonlinear  U = k_b x^2/(r_max^2 - x^2), F = -2 k_b r_max^2 x/(r_max^2 - x^2)^2, x = r - r0
  harmonic   U = K (r - r0)^2, F = -2 K (r - r0)
  angle      U = k_a (theta - theta0)^2, over 1 .. 179 deg

  lmp -in bench/lammps/potentials.in -var out DIR
  /usr/bin/python3 bench/lammps/check_potentials.py DIR

Prints the largest difference of energy and force per table, relative to the
largest value, and exits 1 when one exceeds 1e-12 (the angle's force: 1e-6,
LAMMPS differentiates the energy numerically).
"""
import math
import os
import sys

import numpy as np


def table(path):
    rows = [line.split() for line in open(path)]
    return np.array([r for r in rows if len(r) == 4 and r[0].isdigit()], dtype=float)


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "."
    K, rs = 2e-3, 1e-4
    status = 0
    checks = []
    for p1, p2 in ((4, 2), (12, 6)):
        t = table(os.path.join(d, f"repulsion_{p1}_{p2}.table"))
        r, E, F = t[:, 1], t[:, 2], t[:, 3]
        s = rs / r
        checks.append((f"repulsion ({p1},{p2})", E, K * ((s**p1 - 1) / p1 - (s**p2 - 1) / p2),
                       F, K * (s**p1 - s**p2) / r, 1e-12))
    t = table(os.path.join(d, "bond_nonlinear.table"))
    kb, r0, rm = 1e-4, 1e-3, 9e-4
    x = t[:, 1] - r0
    checks.append(("bond nonlinear", t[:, 2], kb * x * x / (rm * rm - x * x),
                   t[:, 3], -2 * kb * rm * rm * x / (rm * rm - x * x) ** 2, 1e-12))
    t = table(os.path.join(d, "bond_harmonic.table"))
    x = t[:, 1] - 1e-4
    checks.append(("bond harmonic", t[:, 2], 1e6 * x * x, t[:, 3], -2e6 * x, 1e-12))
    # angle_write's force is -dU/dtheta by numerical differentiation of the energy
    # (hence the looser bound), per degree; at theta = 0 and 180 deg exactly LAMMPS
    # clips sin(theta) at 0.001 (dmhs uses atan2, exact there): 1 .. 179 deg
    t = table(os.path.join(d, "angle_harmonic.table"))
    t = t[(t[:, 1] > 0.5) & (t[:, 1] < 179.5)]
    dth = np.radians(t[:, 1] - 90.0)
    checks.append(("angle harmonic", t[:, 2], 0.01 * dth * dth, t[:, 3], -2 * 0.01 * dth * math.pi / 180,
                   1e-6))
    for name, E, Ed, F, Fd, tol_f in checks:
        eE = np.abs(E - Ed).max() / np.abs(Ed).max()
        eF = np.abs(F - Fd).max() / np.abs(Fd).max()
        ok = eE <= 1e-12 and eF <= tol_f
        status |= not ok
        print(f"{name:18s} energy {eE:.1e}  force {eF:.1e}  (largest difference / largest value)"
              f"{'' if ok else '  FAILED'}")
    return status


if __name__ == "__main__":
    sys.exit(main())
