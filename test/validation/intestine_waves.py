#!/usr/bin/python3
"""Runs scripts/post/plot_intestine_waves.py on the quick old-wave and new-wave
runs (red set in pocket 1) and checks what it wrote against their
intestine.csv: one row per run and completed wave plus an "end" row, H read
as 2 and 5, every fraction in [0, 1], red_left_count = red_left N0, the red
set's fractions out of its pocket that add up (downstream + upstream =
red_left), the end rows equal to the runs' last rows; and that the script
fails, naming the file, on a run that tracks no red set.

  intestine_waves.py --script plot_intestine_waves.py --old DIR --new DIR --plain DIR --out DIR
"""
import argparse
import csv
import os
import subprocess
import sys


def fail(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def first_last_rows(run_dir):
    with open(os.path.join(run_dir, "intestine.csv")) as f:
        lines = [l for l in f if not l.startswith("#") and l.strip()]
    names = lines[0].strip().split(",")
    first = dict(zip(names, map(float, lines[1].split(","))))
    last = dict(zip(names, map(float, lines[-1].split(","))))
    return first, last


ap = argparse.ArgumentParser()
ap.add_argument("--script", required=True)
ap.add_argument("--old", required=True)
ap.add_argument("--new", required=True)
ap.add_argument("--plain", required=True, help="a run without a red set")
ap.add_argument("--out", required=True)
a = ap.parse_args()

os.makedirs(a.out, exist_ok=True)
for f in ("intestine-waves.csv", "intestine-waves.png"):
    if os.path.exists(os.path.join(a.out, f)):
        os.remove(os.path.join(a.out, f))
r = subprocess.run([sys.executable, a.script, a.old, a.new, "--out", a.out], capture_output=True, text=True)
print(r.stdout + r.stderr, end="")
if r.returncode != 0:
    fail(f"plot_intestine_waves.py exited {r.returncode}")
png = os.path.join(a.out, "intestine-waves.png")
if not os.path.isfile(png) or os.path.getsize(png) == 0:
    fail(f"{png} not written")
with open(os.path.join(a.out, "intestine-waves.csv"), newline="") as f:
    rows = list(csv.DictReader(f))
want = ["run", "H", "wave", "t", "white_left", "red_left", "red_left_count", "red_downstream", "red_upstream"]
if not rows or list(rows[0].keys()) != want:
    fail(f"intestine-waves.csv: header is not {','.join(want)}")
for run_dir, H in ((a.old, "2"), (a.new, "5")):
    name = os.path.basename(os.path.normpath(run_dir))
    mine = [x for x in rows if x["run"] == name]
    waves = [x["wave"] for x in mine]
    if waves != ["1", "end"]:
        fail(f"{name}: rows for waves {waves}, expected 1 and end (the runs end after one wave)")
    first, last = first_last_rows(run_dir)
    n_red = sum(v for k, v in first.items() if k.startswith("red_"))
    for x in mine:
        if x["H"] != H:
            fail(f"{name}: H = {x['H']}, expected {H} (from its run.json)")
        vals = {k: float(x[k]) for k in want[3:]}
        for k in ("white_left", "red_left", "red_downstream", "red_upstream"):
            if not 0 <= vals[k] <= 1:
                fail(f"{name} wave {x['wave']}: {k} = {vals[k]} outside [0, 1]")
        if abs(vals["red_downstream"] + vals["red_upstream"] - vals["red_left"]) > 1e-5:
            fail(f"{name} wave {x['wave']}: downstream + upstream != red_left")
        if abs(vals["red_left_count"] - vals["red_left"] * n_red) > 0.5:
            fail(f"{name} wave {x['wave']}: red_left_count != red_left x {n_red:g}")
    end = {k: float(v) for k, v in mine[-1].items() if k not in ("run", "H", "wave")}
    red_left = 1 - last["red_1"] / n_red
    white_left = 1 - last["white_0"] / sum(v for k, v in first.items() if k.startswith("white_"))
    if abs(end["red_left"] - red_left) > 1e-5 or abs(end["white_left"] - white_left) > 1e-5:
        fail(f"{name}: end row (red_left {end['red_left']}, white_left {end['white_left']}) differs from "
             f"the run's last row ({red_left:.6g}, {white_left:.6g})")
    print(f"  {name}: H {H}, red out of pocket 1 at the end {end['red_left']:.4g}, white out of pocket 0 "
          f"{end['white_left']:.4g}")

r = subprocess.run([sys.executable, a.script, a.plain, a.new, "--out", a.out], capture_output=True, text=True)
if r.returncode == 0 or "intestine.csv" not in r.stderr or "red" not in r.stderr:
    fail(f"a run without a red set: exit {r.returncode}, stderr '{r.stderr.strip()}'")
print(f"  without a red set: exit {r.returncode}: {r.stderr.strip()}\nPASS")
