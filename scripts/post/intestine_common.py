"""Shared by the colon's plot scripts (plot_intestine.py, plot_intestine_study.py):
the strict reader of a run's intestine-summary.csv."""
import csv
import math
import os
import sys


def die(prog, msg):
    print(f"{prog}: {msg}", file=sys.stderr)
    sys.exit(1)


def read_summary(path, prog, need=(), finite=()):
    """intestine-summary.csv as {key: float}, n/a -> NaN. Exits naming the file and the line when
    the file is missing or malformed, a key of `need` is absent, or a key of `finite` is n/a."""
    if not os.path.isfile(path):
        die(prog, f"{path}: no such file (the run did not finish?)")
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r]
    if len(rows) < 2 or [c.strip() for c in rows[0]] != ["key", "value"]:
        die(prog, f"{path}: not a key,value table")
    out = {}
    for n, r in enumerate(rows[1:], start=2):
        if len(r) != 2:
            die(prog, f"{path}: line {n} has {len(r)} fields, not key,value")
        k, v = r[0].strip(), r[1].strip()
        if v == "n/a":
            out[k] = math.nan
            continue
        try:
            x = float(v)
        except ValueError:
            die(prog, f"{path}: line {n}: {k} = '{v}' is neither a number nor n/a")
        if not math.isfinite(x):
            die(prog, f"{path}: line {n}: {k} = '{v}' is not finite")
        out[k] = x
    missing = [k for k in tuple(need) + tuple(finite) if k not in out]
    if missing:
        die(prog, f"{path}: no {', '.join(missing)}")
    undefined = [k for k in finite if math.isnan(out[k])]
    if undefined:
        die(prog, f"{path}: {', '.join(undefined)} n/a")
    return out
