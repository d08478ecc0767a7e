#!/usr/bin/python3
"""Velocity vectors in the sinus at one or more times (the thesis's Fig. 4.5).

  scripts/post/plot_vein_vectors.py OUTDIR [--time T | --times T1,T2,...] [--window X0,X1]
                                    [--arrows N] [--direction] [--out PATH]

Reads OUTDIR/vein.csv and the snapshot OUTDIR/snap_*.h5 nearest to each time,
interpolates the liquid's velocity with the SPH kernel (vein_grid.py: Lucy,
h = 2.5 dx, Shepard-normalised, masked where the liquid's kernel sum is below
0.5) and draws, per time, a filled contour map of its magnitude |v| [m/s] on a
fine grid and arrows of v on a coarse one (N arrows along the sinus, default 40,
about 15 across it); walls grey, leaflets black. Arrows and colours share one
scale over all panels (the reference arrow above the first panel).

  --time T        one time [s]
  --times T1,...  several times [s], one panel each
                  default: the first cycle's row of the largest inlet velocity
                  (forward phase) and of the most negative one (backward phase,
                  when the flow reverses); the inlet velocity is u_flux when
                  vein.csv has it, else u_mean
  --window X0,X1  x range [mm] (default: the sinus and 10 mm either side)
  --arrows N      arrows along the sinus length (default 40)
  --direction     arrows of one length (the flow's direction only; |v| from the
                  colours), so that the slow sinus flow shows as well as the jet
Writes vein_vectors.png into OUTDIR, or --out (a .png path or a directory).
"""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import vein_common as vc  # noqa: E402
import vein_grid as vg  # noqa: E402

LEVELS = 20
CMAP = mcolors.LinearSegmentedColormap.from_list("pale_blues",
                                                 plt.get_cmap("Blues")(np.linspace(0.04, 0.7, 256)))


def nice(v):
    """A round number near v (1, 2, 2.5 or 5 x 10^k, not above v)."""
    if not v > 0:
        return 1.0
    e = 10.0 ** math.floor(math.log10(v))
    return max(m for m in (1, 2, 2.5, 5, 10) if m * e <= v * (1 + 1e-9)) * e


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir", metavar="OUTDIR", help="output directory of a vein run")
    when = ap.add_mutually_exclusive_group()
    when.add_argument("--time", type=float, default=None, help="one time [s]")
    when.add_argument("--times", default=None, help="times [s], comma-separated (one panel each)")
    ap.add_argument("--window", default=None, help="x range X0,X1 [mm] (default: the sinus +- 10 mm)")
    ap.add_argument("--arrows", type=int, default=40, help="arrows along the sinus (default 40)")
    ap.add_argument("--direction", action="store_true", help="arrows of one length (direction only)")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: OUTDIR)")
    args = ap.parse_args()
    vc.require_dir(args.outdir)
    if args.arrows < 2:
        vc.fail(f"--arrows {args.arrows}: must be at least 2")

    csv_path = os.path.join(args.outdir, "vein.csv")
    cols, info = vc.read_csv(csv_path, need=("t", "u_mean"))
    T = info.get("T", math.nan)
    wanted = vg.requested_times(args.times, args.time, cols, T)

    panels = []
    for t_want, why in wanted:
        t_snap, snap = vc.nearest_snapshot(args.outdir, t_want)
        d = vc.read_snapshot(snap, ["x", "type", "body", "gid", "mass", "rho", "v"])
        geo = vg.geometry(snap, info)
        window = vg.parse_window(args.window, geo)
        gx, gy, fields, S = vg.liquid_grid(d, ["v"], geo, window)
        speed = np.ma.sqrt(fields["v_x"] ** 2 + fields["v_y"] ** 2)
        # the coarse grid of arrows: spacing sinus_length / N along x, about the same across
        step = geo["sinus_length"] / args.arrows
        ymax = 0.5 * geo["sinus_diameter"]
        ny = max(3, int(round(2 * ymax / step)) - 1)
        ay = np.linspace(-ymax, ymax, ny + 2)[1:-1]
        ax_ = np.arange(window[0] + 0.5 * step, window[1], step)
        AX, AY = np.meshgrid(ax_, ay)
        fluid, _, _ = vc.masks(d)
        vol = d["mass"][fluid] / d["rho"][fluid]
        f, s = vg.interpolate(d["x"][fluid, 0], d["x"][fluid, 1], vol, d["v"][fluid], AX.ravel(), AY.ravel(),
                              geo["h"], period=geo["length"], kernel=geo["kernel"])
        ok = s >= vg.MASK_THRESHOLD
        u, uname = vg.inlet_at(cols, t_snap)
        label = (f"t = {t_snap:.3f} s, {vg.phase(cols, t_snap)} phase ({uname} = {u:+.3g} m/s"
                 + (f"; {why}" if why.startswith("peak") else "") + ")")
        panels.append((label, d, geo, gx, gy, speed, AX.ravel()[ok], AY.ravel()[ok], f[ok], step))

    vals = np.concatenate([np.ma.compressed(p[5]) for p in panels])
    vmax = float(np.percentile(vals, 99.5)) if vals.size else 1.0
    vmax = vmax if vmax > 0 else 1.0
    extend = "max" if vals.size and vals.max() > vmax else "neither"
    arrow_speeds = np.concatenate([np.hypot(p[8][:, 0], p[8][:, 1]) for p in panels])
    vref = float(np.percentile(arrow_speeds, 95)) if arrow_speeds.size else 1.0
    vref = vref if vref > 0 else 1.0
    step_mm = panels[0][9] * 1e3
    scale = vref / (1.4 * step_mm)  # m/s per mm of arrow: the 95th percentile is 1.4 spacings long
    key = nice(vref)

    n = len(panels)
    window_mm = vg.extent_mm(panels[0][3])
    ymax_mm = vg.y_extent(panels[0][2]) * 1e3
    pw = 9.0
    pg = vg.PanelGrid(n, 1, pw, pw * 2 * ymax_mm / (window_mm[1] - window_mm[0]), cbar_room=0.0, gap=0.0,
                      right_room=1.0, top=0.6, title=0.45, foot=0.5)
    cs = None
    for i, (label, d, geo, gx, gy, speed, qx, qy, qv, step) in enumerate(panels):
        ax, _ = pg.axes(i, 0, colorbar=False)
        cs = ax.contourf(gx * 1e3, gy * 1e3, speed, levels=np.linspace(0, vmax, LEVELS + 1), cmap=CMAP,
                         extend=extend)
        vg.draw_solids(ax, d, geo)
        if args.direction:
            norm = np.hypot(qv[:, 0], qv[:, 1])
            qv = np.where(norm[:, None] > 0, qv / np.maximum(norm, 1e-300)[:, None], 0.0) * (0.8 * step_mm)
        q = ax.quiver(qx * 1e3, qy * 1e3, qv[:, 0], qv[:, 1], angles="xy", scale_units="xy",
                      scale=1.0 if args.direction else scale,
                      width=0.0016, headwidth=3.5, headlength=4, headaxislength=3.5, color="k", zorder=5)
        vg.setup_map(ax, window_mm, ymax_mm, xlabel=(i == n - 1))
        ax.set_title(label, fontsize=10, loc="left")
        if i == 0 and not args.direction:
            ax.quiverkey(q, 1.0, 1.07, key, f"{key:g} m/s", labelpos="W", coordinates="axes",
                         fontproperties={"size": 9})
    vg.colorbar(pg.fig, cs, pg.side_colorbar_axes(), "m/s", vmax, extend, name="speed |v|")
    arrows = "direction only, " if args.direction else ""
    pg.suptitle(f"{vg.run_title(args.outdir, info)}\nvelocity of the liquid, kernel-interpolated "
                f"(arrows: {arrows}every {step_mm:.2g} mm; walls grey, leaflets black)", fontsize=10.5)
    out = vc.output_path(args.out, args.outdir, "vein_vectors.png")
    pg.fig.savefig(out, dpi=150)
    print(out)


if __name__ == "__main__":
    main()
