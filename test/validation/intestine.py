#!/usr/bin/env python3
"""Intestine quick checks (test/validation/intestine.cmake, doc/validation.md).

--mode run: runs input/intestine-quick.opts (optionally on --ranks N with
  --mpirun) and asserts: the run reaches t_end; intestine.csv holds no NaN;
  fluid in the computation + overflow = initial in every row; each segment
  under a whole +1 sub-period rises by > --min-move and under a whole -1
  sub-period sinks by > --min-move (the schedule's sign); x_F moves
  downstream by > --min-front while pocket 0 squeezes; intestine-summary.csv
  (key,value,note) has the measures that need one whole wave (u_F, alpha_T,
  alpha_end, u_P, u_S) when the run has one, and n/a with a reason for them
  (and Re, Re_P) when it has none; with --compare CSV, the CSV equals the
  given one (to 1e-12 relative).
--mode restart: a checkpoint half way and -restart give the uninterrupted
  run's intestine.csv and intestine-summary.csv (the rows kept for the
  measures are restored).
--mode schedule: a custom schedule file runs (and is followed: the pocket
  given +1 rises); a malformed one fails naming file and line.
"""
import argparse, os, subprocess, sys
import numpy as np


def run(args, outdir, extra, ranks=1):
    os.makedirs(outdir, exist_ok=True)
    cmd = [args.exe, "-options_file", args.opts, "-output_dir", outdir, "-quiet"] + extra
    if ranks > 1:
        cmd = args.mpirun.split() + ["-n", str(ranks)] + cmd
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


def load(outdir):
    path = os.path.join(outdir, "intestine.csv")
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    if len(lines) < 2:
        fail(f"{path}: no rows")
    names = lines[0].strip().split(",")
    rows = []
    for n, l in enumerate(lines[1:], start=2):
        v = l.strip().split(",")
        if len(v) != len(names):
            fail(f"{path}: row {n} has {len(v)} values, the header {len(names)}")
        r = [float(x) for x in v]
        if not np.all(np.isfinite(r)):
            fail(f"{path}: row {n} has a non-finite value: {l.strip()}")
        rows.append(r)
    return names, np.array(rows)


def read_summary(path):
    """intestine-summary.csv (key,value,note) as ({key: value text}, {key: note})."""
    import csv
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows or rows[0][:2] != ["key", "value"]:
        fail(f"{path}: not a key,value[,note] table")
    kv, notes = {}, {}
    for r in rows[1:]:
        if len(r) not in (2, 3):
            fail(f"{path}: {r!r} is not key,value[,note]")
        kv[r[0]] = r[1]
        notes[r[0]] = r[2] if len(r) == 3 else ""
    return kv, notes


def col(names, data, n):
    return data[:, names.index(n)]


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def sign_checks(names, data, min_move):
    """For each pocket and each sub-period fully inside the run: the lift at
    its end relative to the settled lift when the wave starts, against the
    schedule value s_k (+1: up, -1: down)."""
    t, sub = col(names, data, "t"), col(names, data, "sub")
    npk = sum(1 for n in names if n.startswith("lift_"))
    checked = 0
    rest = np.where(sub >= 0)[0][0]  # the settled membrane, when the wave starts
    for r in sorted(set(sub[sub >= 0].astype(int))):
        idx = np.where(sub == r)[0]
        if len(idx) < 3 or idx[-1] == len(sub) - 1:
            continue  # the last sub-period may be cut by t_end
        i1 = idx[-1]
        for k in range(npk):
            s = col(names, data, f"s_{k}")[i1]
            d = col(names, data, f"lift_{k}")[i1] - col(names, data, f"lift_{k}")[rest]
            if s == 0:
                continue
            print(f"  sub-period {r}: pocket {k} schedule {int(s):+d}, lift at its end vs rest {d:+.3e} m")
            if s * d < min_move:
                fail(f"pocket {k} in sub-period {r}: schedule {int(s):+d} but the segment moved {d:+.3e} m")
            checked += 1
    if checked == 0:
        fail("no whole sub-period with a force to check")
    return checked


def mode_run(args):
    rc, out = run(args, args.outdir, args.extra.split(), args.ranks)
    print(out[-3000:])
    if rc != 0:
        fail(f"dmhs exited with {rc}")
    names, data = load(args.outdir)
    t = col(names, data, "t")
    tend = [l.split()[1] for l in open(args.opts) if l.startswith("-t_end")]
    extra = args.extra.split()
    tend += [extra[k + 1] for k in range(len(extra) - 1) if extra[k] == "-t_end"]  # the last one wins
    if not tend:
        fail(f"{args.opts} has no -t_end line to check the run's end against")
    if t[-1] < float(tend[-1]) * (1 - 1e-6) - 1e-4:
        fail(f"run stopped at t = {t[-1]}")
    fluid, over = col(names, data, "fluid"), col(names, data, "overflow")
    n0 = fluid[0] + over[0]
    if np.any(fluid + over != n0):
        fail("fluid + overflow not conserved")
    white = sum(col(names, data, n) for n in names if n.startswith("white_"))
    if np.any(white != white[0]):
        fail("tracked (white) count not conserved")
    if over[-1] < args.min_overflow:
        fail(f"overflow {int(over[-1])} < {args.min_overflow}")
    print(f"  particles: {int(n0)} fluid, conserved in all {len(t)} rows; overflow at the end {int(over[-1])}")
    # weakly compressible and watertight in every row
    rd, ma = col(names, data, "rho_dev"), col(names, data, "mach")
    ins, thr = col(names, data, "in_membrane"), col(names, data, "through")
    print(f"  max |rho/rho0 - 1| {rd.max():.4g} (t = {t[rd.argmax()]:.4g} s), max Mach {ma.max():.4g} "
          f"(t = {t[ma.argmax()]:.4g} s), liquid in the membrane: max {int(ins.max())}, through it: max {int(thr.max())}")
    # where the bound breaks: the count beyond 3 % agrees with the maximum, row by row, and
    # the worst particle's place is a finite position (not the (0, 0) of an empty liquid)
    for n in ("rho_over_3pct", "rho_worst_x", "rho_worst_y"):
        if n not in names:
            fail(f"intestine.csv has no column {n}")
    over3, wx, wy = col(names, data, "rho_over_3pct"), col(names, data, "rho_worst_x"), col(names, data, "rho_worst_y")
    if np.any((over3 > 0) != (rd > 0.03)):
        k = int(np.argmax((over3 > 0) != (rd > 0.03)))
        fail(f"rho_over_3pct {int(over3[k])} disagrees with rho_dev {rd[k]:.4g} at t = {t[k]:.4g} s")
    if not (np.all(np.isfinite(wx)) and np.all(np.isfinite(wy))) or np.any((wx == 0) & (wy == 0)):
        fail("rho_worst_x / rho_worst_y not a particle's position in every row")
    print(f"  worst density at the end at ({wx[-1]:.4g}, {wy[-1]:.4g}) m; rows with liquid beyond 3 %: {int(np.sum(over3 > 0))}")
    if rd.max() > args.max_rho_dev:
        fail(f"density deviation {rd.max():.4g} > {args.max_rho_dev} at t = {t[rd.argmax()]:.4g} s")
    if ma.max() > args.max_mach:
        fail(f"Mach {ma.max():.4g} > {args.max_mach} at t = {t[ma.argmax()]:.4g} s")
    if thr.max() > 0:
        fail(f"{int(thr.max())} liquid particles through the membrane at t = {t[thr.argmax()]:.4g} s")
    if ins.max() > args.max_in_membrane:
        fail(f"{int(ins.max())} liquid particles in the membrane at t = {t[ins.argmax()]:.4g} s")
    summ = os.path.join(args.outdir, "intestine-summary.csv")
    if not os.path.isfile(summ):
        fail(f"{summ} missing")
    kv, notes = read_summary(summ)
    for k in ("u_F_squeeze", "V_w", "Fr", "rho_dev_max", "mach_max", "in_membrane_max", "through_max", "waves"):
        if k not in kv or kv[k] == "n/a" or not np.isfinite(float(kv[k])):
            fail(f"{summ}: {k} missing or not finite ({kv.get(k)!r})")
    # what needs one whole wave is measured with one, and n/a with its reason without one
    whole = ("u_F", "u_F_line", "u_F_line_r2", "u_F_first_wave", "alpha_T", "alpha_end", "u_P", "u_S")
    if float(kv["waves"]) >= 1:
        for k in whole:
            if kv.get(k, "n/a") == "n/a" or not np.isfinite(float(kv[k])):
                fail(f"{summ}: {k} not measured ({kv.get(k)!r}) over {kv['waves']} whole wave(s)")
        if float(kv["u_F"]) > 0 and kv.get("Re", "n/a") == "n/a":
            fail(f"{summ}: Re n/a with u_F = {kv['u_F']} > 0")
        print(f"  alpha after one period {float(kv['alpha_T']):.4g}, u_P {float(kv['u_P']):.4g} m/s, "
              f"u_S {float(kv['u_S']):.4g} m/s, u_F {float(kv['u_F']):.4g} m/s ({notes['u_F']}), Re {kv['Re']}")
    else:
        for k in whole + ("Re", "Re_P"):
            if kv.get(k) != "n/a" or not notes.get(k):
                fail(f"{summ}: {k} = {kv.get(k)!r} (note {notes.get(k)!r}) with no whole wave: "
                     "expected n/a with its reason")
        print(f"  no whole wave: u_F, alpha_T, u_P, u_S, Re n/a ({notes['u_F']}); "
              f"u_F_squeeze {float(kv['u_F_squeeze']):.4g} m/s")
    if args.need_alpha and float(kv["waves"]) < 1:
        fail(f"{summ}: no whole wave: the run must pass one whole wave")
    if abs(float(kv["rho_dev_max"]) - rd.max()) > 1e-6 or int(float(kv["through_max"])) != int(thr.max()):
        fail(f"{summ}: rho_dev_max / through_max disagree with intestine.csv")
    n = sign_checks(names, data, args.min_move)
    print(f"  {n} sign checks passed")
    # the front: from the start of pocket 0's first +1 to its end
    sub, s0, xf = col(names, data, "sub"), col(names, data, "s_0"), col(names, data, "x_F")
    sq = np.where(s0 > 0)[0]
    if len(sq) == 0:
        fail("pocket 0 never squeezes in this run")
    i0, i1 = sq[0], sq[-1]
    dxf = xf[i1] - xf[i0]
    print(f"  x_F: {xf[i0]:.6g} m at t = {t[i0]:.4g} s -> {xf[i1]:.6g} m at t = {t[i1]:.4g} s (+{dxf:.3e} m); "
          f"alpha at the end {col(names, data, 'alpha')[-1]:.4g}")
    if dxf < args.min_front:
        fail(f"front moved {dxf:.3e} m < {args.min_front} m while pocket 0 squeezed")
    if args.compare:
        names2, data2 = load(args.compare)
        if names2 != names or data2.shape != data.shape:
            fail("CSV layout differs from " + args.compare)
        err = np.max(np.abs(data - data2) / np.maximum(1e-30, np.abs(data2) + 1e-12))
        print(f"  largest relative difference to {args.compare}: {err:.3e}")
        if not err <= 1e-12:  # a NaN fails too
            fail("CSV differs from the 1-rank run")
    print("PASS")


def mode_schedule(args):
    os.makedirs(args.outdir, exist_ok=True)
    good = os.path.join(args.outdir, "good.txt")
    # 3 pockets: pocket 2 up, pocket 0 down, in every sub-period
    with open(good, "w") as f:
        f.write("# custom schedule: pocket 2 up, pocket 0 down\n-1 0 1\n\n-1, 0, 1  # commas work too\n")
    rc, out = run(args, os.path.join(args.outdir, "good"), ["-peristalsis_schedule", good, "-t_end", "0.1"])
    print(out[-1500:])
    if rc != 0:
        fail("custom schedule run failed")
    names, data = load(os.path.join(args.outdir, "good"))
    l0, l2 = col(names, data, "lift_0")[-1], col(names, data, "lift_2")[-1]
    print(f"  custom schedule: lift_0 = {l0:+.3e} m (-1), lift_2 = {l2:+.3e} m (+1)")
    if not (l2 > args.min_move and l0 < -args.min_move):
        fail("the custom schedule was not followed")
    bad = os.path.join(args.outdir, "bad.txt")
    with open(bad, "w") as f:
        f.write("# malformed\n1 0 -1\n1 2 0\n")
    rc, out = run(args, os.path.join(args.outdir, "bad"), ["-peristalsis_schedule", bad, "-t_end", "0.01"])
    print(out[-800:])
    if rc != 1 or f"{bad}:3" not in out:
        fail(f"malformed schedule: expected an error naming {bad}:3")
    short = os.path.join(args.outdir, "short.txt")
    with open(short, "w") as f:
        f.write("1 0 -1\n0 1\n")
    rc, out = run(args, os.path.join(args.outdir, "short"), ["-peristalsis_schedule", short, "-t_end", "0.01"])
    if rc != 1 or f"{short}:2" not in out:
        fail(f"short row: expected an error naming {short}:2")
    print("PASS")


def mode_restart(args):
    """Stop at t = 0.13 s (checkpoint at the end), restart to t_end: the CSV
    must equal the uninterrupted run's (--compare)."""
    rc, out = run(args, args.outdir, ["-t_end", "0.13"])
    if rc != 0:
        print(out[-2000:])
        fail("first half failed")
    rc, out = run(args, args.outdir, ["-restart", os.path.join(args.outdir, "checkpoint.h5")])
    print(out[-1200:])
    if rc != 0:
        fail("restart failed")
    a = open(os.path.join(args.outdir, "intestine.csv")).read()
    b = open(os.path.join(args.compare, "intestine.csv")).read()
    if a != b:
        fail("restarted CSV differs from the uninterrupted run")
    # the summary's measures come from the rows kept since the wave's start: restored, not lost
    a = open(os.path.join(args.outdir, "intestine-summary.csv")).read()
    b = open(os.path.join(args.compare, "intestine-summary.csv")).read()
    if a != b:
        fail("restarted intestine-summary.csv differs from the uninterrupted run")
    print("  restarted intestine.csv and intestine-summary.csv identical to the uninterrupted run\nPASS")


ap = argparse.ArgumentParser()
ap.add_argument("--exe", required=True)
ap.add_argument("--opts", required=True)
ap.add_argument("--outdir", required=True)
ap.add_argument("--mode", default="run", choices=["run", "schedule", "restart"])
ap.add_argument("--ranks", type=int, default=1)
ap.add_argument("--mpirun", default="mpirun --oversubscribe --allow-run-as-root")
ap.add_argument("--compare", default="")
ap.add_argument("--extra", default="", help="more dmhs options (one string)")
ap.add_argument("--min-overflow", type=int, default=0)
ap.add_argument("--min-move", type=float, default=5e-4)
ap.add_argument("--min-front", type=float, default=5e-4)
ap.add_argument("--max-rho-dev", type=float, default=0.03, help="max |rho/rho0 - 1| in every row")
ap.add_argument("--max-mach", type=float, default=0.1, help="max |v|/c0 in every row")
ap.add_argument("--need-alpha", action="store_true", help="alpha after one period, u_P, u_S must be measured")
ap.add_argument("--max-in-membrane", type=int, default=0,
                help="liquid particles lodged in the membrane (none may go through it)")
args = ap.parse_args()
{"run": mode_run, "schedule": mode_schedule, "restart": mode_restart}[args.mode](args)
