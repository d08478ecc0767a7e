#!/usr/bin/env python3
"""One vein case at several spacings on common axes (convergence toward dx = 1e-4 m).

  scripts/post/plot_vein_convergence.py RUNDIR [RUNDIR ...] [--out PATH] [--csv PATH]

Each RUNDIR is a run of the same case at its own -vein_dx. Draws against time:
the inlet velocity (u_flux, the volume flux over the width; u_mean of the
inlet slab faint), the clear opening between the tips (their gap less 2 dx,
the two leaflets' half thicknesses), both tips' x and y, and the measurement
point's total stress and displacement. Prints, and writes to --csv
(default <out>.csv), per completed cycle and spacing: the peak inlet
velocity, the largest and smallest clear opening, the measurement point's
time-averaged displacement and peak stress, and each one's difference from
the next finer spacing that reached that cycle (relative, %). Where a run
stops short of a whole cycle (the published dx runs a stretch only), prints
and writes to --stretch-csv (default <out>-stretch.csv) the inlet velocity,
the clear opening and the upper tip's position at every --every seconds up
to the end of the shortest run, each run's value and its difference from
the next finer spacing, and the peak inlet velocity over that stretch.
Writes vein_convergence.png into the first RUNDIR unless --out is given.
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import vein_common as vc  # noqa: E402

NEED = ("t", "u_mean", "gap", "tip_upper_x", "tip_upper_y", "tip_lower_x", "tip_lower_y",
        "probe_stress", "probe_disp")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rundirs", nargs="+")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: the first RUNDIR)")
    ap.add_argument("--csv", default=None, help="table of per-cycle metrics (default: <PNG>.csv)")
    ap.add_argument("--stretch-csv", default=None,
                    help="table over the shortest run's stretch (default: <PNG>-stretch.csv)")
    ap.add_argument("--every", type=float, default=0.1,
                    help="sampling interval of the stretch table [s] (default 0.1)")
    a = ap.parse_args()
    runs = []
    for d in a.rundirs:
        vc.require_dir(d)
        cols, info = vc.read_csv(os.path.join(d, "vein.csv"), need=NEED)
        if "dx" not in info or "T" not in info:
            vc.fail(f"{d}/vein.csv: no dx or T in its '# vein:' comment line")
        runs.append((info["dx"], d, cols, info))
    runs.sort(key=lambda r: -r[0])  # coarsest first
    fig, ax = plt.subplots(6, 1, figsize=(9, 15), sharex=True)
    rows = []
    for k, (dx, d, cols, info) in enumerate(runs):
        c = f"C{k % 10}"
        lab = f"dx = {dx * 1e3:g} mm (to t = {cols['t'][-1]:.2f} s)"
        t = cols["t"]
        u, uname = vc.inlet_velocity(cols)
        ax[0].plot(t, u, color=c, label=f"{lab}, {uname}")
        if uname != "u_mean":
            ax[0].plot(t, cols["u_mean"], color=c, alpha=0.25, lw=0.7)
        ax[1].plot(t, vc.clear_opening(cols, dx) * 1e3, color=c, label=lab)
        ax[2].plot(t, cols["tip_upper_x"] * 1e3, color=c, label=f"{lab}, upper")
        ax[2].plot(t, cols["tip_lower_x"] * 1e3, color=c, ls="--", label=f"{lab}, lower")
        ax[3].plot(t, cols["tip_upper_y"] * 1e3, color=c, label=f"{lab}, upper")
        ax[3].plot(t, cols["tip_lower_y"] * 1e3, color=c, ls="--", label=f"{lab}, lower")
        ax[4].plot(t, cols["probe_stress"], color=c, label=lab)
        ax[5].plot(t, cols["probe_disp"] * 1e3, color=c, label=lab)
        for m in vc.cycle_metrics(cols, info["T"], dx):
            rows.append(dict(m, dx=dx, run=d))
    # differences from the next finer spacing that reached the same cycle
    for r in rows:
        finer = [q for q in rows if q["cycle"] == r["cycle"] and q["dx"] < r["dx"]]
        ref = max(finer, key=lambda q: q["dx"]) if finer else None
        r["vs_dx"] = ref["dx"] if ref else math.nan
        for key, _ in vc.CYCLE_METRICS:
            ok = ref is not None and math.isfinite(ref[key]) and ref[key] != 0 and math.isfinite(r[key])
            r[f"{key}_diff"] = (r[key] / ref[key] - 1) if ok else math.nan
    T = runs[0][3]["T"]
    tmax = max(np.nanmax(r[2]["t"]) for r in runs)
    for axis in ax:
        for k in range(1, int(tmax / T) + 1):
            axis.axvline(k * T, color="0.6", ls=":", lw=1)
        axis.grid(alpha=0.3)
    ax[0].axhline(0, color="0.5", lw=0.8)
    ax[0].set_ylabel("inlet velocity [m/s]")
    ax[1].set_ylabel("clear opening\ngap - 2 dx [mm]")
    ax[2].set_ylabel("tip x [mm]")
    ax[3].set_ylabel("tip y [mm]")
    ax[4].set_ylabel("measurement point |σ| [Pa]")
    ax[5].set_ylabel("measurement point\ndisplacement [mm]")
    ax[5].set_xlabel("t [s]")
    for axis in ax[:2]:
        axis.legend(fontsize=7, loc="best")
    ax[2].legend(fontsize=6, loc="best", ncol=2)
    head = ", ".join(p for p in vc.case_title(runs[0][3], runs[0][1]).split(", ") if not p.startswith("dx ="))
    fig.suptitle(f"{head}: "
                 f"spacings {', '.join(f'{r[0] * 1e3:g}' for r in runs)} mm")
    fig.tight_layout()
    path = vc.output_path(a.out, a.rundirs[0], "vein_convergence.png")
    fig.savefig(path, dpi=100)
    table = a.csv or os.path.splitext(path)[0] + ".csv"
    keys = ["cycle", "dx", "vs_dx"] + [k for k, _ in vc.CYCLE_METRICS] + [f"{k}_diff" for k, _ in vc.CYCLE_METRICS]
    with open(table, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in sorted(rows, key=lambda q: (q["cycle"], -q["dx"])):
            w.writerow([f"{r[k]:.6g}" if isinstance(r[k], float) else r[k] for k in keys])
    print("cycle  dx[mm]  u_peak[m/s]   open_max[mm] open_min[mm] disp_mean[mm]  stress_peak[Pa]"
          "   (difference from the next finer dx)")
    for r in sorted(rows, key=lambda q: (q["cycle"], -q["dx"])):
        def cell(key, scale, fmt):
            v, dv = r[key], r[f"{key}_diff"]
            s = "n/a" if not math.isfinite(v) else format(v * scale, fmt)
            return s + (f" ({dv * 100:+.0f}%)" if math.isfinite(dv) else "")
        print(f"{r['cycle']:5d}  {r['dx'] * 1e3:6g}  {cell('u_peak', 1, '.4f'):13s} "
              f"{cell('open_max', 1e3, '.2f'):12s} {cell('open_min', 1e3, '.2f'):12s} "
              f"{cell('disp_mean', 1e3, '.3f'):14s} {cell('stress_peak', 1, '.3g')}")
    print(path)
    print(table)
    stretch = a.stretch_csv or os.path.splitext(path)[0] + "-stretch.csv"
    if write_stretch(runs, a.every, stretch):
        print(stretch)


STRETCH = (("u", "inlet velocity [m/s]", 1, ".4f"), ("open", "clear opening [mm]", 1e3, ".3f"),
           ("tip_x", "upper tip x [mm]", 1e3, ".3f"), ("tip_y", "upper tip y [mm]", 1e3, ".3f"))


def stretch_series(cols, dx):
    u, _ = vc.inlet_velocity(cols)
    return {"u": u, "open": vc.clear_opening(cols, dx), "tip_x": cols["tip_upper_x"],
            "tip_y": cols["tip_upper_y"]}


def write_stretch(runs, every, path):
    """The runs side by side over the shortest one's stretch, when that is less
    than a whole cycle (the per-cycle table has nothing of it). runs: coarsest
    first. Returns False (and writes nothing) when every run has a whole cycle."""
    T = runs[0][3]["T"]
    t_end = min(float(np.nanmax(r[2]["t"])) for r in runs)
    if t_end >= T or len(runs) < 2:
        return False
    if not every > 0:
        vc.fail(f"--every {every}: must be > 0")
    times = np.arange(1, int(math.floor(t_end / every + 1e-9)) + 1) * every
    if times.size == 0:
        vc.fail(f"the shortest run ends at t = {t_end:g} s, before the first sample at {every:g} s")
    series = [(dx, stretch_series(cols, dx), cols["t"]) for dx, _, cols, _ in runs]
    # each run's series at the sample times, once for the CSV and the printout
    at = [{k: np.interp(times, t, ser[k]) for k, _, _, _ in STRETCH} for _, ser, t in series]
    keys = ["t"]
    for dx, _, _ in series:
        keys += [f"{k}_dx{dx:g}" for k, _, _, _ in STRETCH]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for n, tk in enumerate(times):
            w.writerow([f"{tk:.6g}"] + [f"{v[k][n]:.6g}" for v in at for k, _, _, _ in STRETCH])
    print(f"over the stretch t <= {t_end:.3f} s (the shortest run), each run's value and its "
          "difference from the next finer dx:")
    print("t[s]   " + "  ".join(f"{lab:>28s}" for _, lab, _, _ in STRETCH))
    for n, tk in enumerate(times):
        for j, (dx, _, _) in enumerate(series):
            cells = []
            for k, _, scale, fmt in STRETCH:
                v = float(at[j][k][n])
                cell = format(v * scale, fmt)
                if j + 1 < len(series):
                    ref = float(at[j + 1][k][n])
                    if ref != 0 and math.isfinite(ref):
                        cell += f" ({(v / ref - 1) * 100:+.0f}%)"
                cells.append(f"{cell:>28s}")
            print(f"{tk:5.2f}  dx {dx * 1e3:g} mm  " + "  ".join(cells))
    print("peak inlet velocity over the stretch:")
    for dx, ser, t in series:
        sel = t <= t_end
        k = int(np.nanargmax(ser["u"][sel]))
        print(f"  dx {dx * 1e3:g} mm: {ser['u'][sel][k]:.4f} m/s at t = {t[sel][k]:.3f} s")
    return True


if __name__ == "__main__":
    main()
