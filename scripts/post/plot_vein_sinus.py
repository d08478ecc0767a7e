#!/usr/bin/python3
"""Wash-out of the sinus liquid, one panel per drive period (the thesis's Fig. 4.4).

  scripts/post/plot_vein_sinus.py OUTDIR [--out PATH]

Reads OUTDIR/vein-sinus.csv (t,cycle,gid,x,y,displacement: the liquid that
started in the sinus, once per period) and, for context, the walls (grey) and
leaflets (black) of the snapshot OUTDIR/snap_*.h5 nearest to each cycle's t.
The sinus liquid is coloured by its displacement |x - x0| [mm] (minimum image
in the periodic x) on one colour scale shared by all panels. Writes
vein_sinus.png into OUTDIR, or --out (a .png path or a directory).
"""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import vein_common as vc  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir", metavar="OUTDIR", help="output directory of a vein run")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: OUTDIR)")
    args = ap.parse_args()
    vc.require_dir(args.outdir)

    path = os.path.join(args.outdir, "vein-sinus.csv")
    rows, _ = vc.read_csv(path, need=("cycle", "t", "gid", "x", "y", "displacement"))
    _, info = vc.read_csv(os.path.join(args.outdir, "vein.csv"), need=("t",))
    cycles = np.unique(rows["cycle"][np.isfinite(rows["cycle"])]).astype(int)
    if cycles.size == 0:
        vc.fail(f"{path}: no cycle")
    disp_mm = rows["displacement"] * 1e3
    vmax = float(np.nanmax(disp_mm)) if np.isfinite(disp_mm).any() else 1.0
    vmax = vmax if vmax > 0 else 1.0
    dx_mm = info.get("dx", math.nan) * 1e3
    dx_mm = dx_mm if math.isfinite(dx_mm) else 0.5

    context = []
    for c in cycles:
        t_c = float(np.nanmax(rows["t"][rows["cycle"] == c]))
        t_snap, snap = vc.nearest_snapshot(args.outdir, t_c)
        context.append((c, t_c, t_snap, vc.read_snapshot(snap, ["x", "type", "body"])))
    allx = np.concatenate([d["x"] for *_, d in context]) * 1e3
    xlim = (allx[:, 0].min() - dx_mm, allx[:, 0].max() + dx_mm)
    ylim = (allx[:, 1].min() - dx_mm, allx[:, 1].max() + dx_mm)

    n = len(cycles)
    panel_h = 0.8 * 10 * (ylim[1] - ylim[0]) / (xlim[1] - xlim[0])
    fig, axes = plt.subplots(n, 1, figsize=(10, n * (panel_h + 0.6) + 1.2), sharex=True, squeeze=False)
    axes = axes[:, 0]
    fig.subplots_adjust(left=0.08, right=0.88, top=1 - 0.8 / fig.get_figheight(),
                        bottom=0.55 / fig.get_figheight(), hspace=0.35)
    for ax in axes:
        ax.set_xlim(*xlim)
        ax.set_ylim(*ylim)
        ax.set_aspect("equal")
    for ax, (c, t_c, t_snap, d) in zip(axes, context):
        s = vc.marker_size(ax, dx_mm)
        x_mm = d["x"] * 1e3
        _, wall, solid = vc.masks(d)
        ax.scatter(x_mm[wall, 0], x_mm[wall, 1], s=s, c="0.65", marker="s", linewidths=0)
        ax.scatter(x_mm[solid, 0], x_mm[solid, 1], s=s, c="k", linewidths=0, zorder=3)
        sel = rows["cycle"] == c
        sc = ax.scatter(rows["x"][sel] * 1e3, rows["y"][sel] * 1e3, s=s, c=disp_mm[sel], cmap="plasma",
                        vmin=0, vmax=vmax, linewidths=0, zorder=2)
        ax.set_title(f"cycle {c}: t = {t_c:.3f} s, {sel.sum()} particles, mean displacement "
                     f"{np.nanmean(disp_mm[sel]):.2f} mm (walls, leaflets at t = {t_snap:.3f} s)", fontsize=10)
        ax.set_ylabel("y [mm]")
        cb = fig.colorbar(sc, cax=ax.inset_axes([1.01, 0.0, 0.015, 1.0]))
        cb.set_label("displacement [mm]")
    axes[-1].set_xlabel("x [mm]")
    fig.suptitle(f"{vc.case_title(info)}\nliquid that started in the sinus, once per drive period")
    out = vc.output_path(args.out, args.outdir, "vein_sinus.png")
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()
