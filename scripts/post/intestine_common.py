"""Shared by the colon's plot scripts (plot_intestine.py, plot_intestine_study.py,
plot_intestine_waves.py, plot_intestine_snapshot.py): the strict readers of a
run's intestine.csv (its rows and its '# intestine:' line) and
intestine-summary.csv, and the rows that end each completed wave. The
measures themselves (u_F, alpha, u_P, u_S, Re) are the solver's, read from the
summary: they are defined once, in src/scenes/intestine/intestine_measures.c."""
import csv
import math
import os
import re
import sys

import numpy as np


def die(prog, msg):
    print(f"{prog}: {msg}", file=sys.stderr)
    sys.exit(1)


def read_summary(path, prog, need=(), finite=(), notes=None):
    """intestine-summary.csv (key,value[,note]) as {key: float}, n/a -> NaN; with a dict `notes`,
    each key's note (why a value is n/a, or how it was chosen) goes there. Exits naming the file
    and the line when the file is missing or malformed, a key of `need` is absent, or a key of
    `finite` is n/a (with its reason)."""
    if not os.path.isfile(path):
        die(prog, f"{path}: no such file (the run did not finish?)")
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r]
    header = [c.strip() for c in rows[0]] if rows else []
    if len(rows) < 2 or header not in (["key", "value"], ["key", "value", "note"]):
        die(prog, f"{path}: not a key,value[,note] table")
    out, why = {}, {}
    for n, r in enumerate(rows[1:], start=2):
        if len(r) not in (2, 3):
            die(prog, f"{path}: line {n} has {len(r)} fields, not key,value[,note]")
        k, v = r[0].strip(), r[1].strip()
        why[k] = r[2].strip() if len(r) == 3 else ""
        if notes is not None:
            notes[k] = why[k]
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
        die(prog, f"{path}: {', '.join(k + (f' n/a ({why[k]})' if why[k] else ' n/a') for k in undefined)}")
    return out


def read_comment(path, prog):
    """The '# intestine: ...' line of intestine.csv as {name: float} (pockets, b, dx, level,
    amplitude, t_w, T_w, t_d, fluid); exits naming the file when it is missing or has none."""
    if not os.path.isfile(path):
        die(prog, f"{path}: no such file")
    with open(path) as f:
        line = f.readline()
    if not line.startswith("# intestine:"):
        die(prog, f"{path}: no '# intestine:' line first")
    info = {}
    m = re.match(r"# intestine:\s*(\d+) pockets", line)
    if m:
        info["pockets"] = float(m.group(1))
    for name, value in re.findall(r"(?:,|:)\s*([A-Za-z_]+)\s+([-+0-9.eE]+)", line):
        try:
            info[name] = float(value)
        except ValueError:
            pass
    missing = [k for k in ("pockets", "b", "t_w", "T_w") if k not in info]
    if missing:
        die(prog, f"{path}: the '# intestine:' line has no {', '.join(missing)}")
    return info


def read_series(path, prog):
    """intestine.csv as ({column: array}, [column names]). Exits naming the file and the row when
    the file is missing, has fewer than two rows, a row of the wrong length or a non-finite value."""
    if not os.path.isfile(path):
        die(prog, f"{path}: no such file")
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#") and l.strip()]
    if len(lines) < 3:
        die(prog, f"{path}: fewer than two rows")
    names = lines[0].strip().split(",")
    rows = []
    for n, l in enumerate(lines[1:], start=2):
        v = l.strip().split(",")
        if len(v) != len(names):
            die(prog, f"{path}: row {n} has {len(v)} values, the header {len(names)}")
        try:
            r = [float(x) for x in v]
        except ValueError:
            die(prog, f"{path}: row {n} has a value that is not a number")
        if not all(math.isfinite(x) for x in r):
            die(prog, f"{path}: row {n} has a non-finite value")
        rows.append(r)
    data = np.array(rows)
    return {n: data[:, i] for i, n in enumerate(names)}, names


def pocket_counts(d, names, prefix, n_pockets):
    """The set's count per pocket (and "out", the last column) in every row, or None when the run
    did not track the set."""
    cols = [f"{prefix}_{k}" for k in range(n_pockets + 1)]
    if not all(c in names for c in cols):
        return None
    return np.stack([d[c] for c in cols], axis=1)


def wave_rows(d, T_w, prog, path):
    """(t0, [row closest to the end of each completed wave]): t0 is the first output row of the
    wave (sub >= 0), up to an output interval late."""
    t = d["t"]
    started = np.where(d["sub"] >= 0)[0]
    if len(started) == 0:
        die(prog, f"{path}: the wave never started (sub < 0 in every row)")
    t0 = t[started[0]]
    n_done = int(math.floor((t[-1] - t0) / T_w + 1e-3))
    return t0, [int(np.argmin(np.abs(t - (t0 + n * T_w)))) for n in range(1, n_done + 1)]


def save_png(fig, path, dpi=110):
    """The figure to path through a temporary name, so a reader never sees half a PNG."""
    fig.tight_layout()
    fig.savefig(path + ".tmp.png", dpi=dpi)
    os.replace(path + ".tmp.png", path)
