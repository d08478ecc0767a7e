#!/usr/bin/python3
"""Plots and tables of an intestine (colon) run, from <outdir>/intestine.csv
and <outdir>/intestine-summary.csv (written by dmhs at the end of the run):

  <outdir>/intestine.png          x_F(t) with the least-squares line over the
                                  whole waves, the initial slope and the
                                  front's first advance (u_F is the one the
                                  summary chose); alpha(t) with alpha after one
                                  period and at the last whole wave's end; the
                                  segments' lifts as a map over time and
                                  pocket; N/N0 per pocket after waves; the
                                  liquid's density deviation and Mach number
  <outdir>/intestine-pockets.csv  tracked (white, and red if tracked) count per
                                  pocket after every completed wave, N/N0

Usage: plot_intestine.py OUTDIR [--waves 5,7]
--waves: the waves whose N/N0 profile is drawn (default 5,7 as in the PET
comparison; waves the run did not complete are left out, and the last
completed wave, or the end of the run, is drawn when none of them is).
Exits non-zero, naming the file, when an input is missing, empty or not finite.
The measures (u_F, alpha, u_P, u_S, Re) are read from the summary as the
solver defines them (doc/theory.md, "Peristalsis and tracking"); an n/a value
is shown as n/a with the summary's reason.
"""
import argparse
import math
import os
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import intestine_common as ic  # noqa: E402


PROG = "plot_intestine.py"


def die(msg):
    ic.die(PROG, msg)


def read_summary(path, notes):
    return ic.read_summary(path, PROG, need=("u_F", "alpha_T", "u_P", "u_S", "Re"),
                           finite=("V_w", "T_w", "b", "nu"), notes=notes)


def finite(s, k):
    return math.isfinite(s.get(k, float("nan")))


def short(why):
    """A reason's head ('no whole wave: the rows end at ...' -> 'no whole wave')."""
    return why.split(":")[0]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("outdir")
    ap.add_argument("--waves", default="5,7")
    a = ap.parse_args()
    series = os.path.join(a.outdir, "intestine.csv")
    d, names = ic.read_series(series, PROG)
    notes = {}
    s = read_summary(os.path.join(a.outdir, "intestine-summary.csv"), notes)
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
    x.plot(t, d["x_F"] * 100, "k-", lw=1.0, label="x_F (mean x of the white set)")
    t_d = s.get("t_d", t0)
    chosen = "initial" if s.get("u_F_from_initial", 0) == 1 else "line"
    for key, style, what in (("line", "r--", "whole waves"), ("initial", "m-.", "initial slope")):
        k, t1 = f"u_F_{key}", s.get(f"u_F_{key}_t1", float("nan"))
        if not (finite(s, k) and finite(s, f"{k}_x0") and math.isfinite(t1)):
            continue
        if key == "initial" and t1 >= s.get("u_F_line_t1", float("nan")) - 1e-9:
            continue  # the same window as the line
        tt = np.array([t_d, t1])
        x.plot(tt, (s[f"{k}_x0"] + s[k] * (tt - t_d)) * 100, style, lw=1.6,
               label=f"least squares, {what}: {s[k] * 100:.3g} cm/s, R² {s[f'{k}_r2']:.3g}"
                     + (" = u_F" if finite(s, "u_F") and key == chosen else ""))
    if finite(s, "u_F_squeeze"):
        sq = np.where(d["s_0"] > 0)[0]
        # the first contiguous squeeze only, the rows the solver's slope was fitted to
        # (pocket 0 squeezes again in every later wave)
        gaps = np.where(np.diff(sq) > 1)[0]
        sq = sq[:gaps[0] + 1] if len(gaps) else sq
        if len(sq) > 1:
            ts, xs = t[sq[0]:sq[-1] + 1], d["x_F"][sq[0]:sq[-1] + 1]
            x.plot(ts, (xs.mean() + s["u_F_squeeze"] * (ts - ts.mean())) * 100, "b:", lw=2,
                   label=f"first advance (pocket 0 squeezes): {s['u_F_squeeze'] * 100:.3g} cm/s")
    x.set_xlabel("t [s]")
    x.set_ylabel("x_F [cm]")
    x.set_title("Front penetration (Fig. 3.5)" + ("" if finite(s, "u_F") else
                                                  f"\nu_F n/a: {short(notes.get('u_F', ''))}"), fontsize=10)
    x.legend(fontsize=7)
    # alpha
    x = ax[0, 1]
    x.plot(t, d["alpha"], "k-", lw=1.0)
    if finite(s, "alpha_T"):
        x.axvline(s["alpha_T_t"], color="grey", ls=":")
        pump = (f"u_P = {s['u_P'] * 100:.3g} cm/s" if finite(s, "u_P") else f"u_P n/a ({notes.get('u_P', '')})")
        x.plot([s["alpha_T_t"]], [s["alpha_T"]], "ro",
               label=f"alpha after one period = {s['alpha_T']:.3g}\n{pump}, u_S = {s['u_S'] * 100:.3g} cm/s")
    if finite(s, "alpha_end") and s.get("waves", 0) > 1:
        x.plot([s["alpha_end_t"]], [s["alpha_end"]], "bs",
               label=f"alpha at the end of wave {int(s['waves'])} = {s['alpha_end']:.3g}")
    if x.get_legend_handles_labels()[0]:
        x.legend(fontsize=8)
    x.set_xlabel("t [s]")
    x.set_ylabel("alpha [1]")
    x.set_title("Fraction of the white set out of pocket 0" + ("" if finite(s, "alpha_T") else
                f"\nalpha after one period n/a: {short(notes.get('alpha_T', ''))}"), fontsize=10)
    # lifts: a map over time and pocket (one trace per pocket would overlay into a block)
    x = ax[0, 2]
    lift = np.stack([d[f"lift_{k}"] for k in range(n_pockets)], axis=0) * 1000
    vmax = max(float(np.abs(lift).max()), 1e-6)
    edges_t = np.concatenate([[t[0]], 0.5 * (t[1:] + t[:-1]), [t[-1]]])
    im = x.pcolormesh(edges_t, np.arange(n_pockets + 1) - 0.5, lift, cmap="RdBu_r", vmin=-vmax, vmax=vmax,
                      shading="flat", rasterized=True)
    fig.colorbar(im, ax=x, label="segment lift [mm]")
    x.set_yticks(range(n_pockets))
    x.set_xlabel("t [s]")
    x.set_ylabel("pocket")
    x.set_title("Membrane lift (middle third of each segment)", fontsize=10)
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
    units = {"V_w": " m/s", "u_F": " m/s", "u_F_line": " m/s", "u_F_initial": " m/s", "u_F_first_wave": " m/s",
             "u_F_squeeze": " m/s", "u_P": " m/s", "u_S": " m/s", "h": " m"}
    lines = []
    for k in ("V_w", "waves", "u_F", "u_F_line", "u_F_line_r2", "u_F_initial", "u_F_initial_r2", "u_F_first_wave",
              "u_F_squeeze", "alpha_T", "alpha_end", "u_P", "u_S", "Re", "Re_P", "Ga", "Fr", "Lambda", "h"):
        if k not in s:
            continue
        if math.isfinite(s[k]):
            lines.append(f"{k} = {s[k]:.4g}{units.get(k, '')}")
        else:  # the reason, cut to the panel's width
            why = notes.get(k, "")
            lines.append(f"{k}: n/a" + (f" ({why[:44]}{'...' if len(why) > 44 else ''})" if why else ""))
    if finite(s, "u_F"):
        lines += textwrap.wrap(f"u_F: {notes.get('u_F', '')}", 58)
    x.text(0.0, 1.0, "\n".join(lines), va="top", family="monospace", fontsize=7.5)
    fig.suptitle(f"Intestine: {n_pockets} pockets, b = {s['b'] * 100:g} cm, level {s.get('level', 0) * 100:.3g} cm, "
                 f"nu = {s['nu']:.3g} m^2/s, T_w = {Tw:.3g} s; {n_done} wave(s) completed")
    png = os.path.join(a.outdir, "intestine.png")
    ic.save_png(fig, png)
    print(f"wrote {png} and {os.path.join(a.outdir, 'intestine-pockets.csv')}")


if __name__ == "__main__":
    main()
