#!/usr/bin/python3
"""Stress fields of a vein run at one time (the thesis's Fig. 4.3).

  scripts/post/plot_vein_fields.py OUTDIR [--time T] [--out PATH]

Reads OUTDIR/vein.csv and the snapshot OUTDIR/snap_*.h5 nearest to --time
(default: the row with the largest |u_mean|, the peak flow) and draws four
particle maps of the liquid, coloured by shear rate [1/s], total stress
|sigma| [Pa], pressure force [N/m] and speed |v| [m/s]; walls grey, leaflets
black on top. Each colour scale ends at the liquid's 99.5th percentile (the
colour bar's arrow: larger values exist), so a few spiking particles do not
wash out the map. Writes vein_fields.png into OUTDIR, or --out (a .png path or
a directory).
"""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import vein_common as vc  # noqa: E402

PANELS = [("shear_rate", "shear rate", "1/s"), ("stress_mag", "total stress |σ|", "Pa"),
          ("pressure_force", "pressure force", "N/m"), ("speed", "speed |v|", "m/s")]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir", metavar="OUTDIR", help="output directory of a vein run")
    ap.add_argument("--time", type=float, default=None, help="time [s] (default: peak |u_mean| in vein.csv)")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: OUTDIR)")
    args = ap.parse_args()
    vc.require_dir(args.outdir)

    csv_path = os.path.join(args.outdir, "vein.csv")
    rows, info = vc.read_csv(csv_path, need=("t", "u_mean"))
    if args.time is None:
        u = np.abs(rows["u_mean"])
        if not np.isfinite(u).any():
            vc.fail(f"{csv_path}: no finite u_mean")
        t_want = rows["t"][np.nanargmax(u)]
        why = "peak |u_mean|"
    else:
        t_want, why = args.time, "--time"
    t_snap, snap = vc.nearest_snapshot(args.outdir, t_want)
    d = vc.read_snapshot(snap, ["x", "type", "body"] + [p[0] for p in PANELS])
    x_mm = d["x"] * 1e3
    fluid, wall, solid = vc.masks(d)
    dx_mm = info.get("dx", math.nan) * 1e3
    if not math.isfinite(dx_mm):  # fall back on the lattice of the walls
        dx_mm = float(np.min(np.diff(np.unique(np.round(x_mm[wall, 0], 6))))) if wall.any() else 0.5

    xlim = (x_mm[:, 0].min() - dx_mm, x_mm[:, 0].max() + dx_mm)
    ylim = (x_mm[:, 1].min() - dx_mm, x_mm[:, 1].max() + dx_mm)
    panel_h = 0.82 * 11 * (ylim[1] - ylim[0]) / (xlim[1] - xlim[0])  # inches, at equal aspect
    fig, axes = plt.subplots(len(PANELS), 1, figsize=(11, len(PANELS) * (panel_h + 0.55) + 1.1), sharex=True)
    for ax, (name, label, unit) in zip(axes, PANELS):
        ax.set_xlim(*xlim)
        ax.set_ylim(*ylim)
        ax.set_aspect("equal")
    fig.subplots_adjust(left=0.06, right=0.88, top=1 - 0.85 / fig.get_figheight(),
                        bottom=0.5 / fig.get_figheight(), hspace=0.3)
    for ax, (name, label, unit) in zip(axes, PANELS):
        s = vc.marker_size(ax, dx_mm)
        value = d[name][fluid]
        finite = value[np.isfinite(value)]
        vmax = float(np.percentile(finite, 99.5)) if finite.size else 1.0
        vmax = vmax if vmax > 0 else 1.0
        ax.scatter(x_mm[wall, 0], x_mm[wall, 1], s=s, c="0.6", marker="s", linewidths=0)
        sc = ax.scatter(x_mm[fluid, 0], x_mm[fluid, 1], s=s, c=value, cmap="viridis", vmin=0, vmax=vmax,
                        marker="o", linewidths=0)
        ax.scatter(x_mm[solid, 0], x_mm[solid, 1], s=s, c="k", marker="o", linewidths=0, zorder=3)
        extend = "max" if finite.size and finite.max() > vmax else "neither"
        cb = fig.colorbar(sc, cax=ax.inset_axes([1.01, 0.0, 0.015, 1.0]), extend=extend)
        cb.set_label(f"[{unit}]")
        peak = f", max {finite.max():.3g} {unit}" if finite.size else ""
        ax.set_title(f"{label} [{unit}]{peak}", fontsize=10)
        ax.set_ylabel("y [mm]")
    axes[-1].set_xlabel("x [mm]")
    fig.suptitle(f"{vc.case_title(info)}\nliquid at t = {t_snap:.3f} s ({why}: {t_want:.3f} s); "
                 "walls grey, leaflets black")
    path = vc.output_path(args.out, args.outdir, "vein_fields.png")
    fig.savefig(path, dpi=110)
    print(path)


if __name__ == "__main__":
    main()
