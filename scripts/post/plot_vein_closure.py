#!/usr/bin/python3
"""The valve at closure, one panel per run of a k_a series (the thesis's Fig. 4.8).

  scripts/post/plot_vein_closure.py RUNDIR [RUNDIR ...] [--cycle N | --time T]
                                    [--window X0,X1] [--out PATH]

For each RUNDIR (a vein run; typically one per leaflet stiffness k_a) reads
RUNDIR/vein.csv and picks the closure time: the row of the smallest tip gap in
drive cycle N ((N-1) T < t <= N T; default: the run's last completed cycle, or
all its rows when it has not completed one), or --time T for every run. Draws
the snapshot RUNDIR/snap_*.h5 nearest to it: a filled contour map of the
liquid's speed |v| [m/s] (kernel-interpolated, vein_grid.py; one colour scale
for all panels, ending at the 99.5th percentile), walls grey, leaflets black,
each leaflet's straight root-tip chord dashed and its tip marked. Each panel is
titled with the run's k_a (vein.csv's comment) and directory name.

Prints, per run and leaflet, the tip position (the mid-point of the leaflet's
last particle column), the tip gap (between the two tips, as vein.csv's gap),
the clear opening (the gap less a leaflet's thickness 2 dx) and the largest
distance of the leaflet's mid-line from its chord (the root: the clamped
column's mid-point), signed positive toward the sinus (away from the axis),
negative toward the axis, with where along the chord it lies (s/c: 0 root,
1 tip).

  --cycle N       the drive cycle whose smallest gap is the closure (1-based)
  --time T        one time [s] for every run instead
  --window X0,X1  x range [mm] (default: each run's sinus and 10 mm either side)
Writes vein_closure.png into the first RUNDIR, or --out (a .png path or a
directory).
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

LEVELS = 24
NAMES = {1: "upper", 2: "lower"}


def closure_time(csv_path, cols, T, cycle):
    """(t, why): the row of the smallest gap in the cycle (default: the last completed one)."""
    t = cols["t"]
    gap = cols["gap"]
    # a row a step after k T (the step's overshoot) still belongs to cycle k
    tol = 0.25 * float(np.median(np.diff(t))) if t.size > 1 else 1e-6 * T
    n_done = int(math.floor((t[-1] + tol) / T)) if T > 0 else 0
    if cycle is None:
        if n_done >= 1:
            cycle = n_done
        else:
            print(f"{vc.PROG}: {csv_path}: no completed drive cycle (rows to t = {t[-1]:.3g} s, T = {T:g} s): "
                  "the smallest gap of all rows", file=sys.stderr)
            sel = np.isfinite(gap)
            if not sel.any():
                vc.fail(f"{csv_path}: no finite gap")
            i = np.flatnonzero(sel)[np.argmin(gap[sel])]
            return float(t[i]), "smallest gap so far, cycle 1 incomplete"
    sel = (t > (cycle - 1) * T + tol) & (t <= cycle * T + tol) & np.isfinite(gap)
    if not sel.any():
        vc.fail(f"{csv_path}: no rows in cycle {cycle} ({(cycle - 1) * T:g} < t <= {cycle * T:g} s; "
                f"rows to t = {t[-1]:.3g} s)")
    if cycle > n_done:
        print(f"{vc.PROG}: {csv_path}: cycle {cycle} incomplete (rows to t = {t[-1]:.3g} s): its rows so far",
              file=sys.stderr)
    i = np.flatnonzero(sel)[np.argmin(gap[sel])]
    return float(t[i]), f"smallest gap in cycle {cycle}" + ("" if cycle <= n_done else ", incomplete")


def leaflet_shape(layer0, layer1):
    """(root, tip, deflection, s): the mid-line's ends [m], the signed largest
    distance [m] of the mid-line from the chord root-tip (positive away from the
    axis, toward the sinus) and where along the chord it lies (0 root, 1 tip)."""
    mid = 0.5 * (layer0 + layer1)
    root, tip = mid[0], mid[-1]
    chord = tip - root
    length = float(np.hypot(*chord))
    if length == 0:
        return root, tip, math.nan, math.nan
    e = chord / length
    n = np.array([-e[1], e[0]])
    if n[1] * np.sign(root[1] if root[1] != 0 else 1.0) < 0:  # away from the axis y = 0
        n = -n
    rel = mid - root
    dist = rel @ n
    k = int(np.argmax(np.abs(dist)))
    return root, tip, float(dist[k]), float((rel[k] @ e) / length)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("rundirs", metavar="RUNDIR", nargs="+", help="output directories of vein runs")
    when = ap.add_mutually_exclusive_group()
    when.add_argument("--cycle", type=int, default=None,
                    help="drive cycle N of the closure (default: the last complete one)")
    when.add_argument("--time", type=float, default=None, help="one time [s] for every run")
    ap.add_argument("--window", default=None, help="x range X0,X1 [mm] (default: the sinus +- 10 mm)")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: the first RUNDIR)")
    args = ap.parse_args()
    if args.cycle is not None and args.cycle < 1:
        vc.fail(f"--cycle {args.cycle}: cycles count from 1")
    for r in args.rundirs:
        vc.require_dir(r)

    runs = []
    for run in args.rundirs:
        csv_path = os.path.join(run, "vein.csv")
        cols, info = vc.read_csv(csv_path, need=("t", "u_mean", "gap"))
        T = info.get("T", math.nan)
        if args.time is not None:
            t_want, why = args.time, "--time"
        else:
            if not (math.isfinite(T) and T > 0):
                vc.fail(f"{csv_path}: no drive period 'T' in the '# vein:' comment (give --time)")
            t_want, why = closure_time(csv_path, cols, T, args.cycle)
        t_snap, snap = vc.nearest_snapshot(run, t_want)
        d = vc.read_snapshot(snap, ["x", "type", "body", "gid", "mass", "rho", "speed"])
        geo = vg.geometry(snap, info)
        window = vg.parse_window(args.window, geo)
        gx, gy, fields, _ = vg.liquid_grid(d, ["speed"], geo, window)
        shapes = {b: leaflet_shape(*layers) for b, layers in vg.leaflets(d).items()}
        if len(shapes) < 2:
            vc.fail(f"{snap}: expected two leaflets (body 1 and 2), found {len(shapes)}")
        i = int(np.argmin(np.abs(cols["t"] - t_snap)))
        runs.append(dict(run=run, info=info, ka=vc.run_params(run, info).get("k_a", math.nan), t_want=t_want,
                         why=why, t_snap=t_snap, d=d, geo=geo, gx=gx, gy=gy,
                         speed=fields["speed"], shapes=shapes, gap_csv=float(cols["gap"][i]),
                         u=vg.inlet_at(cols, t_snap)))

    # the table
    print(f"{'run':<28} {'k_a [J]':>8} {'t [s]':>7}  {'leaflet':<6} {'tip x,y [mm]':>16} "
          f"{'gap [mm]':>8} {'opening':>8}  {'deflection [mm]':>15} {'at s/c':>6}")
    for r in runs:
        s1, s2 = r["shapes"][1], r["shapes"][2]
        gap = float(np.hypot(*(s1[1] - s2[1]))) * 1e3
        for b in (1, 2):
            root, tip, defl, where = r["shapes"][b]
            print(f"{os.path.basename(os.path.normpath(r['run'])):<28} {r['ka']:>8g} "
                  f"{r['t_snap']:>7.3f}  {NAMES[b]:<6} {tip[0] * 1e3:>8.2f},{tip[1] * 1e3:>7.2f} "
                  f"{gap:>8.3f} {gap - 2 * r['geo']['dx'] * 1e3:>8.3f}  {defl * 1e3:>+15.3f} {where:>6.2f}")

    vals = np.concatenate([np.ma.compressed(r["speed"]) for r in runs])
    vals = vals[np.isfinite(vals)]
    vmax = float(np.percentile(vals, 99.5)) if vals.size else 1.0
    vmax = vmax if vmax > 0 else 1.0
    extend = "max" if vals.size and vals.max() > vmax else "neither"

    # the parameters all runs share go to the figure's title, the others to each panel's
    parts_of = [vg.run_title(r["run"], r["info"]).split(": ", 1)[-1].split(", ") for r in runs]
    common = [p for p in parts_of[0] if all(p in q for q in parts_of[1:]) and not p.startswith("k_a")]

    n = len(runs)
    widths = [np.diff(vg.extent_mm(r["gx"]))[0] for r in runs]  # one x scale for all panels
    ymax = max(vg.y_extent(r["geo"]) for r in runs) * 1e3
    pw = 7.5
    pg = vg.PanelGrid(n, 1, pw, pw * 2 * ymax / max(widths), cbar_room=0.0, gap=0.0, right_room=1.1, top=0.6,
                      title=0.75, foot=0.5)
    cs = None
    for i, r in enumerate(runs):
        ax, _ = pg.axes(i, 0, colorbar=False)
        gx, gy = r["gx"], r["gy"]
        x0 = vg.extent_mm(gx)[0]
        window_mm = (x0, x0 + max(widths))
        cs = ax.contourf(gx * 1e3, gy * 1e3, r["speed"], levels=np.linspace(0, vmax, LEVELS + 1),
                         cmap="viridis",
                         extend=extend)
        vg.draw_solids(ax, r["d"], r["geo"])
        parts = []
        for b in (1, 2):
            root, tip, defl, where = r["shapes"][b]
            ax.plot([root[0] * 1e3, tip[0] * 1e3], [root[1] * 1e3, tip[1] * 1e3], "--", color="tab:red", lw=1.1,
                    zorder=6)
            ax.plot(tip[0] * 1e3, tip[1] * 1e3, "o", ms=4.5, mfc="white", mec="tab:red", mew=1.2, zorder=7)
            parts.append(f"{NAMES[b]} {defl * 1e3:+.2f}")
        gap = float(np.hypot(*(r["shapes"][1][1] - r["shapes"][2][1]))) * 1e3
        vg.setup_map(ax, window_mm, ymax, xlabel=(i == n - 1))
        ka = next((p for p in parts_of[i] if p.startswith("k_a")), f"k_a = {r['ka']:g} J")
        own = [p for p in parts_of[i] if p not in common and not p.startswith("k_a")]
        name = os.path.basename(os.path.normpath(r["run"])) + (f" ({', '.join(own)})" if own else "")
        u, uname = r["u"]
        ax.set_title(f"{ka} — {name}\n"
                     f"t = {r['t_snap']:.3f} s ({r['why']}), {uname} = {u:+.3g} m/s\n"
                     f"tip gap {gap:.2f} mm (clear opening {gap - 2 * r['geo']['dx'] * 1e3:.2f} mm); "
                     f"deflection from the chord (+ toward the sinus): " + ", ".join(parts) + " mm",
                     fontsize=9, loc="left")
    vg.colorbar(pg.fig, cs, pg.side_colorbar_axes(), "m/s", vmax, extend, name="speed |v|")
    head = f"vein: {', '.join(common)}" if common else "vein runs"
    pg.suptitle(f"{head}\nleaflets at closure: speed |v| of the liquid; chords root-tip dashed, tips ○",
                fontsize=10.5)
    out = vc.output_path(args.out, args.rundirs[0], "vein_closure.png")
    pg.fig.savefig(out, dpi=150)
    print(out)


if __name__ == "__main__":
    main()
