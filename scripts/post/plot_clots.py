#!/usr/bin/python3
"""Clot size against time for each seed (the thesis's Fig. 4.11 analogue) and
a snapshot picture of the clots.

  scripts/post/plot_clots.py OUTDIR [--out DIR]

Reads OUTDIR/clots.csv (step,t,clot_particles,clot_bonds,clot_1..clot_n) and
draws the particle count of each seed's clot against t (clot_1 = P1, the
sinus-side particle of peak stress; clot_2 = P2, the particle of longest
residence, when the seeds were chosen by the vein scene). Then the last
snapshot: liquid, walls, leaflets, the clot particles and their bonds, with
a zoom on each clot (up to three, the connected components of the clot bonds). Writes clots.png and clots_snapshot.png into OUTDIR, or
--out (a directory).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import vein_common as vc  # noqa: E402

CLOT = 3
LABELS = {1: "P1 (peak stress, sinus side)", 2: "P2 (longest residence)"}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--out", help="directory for the PNGs (default: OUTDIR)")
    a = ap.parse_args()
    vc.require_dir(a.outdir)
    path = os.path.join(a.outdir, "clots.csv")
    data = vc.read_csv(path, need=("t", "clot_particles", "clot_bonds"))[0]
    seeds = [n for n in data if n.startswith("clot_") and n[5:].isdigit()]
    if not seeds:
        vc.fail(f"{path}: no clot_<k> column")
    t = data["t"]
    info = {}
    if os.path.isfile(os.path.join(a.outdir, "vein.csv")):
        info = vc.read_csv(os.path.join(a.outdir, "vein.csv"), need=("t",))[1]
    title = vc.case_title(info, a.outdir)  # the run's parameters (run.json)

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for n in seeds:
        k = int(n[5:])
        ax.plot(t, data[n], marker="o", ms=3, label=LABELS.get(k, n))
    ax.set_xlabel("t [s]")
    ax.set_ylabel("clot size [particles]")
    ax.set_title("clot growth per seed (Fig. 4.11 analogue)")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    out = vc.output_path(a.out, a.outdir, "clots.png")
    fig.savefig(out, dpi=130)
    print(f"wrote {out}: {len(t)} rows, final sizes " + ", ".join(f"{n} {int(data[n][-1])}" for n in seeds))

    # the last snapshot: the whole valve, then a zoom on each clot (the
    # connected components of the clot bonds)
    tt, snap = vc.snapshots(a.outdir)[-1]
    d = vc.read_snapshot(snap, ("x", "type", "bonds"))
    x, ty, bonds = d["x"], d["type"].ravel(), d["bonds"]
    clot = ty == CLOT
    cb = bonds[(ty[bonds[:, 0]] == CLOT) & (ty[bonds[:, 1]] == CLOT)]
    parent = {int(i): int(i) for i in np.flatnonzero(clot)}

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for i, j in cb:
        parent[root(int(i))] = root(int(j))
    comps = {}
    for i in parent:
        comps.setdefault(root(i), []).append(i)
    comps = sorted(comps.values(), key=len, reverse=True)[:3]
    fig, axes = plt.subplots(1, 1 + len(comps), figsize=(5 + 3.2 * len(comps), 4.2),
                             gridspec_kw={"width_ratios": [2.2] + [1] * len(comps)})
    axes = np.atleast_1d(axes)
    for ax in axes:
        for typ, colour, size in ((0, "#9ecae1", 2), (1, "#777777", 2), (2, "#2ca02c", 4)):
            m = ty == typ
            ax.scatter(x[m, 0] * 1e3, x[m, 1] * 1e3, s=size, c=colour, lw=0)
        for i, j in cb:
            if abs(x[i, 0] - x[j, 0]) < 0.01:  # not across the periodic seam
                ax.plot([x[i, 0] * 1e3, x[j, 0] * 1e3], [x[i, 1] * 1e3, x[j, 1] * 1e3], c="k", lw=0.8)
        ax.scatter(x[clot, 0] * 1e3, x[clot, 1] * 1e3, s=12, c="#d62728", lw=0, label="clot", zorder=3)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]")
    axes[0].set_ylabel("y [mm]")
    axes[0].set_title(f"t = {tt:.3g} s: {int(clot.sum())} clot particles, {len(cb)} clot bonds")
    axes[0].legend(loc="lower right", fontsize=8)
    for ax, c in zip(axes[1:], comps):
        p = x[c] * 1e3
        mid, half = 0.5 * (p.min(axis=0) + p.max(axis=0)), 0.5 * max(np.ptp(p[:, 0]), np.ptp(p[:, 1])) + 1.5
        ax.set_xlim(mid[0] - half, mid[0] + half)
        ax.set_ylim(mid[1] - half, mid[1] + half)
        ax.set_title(f"clot of {len(c)} particles")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    out = vc.output_path(a.out, a.outdir, "clots_snapshot.png")
    fig.savefig(out, dpi=130)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
