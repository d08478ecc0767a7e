#!/usr/bin/python3
"""Flap check: run dmhs on an options file, then from flap.csv require
 * a steady deflection: over the last 20 % of the run the tip x-displacement
   stays within --steady (relative) of its final value, and it is > 1 % of the height;
 * zero fluid crossings of the flap;
 * near-surface relative speed |v_f - v_flap|/u_max below --slip.
Writes flap.png (settled flow) next to the CSV when --plot is given."""
import argparse, os, subprocess, sys
import numpy as np

p = argparse.ArgumentParser()
p.add_argument("--exe", required=True)
p.add_argument("--opts", required=True)
p.add_argument("--outdir", required=True)
p.add_argument("--steady", type=float, default=0.02)
p.add_argument("--slip", type=float, default=0.25)
p.add_argument("--plot", action="store_true")
a = p.parse_args()
subprocess.run([a.exe, "-options_file", a.opts, "-output_dir", a.outdir, "-quiet"], check=True)
with open(os.path.join(a.outdir, "flap.csv")) as f:
    header = f.readline()
    d = np.genfromtxt(f, delimiter=",", names=True)
height = float(header.split("height")[1].split("m")[0])
t, tip = d["t"], d["tip_dx"]
tail = tip[t >= 0.8 * t[-1]]
spread = np.ptp(tail) / abs(tip[-1])
cross = int(d["crossings"][-1])
slip = d["slip"][t >= 0.8 * t[-1]].mean()
print(f"tip deflection {tip[-1]:.4g} m = {tip[-1]/height:.3f} of the flap height; variation over the last 20 %: "
      f"{spread:.2%} (tolerance {a.steady:.0%}); crossings {cross} (must be 0); near-surface |v_f - v_flap|/u_max "
      f"{slip:.3f} (tolerance {a.slip})")
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
    ax.set_title(f"flap at t = {t[-1]:g} s: tip deflection {tip[-1]/height:.2f} of the height")
    fig.savefig(os.path.join(a.outdir, "flap.png"), dpi=120, bbox_inches="tight")
ok = spread <= a.steady and tip[-1] > 0.01 * height and cross == 0 and slip <= a.slip
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
