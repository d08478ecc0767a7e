"""Bitwise comparison of the particle datasets of two dmhs HDF5 files
(checkpoints or snapshots): every dataset under /particles must have the same
shape, dtype and bytes. Usage: compare_h5.py A.h5 B.h5"""
import sys

import h5py
import numpy as np


def main(a_path, b_path):
    bad = 0
    with h5py.File(a_path, "r") as a, h5py.File(b_path, "r") as b:
        names = sorted(set(a["particles"]) | set(b["particles"]))
        for name in names:
            if name not in a["particles"] or name not in b["particles"]:
                print(f"{name}: only in one file")
                bad += 1
                continue
            x, y = a["particles"][name][()], b["particles"][name][()]
            same = x.shape == y.shape and x.dtype == y.dtype and np.array_equal(
                np.ascontiguousarray(x).view(np.uint8), np.ascontiguousarray(y).view(np.uint8))
            diff = "" if same or x.shape != y.shape else f", max |diff| = {np.max(np.abs(x - y)):.3e}"
            print(f"{name:12s} {str(x.shape):12s} {str(x.dtype):8s} {'bitwise equal' if same else 'DIFFERENT' + diff}")
            bad += not same
        for key in ("step", "t"):
            if key in a.attrs and key in b.attrs and a.attrs[key][0] != b.attrs[key][0]:
                print(f"attribute {key}: {a.attrs[key][0]} != {b.attrs[key][0]}")
                bad += 1
    print(f"{a_path} vs {b_path}: {'IDENTICAL' if not bad else f'{bad} differences'}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
