#!/usr/bin/python3
"""scripts/post/plot_intestine_study.py on synthetic run directories.

  colon_study_plot.py SCRIPT WORKDIR

Writes five intestine-summary.csv files as dmhs does (key,value,note; n/a
with its reason where undefined) under WORKDIR/runs: three usable runs at two
levels, one whose front went back (u_F < 0: Re n/a) and one that ended before
one wave period (alpha_T, u_P, u_S n/a). Checks that the script, without
--out, writes WORKDIR/runs/colon-study.csv (the runs' common parent) with one
row per usable run and the summaries' Re and Re_P (n/a stays n/a, never a
negative Reynolds number), skips the n/a run with a warning naming it and its
reason, and draws a PNG > 10 kB; that a malformed summary (a value neither a
number nor n/a), one without the keys of today's summary, a missing one, and
a set with no usable run each fail with exit status 1 naming the cause; and
that --out writes elsewhere.
"""
import csv
import math
import os
import shutil
import subprocess
import sys

script, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
runs = os.path.join(work, "runs")


def fail(msg):
    sys.exit(f"FAIL: {msg}")


def summary(name, L, nu, Vw, uF, alpha, malformed=None, old=False):
    d = os.path.join(runs, name)
    os.makedirs(d)
    N1, b = 10, 0.02
    uP = alpha / (1 - alpha) * Vw / N1 if alpha is not None else None
    uS = alpha * Vw if alpha is not None else None
    h, g = 0.009, 9.81
    values = {"b": b, "level": L, "nu": nu, "T_w": N1 * b / Vw, "V_w": Vw, "waves": 10 if alpha is not None else 0,
              "u_F": uF, "u_F_from_initial": 0, "u_F_line": uF, "u_F_line_r2": 0.998, "u_F_first_wave": -0.5 * uF,
              "alpha_T": alpha, "alpha_end": None if alpha is None else 0.6, "u_P": uP, "u_S": uS, "h": h,
              "Re": b * uF / nu if uF > 0 else None, "Re_P": b * uP / nu if uP else None,
              "Ga": h ** 3 * g / nu ** 2, "Fr": Vw / math.sqrt(g * h), "Lambda": h / L, "rho_dev_max": 0.012,
              "mach_max": 0.03, "in_membrane_max": 0, "through_max": 0, "fluid": 18380, "overflow": 12,
              "t_end": 138.1}
    notes = {"alpha_T": "not reached: the rows end at 5 s < t_d + T_w = 7 s", "Re": "u_F <= 0: the front did not advance"}
    if old:  # the summary of an older dmhs: key,value, u_F of the first wave, no Re_P
        values = {k: v for k, v in values.items() if k not in ("Re_P", "u_F_line_r2", "u_F_from_initial")}
    with open(os.path.join(d, "intestine-summary.csv"), "w") as f:
        f.write("key,value\n" if old else "key,value,note\n")
        for k, v in values.items():
            cell = "n/a" if v is None else format(v, ".8g")
            f.write(f"{k},{cell}\n" if old else f"{k},{cell},{notes.get(k, '') if v is None else ''}\n")
        if malformed:
            f.write(malformed)
    return d


def run(*args, expect):
    p = subprocess.run([sys.executable, script, *args], capture_output=True, text=True)
    print(p.stdout + p.stderr, end="")
    if p.returncode != expect:
        fail(f"{' '.join(args)}: exit status {p.returncode}, expected {expect}")
    return p.stdout + p.stderr


good = {"L0.0046_nu1e-6_Vw1.45": (0.0046, 1e-6, 0.0145, 0.0021, 0.38),
        "L0.0046_nu1e-4_Vw13": (0.0046, 1e-4, 0.13, 0.004, 0.22),
        "L0.0157_nu5e-4_Vw26": (0.0157, 5e-4, 0.26, 0.0008, 0.15)}
dirs = [summary(n, *v) for n, v in good.items()]
back = summary("L0.0111_nu5e-4_Vw1.45", 0.0111, 5e-4, 0.0145, -0.0005, 0.02)
short = summary("L0.0081_nu1e-5_Vw2.9", 0.0081, 1e-5, 0.029, 0.003, None)
out = run(*dirs, back, short, expect=0)
if f"{short}/intestine-summary.csv" not in out or "skipped" not in out or "not reached" not in out:
    fail("the run with alpha_T n/a was not reported as skipped with its reason")
table = os.path.join(runs, "colon-study.csv")
png = os.path.join(runs, "colon-study.png")
for f in (table, png):
    if not os.path.isfile(f):
        fail(f"{f} not written (the default --out is the runs' common parent)")
with open(table, newline="") as f:
    rows = list(csv.DictReader(f))
want = ["run", "L", "nu", "V_w", "u_F", "u_P", "u_S", "alpha_T", "Re", "Re_P", "Ga", "Fr", "Lambda",
        "rho_dev_max", "mach_max", "through_max", "u_F_from_initial", "u_F_line_r2", "u_F_first_wave",
        "alpha_end", "waves"]
if list(rows[0].keys()) != want:
    fail(f"columns {list(rows[0].keys())}, expected {want}")
if len(rows) != 4 or any(r["run"] == short for r in rows):
    fail(f"{len(rows)} rows, expected the 4 usable runs")
r_back = [r for r in rows if r["run"] == back]
if len(r_back) != 1 or r_back[0]["Re"] != "n/a" or float(r_back[0]["u_F"]) != -0.0005:
    fail(f"the run whose front went back: {r_back}: expected u_F -0.0005 as measured and Re n/a")
for r in rows:
    if r["run"] == back:
        continue
    L, nu, Vw, uF, alpha = good[os.path.basename(r["run"])]
    uP = alpha / (1 - alpha) * Vw / 10
    for key, expected in (("L", L), ("nu", nu), ("V_w", Vw), ("u_F", uF), ("u_P", uP), ("alpha_T", alpha),
                          ("Re", 0.02 * uF / nu), ("Re_P", 0.02 * uP / nu)):
        if abs(float(r[key]) - expected) > 1e-6 * abs(expected):
            fail(f"{r['run']}: {key} = {r[key]}, expected {expected:.8g}")
    print(f"{r['run']}: Re = {float(r['Re']):.4g}, Re_P = {float(r['Re_P']):.4g}: as expected")
size = os.path.getsize(png)
if size <= 10000:
    fail(f"{png}: {size} bytes, expected > 10 kB")

# --out elsewhere
other = os.path.join(work, "plots")
run("--out", other, *dirs, expect=0)
if not os.path.isfile(os.path.join(other, "colon-study.png")):
    fail("--out: no PNG there")
# a malformed summary fails, naming the file
bad = summary("L0.0111_nu5e-5_Vw5.8", 0.0111, 5e-5, 0.058, 0.003, 0.3, malformed="Fr,abc\n")
out = run("--out", other, *dirs, bad, expect=1)
if f"{bad}/intestine-summary.csv" not in out or "neither a number nor n/a" not in out:
    fail("the malformed summary was not named")
# a summary of an older dmhs (u_F of the first wave, no Re_P) fails, naming the file
older = summary("L0.0157_nu1e-6_Vw1.45", 0.0157, 1e-6, 0.0145, 0.002, 0.3, old=True)
out = run("--out", other, *dirs, older, expect=1)
if f"{older}/intestine-summary.csv" not in out or "Re_P" not in out:
    fail("the older summary was not refused naming the file and a missing key")
# a missing summary fails, naming the file
empty = os.path.join(runs, "no-summary")
os.makedirs(empty)
out = run("--out", other, dirs[0], empty, expect=1)
if f"{empty}/intestine-summary.csv: no such file" not in out:
    fail("the missing summary was not named")
# no usable run
out = run("--out", other, short, expect=1)
if "none of the 1 run(s) is usable" not in out:
    fail("a set of unusable runs did not fail")
print("colon study plot: OK")
