#!/usr/bin/python3
"""The error of a channel run's v_x against the start-up series solution, for a
LAMMPS run of bench/lammps/poiseuille.in or couette.in and, beside it, dmhs's
profiles of input/<case>-quick.opts (the same setup).

  /usr/bin/python3 bench/lammps/channel_error.py poiseuille|couette \
      --dump OUT/lammps/profiles.dump [--dmhs OUT/dmhs] [--times 0.01,0.1,1] [--plot PNG]

The error is dmhs's metric (doc/validation.md): over the liquid particles, the
RMS (L2) and the maximum (Linf) of (v_x - v_exact(y, t)) / v_ref, v_ref = F l^2/(8 nu)
(Poiseuille) or the plate speed (Couette). The series are those of
include/dmhs/analytic.h; where dmhs's profile_t<t>.csv is given, its vx_exact
column is checked against them. Prints one row per time; with --plot draws the
profiles (series, LAMMPS, dmhs) at those times.
"""
import argparse
import math
import os
import sys

import numpy as np

L = 1e-3      # channel width l [m]
NU = 1e-6     # kinematic viscosity [m^2/s]
F = 2e-4      # Poiseuille body force [m/s^2]
V = 2.5e-5    # Couette plate speed [m/s]
DT = 1e-4     # time step of both inputs [s]


def series(case, y, t, terms=4000):
    """v_x(y, t) of the start-up flow from rest (walls at y = 0 and y = l)."""
    y = np.asarray(y, dtype=float)[:, None]
    if case == "poiseuille":
        k = 2 * np.arange(terms)[None, :] + 1.0
        s = (4 * F * L * L / (NU * math.pi ** 3 * k ** 3) * np.sin(k * math.pi * y / L)
             * np.exp(-k * k * math.pi ** 2 * NU * t / L ** 2)).sum(axis=1)
        return F / (2 * NU) * y[:, 0] * (L - y[:, 0]) - s
    n = np.arange(1, terms + 1)[None, :].astype(float)
    s = (2 * V * (-1.0) ** n / (n * math.pi) * np.sin(n * math.pi * y / L)
         * np.exp(-n * n * math.pi ** 2 * NU * t / L ** 2)).sum(axis=1)
    return V * y[:, 0] / L + s


def read_dump(path):
    """{step: (y, vx)} from a LAMMPS custom dump with the columns id y vx."""
    frames, f = {}, open(path)
    line = f.readline()
    while line:
        if line.startswith("ITEM: TIMESTEP"):
            step = int(f.readline())
            f.readline()
            n = int(f.readline())
            for _ in range(4):
                f.readline()
            cols = f.readline().split()[2:]
            assert cols == ["id", "y", "vx"], f"{path}: columns {cols}, expected id y vx"
            data = np.array([f.readline().split() for _ in range(n)], dtype=float)
            frames[step] = (data[:, 1], data[:, 2])
        line = f.readline()
    return frames


def read_profile(path):
    d = np.loadtxt(path, delimiter=",", comments="#", skiprows=2)
    return d[:, 0], d[:, 1], d[:, 2]


def pct(x):
    return f"{100 * x:.3g} %"


def errors(vx, exact, vref):
    e = (vx - exact) / vref
    return math.sqrt(np.mean(e * e)), np.abs(e).max()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("case", choices=["poiseuille", "couette"])
    ap.add_argument("--dump", required=True, help="LAMMPS profiles.dump")
    ap.add_argument("--dmhs", help="dmhs output directory with profile_t<t>.csv")
    ap.add_argument("--times", default="0.01,0.1,1", help="report times [s]")
    ap.add_argument("--plot", help="write the profiles to this PNG")
    a = ap.parse_args()
    vref = F * L * L / (8 * NU) if a.case == "poiseuille" else V
    frames = read_dump(a.dump)
    times = [float(t) for t in a.times.split(",")]
    print(f"{a.case}: error of v_x against the series, normalised by v_ref = {vref:g} m/s")
    print(f"{'t [s]':>8} {'LAMMPS L2':>11} {'LAMMPS Linf':>12} {'dmhs L2':>11} {'dmhs Linf':>11}  LAMMPS/dmhs (L2)")
    shown, status = [], 0
    for t in times:
        step = int(round(t / DT))
        if step not in frames:
            print(f"{t:8g}  (no LAMMPS frame at step {step}: the run ended earlier)")
            continue
        y, vx = frames[step]
        exact = series(a.case, y, t)
        l2, linf = errors(vx, exact, vref)
        row = f"{t:8g} {pct(l2):>11} {pct(linf):>12}"
        dm = None
        if a.dmhs:
            path = os.path.join(a.dmhs, f"profile_t{t:g}.csv")
            if os.path.exists(path):
                yd, vd, ed = read_profile(path)
                mine = series(a.case, yd, t)
                gap = np.abs(mine - ed).max() / vref
                if gap > 1e-9:
                    print(f"error: {path}: vx_exact differs from the series here by {gap:.2e} v_ref",
                          file=sys.stderr)
                    status = 1
                d2, dinf = errors(vd, mine, vref)
                dm = (yd, vd)
                row += f" {pct(d2):>11} {pct(dinf):>11}  {l2 / d2:8.3g}x"
            else:
                row += f" {'(no ' + os.path.basename(path) + ')':>23}"
        print(row)
        shown.append((t, y, vx, dm))
    if a.plot and shown:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5))
        yy = np.linspace(0, L, 201)
        for k, (t, y, vx, dm) in enumerate(shown):
            c = f"C{k}"
            ax.plot(series(a.case, yy, t) * 1e6, yy * 1e3, "-", color=c, lw=1, label=f"series, t = {t:g} s")
            ax.plot(vx * 1e6, y * 1e3, "x", color=c, ms=3, label=f"LAMMPS, t = {t:g} s")
            if dm:
                ax.plot(dm[1] * 1e6, dm[0] * 1e3, "o", mfc="none", color=c, ms=3, label=f"dmhs, t = {t:g} s")
        ax.set_xlabel("v_x [um/s]")
        ax.set_ylabel("y [mm]")
        ax.set_title(f"{a.case} (20 x 40 particles): LAMMPS SPH and dmhs against the series")
        ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.02, 0.5))
        fig.savefig(a.plot, dpi=120, bbox_inches="tight")
        print(f"wrote {a.plot}")
    return status


if __name__ == "__main__":
    sys.exit(main())
