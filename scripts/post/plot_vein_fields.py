#!/usr/bin/python3
"""Liquid fields of a vein run in the sinus at one or two times (the thesis's Fig. 4.3).

  scripts/post/plot_vein_fields.py OUTDIR [--time T | --times T1,T2] [--window X0,X1]
                                   [--layout rows|columns] [--out PATH]

Reads OUTDIR/vein.csv (and OUTDIR/vein-summary.csv for nu, when present) and
the snapshot OUTDIR/snap_*.h5 nearest to each time, interpolates the liquid
particles' shear rate [1/s], total stress |sigma| [Pa], pressure force [N/m]
and speed |v| [m/s] onto a regular grid with the SPH kernel (vein_grid.py:
Lucy, h = 2.5 dx, Shepard-normalised, masked where the liquid's kernel sum is
below 0.5) and draws four filled contour maps per time, walls grey and leaflets
black. Each colour scale ends at the 99.5th percentile of its map (the colour
bar's arrow: larger values exist), so a few spiking particles do not wash it out.

  --time T        one time [s]
  --times T1,T2   several times [s], one row of four maps each
                  default: the first cycle's row of the largest inlet velocity
                  (forward phase) and of the most negative one (backward phase;
                  left out when the flow does not reverse). The inlet velocity
                  is u_flux when vein.csv has it, else u_mean; its sign at the
                  snapshot's time names the phase.
  --window X0,X1  x range [mm] (default: the sinus and 10 mm either side)
  --layout        rows: one row of four maps per time (default); columns: one
                  column per time, the four maps stacked (narrower, for print)
Writes vein_fields.png into OUTDIR, or --out (a .png path or a directory).
"""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402

import vein_common as vc  # noqa: E402
import vein_grid as vg  # noqa: E402

PANELS = [("shear_rate", "shear rate", "1/s"), ("stress_mag", "total stress |σ|", "Pa"),
          ("pressure_force", "pressure force", "N/m"), ("speed", "speed |v|", "m/s")]
LEVELS = 24


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir", metavar="OUTDIR", help="output directory of a vein run")
    when = ap.add_mutually_exclusive_group()
    when.add_argument("--time", type=float, default=None, help="one time [s]")
    when.add_argument("--times", default=None, help="times [s], comma-separated (one row each)")
    ap.add_argument("--window", default=None, help="x range X0,X1 [mm] (default: the sinus +- 10 mm)")
    ap.add_argument("--layout", choices=("rows", "columns"), default="rows",
                    help="rows: a row of four maps per time; columns: a column per time")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: OUTDIR)")
    args = ap.parse_args()
    vc.require_dir(args.outdir)

    csv_path = os.path.join(args.outdir, "vein.csv")
    cols, info = vc.read_csv(csv_path, need=("t", "u_mean"))
    T = info.get("T", math.nan)
    wanted = vg.requested_times(args.times, args.time, cols, T)

    names = ["x", "type", "body", "gid", "mass", "rho"] + [p[0] for p in PANELS]
    shots = []
    for t_want, why in wanted:
        t_snap, snap = vc.nearest_snapshot(args.outdir, t_want)
        d = vc.read_snapshot(snap, names)
        geo = vg.geometry(snap, info)
        window = vg.parse_window(args.window, geo)
        gx, gy, fields, _ = vg.liquid_grid(d, [p[0] for p in PANELS], geo, window)
        u, uname = vg.inlet_at(cols, t_snap)
        label = (f"t = {t_snap:.3f} s, {vg.phase(cols, t_snap)} phase ({uname} = {u:+.3g} m/s"
                 + (f"; {why}" if why.startswith("peak") else "") + ")")
        shots.append((label, d, geo, gx, gy, fields))

    n = len(shots)
    window_mm = vg.extent_mm(shots[0][3])
    ymax = vg.y_extent(shots[0][2]) * 1e3
    aspect = 2 * ymax / (window_mm[1] - window_mm[0])
    rows = args.layout == "rows"
    nr, nc = (n, len(PANELS)) if rows else (len(PANELS), n)
    pw = 4.0 if rows else 5.0
    pg = vg.PanelGrid(nr, nc, pw, pw * aspect, head=0.35 if rows else 0.0, top=0.75 if rows else 1.05,
                      foot=0.55 if rows else 0.3)
    for i, (label, d, geo, gx, gy, fields) in enumerate(shots):
        for j, (name, title, unit) in enumerate(PANELS):
            r, c = (i, j) if rows else (j, i)
            ax, cax = pg.axes(r, c)
            f = fields[name]
            vmax, extend = vg.colour_cap(f)
            cs = ax.contourf(gx * 1e3, gy * 1e3, f, levels=np.linspace(0, vmax, LEVELS + 1), cmap="viridis",
                             extend=extend)
            vg.draw_solids(ax, d, geo)
            vg.setup_map(ax, window_mm, ymax, xlabel=rows or r == nr - 1, ylabel=c == 0)
            vg.colorbar(pg.fig, cs, cax, unit, vmax, extend)
            ax.set_title(f"{title} [{unit}]", fontsize=10, loc="left")
        if rows:
            pg.row_label(i, label)
        else:
            pg.fig.text((pg.left + i * pg.col_w) / pg.W, 1 - 0.62 / pg.H, label.replace(" (", "\n("),
                        fontsize=10, fontweight="bold", va="top")
    pg.suptitle(f"{vg.run_title(args.outdir, info)}\n"
                "liquid fields, kernel-interpolated (walls grey, leaflets black)")
    path = vc.output_path(args.out, args.outdir, "vein_fields.png")
    pg.fig.savefig(path, dpi=150)
    print(path)


if __name__ == "__main__":
    main()
