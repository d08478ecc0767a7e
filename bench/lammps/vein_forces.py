#!/usr/bin/python3
"""Force-by-force check of the LAMMPS vein twin: the accelerations LAMMPS
computes (one `run 0` of bench/lammps/vein.in, dump at step 0) on a dmhs
snapshot's state against the accelerations dmhs computed on it (the snapshot's
field `a`), particle by particle.

  dmhs run with -sph_delta 0 -sph_density_predict false -sph_av_alpha 0 (what
  LAMMPS has), snapshot S
  /usr/bin/python3 bench/lammps/vein_data.py D --snapshot S --evaluation-density --out P
  lmp -in bench/lammps/vein.in -var data P.data -var params P.params.in -var t_end 0 \\
      -var dump_every 1 -var out L         (run 0: the forces of the data file's state)
  /usr/bin/python3 bench/lammps/vein_forces.py --snapshot D/S --dump L/vein.0.dump --data P.data \\
      --params P.params.in

The state is the one dmhs's last force evaluation saw up to O(dt^2): positions
x^{n+1}, the half-step density (vein_data.py --evaluation-density), and the
velocity v^{n+1} where dmhs used v_est = v^n + dt a^n. Both include the drive
g0 sin(2 pi t/T) at the state's time (the twin's clock starts there): it is taken
off both, so that what is compared is the particles' forces. Particles are
grouped by what they interact with (within the support h): the liquid away from walls, clamps and leaflets (pressure, Morris
viscosity), the liquid near a leaflet but no wall (plus the liquid-leaflet SPH
terms and the repulsion), the leaflets away from the walls (plus bonds and
angles), and those near a wall, where the two codes' walls differ (LAMMPS: own
velocity zero and integrated density; dmhs: the liquid's extrapolated velocity
and pressure). Per group: RMS and largest |a_dmhs - a_LAMMPS| relative to the
RMS |a_LAMMPS| of the group.
"""
import argparse
import math
import re
import sys

import h5py
import numpy as np

from vein_compare import near


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--snapshot", required=True)
    ap.add_argument("--dump", required=True)
    ap.add_argument("--data", required=True)
    ap.add_argument("--params", required=True)
    a = ap.parse_args()

    params = {}
    for line in open(a.params):
        mm = re.match(r"variable\s+(\S+)\s+equal\s+(\S+)", line)
        if mm:
            params[mm.group(1)] = float(mm.group(2))
    h, length = params["h"], params["length"]
    masses = np.zeros(7)
    lines = open(a.data).read().splitlines()
    i = lines.index("Masses") + 2
    while lines[i].strip():
        t, m = lines[i].split()[:2]
        masses[int(t)] = float(m)
        i += 1

    with open(a.dump) as f:
        dl = f.readlines()
    n = int(dl[3])
    cols = dl[8].split()[2:]
    D = np.loadtxt(dl[9:9 + n], ndmin=2)
    D = D[np.argsort(D[:, cols.index("id")])]
    lt = D[:, cols.index("type")].astype(int)
    x = D[:, [cols.index("x"), cols.index("y")]]
    a_l = D[:, [cols.index("fx"), cols.index("fy")]] / masses[lt][:, None]

    with h5py.File(a.snapshot, "r") as s:
        t = float(s.attrs["time"][0])
        P = s["particles"]
        o = np.argsort(P["gid"][:])
        a_d = P["a"][:, :2][o]
        x_d = P["x"][:, :2][o]
    if len(a_d) != n or np.abs(x_d - x).max() > 1e-12:
        sys.exit("the dump and the snapshot are not the same particles at the same positions")
    # both include the drive at the state's time (LAMMPS's clock starts at t0 = t): taken off
    # both, so that the comparison is of the particle forces
    if abs(params.get("t0", 0.0) - t) > 1e-12:
        sys.exit(f"the twin's t0 = {params.get('t0', 0.0)} s is not the snapshot's time {t} s")
    g = params["g0"] * (math.sin(2 * math.pi * t / params["period"]) if params["period"] > 0 else 1.0)
    liquid = lt == 1
    a_d, a_l = a_d.copy(), a_l.copy()
    for acc in (a_d, a_l):
        acc[liquid, 0] -= g * params["gx"]
        acc[liquid, 1] -= g * params["gy"]

    wall = (lt == 2) | (lt == 5) | (lt == 6)
    leaf = (lt == 3) | (lt == 4)
    idx = np.arange(n)
    near_wall = np.zeros(n, dtype=bool)
    near_leaf = np.zeros(n, dtype=bool)
    near_wall[~wall] = near(x, ~wall, wall, h, length)
    near_leaf[liquid] = near(x, liquid, leaf, h, length)
    groups = [("liquid, only liquid within h", liquid & ~near_wall & ~near_leaf),
              ("liquid near a leaflet, no wall", liquid & near_leaf & ~near_wall),
              ("leaflets, no wall within h", leaf & ~near_wall),
              ("liquid near a wall", liquid & near_wall),
              ("leaflets near a wall or clamp", leaf & near_wall)]
    print(f"t = {t:g} s (the drive, {g:.4g} m/s^2, taken off the liquid's accelerations); "
          f"|a_dmhs - a_LAMMPS| relative to the group's RMS |a_LAMMPS|")
    for name, sel in groups:
        if not sel.any():
            print(f"  {name:34s} (none)")
            continue
        ref = np.sqrt((a_l[sel] ** 2).sum(axis=1).mean())
        e = np.sqrt(((a_d[sel] - a_l[sel]) ** 2).sum(axis=1))
        worst = idx[sel][np.argmax(e)]
        print(f"  {name:34s} {sel.sum():5d} particles  RMS |a| {ref:.3e} m/s^2  diff RMS "
              f"{np.sqrt((e ** 2).mean()) / ref:.2e}  max {e.max() / ref:.2e} (id {worst + 1})")


if __name__ == "__main__":
    main()
