#!/usr/bin/python3
"""Any field of any snapshot of any run, as a contour map of the kernel-interpolated field.

  scripts/post/plot_fields.py OUTDIR [--field NAME] [--time T | --step N] [--out PNG]
  scripts/post/plot_fields.py OUTDIR --list [--time T | --step N]
  scripts/post/plot_fields.py OUTDIR --field NAME --animate OUT.gif|OUT.mp4
                              [--from T0] [--to T1] [--every K] [--fps F]

Reads the run's snapshots (OUTDIR/particles.xdmf for their times and files, else
OUTDIR/snap_*.h5), picks the one nearest --time [s] (or --step, the time step
number; default: the last snapshot) and draws NAME, any dataset of /particles
(--list prints them with their units): a scalar (rho, p, shear_rate, ...), a
vector's magnitude (v, a) or one component (v_x, v_y). The field of the
particles it is drawn for (--over: the liquid, type 0, by default; the solids,
type 2, in a run without liquid) is interpolated onto a regular grid with the
run's SPH kernel and support radius h (the snapshot's sph_kernel and sph_h;
scripts/post/sph_grid.py), Shepard-normalised and blank where their kernel sum
is below 0.5 (outside them); across a periodic boundary of the box (the
snapshot's box_lo, box_hi and periodic) the sums take the nearest image. Walls
(type 1) are drawn grey, solids (type 2) black, clots (type 3) dark red, each
particle about dx wide. Axes in m, mm or um (whichever suits the box), the
colour bar in the field's unit; the title gives the scene, the physics options
the run was given (run.json) and the snapshot's time and step.

The colour scale runs from the 0.5th to the 99.5th percentile of the map (an
arrow on the colour bar: values beyond it exist), symmetric about 0 on a
diverging map when the field takes both signs (the smaller side at least a
tenth of the larger); --vmin and --vmax fix it. An
animation uses one scale for all its frames.

  --field NAME      the field (default: speed where the run writes it, else v)
  --time T          the snapshot nearest T [s]; a T outside the snapshots' times
                    (by more than half their spacing) is an error
  --step N          the snapshot nearest time step N
  --list            print the fields of that snapshot with their units and exit
  --over WHICH      liquid, solid or all (every particle but walls)
  --window X0,X1,Y0,Y1  the region [mm] (default: the particles' extent)
  --nx N            grid points along x (default 800; 400 for an animation)
  --vmin, --vmax    the colour scale's ends (in the field's unit)
  --cmap NAME       a matplotlib colour map (default viridis; RdBu_r for signed)
  --out PATH        the PNG (default OUTDIR/field_<NAME>_<snapshot>.png)
  --animate OUT     a time series instead: every snapshot from --from to --to [s]
                    (default all), every --every-th (default 1), at --fps frames
                    per second (default 10), written by matplotlib's animation
                    writers: PillowWriter for .gif (needs pillow: python3-pil),
                    FFMpegWriter for .mp4 (needs ffmpeg on PATH)

Every error is one line on stderr and exit status 1: a missing directory, no
snapshot, an unknown field (with the list of fields), a time outside the run.
"""
import argparse
import math
import os
import re
import shutil
import sys
import textwrap
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import sph_grid as sg  # noqa: E402
import vein_common as vc  # noqa: E402

FLUID, WALL, SOLID, CLOT = 0, 1, 2, 3
H_OVER_DX = 2.5  # the scenes' usual h/dx, for snapshots without sph_h
# options that steer the run but not its physics: left out of the title
RUN_CONTROL = {"output_dir", "output_interval", "output_snapshots", "progress_interval", "quiet",
               "checkpoint_interval", "checkpoint_at_end", "restart", "restart_allow_change", "dump_final",
               "debug_migration", "debug_halo", "partition_imbalance", "partition_interval", "preflight",
               "options_file", "help", "t_end", "log_view", "dmhs_traceback", "scene"}


def fail(msg):
    vc.fail(msg)


# ---------------------------------------------------------------- the run's snapshots

def snapshot_list(run_dir):
    """[(time, path)] sorted by time: particles.xdmf's index (each step's Time and the
    file of its particles), else the snap_*.h5 files' time attributes."""
    xdmf = os.path.join(run_dir, "particles.xdmf")
    out = []
    if os.path.isfile(xdmf):
        try:
            root = ET.parse(xdmf).getroot()
        except ET.ParseError as e:
            fail(f"{xdmf}: not valid XML ({e})")
        for grid in root.iter("Grid"):
            time = grid.find("Time")
            if time is None:
                continue
            item = next((d for d in grid.iter("DataItem") if d.text and ".h5:" in d.text), None)
            if item is None:
                continue
            name = item.text.strip().split(":", 1)[0]
            out.append((float(time.get("Value")), os.path.join(run_dir, name)))
        out = [(t, p) for t, p in out if os.path.isfile(p)]
    if not out:
        if not any(n.startswith("snap_") and n.endswith(".h5") for n in os.listdir(run_dir)):
            fail(f"{run_dir}: no snapshot (no particles.xdmf, no snap_*.h5; was the run given "
                 f"-output_snapshots false?)")
        out = vc.snapshots(run_dir)
    return sorted(out)


def tolerance(times):
    """Half the snapshots' median spacing [s]: how far outside them a time may lie."""
    return 0.5 * float(np.median(np.diff(times))) if len(times) > 1 else 0.0


def pick_time(snaps, t):
    """The (time, path) nearest t; t outside the snapshots' span is an error."""
    times = np.array([s[0] for s in snaps])
    tol = tolerance(times)
    if not (times[0] - tol <= t <= times[-1] + tol):
        fail(f"--time {t:g} s is outside the run: its {len(times)} snapshot(s) span t = {times[0]:g} .. "
             f"{times[-1]:g} s")
    return snaps[int(np.argmin(np.abs(times - t)))]


def pick_step(snaps, step):
    """The (time, path) whose step attribute is nearest step; outside them an error."""
    import h5py

    steps = []
    for _, p in snaps:
        with h5py.File(p, "r") as f:
            steps.append(int(np.ravel(f.attrs.get("step", [-1]))[0]))
    steps = np.array(steps)
    if not (steps.min() <= step <= steps.max()):
        fail(f"--step {step} is outside the run: its snapshots are at steps {steps.min()} .. {steps.max()}")
    return snaps[int(np.argmin(np.abs(steps - step)))]


# ---------------------------------------------------------------- fields

def field_table(path):
    """{dataset: (unit, width)} of a snapshot's /particles."""
    import h5py

    try:
        with h5py.File(path, "r") as f:
            if "particles" not in f:
                fail(f"{path}: no /particles group (not a dmhs snapshot)")
            out = {}
            for name, ds in f["particles"].items():
                unit = ds.attrs.get("unit", b"")
                unit = unit.decode() if isinstance(unit, bytes) else str(unit)
                out[name] = (unit, ds.shape[1] if ds.ndim == 2 else 1)
            return out
    except OSError as e:
        fail(f"{path}: cannot open ({e})")


def field_names(table):
    """Every name --field takes: scalars, and per vector its magnitude and components."""
    names = []
    for name, (_, width) in sorted(table.items()):
        names.append(name)
        if width > 1:
            names += [f"{name}_x", f"{name}_y"]
    return names


def list_fields(table, path, t):
    print(f"fields of {path} (t = {t:g} s), for --field:")
    for name, (unit, width) in sorted(table.items()):
        kind = "scalar" if width == 1 else f"vector: {name} (magnitude), {name}_x, {name}_y"
        print(f"  {name:<16} [{unit or '1'}]  {kind}")


def resolve_field(name, table, path):
    """(dataset, component: None (scalar), 'mag', 0 or 1, unit, label)."""
    if name in table:
        unit, width = table[name]
        return name, (None if width == 1 else "mag"), unit, (name if width == 1 else f"|{name}|")
    m = re.match(r"^(.*)_(x|y|mag)$", name)
    if m and m.group(1) in table and table[m.group(1)][1] > 1:
        base, comp = m.group(1), m.group(2)
        unit = table[base][0]
        if comp == "mag":
            return base, "mag", unit, f"|{base}|"
        return base, "xy".index(comp), unit, name
    fail(f"unknown field '{name}' in {os.path.basename(path)}; fields: {', '.join(field_names(table))}")


def read_state(path, dataset, comp):
    """{'x' (n, 2), 'type', 'mass', 'rho' (or None), 'value' (n,), 'meta'} of a snapshot."""
    import h5py

    with h5py.File(path, "r") as f:
        p = f["particles"]
        for need in ("x", "type", dataset):
            if need not in p:
                fail(f"{path}: no dataset /particles/{need}")
        a = p[dataset][()]
        if comp == "mag":
            value = np.sqrt(np.sum(a[:, :2].astype(float) ** 2, axis=1))
        elif comp is None:
            value = np.asarray(a, float).ravel()
        else:
            value = np.asarray(a[:, comp], float)
        return {"x": p["x"][:, :2], "type": p["type"][()].ravel(), "value": value,
                "mass": p["mass"][()] if "mass" in p else None, "rho": p["rho"][()] if "rho" in p else None,
                "meta": sg.snapshot_meta(f)}


# ---------------------------------------------------------------- the map

def spacing_of(st):
    """The rest spacing dx [m]: the snapshot's, else the median nearest-neighbour distance."""
    if st["meta"]["dx"]:
        return st["meta"]["dx"]
    x = st["x"][st["type"] != WALL] if (st["type"] != WALL).any() else st["x"]
    sample = x[:: max(1, len(x) // 2000)]
    d = np.sqrt(((sample[:, None, :] - x[None, :, :]) ** 2).sum(-1))
    d[d == 0] = np.inf
    return float(np.median(d.min(axis=1)))


def support(st, opts):
    """(h [m], kernel, how): the snapshot's sph_h and sph_kernel, else -sph_h, else 2.5 dx."""
    meta = st["meta"]
    if meta["h"]:
        return meta["h"], meta["kernel"] or "lucy", "the snapshot's sph_h"
    kernel = opts.get("sph_kernel") or "lucy"
    try:
        return float(opts["sph_h"]), kernel, "-sph_h"
    except (KeyError, ValueError):
        return H_OVER_DX * spacing_of(st), kernel, f"{H_OVER_DX:g} dx (no sph_h in the snapshot)"


def selection(st, over):
    t = st["type"]
    if over == "auto":
        over = "liquid" if (t == FLUID).any() else "solid"
    if over == "liquid":
        sel = t == FLUID
    elif over == "solid":
        sel = t == SOLID
    else:
        sel = t != WALL
    return sel, over


def box_of(st):
    """(lo, hi, periods): the snapshot's box, or the particles' extent and no period."""
    meta = st["meta"]
    if meta["box_lo"] is not None and meta["box_hi"] is not None and meta["periodic"] is not None:
        lo, hi = meta["box_lo"][:2], meta["box_hi"][:2]
        periods = tuple((hi[k] - lo[k]) if meta["periodic"][k] else None for k in range(2))
        return lo, hi, periods
    return st["x"].min(axis=0), st["x"].max(axis=0), (None, None)


def length_unit(extent):
    """(scale, name) for lengths [m] whose extent lies in [1, 1000) of the unit."""
    for scale, name in ((1.0, "m"), (1e3, "mm"), (1e6, "µm")):
        if extent * scale >= 1.0:
            return scale, name
    return 1e6, "µm"


def default_window(st, dx, periods, lo, hi):
    """The particles' extent widened by dx, within the box along periodic directions."""
    x = st["x"]
    w = []
    for k in range(2):
        if periods[k]:
            w += [lo[k], hi[k]]
        else:
            w += [x[:, k].min() - dx, x[:, k].max() + dx]
    return w


def parse_window(text):
    try:
        v = [float(s) * 1e-3 for s in text.split(",")]
    except ValueError:
        v = []
    if len(v) != 4 or not (v[1] > v[0] and v[3] > v[2]):
        fail(f"--window {text!r}: expected X0,X1,Y0,Y1 in mm with X1 > X0 and Y1 > Y0")
    return v


def grid_field(st, window, nx, h, kernel, periods, lo, sel, dx):
    x0, x1, y0, y1 = window
    gx, gy = sg.grid_axes(x0, x1, y0, y1, (x1 - x0) / nx)
    X, Y = np.meshgrid(gx, gy)
    if st["mass"] is not None and st["rho"] is not None:
        with np.errstate(divide="ignore", invalid="ignore"):
            vol = st["mass"][sel] / st["rho"][sel]
        vol = np.where(np.isfinite(vol) & (vol > 0), vol, dx * dx)
    else:
        vol = np.full(int(sel.sum()), dx * dx)
    f, S = sg.interpolate(st["x"][sel, 0], st["x"][sel, 1], vol, st["value"][sel], X.ravel(), Y.ravel(), h,
                          period=periods, origin=tuple(lo), kernel=kernel)
    S = S.reshape(X.shape)
    a = f[:, 0].reshape(X.shape)
    return gx, gy, np.ma.masked_array(a, mask=~(S >= sg.MASK_THRESHOLD) | ~np.isfinite(a))


def colour_scale(maps, vmin, vmax, cmap):
    """(vmin, vmax, cmap, extend) over the unmasked values of maps."""
    vals = np.concatenate([np.ma.compressed(m) for m in maps]) if maps else np.zeros(0)
    vals = vals[np.isfinite(vals)]
    lo_all, hi_all = (float(vals.min()), float(vals.max())) if vals.size else (0.0, 1.0)
    lo, hi = (float(np.percentile(vals, 0.5)), float(np.percentile(vals, 99.5))) if vals.size else (0.0, 1.0)
    signed = lo < 0 < hi and min(-lo, hi) >= 0.1 * max(-lo, hi)  # both signs, both sizeable
    if signed and vmin is None and vmax is None:
        m = max(-lo, hi)
        lo, hi = -m, m
    lo = vmin if vmin is not None else lo
    hi = vmax if vmax is not None else hi
    if not hi > lo:  # a uniform field
        pad = abs(hi) * 1e-6 or 1e-12
        lo, hi = lo - pad, hi + pad
    cmap = cmap or ("RdBu_r" if signed else "viridis")
    below, above = lo_all < lo - 1e-12 * abs(lo), hi_all > hi + 1e-12 * abs(hi)
    extend = "both" if below and above else "min" if below else "max" if above else "neither"
    return lo, hi, cmap, extend


def draw_particles(ax, st, scale, dx):
    """Walls grey squares, solids black and clots dark red dots, about dx wide."""
    x, t = st["x"] * scale, st["type"]
    s = vc.marker_size(ax, dx * scale)
    for typ, colour, marker in ((WALL, "0.62", "s"), (SOLID, "k", "o"), (CLOT, "#8b1a1a", "o")):
        m = t == typ
        if m.any():
            ax.scatter(x[m, 0], x[m, 1], s=s, c=colour, marker=marker, linewidths=0, zorder=3)


def run_options_text(run_dir, st):
    """The physics options the run was given, from run.json (else the snapshot's)."""
    opts = vc.run_options(run_dir)
    if opts is None:
        opts = sg.parse_options(st["meta"]["options"])
    keep = [f"-{k} {v}".strip() for k, v in sorted(opts.items())
            if k not in RUN_CONTROL and not k.startswith(("log_", "malloc", "info"))]
    return opts, " ".join(keep)


def ticks_scaled(cb, lo, hi):
    """Colour bar ticks counted in a power of ten when the values are small or large."""
    import matplotlib.ticker as mticker

    m = max(abs(lo), abs(hi))
    e = int(math.floor(math.log10(m))) if m > 0 and (m < 0.01 or m >= 1e4) else 0
    if e:
        cb.ax.yaxis.set_major_formatter(mticker.FuncFormatter(lambda v, _: f"{v / 10.0 ** e:.3g}"))
    return e


def title_text(scene, options, label, unit, st, snap, h, kernel, how, over, lscale, lunit):
    step = st["meta"]["step"]
    head = f"{scene or 'dmhs'}: " + (options or "the scene's defaults")
    lines = textwrap.wrap(head, 110) or [head]
    lines.append(f"{label} [{unit or '1'}] of the {over} at t = {st['meta']['time']:.6g} s (step {step}, "
                 f"{os.path.basename(snap)}), {kernel} kernel h = {h * lscale:.3g} {lunit} ({how}); "
                 f"walls grey, solids black")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir", metavar="OUTDIR", help="output directory of a dmhs run")
    ap.add_argument("--field", default=None)
    when = ap.add_mutually_exclusive_group()
    when.add_argument("--time", type=float, default=None)
    when.add_argument("--step", type=int, default=None)
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--over", choices=("auto", "liquid", "solid", "all"), default="auto")
    ap.add_argument("--window", default=None)
    ap.add_argument("--nx", type=int, default=None)
    ap.add_argument("--vmin", type=float, default=None)
    ap.add_argument("--vmax", type=float, default=None)
    ap.add_argument("--cmap", default=None)
    ap.add_argument("--levels", type=int, default=24)
    ap.add_argument("--out", default=None)
    ap.add_argument("--animate", default=None, metavar="OUT")
    ap.add_argument("--from", dest="t_from", type=float, default=None)
    ap.add_argument("--to", dest="t_to", type=float, default=None)
    ap.add_argument("--every", type=int, default=1)
    ap.add_argument("--fps", type=float, default=10.0)
    args = ap.parse_args()
    vc.require_dir(args.outdir)
    if args.nx is not None and args.nx < 2:
        fail(f"--nx {args.nx}: at least 2 grid points")
    if args.every < 1:
        fail(f"--every {args.every}: at least 1")
    if args.cmap:
        try:
            matplotlib.colormaps[args.cmap]
        except KeyError:
            fail(f"--cmap {args.cmap}: not a matplotlib colour map")
    writer_cls = None
    if args.animate:
        from matplotlib import animation

        ext = os.path.splitext(args.animate)[1].lower()
        if ext == ".gif":
            try:
                import PIL  # noqa: F401
            except ImportError:
                fail(f"--animate {args.animate}: a GIF needs pillow, which {sys.executable} cannot import "
                     f"(Debian: apt-get install python3-pil)")
            writer_cls = animation.PillowWriter
        elif ext == ".mp4":
            if not animation.writers.is_available("ffmpeg") or not shutil.which("ffmpeg"):
                fail(f"--animate {args.animate}: an MP4 needs ffmpeg on PATH, and there is none; "
                     f"write a .gif instead")
            writer_cls = animation.FFMpegWriter
        else:
            fail(f"--animate {args.animate}: the file must end in .gif or .mp4")

    snaps = snapshot_list(args.outdir)
    if args.step is not None:
        t_snap, snap = pick_step(snaps, args.step)
    elif args.time is not None:
        t_snap, snap = pick_time(snaps, args.time)
    else:
        t_snap, snap = snaps[-1]
    table = field_table(snap)
    if args.list:
        list_fields(table, snap, t_snap)
        return
    field = args.field or ("speed" if "speed" in table else "v")
    dataset, comp, unit, label = resolve_field(field, table, snap)

    # the frames: one snapshot, or a time series
    if args.animate:
        times = np.array([s[0] for s in snaps])
        tol = tolerance(times)
        for flag, t in (("--from", args.t_from), ("--to", args.t_to)):
            if t is not None and not (times[0] - tol <= t <= times[-1] + tol):
                fail(f"{flag} {t:g} s is outside the run: its {len(times)} snapshot(s) span "
                     f"t = {times[0]:g} .. {times[-1]:g} s")
        t0 = args.t_from if args.t_from is not None else -math.inf
        t1 = args.t_to if args.t_to is not None else math.inf
        frames = [s for s in snaps if t0 - 1e-12 <= s[0] <= t1 + 1e-12][:: args.every]
        if not frames:
            fail(f"--from {args.t_from} --to {args.t_to}: no snapshot between them")
    else:
        frames = [(t_snap, snap)]

    first = read_state(frames[0][1], dataset, comp)
    opts, options = run_options_text(args.outdir, first)
    scene = first["meta"]["scene"]
    dx = spacing_of(first)
    h, kernel, how = support(first, opts)
    if kernel not in sg.KERNELS:
        fail(f"{frames[0][1]}: kernel {kernel!r} is not one of {', '.join(sg.KERNELS)}")
    lo, hi, periods = box_of(first)
    sel, over = selection(first, args.over)
    if not sel.any():
        fail(f"{frames[0][1]}: no {over} particles to interpolate (--over liquid, solid or all)")
    window = parse_window(args.window) if args.window else default_window(first, dx, periods, lo, hi)
    nx = args.nx or (400 if args.animate else 800)

    states, maps = [], []
    for t, path in frames:
        st = first if path == frames[0][1] else read_state(path, dataset, comp)
        s_sel = selection(st, over)[0]
        gx, gy, m = grid_field(st, window, nx, h, kernel, periods, lo, s_sel, dx)
        states.append((st, path))
        maps.append(m)
    vmin, vmax, cmap, extend = colour_scale(maps, args.vmin, args.vmax, args.cmap)
    levels = np.linspace(vmin, vmax, max(2, args.levels) + 1)
    lscale, lunit = length_unit(max(window[1] - window[0], window[3] - window[2]))

    # the figure: the map at its equal aspect, a colour bar, the title above
    pw = 9.0
    ph = min(7.0, max(1.2, pw * (window[3] - window[2]) / (window[1] - window[0])))
    pw = min(pw, ph * (window[1] - window[0]) / (window[3] - window[2])) if ph == 7.0 else pw
    n_title = title_text(scene, options, label, unit, first, frames[0][1], h, kernel, how, over, lscale,
                         lunit).count("\n") + 1
    head, foot, left, right = 0.3 + 0.17 * n_title, 0.65, 0.85, 1.35
    fig = plt.figure(figsize=(left + pw + right, head + ph + foot))
    W, H = left + pw + right, head + ph + foot
    ax = fig.add_axes([left / W, foot / H, pw / W, ph / H])
    cax = fig.add_axes([(left + pw + 0.15) / W, foot / H, 0.18 / W, ph / H])
    sm = matplotlib.cm.ScalarMappable(norm=matplotlib.colors.Normalize(vmin, vmax), cmap=cmap)
    cb = fig.colorbar(sm, cax=cax, extend=extend)
    e = ticks_scaled(cb, vmin, vmax)
    unit_text = f"$10^{{{e}}}$ {unit or '1'}" if e else (unit or "1")
    cb.set_label(f"{label} [{unit_text}]")
    suptitle = fig.text(0.5, 1 - 0.08 / H, "", ha="center", va="top", fontsize=9)

    def draw(k):
        st, path = states[k]
        ax.clear()
        ax.contourf(gx * lscale, gy * lscale, maps[k], levels=levels, cmap=cmap, extend=extend)
        ax.set_xlim(window[0] * lscale, window[1] * lscale)
        ax.set_ylim(window[2] * lscale, window[3] * lscale)
        ax.set_aspect("equal", adjustable="box")
        draw_particles(ax, st, lscale, dx)  # after the limits: the markers' size follows them
        ax.set_xlabel(f"x [{lunit}]")
        ax.set_ylabel(f"y [{lunit}]")
        suptitle.set_text(title_text(scene, options, label, unit, st, path, h, kernel, how, over, lscale, lunit))
        return []

    if not args.animate:
        draw(0)
        name = f"field_{field}_{os.path.splitext(os.path.basename(snap))[0]}.png"
        out = vc.output_path(args.out, args.outdir, name)
        fig.savefig(out, dpi=130)
        print(f"{out}: {label} [{unit or '1'}] at t = {t_snap:g} s, colour scale {vmin:.4g} .. {vmax:.4g}")
        return

    from matplotlib import animation

    os.makedirs(os.path.dirname(os.path.abspath(args.animate)), exist_ok=True)
    anim = animation.FuncAnimation(fig, draw, frames=len(states), blit=False)
    anim.save(args.animate, writer=writer_cls(fps=args.fps), dpi=90)
    print(f"{args.animate}: {len(states)} frame(s) of {label} [{unit or '1'}], t = {frames[0][0]:g} .. "
          f"{frames[-1][0]:g} s, colour scale {vmin:.4g} .. {vmax:.4g}")


if __name__ == "__main__":
    main()
