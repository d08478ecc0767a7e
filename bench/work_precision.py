#!/usr/bin/env python3
"""Work-precision of the time stepping: the error of a scene's key outputs
against a converged reference (a small fixed dt, no sub-steps), against the
wall time of the step loop, over fixed dt, automatic dt, solid sub-steps and
a lower sound speed.

  bench/work_precision.py --exe build/dmhs --case flap|vein|colon --out DIR [--plot | --plot-only]
                          [--settings "LABEL;LABEL"]   (only these, the reference and the automatic dt)

Runs the settings one after another (never two at once: the wall times are
compared), writes DIR/<case>.csv with one row per setting
(setting,options,steps,loop_s,error,rho_dev,what,mach; mach: the vein's max Mach) and with --plot
DIR/<case>.png (error against wall time, log-log). The error is the scene's
key output against the reference's, relative to the reference's range:
  flap   the tip's x displacement over time (max |tip - tip_ref| / max |tip_ref|)
  vein   the gap between the tips over time and the two tips' trajectories
         (the larger of max |gap - gap_ref| / range(gap_ref) and max |tip - tip_ref| / range)
  colon  the liquid front x_F and alpha over time (max |x - x_ref| / range(x_ref))
Time series are compared at the reference's output times (interpolated):
output rows are written at the first step past each output time.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

CASES = {
    "flap": {
        "opts": ["-options_file", "input/flap-quick.opts", "-t_end", "0.4"],
        "csv": "flap.csv",
        "reference": ["-dt", "2e-6"],
        "settings": [
            ("fixed dt 4e-6 s", ["-dt", "4e-6"]),
            ("fixed dt 8e-6 s (0.8 x the bonds' limit)", ["-dt", "8e-6"]),
            ("automatic dt", ["-dt", "0"]),
            ("automatic dt, automatic sub-steps", ["-dt", "0", "-solid_substeps", "0"]),
            ("automatic dt, 4 sub-steps", ["-dt", "0", "-solid_substeps", "4"]),
            ("automatic dt, automatic sub-steps, c0/2", ["-dt", "0", "-solid_substeps", "0", "-sph_c0", "0.5"]),
        ],
    },
    "vein": {
        "opts": ["-options_file", "input/vein-quick.opts", "-t_end", "0.25"],
        "csv": "vein.csv",
        # converged: fixed 2e-6 s (a setting below) lies within 1e-3 of its range
        "reference": ["-dt", "1e-6"],
        "settings": [
            ("fixed dt 2e-6 s", ["-dt", "2e-6"]),
            ("fixed dt 3e-6 s", ["-dt", "3e-6"]),
            ("fixed dt 4e-6 s", ["-dt", "4e-6"]),
            ("automatic dt", ["-dt", "0"]),
            ("automatic dt, safety 0.5", ["-dt", "0", "-dt_safety", "0.5"]),
            ("automatic dt, safety 0.25", ["-dt", "0", "-dt_safety", "0.25"]),
            ("automatic dt, automatic sub-steps", ["-dt", "0", "-solid_substeps", "0"]),
            ("automatic dt, c0 20 m/s", ["-dt", "0", "-sph_c0", "20"]),
            ("automatic dt, c0 5 m/s", ["-dt", "0", "-sph_c0", "5"]),
            # the scheme before the vein's default -sph_density_predict
            ("automatic dt, half-step density", ["-dt", "0", "-sph_density_predict", "false"]),
            ("fixed dt 4e-6 s, half-step density", ["-dt", "4e-6", "-sph_density_predict", "false"]),
            ("fixed dt 2e-6 s, half-step density", ["-dt", "2e-6", "-sph_density_predict", "false"]),
            # multi-rate contact (doc/stability.md): the repulsion and the liquid in contact on
            # the sub-steps, the sound speed binding dt
            ("automatic dt, multi-rate contact, respa",
             ["-dt", "0", "-solid_substeps", "0", "-repulsion_substeps", "-solid_substeps_scheme", "respa"]),
            ("automatic dt, multi-rate contact, held",
             ["-dt", "0", "-solid_substeps", "0", "-repulsion_substeps", "-solid_substeps_scheme", "held"]),
            ("automatic dt, safety 0.5, multi-rate contact, respa",
             ["-dt", "0", "-dt_safety", "0.5", "-solid_substeps", "0", "-repulsion_substeps",
              "-solid_substeps_scheme", "respa"]),
        ],
    },
    "colon": {
        "opts": ["-options_file", "input/intestine-quick.opts"],
        "csv": "intestine.csv",
        "reference": ["-dt", "4e-6"],
        "settings": [
            ("automatic dt (the quick input)", ["-dt", "0"]),
            ("automatic dt, safety 0.5", ["-dt", "0", "-dt_safety", "0.5"]),
            ("automatic dt, automatic sub-steps", ["-dt", "0", "-solid_substeps", "0"]),
            ("automatic dt, c0 2.5 m/s", ["-dt", "0", "-sph_c0", "2.5"]),
            ("fixed dt 1e-5 s", ["-dt", "1e-5"]),
        ],
    },
}


def read_csv(path):
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    header, body = rows[0], rows[1:]
    cols = {}
    for k, name in enumerate(header):
        vals = []
        for r in body:
            try:
                vals.append(float(r[k]) if r[k] != "" else math.nan)
            except (ValueError, IndexError):
                vals.append(math.nan)
        cols[name] = np.array(vals)
    return cols


def run(exe, args, outdir):
    cmd = [exe] + args + ["-output_dir", outdir, "-checkpoint_at_end", "false"]
    r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    out = r.stdout + r.stderr
    if r.returncode != 0:
        print(out[-2000:])
        sys.exit(f"FAIL: {' '.join(cmd)} exited with {r.returncode}")
    m = re.search(r"(\d+) steps to t = .* step loop ([0-9.]+) s", out)
    if not m:
        sys.exit(f"FAIL: no summary line from {' '.join(cmd)}")
    dev = re.findall(r"max\|rho/rho0-1\| ([0-9.e+-]+)", out)
    vein = re.search(r"max \|rho/rho0 - 1\| ([0-9.e+-]+), max Mach ([0-9.e+-]+)", out)
    rho_dev = float(vein.group(1)) if vein else (max(float(d) for d in dev) if dev else math.nan)
    mach = float(vein.group(2)) if vein else math.nan
    return int(m.group(1)), float(m.group(2)), rho_dev, mach


def series_error(ref, got, names):
    """largest |got - ref| over time, relative to the reference's range, over the named columns"""
    worst = 0.0
    t = ref["t"]
    for name in names:
        r = ref[name]
        g = np.interp(t, got["t"], got[name])
        scale = np.nanmax(r) - np.nanmin(r)
        if not np.isfinite(scale) or scale <= 0:
            scale = np.nanmax(np.abs(r))
        worst = max(worst, float(np.nanmax(np.abs(g - r)) / scale))
    return worst


METRICS = {
    "flap": (["tip_dx"], "tip x displacement vs t"),
    "vein": (["gap", "tip_upper_x", "tip_upper_y", "tip_lower_x", "tip_lower_y"], "gap and tip trajectories vs t"),
    "colon": (["x_F", "alpha"], "x_F and alpha vs t"),
}


def plot(rows, case, what, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    markers = "osD^vP*Xh<>p"
    for k, r in enumerate(rows[1:]):
        ax.loglog(r[3], max(r[4], 1e-7), markers[k % len(markers)], label=f"{r[0]} ({r[2]} steps)")
    ax.axvline(rows[0][3], color="grey", ls=":", label=f"reference ({rows[0][1]}): {rows[0][3]:.1f} s")
    ax.set_xlabel("wall time of the step loop [s] (1 rank)")
    ax.set_ylabel(f"error of the {what} / range")
    ax.set_title(f"work-precision, {case}")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    fig.savefig(os.path.join(out, f"{case}.png"), dpi=120, bbox_inches="tight")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--case", choices=sorted(CASES), required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--plot", action="store_true")
    ap.add_argument("--plot-only", action="store_true", help="plot DIR/<case>.csv without running")
    ap.add_argument("--settings", help="run only these settings (their labels, separated by ';'), "
                    "besides the reference and the automatic dt")
    a = ap.parse_args()
    exe = os.path.abspath(a.exe)
    case = CASES[a.case]
    os.makedirs(a.out, exist_ok=True)
    names, what = METRICS[a.case]
    if a.plot_only:
        with open(os.path.join(a.out, f"{a.case}.csv")) as f:
            rows = [(r["setting"], r["options"], int(r["steps"]), float(r["loop_s"]), float(r["error"]),
                     float(r["rho_dev"])) for r in csv.DictReader(f)]
        plot(rows, a.case, what, a.out)
        return

    ref_dir = os.path.join(os.path.abspath(a.out), f"{a.case}-reference")
    steps, loop, dev, mach = run(exe, case["opts"] + case["reference"], ref_dir)
    ref = read_csv(os.path.join(ref_dir, case["csv"]))
    rows = [("reference " + " ".join(case["reference"]), " ".join(case["reference"]), steps, loop, 0.0, dev,
             mach)]
    print(f"{a.case}: reference {' '.join(case['reference'])}: {steps} steps, loop {loop:.2f} s")
    only = set(a.settings.split(";")) | {"automatic dt"} if a.settings else None
    if only:
        unknown = only - {label for label, _ in case["settings"]}
        if unknown:
            sys.exit(f"FAIL: --settings: no setting {sorted(unknown)} in case {a.case}")
    for k, (label, extra) in enumerate(case["settings"]):
        if only and label not in only:
            continue
        d = os.path.join(os.path.abspath(a.out), f"{a.case}-{k}")
        steps, loop, dev, mach = run(exe, case["opts"] + extra, d)
        err = series_error(ref, read_csv(os.path.join(d, case["csv"])), names)
        rows.append((label, " ".join(extra), steps, loop, err, dev, mach))
        print(f"{a.case}: {label}: {steps} steps, loop {loop:.2f} s, error {err:.3e} ({what}), "
              f"max|rho/rho0-1| {dev:.3g}")
    path = os.path.join(a.out, f"{a.case}.csv")
    with open(path + ".tmp", "w") as f:
        f.write("setting,options,steps,loop_s,error,rho_dev,what,mach\n")
        for r in rows:
            f.write(f"\"{r[0]}\",\"{r[1]}\",{r[2]},{r[3]:.3f},{r[4]:.4e},{r[5]:.4g},{what},{r[6]:.4g}\n")
    os.replace(path + ".tmp", path)
    if a.plot:
        plot(rows, a.case, what, a.out)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
