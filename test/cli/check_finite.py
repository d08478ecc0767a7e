#!/usr/bin/python3
"""Fails (exit 1) when any CSV value or HDF5 dataset in a directory is not finite.

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
    bad = []
    for path in glob.glob(os.path.join(root, "**", "*.csv"), recursive=True):
        with open(path, newline="") as f:
            for row in csv.reader(line for line in f if not line.startswith("#")):
                for cell in row:
                    try:
                        if not math.isfinite(float(cell)):
                            bad.append(f"{path}: {cell}")
                    except ValueError:
                        pass  # a header
    for path in glob.glob(os.path.join(root, "**", "*.h5"), recursive=True):
        with h5py.File(path, "r") as f:
            def visit(name, obj):
                if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f" and not np.all(np.isfinite(obj[()])):
                    bad.append(f"{path}:{name}")
            f.visititems(visit)
    for b in bad:
        print("non-finite:", b)
    print(f"checked {root}: {'FAIL' if bad else 'all finite'}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
