#!/usr/bin/python3
"""Wash-out of the sinus liquid, one panel per drive period (the thesis's Fig. 4.4).

  scripts/post/plot_vein_sinus.py OUTDIR [--window X0,X1] [--out PATH]

Reads OUTDIR/vein.csv (the drive period T from its comment) and, for each
completed cycle k = 1, 2, ..., the snapshot OUTDIR/snap_*.h5 nearest to t = k T.
The liquid that started in the sinus (tracer = 1) is drawn as a filled contour
map of its displacement |x - x0| [mm] (minimum image in the periodic x), kernel-
interpolated over the tracer liquid alone (vein_grid.py: Lucy, h = 2.5 dx,
Shepard-normalised) and shown where the interpolated tracer indicator (the
tracer's share of the liquid) is at least 0.5 and the liquid's kernel sum at
least 0.5; the other liquid pale blue, walls grey, leaflets black. One colour
scale, shared by all panels, ends at the 99.5th percentile of the maps. A run
that has not completed a cycle yet shows its last snapshot.

  --window X0,X1  x range [mm] (default: the sinus and 10 mm either side)
Writes vein_sinus.png into OUTDIR, or --out (a .png path or a directory).
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402

import vein_common as vc  # noqa: E402
import vein_grid as vg  # noqa: E402

OTHER_LIQUID = "#dbe6f2"
LEVELS = 24


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir", metavar="OUTDIR", help="output directory of a vein run")
    ap.add_argument("--window", default=None, help="x range X0,X1 [mm] (default: the sinus +- 10 mm)")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: OUTDIR)")
    args = ap.parse_args()
    vc.require_dir(args.outdir)

    csv_path = os.path.join(args.outdir, "vein.csv")
    _, info = vc.read_csv(csv_path, need=("t",))
    T = info.get("T", math.nan)
    if not (math.isfinite(T) and T > 0):
        vc.fail(f"{csv_path}: no drive period 'T' in the '# vein:' comment")
    snaps = vc.snapshots(args.outdir)
    times = np.array([s[0] for s in snaps])
    interval = float(np.median(np.diff(times))) if times.size > 1 else T
    n_cycles = int(math.floor(times[-1] / T + 1e-6))
    picks = []
    for k in range(1, n_cycles + 1):
        i = int(np.argmin(np.abs(times - k * T)))
        if abs(times[i] - k * T) <= max(0.51 * interval, 1e-6 * T):
            picks.append((f"end of cycle {k}", k * T, snaps[i]))
    if not picks:
        print(f"{vc.PROG}: {args.outdir}: no completed drive cycle (last snapshot t = {times[-1]:.3g} s, "
              f"T = {T:g} s): drawing the last snapshot", file=sys.stderr)
        picks.append(("last snapshot, cycle 1 incomplete", times[-1], snaps[-1]))

    names = ["x", "type", "body", "gid", "mass", "rho", "tracer", "displacement"]
    panels = []
    for label, t_want, (t_snap, snap) in picks:
        d = vc.read_snapshot(snap, names)
        geo = vg.geometry(snap, info)
        window = vg.parse_window(args.window, geo)
        fluid, _, _ = vc.masks(d)
        tracer = (d["tracer"] == 1).astype(float)
        if not (tracer[fluid] > 0).any():
            vc.fail(f"{snap}: no liquid with tracer = 1 (the sinus liquid)")
        disp_mm = d["displacement"] * 1e3
        gx, gy, fields, S = vg.liquid_grid(d, [], geo, window,
                                           extra={"ind": tracer, "disp_ind": disp_mm * tracer})
        ind = fields["ind"]
        with np.errstate(invalid="ignore", divide="ignore"):
            disp = np.ma.masked_array(fields["disp_ind"].filled(np.nan) / ind.filled(np.nan),
                                      mask=np.ma.getmaskarray(ind) | ~(ind.filled(0) >= 0.5))
        other = np.ma.masked_array(np.ones_like(S), mask=~((S >= vg.MASK_THRESHOLD) & np.ma.getmaskarray(disp)))
        sel = fluid & (tracer > 0)
        stats = (int(sel.sum()), float(np.mean(disp_mm[sel])), float(np.max(disp_mm[sel])))
        panels.append((label, t_snap, d, geo, gx, gy, disp, other, stats))

    vals = np.concatenate([np.ma.compressed(p[6]) for p in panels])
    vals = vals[np.isfinite(vals)]
    vmax = float(np.percentile(vals, 99.5)) if vals.size else 1.0
    vmax = vmax if vmax > 0 else 1.0
    extend = "max" if vals.size and vals.max() > vmax else "neither"

    n = len(panels)
    ncols = 1 if n <= 4 else 2
    nrows = int(math.ceil(n / ncols))
    window_mm = vg.extent_mm(panels[0][4])
    ymax = vg.y_extent(panels[0][3]) * 1e3
    pw = 7.0 if ncols == 1 else 5.5
    pg = vg.PanelGrid(nrows, ncols, pw, pw * 2 * ymax / (window_mm[1] - window_mm[0]), cbar_room=0.0,
                      gap=0.5, right_room=1.1, top=0.7, title=0.5, foot=0.5)
    cs = None
    for i, (label, t_snap, d, geo, gx, gy, disp, other, (count, mean, peak)) in enumerate(panels):
        r, c = divmod(i, ncols)
        ax, _ = pg.axes(r, c, colorbar=False)
        ax.contourf(gx * 1e3, gy * 1e3, other, levels=[0.5, 1.5], colors=[OTHER_LIQUID])
        cs = ax.contourf(gx * 1e3, gy * 1e3, disp, levels=np.linspace(0, vmax, LEVELS + 1), cmap="plasma",
                         extend=extend)
        vg.draw_solids(ax, d, geo)
        vg.setup_map(ax, window_mm, ymax, xlabel=(r == nrows - 1 or i + ncols >= n), ylabel=(c == 0))
        ax.set_title(f"{label}, t = {t_snap:.3f} s\n{count} sinus particles, displacement mean "
                     f"{mean:.2f} mm, max {peak:.3g} mm", fontsize=9.5, loc="left")
    vg.colorbar(pg.fig, cs, pg.side_colorbar_axes(0, nrows - 1), "mm", vmax, extend,
                name="displacement |x − x0|")
    pg.suptitle(f"{vg.run_title(args.outdir, info)}\nliquid that started in the sinus, coloured by its "
                "displacement (other liquid pale blue, walls grey, leaflets black)", fontsize=10.5)
    out = vc.output_path(args.out, args.outdir, "vein_sinus.png")
    pg.fig.savefig(out, dpi=150)
    print(out)


if __name__ == "__main__":
    main()
