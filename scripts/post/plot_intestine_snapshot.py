#!/usr/bin/python3
"""Snapshots of a colon (scene intestine) run, as the thesis's Figs. 3.3 and
3.10: one panel per chosen time of a wave, each with the membrane, the walls,
the liquid, the tracked white set (the liquid first in pocket 0) and the red
set (with -intestine_red) in their own colours, the pocket boundaries (the
folds x = k b, pockets numbered 0 .. N from the closed end), the wave's value
per pocket over the sub-period before that time (+1 up, -1 down: what shaped
the membrane drawn) and a time stamp as a multiple of the sub-period t_w
counted from the wave's start.

  plot_intestine_snapshot.py RUN_DIR [--at 0,1,2,3,4,5] [--wave 1]
                             [--pockets 0-3] [--out PNG]

--at       the panels' times, in t_w after the start of wave --wave (the
           wave starts at t_d + (wave - 1) T_w); each panel shows the snapshot
           closest to its time and is stamped with that snapshot's own time
           in t_w (and in seconds)
--wave     which wave (1 = the first; default 1)
--pockets  the pockets drawn, "A-B" or "A" (default: all, and the overflow weir)
--out      the PNG (default RUN_DIR/intestine-snapshots.png)

t_w, T_w, t_d, b and the pocket count come from the '# intestine:' line of
RUN_DIR/intestine.csv, the snapshots from RUN_DIR/snap_*.h5 (the run needs
snapshots: not -output_snapshots false). Works on a run still going. Exits
with status 1 and one line naming the cause when the directory, intestine.csv
or the snapshots are missing, or a time is not covered by the snapshots.
"""
import argparse
import json
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import intestine_common as ic  # noqa: E402
from snapshot_files import marker_size, snapshot_files  # noqa: E402

PROG = "plot_intestine_snapshot.py"
FLUID, WALL, SOLID = 0, 1, 2  # particle types (snapshot field "type")
WHITE, RED = 1, 2             # tracer values of the tracked sets
COLOURS = {"liquid": "#4f8fd6", "white": "white", "red": "#d62728", "membrane": "#3b2a1a",
           "wall": "0.45", "background": "0.78"}


def die(msg):
    ic.die(PROG, msg)


def snapshots(run_dir):
    return snapshot_files(run_dir, die)


def read_snapshot(path):
    import h5py

    try:
        f = h5py.File(path, "r")
    except OSError as e:
        die(f"{path}: cannot open ({e})")
    with f:
        for name in ("x", "type", "tracer"):
            if f"particles/{name}" not in f:
                die(f"{path}: no dataset /particles/{name} (not an intestine run?)")
        return {"x": f["particles/x"][()][:, :2], "type": f["particles/type"][()],
                "tracer": f["particles/tracer"][()], "time": float(np.ravel(f.attrs["time"])[0])}


def run_options(run_dir):
    """-sph_nu and -peristalsis_h from run.json (None when absent)."""
    try:
        with open(os.path.join(run_dir, "run.json")) as f:
            opts = json.load(f).get("options", "")
    except (OSError, ValueError):
        return None, None
    nu = re.findall(r"-sph_nu\s+(\S+)", opts)
    H = re.findall(r"-peristalsis_h\s+(\d+)", opts)
    return (nu[-1] if nu else None), (int(H[-1]) if H else 2)


def parse_pockets(text, n):
    m = re.fullmatch(r"\s*(\d+)\s*(?:-\s*(\d+))?\s*", text)
    if not m:
        die(f"--pockets {text!r}: expected A-B or A")
    a = int(m.group(1))
    b = int(m.group(2)) if m.group(2) is not None else a
    if not 0 <= a <= b < n:
        die(f"--pockets {text}: the run has pockets 0..{n - 1}")
    return a, b


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--at", default="0,1,2,3,4,5", help="times in t_w after the wave's start")
    ap.add_argument("--wave", type=int, default=1)
    ap.add_argument("--pockets", default=None)
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    if not os.path.isdir(a.run_dir):
        die(f"{a.run_dir}: no such directory")
    series = os.path.join(a.run_dir, "intestine.csv")
    info = ic.read_comment(series, PROG)
    d, names = ic.read_series(series, PROG)
    try:
        at = [float(v) for v in a.at.split(",") if v.strip()]
    except ValueError:
        die(f"--at {a.at!r}: expected numbers (multiples of t_w) separated by commas")
    if not at:
        die("--at: no time given")
    if a.wave < 1:
        die(f"--wave {a.wave}: waves count from 1")
    n_pockets, b, tw, Tw = int(info["pockets"]), info["b"], info["t_w"], info["T_w"]
    dx = info.get("dx", b / 80)
    if "t_d" in info:
        t_d = info["t_d"]
    else:  # a run written before the comment named it: the first row of the wave
        started = np.where(d["sub"] >= 0)[0]
        if len(started) == 0:
            die(f"{series}: the wave never started (sub < 0 in every row)")
        t_d = d["t"][started[0]]
    t_wave = t_d + (a.wave - 1) * Tw
    snaps = snapshots(a.run_dir)
    times = np.array([s[0] for s in snaps])
    spacing = np.median(np.diff(times)) if len(times) > 1 else tw
    chosen = []
    for k in at:
        want = t_wave + k * tw
        i = int(np.argmin(np.abs(times - want)))
        if abs(times[i] - want) > 0.5 * spacing + 1e-9:
            die(f"no snapshot near t = {want:.6g} s ({k:g} t_w into wave {a.wave}): the snapshots span "
                f"{times[0]:.6g} .. {times[-1]:.6g} s")
        chosen.append((k, snaps[i]))

    p0, p1 = parse_pockets(a.pockets, n_pockets) if a.pockets else (0, n_pockets - 1)
    x_lo = p0 * b - (2.5 * dx if p0 == 0 else 0.0)
    x_hi = (p1 + 1) * b + (2.5 * dx if p1 == n_pockets - 1 else 0.0)
    frames = [(k, read_snapshot(p)) for k, (_, p) in chosen]
    # a common y-range: the membrane's bottom to the highest liquid in view
    y_lo, y_hi = math.inf, -math.inf
    for _, f in frames:
        sel = (f["x"][:, 0] >= x_lo) & (f["x"][:, 0] <= x_hi) & (f["type"] != WALL)
        if sel.any():
            y_lo = min(y_lo, f["x"][sel, 1].min())
            y_hi = max(y_hi, f["x"][sel, 1].max())
    if not math.isfinite(y_lo):
        die(f"no particle in x = [{x_lo:.4g}, {x_hi:.4g}] m")
    y_lo -= 3 * dx
    y_hi += 0.25 * (y_hi - y_lo)  # room for the wave's marks
    aspect = (x_hi - x_lo) / (y_hi - y_lo)
    ncols = 1 if aspect >= 4 or len(frames) == 1 else 2
    nrows = math.ceil(len(frames) / ncols)
    width = 15.0
    panel_h = width / ncols / aspect + 0.45
    fig, axes = plt.subplots(nrows, ncols, figsize=(width, nrows * panel_h + 0.9), squeeze=False)
    nu, H = run_options(a.run_dir)
    red_any = False
    s_cols = [f"s_{k}" for k in range(n_pockets)]
    for ax, (k, f) in zip(axes.flat, frames):
        x, typ, tr = f["x"], f["type"], f["tracer"]
        view = (x[:, 0] >= x_lo - dx) & (x[:, 0] <= x_hi + dx)
        ax.set_xlim(x_lo * 100, x_hi * 100)
        ax.set_ylim(y_lo * 100, y_hi * 100)
        ax.set_aspect("equal")
        ax.set_facecolor(COLOURS["background"])
        size = marker_size(ax, dx * 100) * 0.9
        groups = (("wall", view & (typ == WALL)), ("membrane", view & (typ == SOLID)),
                  ("liquid", view & (typ == FLUID) & (tr != WHITE) & (tr != RED)),
                  ("white", view & (typ == FLUID) & (tr == WHITE)),
                  ("red", view & (typ == FLUID) & (tr == RED)))
        for name, sel in groups:
            if sel.any():
                ax.scatter(x[sel, 0] * 100, x[sel, 1] * 100, s=size, c=COLOURS[name], marker="o",
                           linewidths=0, rasterized=True,
                           label={"white": "white set (pocket 0)", "red": "red set"}.get(name, name))
                red_any = red_any or name == "red"
        # the folds between pockets and the wave's value per pocket over the sub-period that
        # led to this shape (the row half a t_w earlier: never on a sub-period's boundary)
        row = int(np.argmin(np.abs(d["t"] - (f["time"] - 0.5 * tw))))
        for j in range(p0, p1 + 2):
            ax.axvline(j * b * 100, color="k", ls="--", lw=0.6, alpha=0.6)
        for j in range(p0, p1 + 1):
            sv = int(d[s_cols[j]][row]) if s_cols[j] in d else 0
            mark = {1: "+1", -1: "-1"}.get(sv, "")
            ax.text((j + 0.5) * b * 100, y_hi * 100 - 0.04 * (y_hi - y_lo) * 100,
                    f"pocket {j}" + (f"  {mark}" if mark else ""), ha="center", va="top", fontsize=8,
                    color="darkred" if sv > 0 else ("navy" if sv < 0 else "k"))
        stamp = round((f["time"] - t_wave) / tw, 2) + 0.0  # + 0.0: no "-0"
        ax.set_title(f"t = {stamp:.3g} t_w" + (f" (wanted {k:g} t_w)" if abs(stamp - k) > 0.05 else "")
                     + f"   [t = {f['time']:.4g} s, wave {a.wave}]", fontsize=9, loc="left")
        ax.set_ylabel("y [cm]", fontsize=8)
        ax.tick_params(labelsize=7)
    for ax in axes.flat[len(frames):]:
        ax.axis("off")
    for ax in axes[-1]:
        ax.set_xlabel("x [cm]", fontsize=8)
    handles, labels = axes.flat[0].get_legend_handles_labels()
    for ax, _ in zip(axes.flat, frames):  # the red set may show only in some panels
        for h, l in zip(*ax.get_legend_handles_labels()):
            if l not in labels:
                handles.append(h)
                labels.append(l)
    leg = fig.legend(handles, labels, loc="lower center", fontsize=8, ncol=len(labels), markerscale=3,
                     facecolor=COLOURS["background"])
    leg.get_frame().set_edgecolor("0.5")
    title = (f"Colon: {n_pockets} pockets of b = {b * 100:g} cm, L = {info.get('level', math.nan) * 100:.3g} cm"
             + (f", nu = {nu} m²/s" if nu else "") + (f", H = {H}" if H else "")
             + f", t_w = {tw:g} s, T_w = {Tw:g} s, V_w = {n_pockets * b / Tw * 100:.3g} cm/s; "
             f"+1/-1: the wave pushed a pocket up/down over the last t_w")
    fig.suptitle(title, fontsize=10, x=0.01, ha="left")
    out = a.out or os.path.join(a.run_dir, "intestine-snapshots.png")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.tight_layout(rect=(0, 0.45 / fig.get_figheight(), 1, 1 - 0.3 / fig.get_figheight()))
    fig.savefig(out + ".tmp.png", dpi=130)
    os.replace(out + ".tmp.png", out)
    print(f"{PROG}: wrote {out} ({len(frames)} panels, wave {a.wave}, t = "
          + ", ".join(f"{round((f['time'] - t_wave) / tw, 2) + 0.0:g}" for _, f in frames) + " t_w)")


if __name__ == "__main__":
    main()
