#!/usr/bin/python3
"""Checks an error.csv written by dmhs (columns step,t,wall_s,l2,linf).

  check_error.py <error.csv> [--at T:MAX_L2 ...] [--all MAX_L2] [--interval DT --t-end T_END]

--at T:MAX_L2   the row whose t is nearest T must exist (within 1 % of T) and have
                l2 <= MAX_L2 (a fraction: 0.01 = 1 %)
--all MAX_L2    every row must have l2 <= MAX_L2
--interval DT --t-end T_END
                a row must exist at each t = k DT, k = 1 .. T_END/DT (within 1 % of DT):
                a run that stopped early or skipped a row fails
Every row must have all five columns, each a finite number (an empty or NaN value
fails; it never compares as a pass), and step and t must increase from row to row.
Exit status 0 when all hold, 1 otherwise; prints each comparison.
"""
import argparse
import csv
import math
import sys

COLUMNS = ("step", "t", "wall_s", "l2", "linf")


def number(text):
    """The value as a finite float, or None (missing, empty, not a number, NaN, inf)."""
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def read_rows(path):
    """Returns (rows, problems): rows as dicts of floats, the lines that are not valid."""
    problems = []
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        if header != list(COLUMNS):
            return [], [f"header is {header}, not {','.join(COLUMNS)}"]
        rows = []
        for line_no, fields in enumerate(reader, start=2):
            values = [number(v) for v in fields]
            if len(fields) != len(COLUMNS) or any(v is None for v in values):
                problems.append(f"line {line_no}: {','.join(fields)!r} is not {len(COLUMNS)} finite numbers")
                continue
            row = dict(zip(COLUMNS, values))
            if rows and not (row["step"] > rows[-1]["step"] and row["t"] > rows[-1]["t"]):
                problems.append(f"line {line_no}: step/t do not increase (t = {row['t']:g} after {rows[-1]['t']:g})")
            rows.append(row)
    return rows, problems


def nearest(rows, t_want, tol):
    row = min(rows, key=lambda r: abs(r["t"] - t_want))
    return row if abs(row["t"] - t_want) <= tol else None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("--at", action="append", default=[], metavar="T:MAX_L2")
    ap.add_argument("--all", type=float, metavar="MAX_L2")
    ap.add_argument("--interval", type=float, metavar="DT")
    ap.add_argument("--t-end", type=float, metavar="T_END")
    args = ap.parse_args()
    if not args.at and args.all is None:
        ap.error("nothing to check: give --at and/or --all")
    if (args.interval is None) != (args.t_end is None) or (args.interval is not None and args.interval <= 0):
        ap.error("--interval DT (> 0) and --t-end T_END go together")
    try:
        rows, problems = read_rows(args.csv)
    except OSError as e:
        print(f"FAIL: cannot read {args.csv}: {e}")
        return 1
    ok = True
    for p in problems:
        print(f"FAIL: {args.csv} {p}")
        ok = False
    if not rows:
        print(f"FAIL: {args.csv} has no valid rows")
        return 1
    if args.interval is not None:
        n = int(math.floor(args.t_end / args.interval + 1e-6))
        missing = [k * args.interval for k in range(1, n + 1)
                   if nearest(rows, k * args.interval, 0.01 * args.interval) is None]
        for t in missing:
            print(f"FAIL: no row at t = {t:.6g} s (one expected every {args.interval:g} s to {args.t_end:g} s)")
        ok = ok and not missing
        print(f"{'FAIL' if missing else 'ok'}: {n - len(missing)} of the {n} rows expected every {args.interval:g} s")
    if args.all is not None:
        worst = max(rows, key=lambda r: r["l2"])
        bad = [r for r in rows if not r["l2"] <= args.all]
        for r in bad:
            print(f"FAIL: t = {r['t']:.6g} s  L2 = {100 * r['l2']:.4f} % > {100 * args.all:.4f} %")
        print(f"{'FAIL' if bad else 'ok'}: every row ({len(rows)}) L2 <= {100 * args.all:.4f} %: "
              f"worst {100 * worst['l2']:.4f} % at t = {worst['t']:.6g} s")
        ok = ok and not bad
    for spec in args.at:
        t_want, limit = (float(v) for v in spec.split(":"))
        row = nearest(rows, t_want, 0.01 * t_want)
        if row is None:
            print(f"FAIL: no row at t = {t_want} s (nearest {nearest(rows, t_want, math.inf)['t']} s)")
            ok = False
            continue
        good = row["l2"] <= limit
        print(f"{'ok' if good else 'FAIL'}: t = {row['t']:.6g} s  L2 = {100 * row['l2']:.4f} %  "
              f"(limit {100 * limit:.4f} %)  wall {row['wall_s']:g} s")
        ok = ok and good
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
