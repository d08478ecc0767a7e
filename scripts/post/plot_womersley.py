#!/usr/bin/python3
"""Plots a pulsatile poiseuille run of dmhs (-body_force_period T > 0) against the
Womersley start-up series.

  scripts/post/plot_womersley.py <output_dir> [--out DIR]

Reads <output_dir>/profile_t*.csv (y,vx,vx_exact per fluid particle at the report
times), <output_dir>/error.csv (step,t,wall_s,l2,linf) and, for the period T,
<output_dir>/run.json, and writes into --out (default: the output directory):
  womersley_profiles.png  v_x(y) at the report times, one panel per period: SPH (mean
                          over each particle row, circles) and the series (lines),
                          normalised by the steady-periodic centreline amplitude v_ref
  womersley_error.png     L2 and Linf error against t, with the drive sin(2 pi t/T)
Prints the table of errors at the report times. Exits non-zero when an input is
missing or unreadable.
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_profile(path):
    with open(path) as f:
        header = f.readline()
    m = re.search(r"t = ([0-9.eE+-]+) s, v_ref = ([0-9.eE+-]+)", header)
    if not m:
        sys.exit(f"plot_womersley: {path} has no '# t = ..., v_ref = ...' header")
    data = np.loadtxt(path, delimiter=",", skiprows=2, ndmin=2)
    return float(m.group(1)), float(m.group(2)), data


def row_means(data, decimals=10):
    """Averages v over particles that share a lattice row (same y up to round-off)."""
    y = np.round(data[:, 0], decimals)
    rows = np.unique(y)
    return rows, np.array([data[y == r, 1].mean() for r in rows]), np.array([data[y == r, 2][0] for r in rows])


def drive_period(output_dir):
    """T from the options recorded in run.json (the last -body_force_period given)."""
    try:
        with open(os.path.join(output_dir, "run.json")) as f:
            options = json.load(f).get("options", "")
    except (OSError, ValueError):
        return None
    found = re.findall(r"-body_force_period\s+(\S+)", options)
    try:
        period = float(found[-1]) if found else None
    except ValueError:
        return None
    return period if period and period > 0 else None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output_dir")
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    out = args.out or args.output_dir
    os.makedirs(out, exist_ok=True)

    with open(os.path.join(args.output_dir, "error.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_womersley: {args.output_dir}/error.csv has no rows")
    t = np.array([float(r["t"]) for r in rows])
    l2 = np.array([float(r["l2"]) for r in rows])
    linf = np.array([float(r["linf"]) for r in rows])
    wall = np.array([float(r["wall_s"]) for r in rows])
    if not (np.all(np.isfinite(l2)) and np.all(np.isfinite(linf))):
        sys.exit(f"plot_womersley: non-finite error in {args.output_dir}/error.csv")
    period = drive_period(args.output_dir)
    # a profile later than the run's last row is left over from an earlier run
    profiles = []
    for p in glob.glob(os.path.join(args.output_dir, "profile_t*.csv")):
        prof = read_profile(p)
        if prof[0] <= t.max() * (1 + 1e-9):
            profiles.append(prof)
    profiles.sort(key=lambda p: p[0])
    if not profiles:
        sys.exit(f"plot_womersley: no profile_t*.csv in {args.output_dir}")

    def label(tp):
        return f"t = {tp:g} s" + (f" ({tp / period:.3g} T)" if period else "")

    n_panels = 1
    if period:
        panel_of = [max(0, math.ceil(p[0] / period - 1e-6) - 1) for p in profiles]
        n_panels = max(panel_of) + 1
    else:
        panel_of = [0] * len(profiles)
    fig, axes = plt.subplots(1, n_panels, figsize=(4.2 * n_panels + 0.8, 5.2), sharey=True, squeeze=False)
    v_ref = profiles[0][1]
    for (tp, vr, data), k in zip(profiles, panel_of):
        ax = axes[0][k]
        y_rows, v_rows, v_exact = row_means(data)
        (line,) = ax.plot(v_exact / vr, y_rows * 1e3, "-", lw=1.2)
        ax.plot(v_rows / vr, y_rows * 1e3, "o", ms=3, mfc="none", color=line.get_color(), label=label(tp))
    for k, ax in enumerate(axes[0]):
        ax.axvline(0, color="0.8", lw=0.8, zorder=0)
        ax.set_xlabel("v_x / v_ref")
        if period and n_panels > 1:
            ax.set_title(f"period {k + 1}: {k * period:g} s < t <= {(k + 1) * period:g} s", fontsize=10)
        ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, frameon=False)
    axes[0][0].set_ylabel("y [mm]")
    fig.suptitle(f"dmhs SPH (circles) against the Womersley start-up series (lines), v_ref = {v_ref:.4g} m/s",
                 fontsize=10)
    fig.tight_layout()
    profiles_png = os.path.join(out, "womersley_profiles.png")
    fig.savefig(profiles_png, dpi=120)

    fig, ax = plt.subplots(figsize=(6.5, 4))
    ax.plot(t, 100 * l2, "o-", ms=3, label="L2 (RMS)")
    ax.plot(t, 100 * linf, "s-", ms=3, label="Linf")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("error / v_ref [%]")
    ax.set_ylim(bottom=0)
    if period:
        ax2 = ax.twinx()
        ts = np.linspace(0, t.max(), 400)
        ax2.plot(ts, np.sin(2 * np.pi * ts / period), "k:", lw=1, label="drive sin(2 pi t/T)")
        ax2.set_ylabel("drive sin(2 pi t/T) (dotted)")
        ax2.set_ylim(-1.1, 1.1)
    ax.legend(loc="upper right")
    ax.set_title(f"error against the series, normalised by v_ref = {v_ref:.4g} m/s", fontsize=10)
    fig.tight_layout()
    error_png = os.path.join(out, "womersley_error.png")
    fig.savefig(error_png, dpi=120)

    print(f"{'t [s]':>10} {'t/T':>6} {'L2 [%]':>10} {'Linf [%]':>10} {'wall [s]':>10}")
    for tp, _, _ in profiles:
        k = int(np.argmin(abs(t - tp)))
        phase = f"{t[k] / period:6.3f}" if period else f"{'':6}"
        print(f"{t[k]:10.4g} {phase} {100 * l2[k]:10.4f} {100 * linf[k]:10.4f} {wall[k]:10.3f}")
    for png in (profiles_png, error_png):
        if not os.path.getsize(png) > 0:
            sys.exit(f"plot_womersley: {png} is empty")
    print(f"plots: {profiles_png}, {error_png}")


if __name__ == "__main__":
    main()
