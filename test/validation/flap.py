#!/usr/bin/python3
"""Flap check: run dmhs on an options file, then from flap.csv require
 * a settled deflection: the tip x-displacement averaged over the last 25 % of
   the run differs from its average over the quarter before by less than
   --drift (relative), and its peak-to-peak wander over the last 25 % stays
   below --steady (relative to that average); the deflection exceeds
   --min-deflection of the flap height;
 * zero fluid crossings of the flap;
 * no-slip: the liquid's velocity extrapolated onto the flap's faces, relative
   to the flap, averaged over the last 25 % of the run, below --slip (in units
   of the channel's peak speed u_max; see flap_slip in src/scenes/flap/flap.c).
Writes flap.png (settled flow) next to the CSV when --plot is given."""
import argparse, os, subprocess, sys
import numpy as np

p = argparse.ArgumentParser()
p.add_argument("--exe", required=True)
p.add_argument("--opts", required=True)
p.add_argument("--outdir", required=True)
p.add_argument("--drift", type=float, default=0.02)
p.add_argument("--steady", type=float, default=0.1)
p.add_argument("--slip", type=float, default=0.05)
p.add_argument("--min-deflection", type=float, default=0.05, help="tip deflection / flap height must exceed this")
p.add_argument("--plot", action="store_true")
p.add_argument("--no-run", action="store_true", help="analyse an existing output directory")
p.add_argument("--extra", default="", help="more dmhs options (one string), e.g. the sub-steps")
p.add_argument("--reference", help="an output directory of the same case: the mean tip deflection over the last "
               "quarter must agree within --tip-tol")
p.add_argument("--tip-tol", type=float, default=0.01)
a = p.parse_args()
if not a.no_run:
    subprocess.run([a.exe, "-options_file", a.opts, "-output_dir", a.outdir, "-quiet"] + a.extra.split(), check=True)


def load(outdir):
    with open(os.path.join(outdir, "flap.csv")) as f:
        header = f.readline()
        return header, np.genfromtxt(f, delimiter=",", names=True)


header, d = load(a.outdir)
height = float(header.split("height")[1].split("m")[0])
t, tip = d["t"], d["tip_dx"]
T = t[-1]
last, before = t >= 0.75 * T, (t >= 0.5 * T) & (t < 0.75 * T)
mean_last, mean_before = tip[last].mean(), tip[before].mean()
drift = abs(mean_last - mean_before) / abs(mean_last)
wander = np.ptp(tip[last]) / abs(mean_last)
cross = int(d["crossings"][-1])
slip = np.nanmean(d["slip"][last])
near = np.nanmean(d["near"][last])
umax = d["u_max"][last].mean()
print(f"tip deflection (mean over the last 25 %) {mean_last:.4g} m = {mean_last/height:.4f} of the flap height "
      f"(> {a.min_deflection}); drift of the mean from the quarter before {drift:.2%} (tolerance {a.drift:.1%}); "
      f"wander over the last 25 % {wander:.2%} (tolerance {a.steady:.1%}); crossings {cross} (must be 0); "
      f"slip on the faces |u(d=0) - v_flap|/u_max {slip:.4f} (tolerance {a.slip}; first fluid layer {near:.4f}); "
      f"u_max {umax:.4g} m/s")
if a.plot:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    q = np.genfromtxt(os.path.join(a.outdir, "flap-particles.csv"), delimiter=",", names=True)
    fig, ax = plt.subplots(figsize=(8, 5))
    sp = np.hypot(q["vx"], q["vy"])
    fl = q["type"] == 0
    sc = ax.scatter(q["x"][fl], q["y"][fl], c=sp[fl], s=6, cmap="viridis")
    ax.quiver(q["x"][fl], q["y"][fl], q["vx"][fl], q["vy"][fl], scale=sp.max() * 40, width=0.0015)
    ax.scatter(q["x"][q["type"] == 1], q["y"][q["type"] == 1], c="grey", s=6)
    ax.scatter(q["x"][q["type"] == 2], q["y"][q["type"] == 2], c="red", s=10)
    fig.colorbar(sc, label="|v| [m/s]")
    ax.set_aspect("equal")
    ax.set_title(f"flap at t = {T:.3g} s: tip deflection {tip[-1]/height:.3f} of the height")
    fig.savefig(os.path.join(a.outdir, "flap.png"), dpi=120, bbox_inches="tight")
ok = drift <= a.drift and wander <= a.steady and mean_last > a.min_deflection * height and cross == 0 and slip <= a.slip
if a.reference:
    _, r = load(a.reference)
    rt, rtip = r["t"], r["tip_dx"]
    # rows are written at the first step past each output time: with another dt
    # the times differ by up to a step, so the reference is interpolated
    if abs(rt[-1] - T) > 0.01 * T:
        print(f"FAIL: {a.reference}/flap.csv ends at t = {rt[-1]:g} s, this run at {T:g} s")
        sys.exit(1)
    rtip = np.interp(t, rt, rtip)
    ref_last = rtip[last].mean()
    diff = abs(mean_last - ref_last) / abs(ref_last)
    print(f"against {a.reference}: mean tip deflection {mean_last:.6g} m vs {ref_last:.6g} m, {diff:.3%} apart "
          f"(tolerance {a.tip_tol:.1%}); largest difference at any time {np.max(np.abs(tip - rtip)) / abs(ref_last):.3%}")
    ok = ok and diff <= a.tip_tol
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
