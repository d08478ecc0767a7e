#!/usr/bin/python3
"""Compares the LAMMPS vein twin (bench/lammps/vein.in, every particle dumped)
with dmhs vein runs from the same state (their snapshots), at the times both
wrote (within dt/2).

  /usr/bin/python3 bench/lammps/vein_compare.py --lammps DIR --dt DT --data P.data \\
      --params P.params.in --dmhs NAME=DIR [--dmhs NAME=DIR ...] [--times 0.1,0.2]

(P: bench/lammps/vein_data.py's output for the twin; its t0 is the common start.)
At each time, per run: the liquid's kinetic energy E_k [J per m of depth], its
mean x velocity <u> [m/s], the mean x velocity at the inlet station u_in
(liquid within dx of x = dx/2, as dmhs's vein.csv), max |v| of the liquid,
mean and largest |rho/rho0 - 1| of the liquid, the ratio of the volume fluxes
sum V v_x/dx through the lattice column at the sinus's middle and at the inlet
station (1 in an incompressible flow), and each leaflet tip's centre (the mean
of its last column) [m]. Then, per dmhs run against LAMMPS, with the
changes since the start: those of E_k, <u> and u_in relative to LAMMPS's; the
particle-by-particle (same ids) RMS difference of the liquid velocities relative
to the RMS of LAMMPS's velocity change, in all, within h of a wall or clamp
particle and elsewhere; the leaflet particles' distance (RMS and largest, in dx);
and the tips' displacements [um].
"""
import argparse
import glob
import os
import re
import sys

import h5py
import numpy as np

# LAMMPS types of bench/lammps/vein_data.py: 1 liquid, 2 wall, 3/4 leaflets, 5/6 clamps


def read_dump(path):
    with open(path) as f:
        lines = f.readlines()
    step = int(lines[1])
    n = int(lines[3])
    cols = lines[8].split()[2:]
    data = np.loadtxt(lines[9:9 + n], ndmin=2)
    d = {c: data[:, k] for k, c in enumerate(cols)}
    order = np.argsort(d["id"])
    d = {c: q[order] for c, q in d.items()}
    return step, {"gid": d["id"].astype(np.int64) - 1, "ltype": d["type"].astype(int),
                  "x": np.column_stack([d["x"], d["y"]]), "v": np.column_stack([d["vx"], d["vy"]]),
                  "rho": d["c_rho"]}


def read_snapshot(path, ltype_of_gid):
    with h5py.File(path, "r") as h:
        t = float(h.attrs["time"][0])
        P = h["particles"]
        gid = P["gid"][:].astype(np.int64)
        o = np.argsort(gid)
        return t, {"gid": gid[o], "ltype": ltype_of_gid[gid[o]], "x": P["x"][:, :2][o],
                   "v": P["v"][:, :2][o], "rho": P["rho"][:][o], "mass": P["mass"][:][o]}


def near(x, sel_from, sel_to, r, length):
    """For every particle in sel_from: is any particle of sel_to within r (periodic in x)?"""
    xf, xt = x[sel_from], x[sel_to]
    out = np.zeros(len(xf), dtype=bool)
    for k in range(0, len(xf), 2048):
        d = xf[k:k + 2048, None, :] - xt[None, :, :]
        d[..., 0] = (d[..., 0] + 0.5 * length) % length - 0.5 * length
        out[k:k + 2048] = ((d ** 2).sum(axis=2) < r * r).any(axis=1)
    return out


def metrics(s, mass_of_type, rho0, dx, length):
    liq = s["ltype"] == 1
    m = mass_of_type[s["ltype"][liq]]
    v = s["v"][liq]
    speed2 = (v ** 2).sum(axis=1)
    x = s["x"][liq, 0]
    xs = 0.5 * dx
    d = (x - xs + 0.5 * length) % length - 0.5 * length
    st = np.abs(d) < dx
    drho = np.abs(s["rho"][liq] / rho0 - 1)
    # the volume flux sum V v_x / dx through the lattice column at the inlet station and at
    # the sinus's middle (x = length/2): equal in an incompressible flow
    vol = m / s["rho"][liq]

    def flux(xc):
        c = np.abs((x - xc + 0.5 * length) % length - 0.5 * length) < 0.5 * dx
        return (vol[c] * v[c, 0]).sum() / dx
    out = {"q_ratio": flux(0.5 * length) / flux(xs) if flux(xs) != 0 else np.nan,"E_k": 0.5 * (m * speed2).sum(), "u_mean": (m * v[:, 0]).sum() / m.sum(),
           "u_in": v[st, 0].mean() if st.any() else np.nan, "max_v": np.sqrt(speed2.max()),
           "mean_drho": drho.mean(), "max_drho": drho.max()}
    for k, lt in ((1, 3), (2, 4)):
        ids = s["gid"][s["ltype"] == lt]
        tip = np.isin(s["gid"], ids[-2:])  # the last column: the two largest gids
        out[f"tip{k}"] = s["x"][tip].mean(axis=0)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--lammps", required=True, help="directory of the twin's vein.<step>.dump")
    ap.add_argument("--dt", type=float, required=True, help="the twin's time step [s]")
    ap.add_argument("--dmhs", action="append", default=[], help="NAME=DIR of a dmhs run (snapshots)")
    ap.add_argument("--params", required=True, help="the twin's params include (vein_data.py)")
    ap.add_argument("--data", required=True, help="the twin's data file (masses, types)")
    ap.add_argument("--times", default="", help="comma list of times to report (default: all common)")
    a = ap.parse_args()

    params = {}
    for line in open(a.params):
        mm = re.match(r"variable\s+(\S+)\s+equal\s+(\S+)", line)
        if mm:
            params[mm.group(1)] = float(mm.group(2))
    rho0, dx, length, h = params["rho0"], params["dx"], params["length"], params["h"]
    mass_of_type = np.zeros(7)
    with open(a.data) as f:
        lines = f.read().splitlines()
    i = lines.index("Masses") + 2
    while lines[i].strip():
        t, mval = lines[i].split()[:2]
        mass_of_type[int(t)] = float(mval)
        i += 1
    i = next(k for k, ln in enumerate(lines) if ln.startswith("Atoms")) + 2
    rows = []
    while i < len(lines) and lines[i].strip():
        p = lines[i].split()
        rows.append((int(p[0]) - 1, int(p[1])))
        i += 1
    rows = np.array(rows)
    ltype_of_gid = np.zeros(rows[:, 0].max() + 1, dtype=int)
    ltype_of_gid[rows[:, 0]] = rows[:, 1]

    lmp = {}
    t0 = params.get("t0", 0.0)
    for path in glob.glob(os.path.join(a.lammps, "vein.*.dump")):
        step, s = read_dump(path)
        lmp[round(t0 + step * a.dt, 12)] = s
    runs = []
    for spec in a.dmhs:
        name, d = spec.split("=", 1)
        snaps = {}
        for path in sorted(glob.glob(os.path.join(d, "snap_*.h5"))):
            t, s = read_snapshot(path, ltype_of_gid)
            snaps[round(t, 12)] = s
        runs.append((name, snaps))

    def at(d, t):  # the output within dt/2 of t
        best = min(d, key=lambda u: abs(u - t), default=None)
        return d[best] if best is not None and abs(best - t) < 0.5 * a.dt else None
    if a.times:
        times = [round(float(t), 12) for t in a.times.split(",")]
    else:
        times = sorted(t for t in lmp if all(at(r, t) is not None for _, r in runs))
    times = [t for t in times if t > t0 + 0.5 * a.dt]
    if not times:
        sys.exit("no time written by LAMMPS and every dmhs run")

    names = ["LAMMPS"] + [n for n, _ in runs]
    S0 = at(lmp, t0)  # the common start (LAMMPS's step 0 is dmhs's state)
    m0 = metrics(S0, mass_of_type, rho0, dx, length) if S0 is not None else None
    print(f"dx = {dx:g} m, start t0 = {t0:g} s; liquid E_k [J/m], <u>, u_in (inlet station), "
          f"max|v| [m/s], |rho/rho0 - 1| mean / max, tips' centres (x, y) [m]")
    if m0 is not None:
        print(f"  start          E_k {m0['E_k']:.4e}  <u> {m0['u_mean']:.4e}  u_in {m0['u_in']:.4e}  "
              f"max|v| {m0['max_v']:.3e}  tip1 ({m0['tip1'][0]:.5f}, {m0['tip1'][1]:+.5f})  "
              f"tip2 ({m0['tip2'][0]:.5f}, {m0['tip2'][1]:+.5f})")
    for t in times:
        print(f"\nt = {t:g} s")
        states = [at(lmp, t)] + [at(r, t) for _, r in runs]
        ms = []
        for name, s in zip(names, states):
            if s is None:
                print(f"  {name:14s} (no output at this time)")
                ms.append(None)
                continue
            m = metrics(s, mass_of_type, rho0, dx, length)
            ms.append(m)
            print(f"  {name:14s} E_k {m['E_k']:.4e}  <u> {m['u_mean']:.4e}  u_in {m['u_in']:.4e}  "
                  f"max|v| {m['max_v']:.3e}  drho {m['mean_drho']:.2e} / {m['max_drho']:.2e}  "
                  f"Q_sinus/Q_in {m['q_ratio']:.3f}  tip1 ({m['tip1'][0]:.5f}, {m['tip1'][1]:+.5f})  tip2 ({m['tip2'][0]:.5f}, "
                  f"{m['tip2'][1]:+.5f})")
        L = states[0]
        if L is None:
            continue
        liq = L["ltype"] == 1
        leaf = (L["ltype"] == 3) | (L["ltype"] == 4)
        # differences relative to what LAMMPS's liquid did: its speed from rest, or its
        # velocity change since a common start t0 > 0
        v_start = S0["v"][liq] if S0 is not None else 0.0
        vref = np.sqrt(((L["v"][liq] - v_start) ** 2).sum(axis=1).mean())
        # the liquid within h of a wall or clamp particle (in LAMMPS's positions), where the
        # two codes' walls differ, and the rest
        walls = (L["ltype"] == 2) | (L["ltype"] == 5) | (L["ltype"] == 6)
        by_wall = near(L["x"], liq, walls, h, length)
        for (name, _), s, m in zip(runs, states[1:], ms[1:]):
            if s is None:
                continue
            if not np.array_equal(s["gid"], L["gid"]):
                print(f"  {name}: not the same particles as LAMMPS")
                continue
            dv2 = ((s["v"][liq] - L["v"][liq]) ** 2).sum(axis=1)
            rel_v = np.sqrt(dv2.mean()) / vref
            rel_wall = np.sqrt(dv2[by_wall].mean()) / vref
            rel_rest = np.sqrt(dv2[~by_wall].mean()) / vref
            dxl = s["x"][leaf] - L["x"][leaf]
            dxl[:, 0] = (dxl[:, 0] + 0.5 * length) % length - 0.5 * length
            e = np.sqrt((dxl ** 2).sum(axis=1))
            if m0 is None:
                print(f"  {name}: LAMMPS wrote no state at t0 = {t0:g} s")
                continue

            def rel(q):  # the change since t0, dmhs against LAMMPS
                return (m[q] - m0[q]) / (ms[0][q] - m0[q]) - 1

            def um(d):
                return f"({d[0] * 1e6:+.3g}, {d[1] * 1e6:+.3g})"
            tips = "  ".join(f"tip{k} {um(m[f'tip{k}'] - m0[f'tip{k}'])} against "
                             f"{um(ms[0][f'tip{k}'] - m0[f'tip{k}'])} um" for k in (1, 2))
            print(f"  {name} - LAMMPS (changes since t0): E_k {rel('E_k'):+.2%}  <u> "
                  f"{rel('u_mean'):+.2%}  u_in {rel('u_in'):+.2%}; liquid velocities: RMS difference "
                  f"{rel_v:.2%} of LAMMPS's RMS change ({rel_wall:.2%} within h of a wall, {by_wall.sum()} "
                  f"particles; {rel_rest:.2%} elsewhere); leaflet particles {np.sqrt((e ** 2).mean()) / dx:.2g} "
                  f"dx apart (RMS), {e.max() / dx:.2g} dx (max); tips moved {tips}")

if __name__ == "__main__":
    main()
