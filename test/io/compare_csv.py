#!/usr/bin/python3
"""Compares two diagnostic CSV files line by line, text for text, except the
wall-clock columns (header names starting with 'wall', e.g. error.csv's
wall_s), which differ from run to run. Exits 1 at the first difference, and
when a file is empty (two empty files would compare equal without a check).

  compare_csv.py A.csv B.csv
"""
import sys


def columns(path):
    with open(path) as f:
        lines = f.read().splitlines()
    drop = set()
    for line in lines:
        if not line.startswith("#") and line and not line[0].isdigit() and line[0] not in "+-.":
            drop = {k for k, name in enumerate(line.split(",")) if name.startswith("wall")}
            break
    return [",".join(c for k, c in enumerate(line.split(",")) if k not in drop) for line in lines]


def main(a_path, b_path):
    a, b = columns(a_path), columns(b_path)
    if not a or not b:
        print(f"{a_path} vs {b_path}: {'both files are' if not a and not b else 'a file is'} empty")
        return 1
    for k, (x, y) in enumerate(zip(a, b)):
        if x != y:
            print(f"{a_path} vs {b_path}: line {k + 1} differs:\n  {x}\n  {y}")
            return 1
    if len(a) != len(b):
        print(f"{a_path} vs {b_path}: {len(a)} lines against {len(b)}")
        return 1
    print(f"{a_path} vs {b_path}: identical ({len(a)} lines)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
