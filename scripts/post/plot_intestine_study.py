#!/usr/bin/python3
"""The colon study across runs (the thesis's Fig. 3.9), from every run
directory's intestine-summary.csv (written by dmhs at the end of a run):

  plot_intestine_study.py DIR [DIR ...] [--out OUTDIR]

writes
  OUTDIR/colon-study.csv  one row per usable run: run, L [m], nu [m^2/s],
                          V_w, u_F, u_P, u_S [m/s], alpha_T [1],
                          Re = b u_F/nu, Re_P = b u_P/nu, Ga, Fr, Lambda,
                          rho_dev_max, mach_max [1], through_max [particles],
                          then u_F_from_initial (1: u_F is the initial
                          slope), u_F_line_r2 (the whole-run line's R^2),
                          u_F_first_wave [m/s], alpha_end [1] (at the last
                          whole wave's end), waves
                          ("n/a" where the run's summary has n/a)
  OUTDIR/colon-study.png  (a) Re against Re_P, log-log, with the line
                          Re = Re_P (u_F ~ u_P for Re > 1, u_F < u_P for
                          Re < 1), coloured by level; (b) u_F against u_P;
                          (c) alpha after one period against V_w
OUTDIR defaults to the common parent directory of the DIRs (for
output/colon-study/L*_nu*_Vw* that is output/colon-study); it is never the
repository's doc/ by default (give --out for that).

Every measure is the solver's, read from the summary (u_F, Re and Re_P as
doc/theory.md defines them); Re and Re_P are n/a for a front or a pouring
estimate that did not advance, and such a run is left out of (a) only. A run
whose alpha_T, u_P or u_F is n/a (it ended before one wave period, or no front
was measured) is skipped with a warning naming it and the summary's reason. A
missing or malformed summary, or one without these keys (written by an older
dmhs), is an error naming the file (exit status 1), and so is a set of
directories none of which is usable.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import intestine_common as ic  # noqa: E402

PROG = "plot_intestine_study.py"
# keys every summary must have; those in FINITE must also be numbers (not n/a)
NEED = ("b", "level", "nu", "T_w", "V_w", "u_F", "alpha_T", "u_P", "u_S", "Re", "Re_P", "Ga", "Fr", "Lambda",
        "rho_dev_max", "mach_max", "through_max", "u_F_from_initial", "u_F_line_r2", "u_F_first_wave",
        "alpha_end", "waves")
FINITE = ("b", "level", "nu", "V_w")
USABLE = ("alpha_T", "u_P", "u_F")  # n/a here: the run is skipped
COLUMNS = ("run", "L", "nu", "V_w", "u_F", "u_P", "u_S", "alpha_T", "Re", "Re_P", "Ga", "Fr", "Lambda",
           "rho_dev_max", "mach_max", "through_max", "u_F_from_initial", "u_F_line_r2", "u_F_first_wave",
           "alpha_end", "waves")


def die(msg):
    print(f"{PROG}: {msg}", file=sys.stderr)
    sys.exit(1)


def warn(msg):
    print(f"{PROG}: warning: {msg}", file=sys.stderr)


def read_summary(path, notes):
    """key -> float (n/a -> NaN), the notes into `notes`; dies naming the file when missing or
    malformed."""
    out = ic.read_summary(path, PROG, NEED, FINITE, notes=notes)
    if out["nu"] <= 0 or out["b"] <= 0:
        die(f"{path}: nu and b must be > 0")
    return out


def default_out(dirs):
    parents = [os.path.dirname(os.path.abspath(d.rstrip("/") or "/")) for d in dirs]
    out = os.path.commonpath(parents)
    doc = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "doc")
    if out == doc or out.startswith(doc + os.sep):
        die(f"the runs' common parent {out} lies in the repository's doc/: give --out")
    return out


def cell(v):
    if isinstance(v, str):
        return v
    return "n/a" if math.isnan(v) else f"{v:.8g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dirs", metavar="DIR", nargs="+", help="output directories of intestine runs")
    ap.add_argument("--out", metavar="OUTDIR", default=None,
                    help="directory of colon-study.csv and colon-study.png (default: the DIRs' common parent)")
    a = ap.parse_args()
    runs = []
    for d in a.dirs:
        path = os.path.join(d, "intestine-summary.csv")
        notes = {}
        s = read_summary(path, notes)
        bad = [k for k in USABLE if math.isnan(s[k])]
        if bad:
            warn(f"{path}: " + ", ".join(f"{k} n/a ({notes[k]})" if notes.get(k) else f"{k} n/a" for k in bad)
                 + ": skipped")
            continue
        s["run"] = d.rstrip("/")
        s["L"] = s["level"]
        runs.append(s)
    if not runs:
        die(f"none of the {len(a.dirs)} run(s) is usable (every one skipped)")
    out = a.out if a.out is not None else default_out(a.dirs)
    os.makedirs(out, exist_ok=True)
    runs.sort(key=lambda r: (r["L"], r["nu"], r["V_w"], r["run"]))

    csv_path = os.path.join(out, "colon-study.csv")
    with open(csv_path + ".tmp", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(COLUMNS)
        for r in runs:
            w.writerow([cell(r[c]) for c in COLUMNS])
    os.replace(csv_path + ".tmp", csv_path)

    levels = sorted({r["L"] for r in runs})
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(levels)))
    colour = {L: c for L, c in zip(levels, colours)}
    fig, ax = plt.subplots(1, 3, figsize=(16, 5))
    # (a) Re against Re_P: the points with both > 0 on the log-log axes
    x = ax[0]
    pos = [r for r in runs if math.isfinite(r["Re"]) and math.isfinite(r["Re_P"])]
    for L in levels:
        sel = [r for r in pos if r["L"] == L]
        if sel:
            x.loglog([r["Re_P"] for r in sel], [r["Re"] for r in sel], "o", color=colour[L],
                     label=f"L = {L * 1e3:g} mm")
    if pos:
        lo = min(min(r["Re"], r["Re_P"]) for r in pos) / 2
        hi = max(max(r["Re"], r["Re_P"]) for r in pos) * 2
        x.loglog([lo, hi], [lo, hi], "k--", lw=1, label="Re = Re_P")
        x.set_xlim(lo, hi)
        x.set_ylim(lo, hi)
        x.legend(fontsize=8)
    else:
        x.set_xscale("log")
        x.set_yscale("log")
    n_off = len(runs) - len(pos)
    x.set_xlabel("Re_P = b u_P / nu [1]")
    x.set_ylabel("Re = b u_F / nu [1]")
    x.set_title("Re against Re_P (Fig. 3.9)" + (f"; {n_off} run(s) with Re or Re_P n/a not drawn" if n_off else ""),
                fontsize=10)
    x.grid(True, which="both", alpha=0.3)
    # (b) u_F against u_P
    x = ax[1]
    for L in levels:
        sel = [r for r in runs if r["L"] == L]
        x.plot([r["u_P"] * 100 for r in sel], [r["u_F"] * 100 for r in sel], "o", color=colour[L],
               label=f"L = {L * 1e3:g} mm")
    lo = min(min(r["u_F"], r["u_P"]) for r in runs) * 100
    hi = max(max(r["u_F"], r["u_P"]) for r in runs) * 100
    lo = min(lo, 0.0)
    hi = hi if hi > lo else lo + 1
    x.plot([lo, hi], [lo, hi], "k--", lw=1, label="u_F = u_P")
    x.set_xlabel("u_P = alpha/(1 - alpha) V_w/(N+1) [cm/s]")
    x.set_ylabel("u_F (least squares over the whole waves, or initial slope) [cm/s]", fontsize=8)
    x.set_title("Front velocity against the pumping velocity", fontsize=10)
    x.legend(fontsize=8)
    x.grid(True, alpha=0.3)
    # (c) alpha against V_w, one line per (L, nu)
    x = ax[2]
    markers = "osd^v<>ph*"
    nus = sorted({r["nu"] for r in runs})
    for L in levels:
        for k, nu in enumerate(nus):
            sel = sorted((r for r in runs if r["L"] == L and r["nu"] == nu), key=lambda r: r["V_w"])
            if sel:
                x.plot([r["V_w"] * 100 for r in sel], [r["alpha_T"] for r in sel], "-", marker=markers[k % 10],
                       color=colour[L], lw=0.8, label=f"L = {L * 1e3:g} mm, nu = {nu:g} m²/s")
    speeds = sorted({r["V_w"] * 100 for r in runs})
    if len(speeds) > 1:
        x.set_xscale("log")
    if len(speeds) <= 8:  # the study's grid: a tick at every wave speed
        x.set_xticks(speeds)
        x.set_xticklabels([f"{v:.3g}" for v in speeds])
        x.minorticks_off()
    x.set_xlabel("V_w = (N+1) b / T_w [cm/s]")
    x.set_ylabel("alpha after one period [1]")
    x.set_title("Fraction of the white set out of pocket 0", fontsize=10)
    x.legend(fontsize=6, ncol=2 if len(levels) * len(nus) > 8 else 1)
    x.grid(True, which="both", alpha=0.3)
    fig.suptitle(f"Colon study: {len(runs)} run(s), levels {', '.join(f'{L * 1e3:g}' for L in levels)} mm, "
                 f"nu {', '.join(f'{nu:g}' for nu in nus)} m²/s")
    png = os.path.join(out, "colon-study.png")
    ic.save_png(fig, png)
    print(f"{PROG}: {len(runs)} run(s) of {len(a.dirs)}: wrote {csv_path} and {png}")


if __name__ == "__main__":
    main()
