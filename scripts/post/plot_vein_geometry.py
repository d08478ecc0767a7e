#!/usr/bin/python3
"""The vein geometry at t = 0, annotated, with a zoom on the upper leaflet's root.

  scripts/post/plot_vein_geometry.py OUTDIR [--out PATH]

Reads the first snapshot OUTDIR/snap_*.h5, OUTDIR/vein.csv (its comment line)
and OUTDIR/vein-summary.csv. Draws the liquid (light blue; the liquid that
started in the sinus, tracer 1, in orange), walls grey and leaflets black, with
the channel width W, sinus diameter D and length, the leaflet length L and
root angle, and the tips' rest gap. W, the root and the angle come from the
particles (the clamped root column sits at (x_root, +-W/2)); D and the sinus
length from the run's options when given (-vein_sinus_diameter,
-vein_sinus_length), otherwise from the particles: the sinus length as twice
the distance from the root to the sinus' centre, D from the smallest
half-ellipse that keeps every liquid column's top dx/2 inside (a lower bound,
within a fraction of dx).
The second panel zooms on the upper root with the bonds. Writes
vein_geometry.png into OUTDIR, or --out (a .png path or a directory).
"""
import argparse
import math
import os
import re

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Arc  # noqa: E402

import vein_common as vc  # noqa: E402

BLUE, ORANGE = "#9ecae1", "#fd8d3c"


def option(path, name):
    with h5py.File(path, "r") as f:
        opts = f.attrs.get("options", b"")
    opts = opts.decode() if isinstance(opts, bytes) else str(opts)
    found = re.findall(rf"{re.escape(name)}\s+(\S+)", opts)
    try:
        return float(found[-1]) if found else None
    except ValueError:
        return None


def dim(ax, p, q, text, offset=(0, 0), at=0.5, **kw):
    """A double arrow from p to q (mm) with a label at the fraction `at` along it (+ offset, points)."""
    ax.annotate("", xy=q, xytext=p, arrowprops=dict(arrowstyle="<->", color="crimson", lw=1.2, shrinkA=0,
                                                    shrinkB=0))
    mid = (p[0] + at * (q[0] - p[0]), p[1] + at * (q[1] - p[1]))
    ax.annotate(text, mid, xytext=offset, textcoords="offset points", color="crimson", fontsize=9,
                ha=kw.get("ha", "center"), va=kw.get("va", "center"),
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))


def draw(ax, d, s, leaflet_label="leaflet"):
    fluid, wall, leaflet = vc.masks(d)
    x = d["x"] * 1e3
    sinus = fluid & (d["tracer"] == 1)
    ax.scatter(x[wall, 0], x[wall, 1], s=s, c="0.6", marker="s", linewidths=0, label="wall")
    ax.scatter(x[fluid & ~sinus, 0], x[fluid & ~sinus, 1], s=s, c=BLUE, linewidths=0, label="liquid")
    ax.scatter(x[sinus, 0], x[sinus, 1], s=s, c=ORANGE, linewidths=0, label="sinus liquid (tracer 1)")
    free = leaflet & (d["type"] == vc.SOLID)
    ax.scatter(x[free, 0], x[free, 1], s=s, c="k", linewidths=0, zorder=3, label=leaflet_label)
    clamp = leaflet & ~free
    ax.scatter(x[clamp, 0], x[clamp, 1], s=s, c="k", marker="s", linewidths=0, zorder=3,
               label="leaflet root (clamped)")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir", metavar="OUTDIR", help="output directory of a vein run")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: OUTDIR)")
    args = ap.parse_args()
    vc.require_dir(args.outdir)

    _, info = vc.read_csv(os.path.join(args.outdir, "vein.csv"), need=("t",))
    sm = vc.read_summary(os.path.join(args.outdir, "vein-summary.csv"), need=("leaflet_length", "gap_rest", "dx"))
    t0, snap = vc.snapshots(args.outdir)[0]
    d = vc.read_snapshot(snap, ["x", "type", "body", "tracer", "bonds"])
    fluid, wall, leaflet = vc.masks(d)
    x = d["x"] * 1e3
    dx = sm["dx"] * 1e3
    L = sm["leaflet_length"] * 1e3
    gap = info.get("rest gap", sm["gap_rest"] * 1e3 if math.isfinite(sm["gap_rest"]) else math.nan)
    gap = gap * 1e3 if "rest gap" in info else gap
    upper = leaflet & (d["body"] == 1)
    lower = leaflet & (d["body"] == 2)
    if not upper.any() or not lower.any():
        vc.fail(f"{snap}: no leaflet particles (body 1 and 2)")
    clamp_u = upper & (d["type"] != vc.SOLID)
    root = x[clamp_u].mean(axis=0) if clamp_u.any() else x[upper][np.argmin(x[upper, 0])]
    W = 2 * root[1]
    free_u = upper & (d["type"] == vc.SOLID)
    slope = np.polyfit(x[free_u, 0], x[free_u, 1], 1)[0]
    theta = math.degrees(math.atan(-slope))
    tip_x = x[free_u, 0].max()
    # the sinus' centre: the middle of the liquid's top row (far from the leaflets, symmetric)
    y_top = np.abs(x[fluid, 1]).max()
    top = fluid & (np.abs(x[:, 1]) > y_top - 0.25 * dx)
    xc = 0.5 * (x[top, 0].min() + x[top, 0].max())
    D_opt, S_opt = option(snap, "-vein_sinus_diameter"), option(snap, "-vein_sinus_length")
    S = S_opt * 1e3 if S_opt else 2 * (xc - root[0])
    if D_opt:
        D = D_opt * 1e3
    else:  # every liquid column's top lies >= dx/2 below the half-ellipse W/2 + B sqrt(1 - u^2)
        B = 0.0
        for c in np.unique(x[fluid & (np.abs(x[:, 0] - xc) < 0.5 * S), 0]):
            sq = math.sqrt(1 - ((c - xc) / (0.5 * S)) ** 2)
            B = max(B, (np.abs(x[fluid & (x[:, 0] == c), 1]).max() + 0.5 * dx - 0.5 * W) / sq)
        D = W + 2 * B
    how_D = "" if D_opt else " (fit)"

    xlim = (x[:, 0].min() - dx, x[:, 0].max() + dx)
    ylim = (x[:, 1].min() - 2.5 * dx, x[:, 1].max() + 4 * dx)
    # the layout in inches, the main panel as high as its equal aspect needs: from the top the
    # title, the panel's title and legend, the panel, its x axis, the zoom's title, the zoom
    zx, zy = (root[0] - 3, root[0] + 5), (root[1] - 2.5, root[1] + 3.2)
    fw, left, pw = 11.0, 0.77, 9.9
    ph = pw * (ylim[1] - ylim[0]) / (xlim[1] - xlim[0])
    head, axis_room, ztitle, zh, foot = 1.25, 0.65, 0.45, 2.9, 0.55
    zw = zh * (zx[1] - zx[0]) / (zy[1] - zy[0])
    fh = head + ph + axis_room + ztitle + zh + foot
    fig = plt.figure(figsize=(fw, fh))
    ax = fig.add_axes([left / fw, (fh - head - ph) / fh, pw / fw, ph / fh])
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_aspect("equal")
    # the leaflet's length and angle in the legend: as a label beside the leaflet it covered the
    # rest gap's label at the tips (short leaflets) or the sinus wall (long ones)
    draw(ax, d, vc.marker_size(ax, dx), leaflet_label=f"leaflet, L = {L:.1f} mm at {theta:.2f}° to the axis")
    xs = xlim[0] + 0.08 * (xlim[1] - xlim[0])
    dim(ax, (xs, -0.5 * W), (xs, 0.5 * W), f"W = {W:.2f} mm", offset=(4, 0), ha="left")
    dim(ax, (xc, -0.5 * D), (xc, 0.5 * D), f"D = {D:.2f} mm{how_D}", offset=(4, 0), at=0.1, ha="left")
    ytop = x[:, 1].max() + 2 * dx
    dim(ax, (xc - 0.5 * S, ytop), (xc + 0.5 * S, ytop), f"sinus length {S:.2f} mm", offset=(0, 7))
    ax.plot([xc - 0.5 * S] * 2, [0.5 * W, ytop], color="crimson", lw=0.6, ls=":")
    ax.plot([xc + 0.5 * S] * 2, [0.5 * W, ytop], color="crimson", lw=0.6, ls=":")
    dim(ax, (tip_x + dx, -0.5 * gap), (tip_x + dx, 0.5 * gap), f"rest gap {gap:.2f} mm", offset=(4, 0), ha="left")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.legend(loc="lower left", fontsize=8, ncol=5, markerscale=2, bbox_to_anchor=(0, 1.0), frameon=False,
              columnspacing=1.2, handletextpad=0.3)
    # counted as dmhs counts them: the clamped root columns are wall particles
    clamps = leaflet & (d["type"] != vc.SOLID)
    ax.set_title(f"t = {t0:g} s: {fluid.sum()} liquid ({(fluid & (d['tracer'] == 1)).sum()} in the sinus), "
                 f"{(wall | clamps).sum()} wall ({clamps.sum()} of them leaflet clamps), "
                 f"{(leaflet & ~clamps).sum()} leaflet particles", fontsize=10, pad=22)
    ax.add_patch(plt.Rectangle((zx[0], zy[0]), zx[1] - zx[0], zy[1] - zy[0], fill=False, ls="--", lw=0.8))

    az = fig.add_axes([(fw - zw) / 2 / fw, foot / fh, zw / fw, zh / fh])
    az.set_xlim(*zx)
    az.set_ylim(*zy)
    az.set_aspect("equal")
    draw(az, d, vc.marker_size(az, 0.45 * dx))
    if d["bonds"].size:
        b = d["bonds"]
        keep = upper[b[:, 0]] & upper[b[:, 1]]
        for i, j in b[keep]:
            az.plot(x[[i, j], 0], x[[i, j], 1], color="0.45", lw=0.8, zorder=4)
    r_arc = 3.0
    az.plot([root[0], root[0] + r_arc * 1.15], [root[1]] * 2, color="crimson", lw=0.8, ls="--")
    az.add_patch(Arc(root, 2 * r_arc, 2 * r_arc, theta1=-theta, theta2=0, color="crimson", lw=1.5,
                     zorder=5))
    # above the dashed line's end, right-aligned: inside the panel whatever the angle
    az.annotate(f"θ = {theta:.2f}°", (root[0] + r_arc * 1.15, root[1]), xytext=(0, 4),
                textcoords="offset points", color="crimson", fontsize=9, va="bottom", ha="right",
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8), zorder=6)
    # the label inside the panel's lower left (offset points from the root ran over the y tick labels)
    az.annotate(f"root (x = {root[0]:.2f} mm, y = W/2)", root, xytext=(0.03, 0.2), textcoords="axes fraction",
                fontsize=9, ha="left", arrowprops=dict(arrowstyle="->", lw=0.7),
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))
    az.set_xlabel("x [mm]")
    az.set_ylabel("y [mm]")
    az.set_title(f"upper leaflet root (dashed box above): bonds grey, clamped column square, dx = {dx:g} mm",
                 fontsize=10)
    fig.suptitle(vc.case_title(info, args.outdir), y=1 - 0.12 / fh, va="top")
    out = vc.output_path(args.out, args.outdir, "vein_geometry.png")
    fig.savefig(out, dpi=110)
    print(f"W = {W:.3f} mm, D = {D:.3f} mm, sinus {S:.3f} mm from x = {xc - 0.5 * S:.3f} mm, "
          f"L = {L:.2f} mm, theta = {theta:.3f} deg, rest gap {gap:.3f} mm")
    print(out)


if __name__ == "__main__":
    main()
