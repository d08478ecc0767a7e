#!/usr/bin/env python3
"""Inlet velocity of several vein runs against time and per drive cycle, beside the thesis's peaks.

  scripts/post/plot_vein_inlet.py RUNDIR [RUNDIR ...] [--out PATH]

The comparison across runs (one run's own inlet velocities, u_flux, u_mean and
u_centre, are a panel of plot_vein_probe.py). Two panels:
  1. the cross-section mean inlet velocity (u_flux, the volume flux over the
     width, where vein.csv has it, else the inlet slab's u_mean) against t, one
     colour per run labelled by its dx and g0;
  2. each run's peak forward inlet velocity per drive cycle (filled: a
     completed cycle; open: the cycle the run stopped in).
Where a run's g0 is one of the thesis's (peak inlet velocities 0.03 / 0.07 /
0.13 m/s for g0 = 0.1 / 0.25 / 0.4 m/s^2), that peak is a dashed line of the
run's colour in both panels, listed in the legend; the title says when no run
has one. Prints each run's peak over the first cycle. Writes vein_inlet.png
into the first RUNDIR unless --out is given.
"""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import vein_common as vc  # noqa: E402

THESIS = {0.1: 0.03, 0.25: 0.07, 0.4: 0.13}


def thesis_peak(g0):
    """The thesis's peak inlet velocity [m/s] for g0 [m/s^2], or None."""
    for g, u in THESIS.items():
        if math.isfinite(g0) and abs(g0 - g) <= 1e-9 * g:
            return u
    return None


def cycle_peaks(t, u, T):
    """[(cycle, peak forward u, completed)] per drive cycle k T < t <= (k+1) T; rows
    within half a row spacing of a cycle's end count to it (the run's last row may
    pass t_end by a step)."""
    out = []
    if not (math.isfinite(T) and T > 0) or t.size < 2:
        return out
    tol = 0.5 * float(np.median(np.diff(t)))
    for k in range(int(math.ceil((t[-1] - tol) / T))):
        m = (t > k * T + tol) & (t <= (k + 1) * T + tol) & np.isfinite(u)
        if m.any():
            out.append((k + 1, float(np.max(u[m])), bool(t[-1] >= (k + 1) * T - tol)))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("rundirs", metavar="RUNDIR", nargs="+", help="output directories of vein runs")
    ap.add_argument("--out", default=None, help="PNG path or directory (default: the first RUNDIR)")
    a = ap.parse_args()
    for d in a.rundirs:
        vc.require_dir(d)
    fig, axs = plt.subplots(2, 1, figsize=(10, 7.5), gridspec_kw={"height_ratios": [3, 2]})
    seen, drawn_thesis, infos = set(), {}, []
    ncycles, partial = 0, False
    print("run, dx [m], g0 [m/s^2], T [s], t_end [s], peak cross-section mean (u_flux or u_mean), "
          "peak u_centre over the first cycle [m/s]")
    for k, d in enumerate(a.rundirs):
        cols, info = vc.read_csv(os.path.join(d, "vein.csv"), need=("t", "u_mean", "u_centre"))
        infos.append(info)
        p = vc.run_params(d, info)
        t, uc = cols["t"], cols["u_centre"]
        um, uname = vc.inlet_velocity(cols)
        T = p.get("T", info.get("T", math.inf))
        first = t <= T * (1 + 1e-9)
        dx, g0 = p.get("dx", math.nan), p.get("g0", math.nan)
        label = f"dx = {dx * 1e3:g} mm, g0 = {g0:g} m/s² ({uname})"
        if (dx, g0) in seen:
            label += f" — {os.path.basename(os.path.normpath(d))}"
        seen.add((dx, g0))
        c = f"C{k % 10}"
        axs[0].plot(t, um, color=c, label=label)
        peaks = cycle_peaks(t, um, T)
        done = [q for q in peaks if q[2]]
        part = [q for q in peaks if not q[2]]
        axs[1].plot([q[0] for q in peaks], [q[1] for q in peaks], "-", color=c, lw=0.8)
        axs[1].plot([q[0] for q in done], [q[1] for q in done], "o", color=c, label=label)
        if part:
            partial = True
            axs[1].plot([q[0] for q in part], [q[1] for q in part], "o", mfc="white", mec=c)
        ncycles = max(ncycles, len(peaks))
        u_ref = thesis_peak(g0)
        if u_ref is not None and (g0, c) not in drawn_thesis:
            drawn_thesis[(g0, c)] = u_ref
            for i, ax in enumerate(axs):
                ax.axhline(u_ref, color=c, ls="--", lw=1,
                           label=f"thesis's peak for g0 = {g0:g} m/s²: {u_ref:g} m/s" if i == 0 else None)
        print(f"{d}, {dx:g}, {g0:g}, {T:g}, {t[-1]:g}, {np.nanmax(np.abs(um[first])):.4g}, "
              f"{np.nanmax(np.abs(uc[first])):.4g}")
    axs[0].axhline(0, color="0.5", lw=0.8)
    axs[0].set_xlabel("t [s]")
    axs[0].set_ylabel("cross-section mean inlet velocity [m/s]")
    axs[1].set_xlabel("drive cycle")
    axs[1].set_ylabel("peak forward inlet\nvelocity per cycle [m/s]")
    axs[1].set_xlim(0.5, max(ncycles, 1) + 0.5)
    axs[1].set_xticks(range(1, max(ncycles, 1) + 1) if ncycles <= 20 else
                      range(1, ncycles + 1, int(math.ceil(ncycles / 10))))
    axs[1].set_ylim(bottom=min(0.0, axs[1].get_ylim()[0]))
    # the legends beside the panels: they never hide a curve
    axs[0].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    if partial:
        axs[1].plot([], [], "o", mfc="white", mec="0.3", label="cycle still running at the run's end")
    axs[1].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    for ax in axs:
        ax.grid(alpha=0.3)
    shared = [q for q in vc.shared_parts(a.rundirs, infos) if not q.startswith(("dx =", "g0 ="))]
    note = ("dashed: the thesis's peak inlet velocity for the run's g0" if drawn_thesis else
            "no run has one of the thesis's g0 (0.1, 0.25, 0.4 m/s²): no thesis peak to compare")
    fig.suptitle("vein: inlet velocity at x = 0" + (f" — {', '.join(shared)}" if shared else "") + f"\n{note}",
                 fontsize=11)
    path = vc.output_path(a.out, a.rundirs[0], "vein_inlet.png")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(path)


if __name__ == "__main__":
    main()
