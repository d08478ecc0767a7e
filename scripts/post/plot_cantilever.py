#!/usr/bin/python3
"""Tip deflection of a cantilever run against beam theory.

  scripts/post/plot_cantilever.py OUTDIR [--out PNG]

Reads OUTDIR/cantilever.csv (t, tip_dx, tip_dy [m], kinetic, potential [J];
the '# key = value' header gives L, EI, kGA, mu, the particle mass, the tip
load F [N] and the damping rate gamma [1/s]) and compares the tip deflection
w = -tip_dy with the beam theory of doc/theory.md ("Mass-spring leaflets as
Timoshenko beams"), the same formulas test/validation/cantilever.py checks:
  static    w = F L^3/(3 EI) + F L/(kGA) (Timoshenko); F L^3/(3 EI) (Euler-Bernoulli)
  frequency 1/w1^2 = 1/wb^2 + 1/ws^2, wb = 1.8751^2 sqrt(EI/(mu L^4)),
            ws = (pi/2) sqrt(kGA/(mu L^2)), with the lattice's lumped tip mass m:
            w1 / sqrt(1 + m/(0.2427 mu L))
  damping   every underdamped mode decays as exp(-gamma t/2); the first one
            oscillates at sqrt(w1^2 - gamma^2/4)
Writes cantilever.png (default: into OUTDIR): the tip deflection against t
with the static deflections, and its distance from the Timoshenko value on a
log scale with the decay envelope (damped run) or the oscillation against the
beam-theory period (undamped run). Prints the measured and predicted values.
Exits non-zero when the CSV is missing, has no rows or lacks a constant.
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

NEED = ("L", "EI", "kGA", "mu", "mass", "F")


def fail(msg):
    sys.exit(f"plot_cantilever: {msg}")


def read(path):
    """The '# key = value' constants and the data rows of cantilever.csv."""
    consts, rows = {}, []
    try:
        with open(path) as f:
            for line in f:
                if line.startswith("#"):
                    key, eq, value = line[1:].partition("=")
                    if eq:
                        try:
                            consts[key.strip()] = float(value)
                        except ValueError:
                            pass
                else:
                    rows.append(line)
    except OSError as e:
        fail(f"cannot read {path}: {e.strerror}")
    missing = [k for k in NEED if k not in consts]
    if missing:
        fail(f"{path}: header lacks {', '.join(missing)}")
    if len(rows) < 3:
        fail(f"{path}: {max(len(rows) - 1, 0)} data rows, need at least 2")
    data = np.genfromtxt(rows, delimiter=",", names=True)
    for k in ("t", "tip_dy"):
        if k not in data.dtype.names:
            fail(f"{path}: no column {k}")
    if not np.all(np.isfinite(data["tip_dy"])):
        fail(f"{path}: tip_dy has non-finite values")
    return consts, data


def up_crossings(t, x):
    """Times at which x crosses 0 upwards (linear interpolation between samples)."""
    return np.array([t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
                     for i in range(len(x) - 1) if x[i] < 0 <= x[i + 1]])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--out", help="PNG to write (default: OUTDIR/cantilever.png)")
    a = ap.parse_args()
    if not os.path.isdir(a.outdir):
        fail(f"{a.outdir}: no such output directory")
    c, d = read(os.path.join(a.outdir, "cantilever.csv"))
    L, EI, kGA, mu, m, F = (c[k] for k in NEED)
    gamma = c.get("gamma", 0.0)
    t, w = d["t"], -d["tip_dy"]

    bend, shear = L**3 / (3 * EI), L / kGA
    w_timo, w_eb = F * (bend + shear), F * bend
    wb = 1.8751**2 * math.sqrt(EI / (mu * L**4))
    ws = 0.5 * math.pi * math.sqrt(kGA / (mu * L**2))
    w1 = 1 / math.sqrt(1 / wb**2 + 1 / ws**2) / math.sqrt(1 + m / (0.2427 * mu * L))
    wd = math.sqrt(w1**2 - 0.25 * gamma**2) if gamma < 2 * w1 else 0.0

    # oscillation: about the last value when damped (it settles there), else about the mean
    ref = w[-1] if gamma > 0 else w.mean()
    # (damped: only while the envelope is above 1e-3, before round-off and the
    # output sampling decide the crossings)
    live = t < 2 * math.log(1e3) / gamma if gamma > 0 else np.ones_like(t, dtype=bool)
    up = up_crossings(t[live], (w - ref)[live])
    periods = np.diff(up)
    w_meas = 2 * math.pi / periods.mean() if len(periods) else float("nan")
    w_pred = wd if gamma > 0 else w1
    # the static deflection the run found: where a damped run settles, or the mean
    # over whole periods of an undamped step response
    if gamma > 0:
        w_stat, what = w[-1], f"last row (t = {t[-1]:.4g} s)"
    else:
        whole = (t >= up[0]) & (t <= up[-1]) if len(up) >= 2 else np.ones_like(t, dtype=bool)
        w_stat, what = w[whole].mean(), "mean over whole periods"
    err = (w_stat - w_timo) / w_timo

    print(f"cantilever: L = {L:g} m, EI = {EI:.4g} N m^2, kGA = {kGA:.4g} N, F = {F:.4g} N, "
          f"gamma = {gamma:.4g} 1/s")
    print(f"static tip deflection: Timoshenko {w_timo:.6g} m (shear share {shear / (bend + shear):.1%}), "
          f"Euler-Bernoulli {w_eb:.6g} m; {what} {w_stat:.6g} m ({err:+.3%} from Timoshenko)")
    if len(periods):
        print(f"oscillation: {2 * math.pi / w_meas:.4g} s period over {len(periods)} period(s) "
              f"({w_meas:.5g} rad/s); beam theory {w_pred:.5g} rad/s ({(w_meas - w_pred) / w_pred:+.2%})")

    ms, um = 1e3, 1e6
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    ax = axes[0]
    ax.plot(t * ms, w * um, "k-", lw=1.2, label="dmhs: tip deflection $-\\Delta y$")
    ax.axhline(w_timo * um, color="C0", ls="--", label=f"Timoshenko F L³/3EI + F L/kGA = {w_timo * um:.4g} µm")
    ax.axhline(w_eb * um, color="C1", ls=":", label=f"Euler-Bernoulli F L³/3EI = {w_eb * um:.4g} µm")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("tip deflection [µm]")
    ax.set_title(f"{what}: {err:+.2%} from Timoshenko", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="best")

    ax = axes[1]
    if gamma > 0:
        dev = np.abs(w - w_timo) / w_timo
        ax.semilogy(t * ms, np.maximum(dev, 1e-12), "k-", lw=1, label="dmhs: |w - w_Timoshenko| / w_Timoshenko")
        ax.semilogy(t * ms, np.exp(-0.5 * gamma * t), "C2--", label=f"envelope exp(-γt/2), γ = {gamma:.4g} 1/s")
        ax.set_ylabel("relative distance from the static deflection [1]")
        ax.set_ylim(max(dev[dev > 0].min() if np.any(dev > 0) else 1e-12, 1e-12) / 2, 2)
        title = "decay to the static deflection"
    else:
        ax.plot(t * ms, (w - ref) * um, "k-", lw=1, label="dmhs: w - mean")
        amp = np.max(np.abs(w - ref))
        ax.plot(t * ms, amp * np.sin(w1 * (t - up[0]) if len(up) else w1 * t) * um, "C0--", lw=1,
                label=f"period 2π/ω1 of beam theory, ω1 = {w1:.5g} rad/s")
        ax.set_ylabel("tip deflection about its mean [µm]")
        title = "free oscillation"
    if len(periods):
        title += f": measured {w_meas:.5g} rad/s, theory {w_pred:.5g} rad/s"
    ax.set_title(title, fontsize=10)
    ax.set_xlabel("t [ms]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
    fig.suptitle(f"cantilever: L = {L * 1e3:.3g} mm, EI = {EI:.3g} N m², kGA = {kGA:.3g} N, "
                 f"tip load F = {F:.3g} N, damping γ = {gamma:.4g} 1/s (per unit depth)", fontsize=11)
    fig.tight_layout()
    out = a.out or os.path.join(a.outdir, "cantilever.png")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
