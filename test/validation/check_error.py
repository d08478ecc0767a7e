#!/usr/bin/python3
"""Checks an error.csv written by dmhs (columns step,t,wall_s,l2,linf).

  check_error.py <error.csv> --at T:MAX_L2 [--at T:MAX_L2 ...]

For each T, the row whose t is nearest T must exist (within 1 % of T) and
have l2 <= MAX_L2 (a fraction: 0.01 = 1 %). Every value must be finite.
Exit status 0 when all hold, 1 otherwise; prints each comparison.
"""
import argparse
import csv
import math
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("--at", action="append", required=True, metavar="T:MAX_L2")
    args = ap.parse_args()
    with open(args.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        print(f"FAIL: {args.csv} has no rows")
        return 1
    ok = True
    for row in rows:
        if not all(math.isfinite(float(row[k])) for k in ("t", "wall_s", "l2", "linf")):
            print(f"FAIL: non-finite value in row {row}")
            ok = False
    for spec in args.at:
        t_want, limit = (float(v) for v in spec.split(":"))
        row = min(rows, key=lambda r: abs(float(r["t"]) - t_want))
        t, l2 = float(row["t"]), float(row["l2"])
        if abs(t - t_want) > 0.01 * t_want:
            print(f"FAIL: no row at t = {t_want} s (nearest {t} s)")
            ok = False
            continue
        verdict = "ok" if l2 <= limit else "FAIL"
        print(f"{verdict}: t = {t:.6g} s  L2 = {100 * l2:.4f} %  (limit {100 * limit:.4f} %)  wall {row['wall_s']} s")
        ok = ok and l2 <= limit
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
