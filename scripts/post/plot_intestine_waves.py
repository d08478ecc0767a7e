#!/usr/bin/python3
"""The original wave against the new one (the thesis's Fig. 3.12), from two
colon runs that track a red set (`-intestine_red -intestine_red_pocket P`)
and differ in their wave (`-peristalsis_h 2` and `5`):

  plot_intestine_waves.py OLD_DIR NEW_DIR [--out OUTDIR]

writes
  OUTDIR/intestine-waves.csv  one row per run and completed wave (and one
                              "end" row per run): run, H, wave, t [s],
                              white_left (fraction of the white set out of
                              pocket 0), red_left (fraction of the red set
                              out of its pocket), red_left_count,
                              red_downstream, red_upstream (fractions past
                              and before the red pocket; "out" counts as
                              downstream)
  OUTDIR/intestine-waves.png  (a) the red set out of its pocket against t,
                              both runs, with the new/old ratio at the end;
                              (b) the white set out of pocket 0 against t;
                              (c) the red set's N/N0 per pocket at the end
OUTDIR defaults to NEW_DIR's parent directory.

Each run's H is read from its run.json (-peristalsis_h; 2 when absent). The
red pocket is where the whole red set sits in the first row. Exits non-zero,
naming the file, when a run's intestine.csv or intestine-summary.csv is
missing or malformed, when a run tracks no red set, or when the two runs'
red sets start in different pockets.
"""
import argparse
import json
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import intestine_common as ic  # noqa: E402

PROG = "plot_intestine_waves.py"


def wave_height(run_dir):
    """-peristalsis_h from the run's run.json (the last one given wins), 2 (the default) when the
    run gave none; None when there is no readable run.json."""
    path = os.path.join(run_dir, "run.json")
    try:
        with open(path) as f:
            opts = json.load(f).get("options", "")
    except (OSError, ValueError):
        return None
    found = re.findall(r"-peristalsis_h\s+(\d+)", opts)
    return int(found[-1]) if found else 2


def read_run(run_dir):
    series = os.path.join(run_dir, "intestine.csv")
    d, names = ic.read_series(series, PROG)
    s = ic.read_summary(os.path.join(run_dir, "intestine-summary.csv"), PROG, finite=("T_w",))
    n_pockets = sum(1 for n in names if n.startswith("lift_"))
    white = ic.pocket_counts(d, names, "white", n_pockets)
    red = ic.pocket_counts(d, names, "red", n_pockets)
    if white is None:
        ic.die(PROG, f"{series}: no white_* columns")
    if red is None:
        ic.die(PROG, f"{series}: no red_* columns (run it with -intestine_red)")
    n_red, n_white = red[0].sum(), white[0].sum()
    if n_red <= 0 or n_white <= 0:
        ic.die(PROG, f"{series}: an empty tracked set in the first row")
    pocket = int(np.argmax(red[0]))
    if red[0][pocket] != n_red:
        ic.die(PROG, f"{series}: the red set is not in one pocket in the first row")
    _, rows = ic.wave_rows(d, s["T_w"], PROG, series)
    return {
        "name": os.path.basename(os.path.normpath(run_dir)),
        "H": wave_height(run_dir),
        "t": d["t"],
        "pocket": pocket,
        "white": white / n_white,
        "red": red / n_red,
        "n_red": n_red,
        "rows": rows,
    }


def table_rows(r):
    p = r["pocket"]
    marks = [(str(n), i) for n, i in enumerate(r["rows"], start=1)] + [("end", len(r["t"]) - 1)]
    for wave, i in marks:
        red = r["red"][i]
        yield [r["name"], "n/a" if r["H"] is None else str(r["H"]), wave, f"{r['t'][i]:.6g}",
               f"{1 - r['white'][i][0]:.6g}", f"{1 - red[p]:.6g}",
               f"{round((1 - red[p]) * r['n_red'])}", f"{red[p + 1:].sum():.6g}",
               f"{red[:p].sum():.6g}"]


def label(r):
    return r["name"] if r["H"] is None else f"{r['name']} (H = {r['H']})"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("old_dir")
    ap.add_argument("new_dir")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    runs = [read_run(a.old_dir), read_run(a.new_dir)]
    if runs[0]["pocket"] != runs[1]["pocket"]:
        ic.die(PROG, f"the red sets start in pockets {runs[0]['pocket']} and {runs[1]['pocket']}")
    out = a.out or os.path.dirname(os.path.abspath(os.path.normpath(a.new_dir)))
    os.makedirs(out, exist_ok=True)

    csv_path = os.path.join(out, "intestine-waves.csv")
    with open(csv_path + ".tmp", "w") as f:
        f.write("run,H,wave,t,white_left,red_left,red_left_count,red_downstream,red_upstream\n")
        for r in runs:
            for row in table_rows(r):
                f.write(",".join(row) + "\n")
    os.replace(csv_path + ".tmp", csv_path)

    p = runs[0]["pocket"]
    left_end = [1 - r["red"][-1][p] for r in runs]
    ratio = left_end[1] / left_end[0] if left_end[0] > 0 else float("inf")
    fig, ax = plt.subplots(1, 3, figsize=(16, 4.8))
    for r, style in zip(runs, ("b-", "r-")):
        ax[0].plot(r["t"], 1 - r["red"][:, p], style, label=label(r))
        ax[1].plot(r["t"], 1 - r["white"][:, 0], style, label=label(r))
    ax[0].set_title(f"Red set (pocket {p}) out of its pocket; new/old at the end: {ratio:.3g}",
                    fontsize=10)
    ax[1].set_title("White set (pocket 0) out of pocket 0", fontsize=10)
    for x in ax[:2]:
        x.set_xlabel("t [s]")
        x.set_ylabel("fraction [1]")
        x.legend(fontsize=8)
    n = runs[0]["red"].shape[1]
    kk = np.arange(n)
    for j, r in enumerate(runs):
        ax[2].bar(kk + (j - 0.5) * 0.4, r["red"][-1], width=0.4,
                  label=f"{label(r)}, t = {r['t'][-1]:.3g} s")
    ax[2].set_xticks(kk)
    ax[2].set_xticklabels([str(k) for k in range(n - 1)] + ["out"])
    ax[2].set_xlabel("pocket")
    ax[2].set_ylabel("red N/N0 [1]")
    ax[2].set_title("Red set per pocket at the end (Fig. 3.12)", fontsize=10)
    ax[2].legend(fontsize=8)
    png = os.path.join(out, "intestine-waves.png")
    ic.save_png(fig, png)
    print(f"wrote {png} and {csv_path}")


if __name__ == "__main__":
    main()
