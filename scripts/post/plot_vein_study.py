#!/usr/bin/python3
"""The vein study across runs (the thesis's Figs. 4.7 and 4.9).

  scripts/post/plot_vein_study.py RUNDIR [RUNDIR ...] [--out PREFIX] [--length L]

Reads RUNDIR/vein-summary.csv of every run and writes
  <PREFIX>vein_study_ka.png        the runs with leaflet length --length (default
                                   0.0256 m, matched to half the run's dx: a coarse
                                   run rounds L to whole dx) and the most common g0
                                   among them: the measurement point's displacement
                                   (time average +- std) and its peak stress per
                                   cycle (mean +- std) against k_a (log axis)
  <PREFIX>vein_study_velocity.png  the runs at the most common k_a: displacement and
                                   peak stress against the peak inlet velocity of the
                                   first cycle, one line per leaflet length
PREFIX defaults to the first RUNDIR + '/'. Prints a table of the runs (u: the
peak u_flux of the first cycle, the thesis's V; disp, stress: the measurement
point's means); runs with empty cells are drawn where possible and listed as
"no measurement point".
"""
import argparse
import collections
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import vein_common as vc  # noqa: E402

NEED = ("leaflet_length", "g0", "ka_ref", "dx", "u_flux_peak_cycle1", "disp_mean", "disp_std",
        "peak_stress_mean", "peak_stress_std")


def most_common(values):
    """The most frequent value (the smallest of the tied ones)."""
    counts = collections.Counter(values)
    best = max(counts.values())
    return min(v for v, n in counts.items() if n == best)


def group_lengths(runs):
    """Leaflet lengths that agree within half the coarser dx count as one: [(L, [runs])]."""
    groups = []
    for r in sorted(runs, key=lambda r: r["leaflet_length"]):
        if groups and abs(r["leaflet_length"] - groups[-1][0]) <= 0.5 * max(r["dx"], groups[-1][1][0]["dx"]) + 1e-12:
            groups[-1][1].append(r)
        else:
            groups.append((r["leaflet_length"], [r]))
    return groups


def errorbars(ax, x, y, err, **kw):
    x, y, err = map(np.asarray, (x, y, err))
    ok = np.isfinite(x) & np.isfinite(y)
    if ok.any():
        ax.errorbar(x[ok], y[ok], yerr=np.where(np.isfinite(err[ok]), err[ok], 0), capsize=3, **kw)
    return ok.any()


def no_data(ax, what):
    ax.text(0.5, 0.5, f"no {what} in these runs\n(empty in vein-summary.csv)", transform=ax.transAxes,
            ha="center", va="center", color="0.4")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("rundirs", metavar="RUNDIR", nargs="+", help="output directories of vein runs")
    ap.add_argument("--out", default=None, metavar="PREFIX", help="prefix of the PNG paths (default: RUNDIR/)")
    ap.add_argument("--length", type=float, default=0.0256, help="leaflet length of the k_a study [m]")
    args = ap.parse_args()
    runs = []
    for d in args.rundirs:
        vc.require_dir(d)
        sm = vc.read_summary(os.path.join(d, "vein-summary.csv"), need=NEED)
        sm["dir"] = d
        # k_a as the run had it (run.json: -angle_k given explicitly overrides -vein_leaflet_ka)
        sm["ka_ref"] = vc.run_params(d, sm).get("k_a", sm["ka_ref"])
        runs.append(sm)
    prefix = args.out if args.out is not None else args.rundirs[0].rstrip("/") + "/"
    if os.path.dirname(prefix):
        os.makedirs(os.path.dirname(prefix), exist_ok=True)

    def cell(v, fmt):
        return "empty" if math.isnan(v) else format(v, fmt)

    width = max(12, max(len(r["dir"]) for r in runs))
    print(f"{'run':<{width}} {'L [m]':>8} {'g0':>6} {'k_a [J]':>8} {'u [m/s]':>8} {'disp [m]':>10} "
          f"{'stress [Pa]':>11}")
    for r in runs:
        print(f"{r['dir']:<{width}} {cell(r['leaflet_length'], '8.4g'):>8} {cell(r['g0'], '6.3g'):>6} "
              f"{cell(r['ka_ref'], '8.3g'):>8} {cell(r['u_flux_peak_cycle1'], '8.4f'):>8} "
              f"{cell(r['disp_mean'], '10.4g'):>10} {cell(r['peak_stress_mean'], '11.4g'):>11}")
    for r in runs:
        missing = [k for k in ("disp_mean", "peak_stress_mean") if math.isnan(r[k])]
        if missing:
            print(f"{r['dir']}: no measurement point ({', '.join(missing)} empty in vein-summary.csv)")

    # (a) k_a at the study's leaflet length and its most common g0
    ka_runs = [r for r in runs if abs(r["leaflet_length"] - args.length) <= 0.5 * r["dx"] + 1e-12]
    fig, ax = plt.subplots(1, 2, figsize=(10, 4.2))
    if ka_runs:
        g0 = most_common([r["g0"] for r in ka_runs])
        sel = sorted((r for r in ka_runs if r["g0"] == g0), key=lambda r: r["ka_ref"])
        ka = [r["ka_ref"] for r in sel]
        if not errorbars(ax[0], ka, [r["disp_mean"] * 1e3 for r in sel], [r["disp_std"] * 1e3 for r in sel],
                         fmt="o-", color="tab:blue"):
            no_data(ax[0], "displacement")
        if not errorbars(ax[1], ka, [r["peak_stress_mean"] for r in sel], [r["peak_stress_std"] for r in sel],
                         fmt="s-", color="tab:red"):
            no_data(ax[1], "peak stress per cycle")
        lengths = ", ".join(sorted({f"{r['leaflet_length'] * 1e3:g}" for r in sel}))
        title = (f"vein study: L = {args.length * 1e3:g} mm (runs: {lengths} mm), g0 = {g0:g} m/s², "
                 f"{len(sel)} run(s)")
        others = [p for p in vc.shared_parts([r["dir"] for r in sel], sel)
                  if not p.startswith(("L =", "g0 =", "k_a ="))]
        if others:
            title += "\n" + ", ".join(others)
        if min(ka) == max(ka):
            for a in ax:
                a.set_xlim(min(ka) / 3, min(ka) * 3)
    else:
        title = f"vein study: no run with L = {args.length * 1e3:g} mm"
        for a in ax:
            no_data(a, f"L = {args.length * 1e3:g} mm run")
    for a in ax:
        a.set_xscale("log")
        a.set_xlabel("k_a (at dx = 0.1 mm) [J]")
        a.grid(True, which="both", alpha=0.3)
    ax[0].set_ylabel("displacement, time average ± std [mm]")
    ax[1].set_ylabel("peak stress per cycle, mean ± std [Pa]")
    fig.suptitle(title)
    fig.tight_layout()
    out_ka = prefix + "vein_study_ka.png"
    fig.savefig(out_ka, dpi=110)
    print(out_ka)

    # (b) against the peak inlet velocity, one line per leaflet length, at the most common k_a
    ka0 = most_common([r["ka_ref"] for r in runs])
    fig, ax = plt.subplots(1, 2, figsize=(10, 4.2))
    drawn = [False, False]
    for L, group in group_lengths([r for r in runs if r["ka_ref"] == ka0]):
        group = sorted(group, key=lambda r: r["u_flux_peak_cycle1"])
        u = [r["u_flux_peak_cycle1"] for r in group]
        label = f"L = {L * 1e3:g} mm"
        drawn[0] |= errorbars(ax[0], u, [r["disp_mean"] * 1e3 for r in group], [r["disp_std"] * 1e3 for r in group],
                              fmt="o-", label=label)
        drawn[1] |= errorbars(ax[1], u, [r["peak_stress_mean"] for r in group],
                              [r["peak_stress_std"] for r in group], fmt="s-", label=label)
    if drawn[0] != drawn[1]:  # one panel empty: the same velocity range on both
        ax[int(drawn[0])].set_xlim(ax[int(drawn[1])].get_xlim())
    for a, ok, what in zip(ax, drawn, ("displacement", "peak stress per cycle")):
        a.set_xlabel("peak inlet velocity u_flux, first cycle [m/s]")
        a.grid(True, alpha=0.3)
        if ok:
            a.legend(fontsize=8)
        else:
            no_data(a, what)
    ax[0].set_ylabel("displacement, time average ± std [mm]")
    ax[1].set_ylabel("peak stress per cycle, mean ± std [Pa]")
    sel = [r for r in runs if r["ka_ref"] == ka0]
    others = [p for p in vc.shared_parts([r["dir"] for r in sel], sel)
              if not p.startswith(("L =", "g0 =", "k_a ="))]
    fig.suptitle(f"vein study: k_a = {ka0:g} J, {len(sel)} run(s)" + ("\n" + ", ".join(others) if others else ""))
    fig.tight_layout()
    out_u = prefix + "vein_study_velocity.png"
    fig.savefig(out_u, dpi=110)
    print(out_u)


if __name__ == "__main__":
    main()
