#!/usr/bin/python3
"""Fails (exit 1) when any CSV value or HDF5 dataset in a directory is not finite,
or when the directory does not exist (a wrong path must not pass as "all finite").

  check_finite.py DIR
"""
import csv
import glob
import math
import os
import sys

import h5py
import numpy as np


def main():
    root = sys.argv[1]
    if not os.path.isdir(root):
        print(f"checked {root}: FAIL: no such directory")
        return 1
    bad = []
    csvs = glob.glob(os.path.join(root, "**", "*.csv"), recursive=True)
    h5s = glob.glob(os.path.join(root, "**", "*.h5"), recursive=True)
    for path in csvs:
        with open(path, newline="") as f:
            for row in csv.reader(line for line in f if not line.startswith("#")):
                for cell in row:
                    try:
                        if not math.isfinite(float(cell)):
                            bad.append(f"{path}: {cell}")
                    except ValueError:
                        pass  # a header
    for path in h5s:
        with h5py.File(path, "r") as f:
            def visit(name, obj):
                if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f" and not np.all(np.isfinite(obj[()])):
                    bad.append(f"{path}:{name}")
            f.visititems(visit)
    for b in bad:
        print("non-finite:", b)
    print(f"checked {root} ({len(csvs)} CSV, {len(h5s)} HDF5 files): {'FAIL' if bad else 'all finite'}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
