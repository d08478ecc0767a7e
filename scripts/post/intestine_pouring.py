#!/usr/bin/python3
"""The pouring mode's distribution over the pockets (the thesis's Table 3.2) beside a run's own.

  scripts/post/intestine_pouring.py RUNDIR [--periods 3] [--haustrum-period S] [--alpha A]
                                    [--out PATH]

In the pouring mode a fraction alpha of the white set (the liquid that starts in
pocket 0) leaves pocket 0 while the wave squeezes it, and of what reaches a pocket
the same fraction goes on when the wave squeezes that one: pocket k holds
(1 - alpha) alpha^k n_P once the wave has passed it. alpha is the fraction that left
pocket 0 after one haustrum period, the time the wave takes to move on by one
pocket, t_H = 2 t_w: pocket k is squeezed from sub-period 2k + 1 (doc/theory.md), so
pocket 0 from t0 + t_w (t0: the wave's start, the first row of sub-period 0) and
pocket 1 from t0 + 3 t_w, by when the liquid pushed into pocket 1 but not poured has
flowed back. Period m ends at t0 + t_w + m t_H; --haustrum-period changes t_H.

Reads RUNDIR/intestine.csv (its '# intestine:' line: t_w, T_w, the pockets; the white
count per pocket in every row) and RUNDIR/intestine-summary.csv (alpha_T: the same
fraction after a whole wave T_w, the solver's alpha). For each haustrum period
m = 1 .. --periods: the row nearest its end, the white set's share in each of the
first four pockets (the last column "out": over the weir, when the run has fewer
pockets), and the model's (1 - alpha) alpha^k with alpha measured after one haustrum
period and, as a second row, with alpha_T; --alpha A adds the model at a given alpha
(the thesis's typical 0.1, say). Writes the table to
RUNDIR/intestine-pouring.csv (or --out) and prints it as markdown. A period beyond the
run's rows is n/a, not extrapolated."""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import intestine_common as ic  # noqa: E402

PROG = "intestine_pouring.py"
N_SHOWN = 4  # the thesis's table: the first four pockets


def fmt(x, digits=4):
    return "n/a" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:.{digits}g}"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("rundir")
    p.add_argument("--periods", type=int, default=3, help="haustrum periods after the wave's start (3)")
    p.add_argument("--haustrum-period", type=float, default=None,
                   help="the haustrum period t_H [s] (default 2 t_w)")
    p.add_argument("--alpha", type=float, default=None,
                   help="also the model at this alpha (e.g. the thesis's typical 0.1)")
    p.add_argument("--out", default=None, help="CSV path (default RUNDIR/intestine-pouring.csv)")
    a = p.parse_args()
    if a.alpha is not None and not 0.0 <= a.alpha < 1.0:
        ic.die(PROG, f"--alpha {a.alpha}: not in [0, 1)")
    if a.periods < 1:
        ic.die(PROG, f"--periods {a.periods}: give at least 1")
    series = os.path.join(a.rundir, "intestine.csv")
    info = ic.read_comment(series, PROG)
    d, names = ic.read_series(series, PROG)
    summary = ic.read_summary(os.path.join(a.rundir, "intestine-summary.csv"), PROG, need=("alpha_T",))
    n_pockets = int(info["pockets"])
    counts = ic.pocket_counts(d, names, "white", n_pockets)
    if counts is None:
        ic.die(PROG, f"{series}: no white_0 .. white_{n_pockets} columns (the run tracked no white set)")
    t_H = a.haustrum_period if a.haustrum_period is not None else 2.0 * info["t_w"]
    if not (t_H > 0 and math.isfinite(t_H)):
        ic.die(PROG, f"--haustrum-period {t_H}: not a positive time")
    t = d["t"]
    t0, _ = ic.wave_rows(d, info["T_w"], PROG, series)
    first = int(np.argmin(np.abs(t - t0)))
    n_P = float(counts[first].sum())
    if n_P <= 0 or counts[first, 0] != n_P:
        ic.die(PROG, f"{series}: at the wave's start (t = {t0:g} s) the white set is not all in pocket 0")
    n_cols = min(N_SHOWN, counts.shape[1])
    labels = [f"pocket {k}" if k < n_pockets else "out" for k in range(n_cols)]
    tol = 0.5 * float(np.median(np.diff(t))) if len(t) > 1 else 0.0

    def share_at(time):
        """(row time, shares of the first n_cols columns), or None beyond the rows."""
        if time > t[-1] + tol:
            return None
        i = int(np.argmin(np.abs(t - time)))
        return t[i], counts[i, :n_cols] / n_P

    rows = []
    for m in range(1, a.periods + 1):
        got = share_at(t0 + info["t_w"] + m * t_H)
        rows.append((m, got))
    if rows[0][1] is None:
        ic.die(PROG, f"{series}: the rows end at t = {t[-1]:g} s, before one haustrum period "
                     f"(t0 + t_w + t_H = {t0 + info['t_w'] + t_H:g} s): alpha after one haustrum "
                     "period is not defined")
    alpha_H = 1.0 - rows[0][1][1][0]
    alpha_T = summary["alpha_T"]

    def model(alpha):
        if math.isnan(alpha):
            return [math.nan] * n_cols
        return [(1.0 - alpha) * alpha ** k for k in range(n_cols)]

    table = []  # (what, t, values)
    for m, got in rows:
        if got is None:
            table.append((f"run after {m} haustrum period(s)", math.nan, [math.nan] * n_cols))
        else:
            table.append((f"run after {m} haustrum period(s)", got[0] - t0, list(got[1])))
    table.append(("pouring model (1 - alpha) alpha^k with alpha after one haustrum period", math.nan,
                  model(alpha_H)))
    table.append(("pouring model (1 - alpha) alpha^k with alpha_T (after one wave)", math.nan,
                  model(alpha_T)))
    if a.alpha is not None:
        table.append((f"pouring model (1 - alpha) alpha^k with alpha = {a.alpha:g} (given)", math.nan,
                      model(a.alpha)))

    out = a.out or os.path.join(a.rundir, "intestine-pouring.csv")
    tmp = out + ".tmp"
    with open(tmp, "w") as f:
        f.write(f"# t_w {info['t_w']:g} s, T_w {info['T_w']:g} s, haustrum period {t_H:g} s, n_P {n_P:g}, "
                f"alpha after one haustrum period {alpha_H:.6g}, alpha_T {fmt(alpha_T, 6)}\n")
        f.write("what,t_minus_t0," + ",".join(f"N_{k}/n_P" for k in range(n_cols)) + "\n")
        for what, tt, v in table:
            f.write(f"{what},{fmt(tt, 6)}," + ",".join(fmt(x, 6) for x in v) + "\n")
    os.replace(tmp, out)

    print(f"{a.rundir}: t_w = {info['t_w']:g} s, haustrum period t_H = {t_H:g} s, T_w = {info['T_w']:g} s, "
          f"n_P = {n_P:g}; alpha after one haustrum period {alpha_H:.4g}, after one wave (alpha_T) {fmt(alpha_T)}")
    print("| | t - t0 [s] | " + " | ".join(labels) + " |")
    print("|---|---|" + "---|" * n_cols)
    for what, tt, v in table:
        print(f"| {what} | {fmt(tt)} | " + " | ".join(fmt(x) for x in v) + " |")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
