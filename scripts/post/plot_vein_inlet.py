#!/usr/bin/env python3
"""Inlet velocity against time for several vein runs (scene vein).

  scripts/post/plot_vein_inlet.py RUNDIR [RUNDIR ...] [--out PATH]

Draws the cross-section mean inlet velocity (u_flux, the volume flux over
the width, where vein.csv has it, else the inlet slab's u_mean) and u_centre
(axis) at the inlet station from each run's vein.csv, one colour per run labelled by its dx and g0, with
the thesis's peak inlet velocities (0.03 / 0.07 / 0.13 m/s for g0 = 0.1 /
0.25 / 0.4 m/s^2) as dashed lines, and prints each run's peak over the first
cycle. Writes vein_inlet.png into the first RUNDIR unless --out is given.
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import vein_common as vc

THESIS = {0.1: 0.03, 0.25: 0.07, 0.4: 0.13}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rundirs", nargs="+")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: the first RUNDIR)")
    a = ap.parse_args()
    fig, axs = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    seen = set()
    print("run, dx [m], g0 [m/s^2], T [s], t_end [s], peak cross-section mean (u_flux or u_mean), "
          "peak u_centre over the first cycle [m/s]")
    for k, d in enumerate(a.rundirs):
        vc.require_dir(d)
        cols, info = vc.read_csv(os.path.join(d, "vein.csv"), need=("t", "u_mean", "u_centre"))
        t, uc = cols["t"], cols["u_centre"]
        um, uname = vc.inlet_velocity(cols)
        T = info.get("T", np.inf)
        first = t <= T * (1 + 1e-9)
        dx, g0 = info.get("dx", np.nan), info.get("g0", np.nan)
        label = f"dx = {dx * 1e3:g} mm, g0 = {g0:g} m/s²"
        if (dx, g0) in seen:
            label += f" ({os.path.basename(os.path.normpath(d))})"
        seen.add((dx, g0))
        c = f"C{k % 10}"
        axs[0].plot(t, um, color=c, label=label)
        axs[1].plot(t, uc, color=c, label=label)
        print(f"{d}, {dx:g}, {g0:g}, {T:g}, {t[-1]:g}, {np.nanmax(np.abs(um[first])):.4g}, "
              f"{np.nanmax(np.abs(uc[first])):.4g}")
        if g0 in THESIS:
            for ax in axs:
                ax.axhline(THESIS[g0], color=c, ls="--", lw=0.8)
    axs[0].set_ylabel("cross-section mean [m/s]\n(u_flux; u_mean where absent)")
    axs[1].set_ylabel("u_centre (axis) [m/s]")
    axs[1].set_xlabel("t [s]")
    axs[0].legend(fontsize=8)
    axs[0].set_title("inlet velocity at x = 0; dashed: the thesis's peak for that g0")
    for ax in axs:
        ax.grid(alpha=0.3)
    path = vc.output_path(a.out, a.rundirs[0], "vein_inlet.png")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(path)


if __name__ == "__main__":
    main()
