#!/usr/bin/python3
"""Tip displacement and slip of a flap run against time, and the settled flow.

  scripts/post/plot_flap.py OUTDIR [--out DIR]

Reads OUTDIR/flap.csv (t [s], tip_dx, tip_dy [m], crossings, slip, near
[1, over u_max], u_max [m/s]; the header gives the flap height) and writes
into --out (default: OUTDIR):
  flap_history.png  top: the tip displacement along and across the flow against
                    t, in um and as a fraction of the flap height, with the
                    mean over the last quarter of the run (the window
                    test/validation/flap.py checks); bottom: the slip on the
                    flap's faces |u(d=0) - v_flap|/u_max and the first fluid
                    layer's relative speed, with u_max on the right axis
  flap_flow.png     the particles at the end of the run (OUTDIR/flap-particles.csv,
                    written by the scene's finish): liquid coloured by |v| with
                    arrows, walls grey, the flap red; only when that file exists
Prints the last-quarter means. Exits non-zero when flap.csv is missing, has
fewer than two rows or lacks a column.
"""
import argparse
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

COLUMNS = ("t", "tip_dx", "tip_dy", "crossings", "slip", "near", "u_max")


def fail(msg):
    sys.exit(f"plot_flap: {msg}")


def read(path):
    try:
        with open(path) as f:
            header = f.readline()
            data = np.genfromtxt(f, delimiter=",", names=True)
    except OSError as e:
        fail(f"cannot read {path}: {e.strerror}")
    m = re.search(r"height ([0-9.eE+-]+) m", header)
    if not m:
        fail(f"{path}: first line has no '# flap: height ... m'")
    if data.dtype.names is None or any(c not in data.dtype.names for c in COLUMNS):
        fail(f"{path}: needs the columns {','.join(COLUMNS)}")
    data = np.atleast_1d(data)
    if len(data) < 2:
        fail(f"{path}: {len(data)} data row(s), need at least 2")
    return float(m.group(1)), data


def history(outdir, height, d, out):
    t, um = d["t"], 1e6
    last = t >= 0.75 * t[-1]
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True)
    ax.plot(t, d["tip_dx"] * um, "C0-", label="tip_dx (along the flow)")
    ax.plot(t, d["tip_dy"] * um, "C1-", label="tip_dy (across)")
    mean = d["tip_dx"][last].mean()
    ax.hlines(mean * um, t[last][0], t[-1], colors="k", linestyles="--",
              label=f"mean over the last quarter: {mean * um:.4g} µm = {mean / height:.4f} of the height")
    ax.set_ylabel("tip displacement [µm]")
    sec = ax.secondary_yaxis("right", functions=(lambda y: y / (height * um), lambda f: f * height * um))
    sec.set_ylabel("tip displacement / flap height [1]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title(f"flap of height {height * 1e3:.3g} mm: fluid crossings {int(d['crossings'][-1])} "
                 f"(must stay 0)", fontsize=10)

    bx.plot(t, d["slip"], "C3-", lw=1, label="slip on the faces |u(d=0) - v_flap| / u_max")
    bx.plot(t, d["near"], "C2-", lw=1, alpha=0.7, label="first fluid layer |u - v_flap| / u_max")
    bx.set_ylabel("relative speed / u_max [1]")
    bx.set_xlabel("t [s]")
    bx.set_ylim(bottom=0)
    bx.grid(alpha=0.3)
    cx = bx.twinx()
    cx.plot(t, d["u_max"] * 1e3, "k:", lw=1, label="u_max (right axis)")
    cx.set_ylabel("u_max, largest fluid speed [mm/s]")
    cx.set_ylim(bottom=0)
    lines = bx.get_legend_handles_labels()
    more = cx.get_legend_handles_labels()
    bx.legend(lines[0] + more[0], lines[1] + more[1], fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    slip = np.nanmean(d["slip"][last])
    print(f"flap: last quarter ({t[last][0]:.3g}-{t[-1]:.3g} s): tip_dx {mean:.5g} m = {mean / height:.4f} of the "
          f"height, slip {slip:.4f} u_max, u_max {d['u_max'][last].mean():.4g} m/s; "
          f"crossings {int(d['crossings'][-1])}")
    print(f"wrote {out}")


def flow(outdir, height, t_end, tip_end, out):
    path = os.path.join(outdir, "flap-particles.csv")
    q = np.genfromtxt(path, delimiter=",", names=True)
    if q.dtype.names is None or any(c not in q.dtype.names for c in ("x", "y", "vx", "vy", "type")):
        fail(f"{path}: needs the columns x,y,vx,vy,type")
    mm = 1e3
    fl = q["type"] == 0
    sp = np.hypot(q["vx"], q["vy"])
    fig, ax = plt.subplots(figsize=(8, 5))
    sc = ax.scatter(q["x"][fl] * mm, q["y"][fl] * mm, c=sp[fl] * mm, s=6, cmap="viridis")
    ax.quiver(q["x"][fl] * mm, q["y"][fl] * mm, q["vx"][fl], q["vy"][fl], scale=max(sp.max(), 1e-30) * 40,
              width=0.0015)
    ax.scatter(q["x"][q["type"] == 1] * mm, q["y"][q["type"] == 1] * mm, c="grey", s=6, label="wall")
    ax.scatter(q["x"][q["type"] == 2] * mm, q["y"][q["type"] == 2] * mm, c="red", s=10, label="flap")
    fig.colorbar(sc, label="|v| [mm/s]")
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(f"flap at t = {t_end:.3g} s: tip displacement {tip_end / height:.3f} of the height", fontsize=10)
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"wrote {out}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--out", help="directory for the PNGs (default: OUTDIR)")
    a = ap.parse_args()
    if not os.path.isdir(a.outdir):
        fail(f"{a.outdir}: no such output directory")
    height, d = read(os.path.join(a.outdir, "flap.csv"))
    outdir = a.out or a.outdir
    os.makedirs(outdir, exist_ok=True)
    history(a.outdir, height, d, os.path.join(outdir, "flap_history.png"))
    if os.path.exists(os.path.join(a.outdir, "flap-particles.csv")):
        flow(a.outdir, height, d["t"][-1], d["tip_dx"][-1], os.path.join(outdir, "flap_flow.png"))


if __name__ == "__main__":
    main()
