#!/usr/bin/env python3
"""Vein quick checks (test/validation/vein.cmake, doc/validation.md "Vein").

--mode run: runs input/vein-quick.opts (on --ranks N with --mpirun) and
  asserts: the run reaches t_end (exit 0); no CSV holds a NaN or inf; the
  tips' gap rises above --open x the rest gap while the flow goes forward and
  falls below --close x the rest gap while it goes backward; the upper tip
  stays above the lower one (the leaflets never pass through each other);
  no fluid particle crossed a leaflet; max |rho/rho0 - 1| <= --max-rho-dev
  and max Mach <= --max-mach in every row; the measurement point was chosen;
  u_flux (the volume flux over the width) follows the inlet slab's u_mean:
  their RMS difference is below 15 % of the peak |u_mean| (a flux scaled by a
  wrong length or width, or missing a part of the liquid, is not).
  With --compare DIR: vein.csv, vein-sinus.csv and vein-summary.csv are
  byte for byte those of DIR (rank-count invariance).
  With --near DIR: the gap and the tips' positions within --near-tol of
  their range in DIR's vein.csv over t <= --near-t-max (another time
  stepping of the same case).
--mode restart: runs to --t-stop (checkpoint), restarts from it to t_end,
  and compares the three CSVs byte for byte with --compare DIR (the
  uninterrupted run).
"""
import argparse, math, os

from case_common import compare as compare_files, fail, opt_value, read_csv, run

CSVS = ["vein.csv", "vein-sinus.csv", "vein-summary.csv"]


def read_summary(path):
    """key,value rows; a value is a finite number or empty (not measured), never NaN."""
    if not os.path.isfile(path) or os.path.getsize(path) == 0:
        fail(f"{path} is missing or empty")
    out = {}
    lines = open(path).read().splitlines()
    if lines[0] != "key,value":
        fail(f"{path}: header {lines[0]!r}")
    for n, l in enumerate(lines[1:], 2):
        k, v = l.split(",")
        if v == "":
            out[k] = None
            continue
        x = float(v)
        if not math.isfinite(x):
            fail(f"{path}:{n}: non-finite {k} = {v}")
        out[k] = x
    for k in ("gap_rest", "u_mean_peak_cycle1", "u_flux_peak_cycle1", "crossings", "rho_dev_max", "mach_max"):
        if out.get(k) is None:
            fail(f"{path}: {k} missing")
    return out


def col(names, rows, name):
    if name not in names:
        fail(f"column {name} missing")
    k = names.index(name)
    return [r[k] for r in rows]


def mode_run(args):
    run(args, args.outdir, args.extra.split(), args.ranks)
    for c in CSVS[:2]:
        read_csv(os.path.join(args.outdir, c))
    summary = read_summary(os.path.join(args.outdir, "vein-summary.csv"))
    names, rows = read_csv(os.path.join(args.outdir, "vein.csv"))
    t = col(names, rows, "t")
    t_end = float(opt_value(args.opts, "-t_end"))
    if t[-1] < t_end * (1 - 1e-6) - 1e-4:
        fail(f"vein.csv stops at t = {t[-1]} < t_end = {t_end}")
    rest = summary["gap_rest"]
    gap, u = col(names, rows, "gap"), col(names, rows, "u_mean")
    fwd = [g for g, v in zip(gap, u) if v > 0]
    bwd = [g for g, v in zip(gap, u) if v < 0]
    if not fwd or not bwd:
        fail("the flow did not go both ways")
    print(f"  rest gap {rest:.4g} m; forward flow: gap up to {max(fwd):.4g} m; backward flow: down to {min(bwd):.4g} m")
    if max(fwd) < args.open * rest:
        fail(f"the valve did not open: largest gap in forward flow {max(fwd):.4g} m < {args.open} x rest")
    if min(bwd) > args.close * rest:
        fail(f"the valve did not close: smallest gap in backward flow {min(bwd):.4g} m > {args.close} x rest")
    flux = col(names, rows, "u_flux")
    rms = math.sqrt(sum((a - b) ** 2 for a, b in zip(flux, u)) / len(u))
    peak = max(abs(v) for v in u)
    print(f"  u_flux against u_mean: RMS difference {rms:.3g} m/s, peak |u_mean| {peak:.3g} m/s")
    if rms > 0.15 * peak:
        fail(f"u_flux does not follow u_mean: RMS difference {rms:.3g} m/s > 15 % of {peak:.3g} m/s")
    up, lo = col(names, rows, "tip_upper_y"), col(names, rows, "tip_lower_y")
    if any(a <= b for a, b in zip(up, lo)):
        fail("the upper tip went below the lower one: the leaflets passed through each other")
    cr = col(names, rows, "crossings")
    if cr[-1] != 0:
        fail(f"{int(cr[-1])} fluid particles crossed a leaflet")
    rd, ma = max(col(names, rows, "rho_dev")), max(col(names, rows, "mach"))
    print(f"  crossings 0; max |rho/rho0 - 1| {rd:.3g}; max Mach {ma:.3g}")
    if rd > args.max_rho_dev:
        fail(f"density deviation {rd:.3g} > {args.max_rho_dev}")
    if ma > args.max_mach:
        fail(f"Mach {ma:.3g} > {args.max_mach}")
    probe = [p for p in col(names, rows, "probe_gid") if p is not None]
    if not probe or len(set(probe)) != 1:
        fail("the measurement point was not chosen (or changed)")
    # the summary's peak stress covers every whole cycle from the one in which the point was chosen
    # by its quarter period on (rows and the run's end land within a step of their nominal times)
    T, tol = summary["period"], 1e-3 * summary["period"]
    t_probe = next(a for a, p in zip(t, col(names, rows, "probe_gid")) if p is not None)
    want = sum(1 for c in range(int(t[-1] / T + 1e-3) + 1)
               if (c + 1) * T <= t[-1] + tol and t_probe <= c * T + 0.25 * T + tol)
    print(f"  measurement point chosen at t = {t_probe:.7g} s; whole cycles since: {want}, "
          f"in the summary: {summary['n_cycles']:g}")
    if summary["n_cycles"] != want:
        fail(f"vein-summary.csv counts {summary['n_cycles']:g} cycles of peak stress, not the {want} whole "
             f"cycles after the point was chosen at t = {t_probe:.7g} s (T = {T:g} s, run to {t[-1]:.7g} s)")
    if args.max_leaflet_speed:
        leaflet_speed(args)
    if args.compare:
        compare_files(args.outdir, args.compare, CSVS)
    if args.near:
        near(args, names, rows)
    print("PASS")


def leaflet_speed(args):
    """The leaflets' fastest particle in every snapshot below --max-leaflet-speed (a leaflet
    that rings moves its particles at m/s while the valve as a whole moves at mm/s)."""
    import glob
    import h5py
    import numpy as np
    snaps = sorted(glob.glob(os.path.join(args.outdir, "snap_*.h5")))
    if len(snaps) < 2:
        fail(f"--max-leaflet-speed: no snapshots in {args.outdir}")
    worst, at = 0.0, None
    for f in snaps:
        with h5py.File(f, "r") as h:
            typ, v = h["/particles/type"][()], h["/particles/v"][()]
            speed = np.hypot(v[:, 0], v[:, 1])[typ == 2]
            if speed.size and speed.max() > worst:
                worst, at = float(speed.max()), os.path.basename(f)
    print(f"  leaflets' fastest particle over {len(snaps)} snapshots: {worst:.3g} m/s ({at})")
    if worst > args.max_leaflet_speed:
        fail(f"a leaflet particle moved at {worst:.3g} m/s > {args.max_leaflet_speed} m/s in {at}: the leaflets ring")


def near(args, names, rows):
    """The gap and both tips' positions within --near-tol of their range in --near DIR's vein.csv
    (another time stepping of the same case) over t <= --near-t-max, at this run's rows
    (the other's interpolated linearly: rows land at the first step past each output time)."""
    rn, rr = read_csv(os.path.join(args.near, "vein.csv"))
    t, tr = col(names, rows, "t"), col(rn, rr, "t")
    worst = 0.0
    for c in ["gap", "tip_upper_x", "tip_upper_y", "tip_lower_x", "tip_lower_y"]:
        y, yr = col(names, rows, c), col(rn, rr, c)
        sel = [k for k, a in enumerate(tr) if a <= args.near_t_max]
        if len(sel) < 2:
            fail(f"{args.near}/vein.csv has fewer than 2 rows up to t = {args.near_t_max} s")
        span = max(yr[k] for k in sel) - min(yr[k] for k in sel)
        if not span > 0:
            fail(f"{c} does not move in {args.near}/vein.csv up to t = {args.near_t_max} s")
        err, n = 0.0, 0
        for a, v in zip(t, y):
            if a > args.near_t_max or a > tr[-1]:
                continue
            k = next(k for k in range(1, len(tr)) if tr[k] >= a)
            w = (a - tr[k - 1]) / (tr[k] - tr[k - 1])
            err = max(err, abs(v - (yr[k - 1] + w * (yr[k] - yr[k - 1]))))
            n += 1
        if n < len(sel) // 2:
            fail(f"only {n} rows of this run up to t = {args.near_t_max} s to compare with {args.near}")
        print(f"  {c}: largest difference from {args.near} {err:.3g} m, {err / span:.3g} of its range {span:.3g} m")
        worst = max(worst, err / span)
    if worst > args.near_tol:
        fail(f"the leaflets' motion departs from {args.near} by {worst:.3g} of its range (> {args.near_tol})")


def mode_restart(args):
    run(args, args.outdir, args.extra.split() + ["-t_end", str(args.t_stop)], args.ranks)
    run(args, args.outdir, args.extra.split() + ["-restart", os.path.join(args.outdir, "checkpoint.h5")],
        args.restart_ranks)
    compare_files(args.outdir, args.compare, CSVS)
    print("PASS")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--opts", required=True)
    p.add_argument("--outdir", required=True)
    p.add_argument("--mode", default="run", choices=["run", "restart"])
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--restart-ranks", type=int, default=1)
    p.add_argument("--mpirun", default="mpirun")
    p.add_argument("--extra", default="")
    p.add_argument("--compare")
    p.add_argument("--t-stop", type=float, default=0.0)
    p.add_argument("--open", type=float, default=1.2)
    p.add_argument("--close", type=float, default=0.9)
    p.add_argument("--max-rho-dev", type=float, default=0.03)
    p.add_argument("--max-mach", type=float, default=0.1)
    p.add_argument("--max-leaflet-speed", type=float, default=0.0,
                   help="the leaflets' fastest particle in every snapshot below this [m/s] (0: not checked)")
    p.add_argument("--near", help="a run of the same case to agree with (another time stepping)")
    p.add_argument("--near-tol", type=float, default=0.02)
    p.add_argument("--near-t-max", type=float, default=0.25)
    args = p.parse_args()
    mode_run(args) if args.mode == "run" else mode_restart(args)


if __name__ == "__main__":
    main()
