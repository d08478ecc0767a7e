#!/usr/bin/python3
"""Plots a Poiseuille or Couette run of dmhs against the series solution.

  scripts/post/plot_channel.py <output_dir> [--out DIR]

Reads <output_dir>/profile_t*.csv (y,vx,vx_exact per fluid particle, written
at the report times) and <output_dir>/error.csv (step,t,wall_s,l2,linf), and
writes into --out (default: the output directory):
  profiles.png   v_x(y): SPH (mean over each particle row) and the series
  error.png      normalised L2 and Linf error against t, and wall-clock on a second axis
Prints the table of errors at the report times.
"""
import argparse
import csv
import glob
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
    data = np.loadtxt(path, delimiter=",", skiprows=2, ndmin=2)
    return float(m.group(1)), float(m.group(2)), data


def row_means(data, decimals=10):
    """Averages v over particles that share a lattice row (same y up to round-off)."""
    y = np.round(data[:, 0], decimals)
    rows = np.unique(y)
    return rows, np.array([data[y == r, 1].mean() for r in rows])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output_dir")
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    out = args.out or args.output_dir
    os.makedirs(out, exist_ok=True)

    with open(os.path.join(args.output_dir, "error.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    t_last = max(float(r["t"]) for r in rows) if rows else 0.0
    # a profile later than the run's last row is left over from an earlier run
    profiles = sorted(p for p in glob.glob(os.path.join(args.output_dir, "profile_t*.csv"))
                      if read_profile(p)[0] <= t_last * (1 + 1e-9))
    if not profiles:
        sys.exit(f"plot_channel: no profile_t*.csv in {args.output_dir}")
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for path in profiles:
        t, v_ref, data = read_profile(path)
        order = np.argsort(data[:, 0])
        y_rows, v_rows = row_means(data)
        (line,) = ax.plot(data[order, 2] / v_ref, data[order, 0] * 1e3, "-", lw=1)
        ax.plot(v_rows / v_ref, y_rows * 1e3, "o", ms=3, mfc="none", color=line.get_color(), label=f"t = {t:g} s")
    ax.set_xlabel("v_x / v_ref")
    ax.set_ylabel("y [mm]")
    ax.set_title("dmhs SPH (circles) against the series solution (lines)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profiles.png"), dpi=120)

    t = np.array([float(r["t"]) for r in rows])
    l2 = np.array([float(r["l2"]) for r in rows])
    linf = np.array([float(r["linf"]) for r in rows])
    wall = np.array([float(r["wall_s"]) for r in rows])
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.semilogy(t, 100 * l2, label="L2 (RMS)")
    ax.semilogy(t, 100 * linf, label="Linf")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("error / v_ref [%]")
    ax2 = ax.twinx()
    ax2.plot(t, wall, "k:", label="wall-clock")
    ax2.set_ylabel("wall-clock [s] (dotted)")
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error.png"), dpi=120)

    print(f"{'t [s]':>10} {'L2 [%]':>10} {'Linf [%]':>10} {'wall [s]':>10}")
    for path in profiles:
        tp, _, _ = read_profile(path)
        k = int(np.argmin(abs(t - tp)))
        print(f"{t[k]:10.4g} {100 * l2[k]:10.4f} {100 * linf[k]:10.4f} {wall[k]:10.3f}")
    print(f"plots: {os.path.join(out, 'profiles.png')}, {os.path.join(out, 'error.png')}")


if __name__ == "__main__":
    main()
