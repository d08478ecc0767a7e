#!/usr/bin/python3
"""scripts/post/intestine_pouring.py (the thesis's Table 3.2 beside a run's pocket counts)
on a made-up run whose counts are known, on rows that end too soon, and on the quick run.

  intestine_pouring.py --script intestine_pouring.py --work DIR [--quick DIR]"""
import argparse
import csv
import math
import os
import subprocess
import sys


def fail(msg):
    print(f"FAIL: {msg}", file=sys.stderr)
    sys.exit(1)


def made_up(d, t_end, alpha_T="0.3"):
    """3 pockets, t_w 0.5 s (t_H 1 s: period m ends at t = 0.5 + m), T_w 4.5 s; the white
    set of 100 all in pocket 0 at t = 0, then the counts of `steps` from each whole second on."""
    os.makedirs(d, exist_ok=True)
    steps = {0: (100, 0, 0, 0), 1: (80, 16, 3, 1), 2: (70, 20, 7, 3), 3: (64, 22, 9, 5),
             4: (60, 23, 10, 7), 5: (58, 23, 11, 8)}
    with open(os.path.join(d, "intestine.csv"), "w") as f:
        f.write("# intestine: 3 pockets, b 0.02 m, dx 0.0005 m, level 0.0046 m, amplitude 0.003 m, "
                "t_w 0.5 s, T_w 4.5 s, t_d 0 s, fluid 400\n")
        f.write("t,sub,x_F,white_0,white_1,white_2,white_3,alpha\n")
        n = int(round(t_end / 0.1))
        for i in range(n + 1):
            t = 0.1 * i
            c = steps[int(math.floor(t + 1e-9))]
            f.write(f"{t:.1f},{int(t / 0.5)},0.01,{c[0]},{c[1]},{c[2]},{c[3]},{1 - c[0] / 100}\n")
    with open(os.path.join(d, "intestine-summary.csv"), "w") as f:
        f.write(f"key,value\nb,0.02\nT_w,4.5\nalpha_T,{alpha_T}\n")


def run(script, d, *extra):
    return subprocess.run([sys.executable, script, d, *extra], capture_output=True, text=True)


def table(path):
    with open(path) as f:
        rows = [r for r in csv.reader(l for l in f if not l.startswith("#"))]
    return {r[0]: r[1:] for r in rows[1:]}


def near(a, b, what):
    if a == "n/a" or abs(float(a) - b) > 1e-6 * max(1.0, abs(b)):
        fail(f"{what}: {a}, expected {b:.6g}")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--script", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--quick", default=None)
    a = p.parse_args()

    d = os.path.join(a.work, "made-up")
    made_up(d, 5.0)
    r = run(a.script, d, "--periods", "6", "--alpha", "0.1")
    if r.returncode:
        fail(f"made-up run: exit {r.returncode}: {r.stderr}")
    tab = table(os.path.join(d, "intestine-pouring.csv"))
    want = {1: (0.80, 0.16, 0.03, 0.01), 2: (0.70, 0.20, 0.07, 0.03), 3: (0.64, 0.22, 0.09, 0.05)}
    for m, v in want.items():
        key = f"run after {m} haustrum period(s)"
        if key not in tab:
            fail(f"no row '{key}'")
        near(tab[key][0], 0.5 + m, f"{key}: t - t0")
        for k in range(4):
            near(tab[key][1 + k], v[k], f"{key}: pocket {k}")
    if tab["run after 6 haustrum period(s)"][1:] != ["n/a"] * 4:
        fail(f"a period beyond the rows should be n/a: {tab['run after 6 haustrum period(s)']}")
    for key, alpha in (("pouring model (1 - alpha) alpha^k with alpha after one haustrum period", 0.2),
                       ("pouring model (1 - alpha) alpha^k with alpha_T (after one wave)", 0.3),
                       ("pouring model (1 - alpha) alpha^k with alpha = 0.1 (given)", 0.1)):
        for k in range(4):
            near(tab[key][1 + k], (1 - alpha) * alpha ** k, f"{key}: pocket {k}")
    if "alpha after one haustrum period 0.2, after one wave (alpha_T) 0.3" not in r.stdout:
        fail(f"the printed alphas: {r.stdout}")

    # alpha_T n/a (no whole wave): its model column n/a, not 1 - 0
    made_up(d, 5.0, alpha_T="n/a")
    r = run(a.script, d)
    if r.returncode:
        fail(f"made-up run with alpha_T n/a: exit {r.returncode}: {r.stderr}")
    tab = table(os.path.join(d, "intestine-pouring.csv"))
    if tab["pouring model (1 - alpha) alpha^k with alpha_T (after one wave)"][1:] != ["n/a"] * 4:
        fail("alpha_T n/a should give an n/a model row")

    r = run(a.script, d, "--alpha", "1")
    if r.returncode != 1 or "--alpha 1.0: not in [0, 1)" not in r.stderr:
        fail(f"--alpha 1: exit {r.returncode}, stderr {r.stderr!r}")

    # rows that end before one haustrum period: an error naming the file, no table
    short = os.path.join(a.work, "short")
    made_up(short, 0.8)
    r = run(a.script, short)
    if r.returncode != 1 or "before one haustrum period" not in r.stderr:
        fail(f"short run: exit {r.returncode}, stderr {r.stderr!r}")
    if os.path.exists(os.path.join(short, "intestine-pouring.csv")):
        fail("short run: a table was written")

    if a.quick:  # the quick run: alpha after one period from its own rows
        r = run(a.script, a.quick, "--out", os.path.join(a.work, "quick-pouring.csv"))
        if r.returncode:
            fail(f"quick run: exit {r.returncode}: {r.stderr}")
        with open(os.path.join(a.quick, "intestine.csv")) as f:
            lines = [l.strip().split(",") for l in f if not l.startswith("#")]
        names, rows = lines[0], [[float(x) for x in l] for l in lines[1:] if l != [""]]
        col = {n: i for i, n in enumerate(names)}
        t0 = next(rw[col["t"]] for rw in rows if rw[col["sub"]] >= 0)
        first = min(rows, key=lambda rw: abs(rw[col["t"]] - t0))
        n_P = sum(first[col[f"white_{k}"]] for k in range(4))
        one = min(rows, key=lambda rw: abs(rw[col["t"]] - (t0 + 3 * 0.06)))  # t_w + t_H
        alpha = 1 - one[col["white_0"]] / n_P
        tab = table(os.path.join(a.work, "quick-pouring.csv"))
        near(tab["run after 1 haustrum period(s)"][1], 1 - alpha, "quick run: pocket 0 after one period")
        near(tab["pouring model (1 - alpha) alpha^k with alpha after one haustrum period"][2],
             (1 - alpha) * alpha, "quick run: the model's pocket 1")
    print("intestine_pouring.py: OK")


if __name__ == "__main__":
    main()
