#!/usr/bin/python3
"""Plots and tables of an intestine (colon) run, from <outdir>/intestine.csv
and <outdir>/intestine-summary.csv (written by dmhs at the end of the run):

  <outdir>/intestine.png          x_F(t) with the least-squares u_F and the
                                  initial slope u_F0; alpha(t); the segments'
                                  lifts; N/N0 per pocket after waves; the
                                  liquid's density deviation and Mach number
  <outdir>/intestine-pockets.csv  tracked (white, and red if tracked) count per
                                  pocket after every completed wave, N/N0

Usage: plot_intestine.py OUTDIR [--waves 5,7]
--waves: the waves whose N/N0 profile is drawn (default 5,7 as in the PET
comparison; waves the run did not complete are left out, and the last
completed wave, or the end of the run, is drawn when none of them is).
Exits non-zero, naming the file, when an input is missing, empty or not finite.
"""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import intestine_common as ic  # noqa: E402


PROG = "plot_intestine.py"


def die(msg):
    ic.die(PROG, msg)


def read_summary(path):
    return ic.read_summary(path, PROG, finite=("u_F", "V_w", "T_w", "b", "nu"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("outdir")
    ap.add_argument("--waves", default="5,7")
    a = ap.parse_args()
    series = os.path.join(a.outdir, "intestine.csv")
    d, names = ic.read_series(series, PROG)
    s = read_summary(os.path.join(a.outdir, "intestine-summary.csv"))
    t = d["t"]
    n_pockets = sum(1 for n in names if n.startswith("lift_"))
    Tw = s["T_w"]
    t0, wave_rows = ic.wave_rows(d, Tw, PROG, series)
    n_done = len(wave_rows)
    sets = [("white", ic.pocket_counts(d, names, "white", n_pockets))]
    red = ic.pocket_counts(d, names, "red", n_pockets)
    if red is not None:
        sets.append(("red", red))

    tmp = os.path.join(a.outdir, "intestine-pockets.csv.tmp")
    with open(tmp, "w") as f:
        f.write("set,wave,t," + ",".join(f"N_{k}/N0" for k in range(n_pockets + 1)) + "\n")
        for name, c in sets:
            n0 = c[0].sum()
            if n0 <= 0:
                die(f"intestine.csv: the {name} set is empty")
            for n, i in enumerate(wave_rows, start=1):
                f.write(f"{name},{n},{t[i]:.6g}," + ",".join(f"{x / n0:.6g}" for x in c[i]) + "\n")
            f.write(f"{name},end,{t[-1]:.6g}," + ",".join(f"{x / n0:.6g}" for x in c[-1]) + "\n")
    os.replace(tmp, os.path.join(a.outdir, "intestine-pockets.csv"))

    fig, ax = plt.subplots(2, 3, figsize=(15, 8.5))
    # x_F
    x = ax[0, 0]
    x.plot(t, d["x_F"] * 100, "k-", lw=1.2, label="x_F (mean x of the white set)")
    first = (t >= t0) & (t <= t0 + Tw)
    tw = t[first]
    if len(tw) > 1:  # the fitted line passes through the rows' mean point
        tm, xm = tw.mean(), d["x_F"][first].mean()
        x.plot(tw, (xm + s["u_F"] * (tw - tm)) * 100, "r--",
               label=f"least squares, first wave: u_F = {s['u_F'] * 100:.3g} cm/s")
    if math.isfinite(s.get("u_F_initial", float("nan"))):
        sq = np.where(d["s_0"] > 0)[0]
        # the first contiguous squeeze only, the rows the solver's slope was fitted to
        # (pocket 0 squeezes again in every later wave)
        gaps = np.where(np.diff(sq) > 1)[0]
        sq = sq[:gaps[0] + 1] if len(gaps) else sq
        if len(sq) > 1:
            ts, xs = t[sq[0]:sq[-1] + 1], d["x_F"][sq[0]:sq[-1] + 1]
            x.plot(ts, (xs.mean() + s["u_F_initial"] * (ts - ts.mean())) * 100, "b:", lw=2,
                   label=f"initial slope (pocket 0 squeezes): {s['u_F_initial'] * 100:.3g} cm/s")
    x.set_xlabel("t [s]")
    x.set_ylabel("x_F [cm]")
    x.set_title("Front penetration (Fig. 3.5)")
    x.legend(fontsize=8)
    # alpha
    x = ax[0, 1]
    x.plot(t, d["alpha"], "k-")
    if math.isfinite(s.get("alpha_T", float("nan"))):
        x.axvline(t0 + Tw, color="grey", ls=":")
        x.plot([t0 + Tw], [s["alpha_T"]], "ro",
               label=f"alpha after one period = {s['alpha_T']:.3g}\nu_P = {s['u_P'] * 100:.3g} cm/s, "
                     f"u_S = {s['u_S'] * 100:.3g} cm/s")
        x.legend(fontsize=8)
    x.set_xlabel("t [s]")
    x.set_ylabel("alpha [1]")
    x.set_title("Fraction of the white set out of pocket 0")
    # lifts
    x = ax[0, 2]
    for k in range(n_pockets):
        x.plot(t, d[f"lift_{k}"] * 1000, lw=1, label=f"pocket {k}")
    x.set_xlabel("t [s]")
    x.set_ylabel("segment lift [mm]")
    x.set_title("Membrane lift (middle third of each segment)")
    x.legend(fontsize=7, ncol=2)
    # N/N0 per pocket
    x = ax[1, 0]
    want = [int(w) for w in a.waves.split(",") if w.strip()]
    shown = [w for w in want if w <= n_done] or ([n_done] if n_done >= 1 else [])
    kk = np.arange(n_pockets + 1)
    for name, c in sets:
        n0 = c[0].sum()
        for w in shown:
            x.plot(kk, c[wave_rows[w - 1]] / n0, "o-", label=f"{name}, after wave {w}")
        if not shown:
            x.plot(kk, c[-1] / n0, "o-", label=f"{name}, end of run (t = {t[-1]:.3g} s)")
    x.set_xticks(kk)
    x.set_xticklabels([str(k) for k in range(n_pockets)] + ["out"])
    x.set_xlabel("pocket")
    x.set_ylabel("N/N0 [1]")
    x.set_title("Tracked liquid per pocket (Fig. 3.4, simulation)", fontsize=10)
    x.legend(fontsize=8)
    # credibility
    x = ax[1, 1]
    x.plot(t, d["rho_dev"] * 100, "b-", label="max |rho/rho0 - 1| [%]")
    x.plot(t, d["mach"] * 100, "r-", label="max Mach x 100")
    x.axhline(3, color="b", ls=":", lw=0.8)
    x.axhline(10, color="r", ls=":", lw=0.8)
    x.set_xlabel("t [s]")
    x.set_ylabel("[%]")
    x.set_title(f"Liquid bounds; in / through the membrane: max {int(d['in_membrane'].max())} / "
                f"{int(d['through'].max())}", fontsize=10)
    x.legend(fontsize=8)
    # numbers
    x = ax[1, 2]
    x.axis("off")
    lines = [f"{k} = {s[k]:.4g}" if math.isfinite(s[k]) else f"{k}: n/a"
             for k in ("V_w", "u_F", "u_F_initial", "alpha_T", "u_P", "u_S", "Re", "Ga", "Fr", "Lambda", "h")
             if k in s]
    units = {"V_w": " m/s", "u_F": " m/s", "u_F_initial": " m/s", "u_P": " m/s", "u_S": " m/s", "h": " m"}
    lines = [l + (units.get(l.split()[0], "") if "n/a" not in l else "") for l in lines]
    x.text(0.02, 0.98, "\n".join(lines), va="top", family="monospace", fontsize=10)
    fig.suptitle(f"Intestine: {n_pockets} pockets, b = {s['b'] * 100:g} cm, level {s.get('level', 0) * 100:.3g} cm, "
                 f"nu = {s['nu']:.3g} m^2/s, T_w = {Tw:.3g} s; {n_done} wave(s) completed")
    png = os.path.join(a.outdir, "intestine.png")
    ic.save_png(fig, png)
    print(f"wrote {png} and {os.path.join(a.outdir, 'intestine-pockets.csv')}")


if __name__ == "__main__":
    main()
