"""A run's snapshot files, shared by the plot scripts of every case.

  snapshot_files(run_dir, fail)   [(time, path)] of RUN_DIR/snap_*.h5, sorted by time;
                                  fail(message) is called (and must not return) when there
                                  is none or one cannot be read
  marker_size(ax, spacing)        scatter size [pt^2] that draws a particle spacing wide
"""
import glob
import os

import numpy as np


def snapshot_files(run_dir, fail):
    import h5py

    paths = sorted(glob.glob(os.path.join(run_dir, "snap_*.h5")))
    if not paths:
        fail(f"{os.path.join(run_dir, 'snap_*.h5')}: no snapshot (was the run made with -output_snapshots false?)")
    out = []
    for p in paths:
        try:
            with h5py.File(p, "r") as f:
                out.append((float(np.ravel(f.attrs["time"])[0]), p))
        except (OSError, KeyError) as e:
            fail(f"{p}: unreadable or no 'time' attribute ({e})")
    return sorted(out)


def marker_size(ax, spacing):
    """Scatter size [pt^2] that draws a particle about `spacing` (data units of x) wide."""
    fig = ax.figure
    ax.apply_aspect()
    x0, x1 = ax.get_xlim()
    width_pt = ax.get_position().width * fig.get_figwidth() * 72.0
    return (spacing * width_pt / abs(x1 - x0)) ** 2
