#!/usr/bin/python3
"""Plots peristaltic_channel runs of dmhs against Shapiro, Jaffrin & Weinberg's
long-wavelength flux Q_theory = 2 a c 3 phi^2/(2 + phi^2).

  scripts/post/plot_peristaltic.py <output_dir> [<output_dir> ...] [--out PNG]

Reads each <output_dir>/flux.csv (cycle,t,Q_mean,Q_theory: one row per completed
wave period) and, for phi = b/a, <output_dir>/run.json (the last -peristaltic_a
and -peristaltic_b given; the scene's defaults 1e-3 and 0.5e-3 m otherwise), and
writes --out (default <first output_dir>/peristaltic_flux.png):
  left   Q_mean/Q_theory of each run's last period against phi, with the 5 % band
  right  Q_mean/Q_theory per period, one line per run
Prints one line per run. Exits non-zero when a flux.csv is missing, has the wrong
header, no row or a non-finite value, or when the PNG cannot be written.
"""
import argparse
import json
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HEADER = "cycle,t,Q_mean,Q_theory"


def read_flux(output_dir):
    path = os.path.join(output_dir, "flux.csv")
    try:
        with open(path) as f:
            lines = f.read().splitlines()
    except OSError as e:
        sys.exit(f"plot_peristaltic: cannot read {path}: {e.strerror}")
    if not lines or lines[0] != HEADER:
        sys.exit(f"plot_peristaltic: {path}: expected the header {HEADER!r}")
    try:
        rows = np.array([[float(c) for c in l.split(",")] for l in lines[1:]], ndmin=2)
    except ValueError:
        sys.exit(f"plot_peristaltic: {path}: a value is not a number")
    if rows.size == 0 or rows.shape[1] != 4:
        sys.exit(f"plot_peristaltic: {path}: no completed wave period")
    if not np.all(np.isfinite(rows)) or np.any(rows[:, 3] <= 0):
        sys.exit(f"plot_peristaltic: {path}: a non-finite value or Q_theory <= 0")
    return rows


def option(options, name, default):
    found = re.findall(r"-" + name + r"\s+(\S+)", options)
    try:
        return float(found[-1]) if found else default
    except ValueError:
        return default


def amplitude_ratio(output_dir):
    try:
        with open(os.path.join(output_dir, "run.json")) as f:
            options = json.load(f).get("options", "")
    except (OSError, ValueError):
        options = ""
    return option(options, "peristaltic_b", 0.5e-3) / option(options, "peristaltic_a", 1e-3)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("output_dirs", nargs="+")
    ap.add_argument("--out")
    a = ap.parse_args()
    out = a.out or os.path.join(a.output_dirs[0], "peristaltic_flux.png")
    runs = [(d, amplitude_ratio(d), read_flux(d)) for d in a.output_dirs]
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    phis = np.array([phi for _, phi, _ in runs])
    last = np.array([rows[-1, 2] / rows[-1, 3] for _, _, rows in runs])
    span = np.linspace(0, 1, 2)
    left.fill_between(span, 0.95, 1.05, color="0.9", label="5 %")
    left.axhline(1.0, color="k", lw=0.8, label="theory")
    left.plot(phis, last, "o", label="SPH, last period")
    left.set(xlim=(0, 1), xlabel=r"$\phi = b/a$", ylabel=r"$Q_{mean}/Q_{theory}$",
             title="Time-mean flux over a wave period")
    left.legend()
    for d, phi, rows in runs:
        right.plot(rows[:, 0], rows[:, 2] / rows[:, 3], "o-", label=f"phi = {phi:g}")
        print(f"{d}: phi = {phi:g}, period {int(rows[-1, 0])}: Q_mean/Q_theory = "
              f"{rows[-1, 2] / rows[-1, 3]:.4f}")
    right.axhline(1.0, color="k", lw=0.8)
    right.set(xlabel="wave period", ylabel=r"$Q_{mean}/Q_{theory}$", title="Per period")
    right.xaxis.get_major_locator().set_params(integer=True)
    right.legend()
    fig.tight_layout()
    try:
        fig.savefig(out, dpi=120)
    except OSError as e:
        sys.exit(f"plot_peristaltic: cannot write {out}: {e.strerror}")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
