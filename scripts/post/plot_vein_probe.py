#!/usr/bin/python3
"""Measurement point, inlet velocities and tip gap against time (the thesis's Fig. 4.6).

  scripts/post/plot_vein_probe.py OUTDIR [--out PATH]

Reads OUTDIR/vein.csv and OUTDIR/vein-summary.csv and draws four stacked
panels over a shared t axis:
  1. the measurement point's displacement |x - x0| [mm] (empty cells, before it
     is chosen, are gaps), with the summary's time average +- std;
  2. its total stress |sigma| [Pa] (log axis when every value is positive),
     with the summary's mean peak per cycle +- std when there is one;
  3. the inlet velocities u_flux (when vein.csv has it), u_mean and u_centre [m/s];
  4. the gap between the leaflet tips [mm], the rest gap dashed.
Dotted vertical lines mark the drive periods. The legends stand right of their
panels, where they hide no part of a curve. Writes vein_probe.png into OUTDIR,
or --out (a .png path or a directory).
"""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import vein_common as vc  # noqa: E402

NEED = ("t", "u_mean", "u_centre", "gap", "probe_gid", "probe_stress", "probe_disp")


def band(ax, mean, std, scale, label, color):
    if math.isfinite(mean):
        ax.axhline(mean * scale, color=color, ls="--", lw=1, label=label)
        if math.isfinite(std):
            ax.axhspan((mean - std) * scale, (mean + std) * scale, color=color, alpha=0.12, lw=0)


def legend(ax):
    """The panel's legend beside it, right of the axes: inside, 'best' still hid the
    last part of a curve that ends high (the stress at the run's end)."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir", metavar="OUTDIR", help="output directory of a vein run")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: OUTDIR)")
    args = ap.parse_args()
    vc.require_dir(args.outdir)

    csv_path = os.path.join(args.outdir, "vein.csv")
    r, info = vc.read_csv(csv_path, need=NEED)
    sm = vc.read_summary(os.path.join(args.outdir, "vein-summary.csv"), need=("gap_rest",))
    t = r["t"]
    chosen = np.isfinite(r["probe_gid"])
    gids = np.unique(r["probe_gid"][chosen]).astype(int)
    T = info.get("T", sm.get("period", math.nan))

    fig, ax = plt.subplots(4, 1, figsize=(10.5, 10), sharex=True)
    c0 = "tab:blue"
    ax[0].plot(t, r["probe_disp"] * 1e3, ".-", color=c0, ms=3, label="measurement point")
    band(ax[0], sm.get("disp_mean", math.nan), sm.get("disp_std", math.nan), 1e3, "time average ± std", "tab:orange")
    ax[0].set_ylabel("displacement [mm]")
    legend(ax[0])

    stress = r["probe_stress"]
    ax[1].plot(t, stress, ".-", color="tab:red", ms=3, label="measurement point")
    finite = stress[np.isfinite(stress)]
    if finite.size and (finite > 0).all():
        ax[1].set_yscale("log")
    band(ax[1], sm.get("peak_stress_mean", math.nan), sm.get("peak_stress_std", math.nan), 1.0,
         "peak per cycle, mean ± std", "tab:purple")
    if not math.isfinite(sm.get("peak_stress_mean", math.nan)):
        ax[1].text(1.02, 0.8, "no completed cycle after\nthe point was chosen:\nno peak-per-cycle mean",
                   transform=ax[1].transAxes, va="top", fontsize=8, color="0.3")
    ax[1].set_ylabel("total stress |σ| [Pa]")
    legend(ax[1])

    if "u_flux" in r:
        ax[2].plot(t, r["u_flux"], "-", color="k", lw=1.2, label="u_flux (volume flux / width)")
    ax[2].plot(t, r["u_mean"], "-", label="u_mean (cross-section)")
    ax[2].plot(t, r["u_centre"], "-", label="u_centre (axis)")
    ax[2].axhline(0, color="0.5", lw=0.8)
    ax[2].set_ylabel("inlet velocity [m/s]")
    legend(ax[2])

    ax[3].plot(t, r["gap"] * 1e3, "-", color="k", label="tip gap")
    ax[3].axhline(sm["gap_rest"] * 1e3, color="0.4", ls="--", label=f"rest gap {sm['gap_rest'] * 1e3:g} mm")
    ax[3].set_ylabel("gap [mm]")
    ax[3].set_xlabel("t [s]")
    legend(ax[3])

    if math.isfinite(T) and T > 0:
        for a in ax:
            for k in range(1, int(np.nanmax(t) / T) + 1):
                a.axvline(k * T, color="0.6", ls=":", lw=1)
    if chosen.any():
        t_pick = t[chosen][0]
        for a in ax[:2]:
            a.axvline(t_pick, color="tab:green", ls="-.", lw=1)
        ax[0].text(t_pick, 0.05, f" chosen at t = {t_pick:.3f} s", transform=ax[0].get_xaxis_transform(),
                   fontsize=8, color="tab:green")
        probe = "gid " + ", ".join(str(g) for g in gids)
    else:
        probe = "not chosen"
        for a in ax[:2]:
            a.text(0.5, 0.5, "no measurement point in vein.csv", transform=a.transAxes, ha="center")
    fig.suptitle(f"{vc.case_title(info, args.outdir)}\nmeasurement point ({probe}), inlet velocities and tip gap")
    fig.tight_layout()
    out = vc.output_path(args.out, args.outdir, "vein_probe.png")
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()
