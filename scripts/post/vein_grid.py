"""Kernel interpolation of a vein snapshot's liquid onto a regular grid, and the
drawing helpers shared by the plot_vein_*.py field maps (scene vein).

  geometry(snap_path, info)   the scene's lengths [m] from the snapshot's 'options'
                              attribute (defaults of src/scenes/vein/vein.c otherwise)
  interpolate(...)            Shepard-normalised SPH sums at arbitrary points
                              (sph_grid.py, the one implementation for every scene)
  liquid_grid(...)            liquid fields on a regular grid, masked outside the liquid
  draw_solids(ax, d, geo)     walls (grey) and leaflets (black), x and y in mm
  leaflets(d)                 each leaflet's two particle layers, sorted root to tip
  PanelGrid, colorbar, setup_map   the map figures' layout (in inches), colour bars
  run_title(outdir, info)     'vein: L = 25.6 mm, g0 = 0.1 m/s², k_a = 0.01 J, T = 4 s,
                              dx = 0.4 mm, ν = 1e-05 m²/s'
  phase(cols, t)              'forward' / 'backward' from the inlet velocity at t
  default_times(cols, T)      the first cycle's forward and backward peaks

Interpolation (the run's kernel and support radius h, the snapshot's sph_kernel
and sph_h; the scene's default Lucy, h = 2.5 dx):
    W(q) = 5 / (pi h^2) (1 + 3q) (1 - q)^3,  q = r/h < 1,
    f(x) = sum_j f_j V_j W(x - x_j) / sum_j V_j W(x - x_j),  V_j = m_j / rho_j,
over the liquid particles only, minimum image in the periodic x (sph_grid.py).
The kernel sum S(x) = sum_j V_j W is ~1 inside the liquid and falls to ~0.5 at
its free edge (half the kernel covered); grid points with S < 0.5 (inside walls
and leaflets, beyond the domain) are masked.
"""
import math
import os
import re

import numpy as np

import vein_common as vc
import sph_grid as sg
from sph_grid import MASK_THRESHOLD, grid_axes, interpolate  # noqa: F401 (the vein scripts use them)

# src/scenes/vein/vein.c's defaults (the reference case, run 1 of the study)
DEFAULTS = {"length": 0.09, "width": 0.008, "sinus_diameter": 0.014, "sinus_length": 0.04,
            "leaflet_length": 0.0256, "leaflet_gap": 1e-3, "dx": 1e-4, "wall_layers": 3}
CLOT, CLOT_COLOR = 3, "#8b1a1a"
H_OVER_DX = 2.5


def read_options(path):
    """The run's command-line options ('options' attribute of a snapshot, else
    run.json in the same directory) as {name without the dash: string}."""
    import h5py

    text = ""
    try:
        with h5py.File(path, "r") as f:
            raw = f.attrs.get("options", b"")
            text = raw.decode() if isinstance(raw, bytes) else str(raw)
    except OSError as e:
        vc.fail(f"{path}: cannot open ({e})")
    if not text:
        return vc.run_options(os.path.dirname(path))
    return sg.parse_options(text)


def geometry(snap_path, info=None):
    """{'length', 'width', 'sinus_diameter', 'sinus_length', 'leaflet_length', 'dx',
    'h', 'x_root', 'x_sinus_end', 'wall_layers'} [m] and 'kernel' of the run that
    wrote snap_path: the -vein_* options it ran with, the vein.csv comment's dx
    (info), else the scene's defaults; h and the kernel from the snapshot's sph_h and
    sph_kernel (else -sph_h, or 2.5 dx, and Lucy)."""
    opts = read_options(snap_path)
    geo = {}
    for key, value in DEFAULTS.items():
        s = opts.get("vein_" + key, "")
        try:
            geo[key] = float(s) if s else value
        except ValueError:
            geo[key] = value
    if "vein_dx" not in opts and info and math.isfinite(info.get("dx", math.nan)):
        geo["dx"] = info["dx"]
    geo["h"] = H_OVER_DX * geo["dx"]
    geo["kernel"] = "lucy"
    try:
        geo["h"] = float(opts["sph_h"]) if opts.get("sph_h") else geo["h"]
    except ValueError:
        pass
    geo["kernel"] = opts.get("sph_kernel") or geo["kernel"]
    import h5py

    with h5py.File(snap_path, "r") as f:
        meta = sg.snapshot_meta(f)
    geo["h"] = meta["h"] or geo["h"]
    geo["kernel"] = meta["kernel"] or geo["kernel"]
    geo["x_root"] = 0.5 * geo["length"] - 0.5 * geo["sinus_length"]
    geo["x_sinus_end"] = 0.5 * geo["length"] + 0.5 * geo["sinus_length"]
    return geo


def y_extent(geo):
    """|y| of the walls' outer edge [m] (the sinus's wall band)."""
    return 0.5 * geo["sinus_diameter"] + (geo["wall_layers"] + 0.5) * geo["dx"]


def liquid_grid(d, names, geo, window, spacing=None, nx=1000, threshold=MASK_THRESHOLD,
                extra=None, select=None):
    """Liquid fields of a snapshot d (read with x, type, body, mass, rho and the
    names) on a regular grid over x in window (x0, x1) [m] and the walls' y range.

    names: per-particle datasets (a 2-column one such as v gives name_x, name_y);
    extra: {name: per-particle array over all particles} interpolated too;
    select: a particle mask that further restricts the liquid summed over.
    spacing [m] defaults to (x1 - x0)/nx. Returns (gx, gy, fields, S): gx, gy the
    grid coordinates [m], fields {name: masked (ny, nx) array}, masked where the
    liquid's kernel sum S < threshold (walls, leaflets)."""
    fluid, _, _ = vc.masks(d)
    if select is not None:
        fluid = fluid & select
    x0, x1 = window
    ymax = y_extent(geo)
    if spacing is None:
        spacing = (x1 - x0) / nx
    gx, gy = grid_axes(x0, x1, -ymax, ymax, spacing)
    columns, labels = [], []
    for name in names:
        a = np.asarray(d[name], float)
        if a.ndim == 2:
            for c, axis in zip(range(a.shape[1]), "xy"):
                columns.append(a[fluid, c])
                labels.append(f"{name}_{axis}")
        else:
            columns.append(a[fluid])
            labels.append(name)
    for name, a in (extra or {}).items():
        columns.append(np.asarray(a, float)[fluid])
        labels.append(name)
    vol = d["mass"][fluid] / d["rho"][fluid]
    X, Y = np.meshgrid(gx, gy)
    values = np.column_stack(columns) if columns else np.zeros((int(fluid.sum()), 0))
    f, S = interpolate(d["x"][fluid, 0], d["x"][fluid, 1], vol, values, X.ravel(), Y.ravel(),
                       geo["h"], period=geo["length"], kernel=geo["kernel"])
    S = S.reshape(X.shape)
    outside = ~(S >= threshold)
    fields = {}
    for i, lab in enumerate(labels):
        a = f[:, i].reshape(X.shape)
        fields[lab] = np.ma.masked_array(a, mask=outside | ~np.isfinite(a))
    return gx, gy, fields, S


def leaflets(d):
    """{body: (layer0, layer1)}: each leaflet's particle layers [m] (n_columns x 2),
    sorted root (the clamped column) to tip by gid (column c, layer l = first + 2c + l;
    layer 0 faces the sinus). Needs x, body and gid."""
    out = {}
    for b in (1, 2):
        sel = np.flatnonzero(d["body"] == b)
        if sel.size < 4:
            continue
        sel = sel[np.argsort(d["gid"][sel])]
        if sel.size % 2:
            sel = sel[:-1]
        pts = d["x"][sel].reshape(-1, 2, 2)
        out[b] = (pts[:, 0, :], pts[:, 1, :])
    return out


def wall_surface(geo, x):
    """|y| of the wall surface [m] at x [m] (src/scenes/vein/vein.c: W/2, and the
    half-ellipse of semi-axes A = sinus_length/2, B = (D - W)/2 over the sinus)."""
    A = 0.5 * geo["sinus_length"]
    B = 0.5 * (geo["sinus_diameter"] - geo["width"])
    u = (np.mod(x, geo["length"]) - 0.5 * geo["length"]) / A
    return 0.5 * geo["width"] + np.where(np.abs(u) < 1, B * np.sqrt(np.clip(1 - u * u, 0, 1)), 0.0)


def wall_offset(geo, x, r):
    """|y| [m] of the curve at distance r outside the wall surface (the upper
    envelope of the discs of radius r centred on the surface)."""
    k = np.linspace(-r, r, 41)
    return np.max(wall_surface(geo, x[:, None] + k[None, :]) + np.sqrt(np.maximum(r * r - k * k, 0))[None, :],
                  axis=1)


def _wall_columns(x, dx):
    """Lattice columns of wall particles: (x of the column centres, min |y|, max |y|)."""
    col = np.round(x[:, 0] / dx - 0.5).astype(np.int64)
    order = np.argsort(col, kind="stable")
    col, ay = col[order], np.abs(x[order, 1])
    uniq, first = np.unique(col, return_index=True)
    return (uniq + 0.5) * dx, np.minimum.reduceat(ay, first), np.maximum.reduceat(ay, first), uniq


def draw_solids(ax, d, geo, wall_color="0.62", leaflet_color="k", zorder=3):
    """Walls as grey bands and each leaflet as a black strip, x and y in mm.

    A wall band runs from the wall surface of the geometry (wall_surface: the
    liquid's boundary, a smooth curve) out to wall_layers dx beyond it (where the
    wall particles end); where the particles do not fit that geometry (a column's
    first wall particle not within 0.3 .. 3 dx of it), from the innermost to the
    outermost wall particle of each lattice column, widened by dx/2. A leaflet is
    the outline of its two particle layers widened by dx/2 (a particle's half
    spacing) on every side; clot particles (type 3), if any, dark red dots. Needs
    x, type, body (and gid for the strips; without it, the leaflets are drawn as
    points)."""
    _, wall, solid = vc.masks(d)
    dx = geo["dx"]
    x = d["x"]
    for side in (1, -1):
        sel = wall & (side * x[:, 1] > 0)
        if not sel.any():
            continue
        xs, lo, hi, cols = _wall_columns(x[sel], dx)
        surf = wall_surface(geo, xs)
        fits = bool(np.all((lo - surf > 0.3 * dx) & (lo - surf < 3.0 * dx)))
        breaks = np.flatnonzero(np.diff(cols) > 1) + 1  # missing columns: separate bands
        for part in np.split(np.arange(cols.size), breaks):
            a, b = xs[part[0]] - 0.5 * dx, xs[part[-1]] + 0.5 * dx
            xf = np.linspace(a, b, max(2, int(round((b - a) / (dx / 8))) + 1))
            if fits:  # the geometry's band: the surface and its offset by the layers' width
                inner, outer = wall_surface(geo, xf), wall_offset(geo, xf, geo["wall_layers"] * dx)
            else:
                inner = np.interp(xf, xs[part], lo[part]) - 0.5 * dx
                outer = np.interp(xf, xs[part], hi[part]) + 0.5 * dx
            ax.fill_between(xf * 1e3, side * inner * 1e3, side * outer * 1e3, color=wall_color, lw=0,
                            zorder=zorder)
    if "gid" in d:
        for layer0, layer1 in leaflets(d).values():
            across = 0.5 * (layer0 - layer1)  # dx/2 from each layer outward
            along = np.diff(0.5 * (layer0 + layer1), axis=0)
            along /= np.maximum(np.linalg.norm(along, axis=1, keepdims=True), 1e-300)
            out0, out1 = layer0 + across, layer1 - across
            half = 0.5 * dx
            outline = np.vstack([out0[:1] - half * along[:1], out0, out0[-1:] + half * along[-1:],
                                 out1[-1:] + half * along[-1:], out1[::-1], out1[:1] - half * along[:1]])
            ax.fill(outline[:, 0] * 1e3, outline[:, 1] * 1e3, color=leaflet_color, lw=0,
                    zorder=zorder + 1)
    elif solid.any():
        ax.plot(x[solid, 0] * 1e3, x[solid, 1] * 1e3, ".", color=leaflet_color, ms=1.5,
                zorder=zorder + 1)
    clot = d["type"] == CLOT
    if clot.any():  # clots (module agglomeration): not liquid, so blank in the maps
        ax.plot(x[clot, 0] * 1e3, x[clot, 1] * 1e3, "o", color=CLOT_COLOR, ms=2.0, mew=0, zorder=zorder + 2)


class PanelGrid:
    """A figure of nrows x ncols map panels of pw x ph inches, laid out in inches
    so that titles, tick labels and colour bars never overlap: per row a head line
    (row_label), the panels' titles, the panel, its x tick labels and x label;
    per column the panel and cbar_room for its own colour bar (axes(r, c)), or
    cbar_room = 0 and right_room for one colour bar shared by all
    (side_colorbar_axes)."""

    def __init__(self, nrows, ncols, pw, ph, head=0.0, title=0.3, foot=0.55, left=0.65,
                 cbar=0.13, cbar_room=1.0, gap=0.3, top=0.75, bottom=0.1, right_room=0.0):
        import matplotlib.pyplot as plt

        self.pw, self.ph, self.head, self.title, self.foot = pw, ph, head, title, foot
        self.left, self.cbar, self.cbar_room, self.gap, self.top = left, cbar, cbar_room, gap, top
        self.nrows, self.ncols = nrows, ncols
        self.row_h = head + title + ph + foot
        self.col_w = pw + cbar_room + gap
        self.W = left + ncols * self.col_w - gap + 0.15 + right_room
        self.H = top + nrows * self.row_h + bottom
        self.fig = plt.figure(figsize=(self.W, self.H))

    def _y(self, r):
        return self.H - self.top - r * self.row_h  # top of row r [in]

    def axes(self, r, c, colorbar=True):
        x0 = self.left + c * self.col_w
        y0 = self._y(r) - self.head - self.title - self.ph
        ax = self.fig.add_axes([x0 / self.W, y0 / self.H, self.pw / self.W, self.ph / self.H])
        cax = None
        if colorbar:
            cax = self.fig.add_axes([(x0 + self.pw + 0.08) / self.W, y0 / self.H, self.cbar / self.W,
                                     self.ph / self.H])
        return ax, cax

    def side_colorbar_axes(self, r0=0, r1=None):
        """A colour bar's axes right of the last column (give the grid right_room for
        it and its labels), spanning the panels of rows r0 .. r1 (default: all)."""
        r1 = self.nrows - 1 if r1 is None else r1
        x0 = self.left + self.ncols * self.col_w - self.gap + 0.12
        y_top = self._y(r0) - self.head - self.title
        y_bot = self._y(r1) - self.head - self.title - self.ph
        return self.fig.add_axes([x0 / self.W, y_bot / self.H, self.cbar / self.W, (y_top - y_bot) / self.H])

    def row_label(self, r, text, c=0, **kw):
        kw.setdefault("fontsize", 10)
        kw.setdefault("fontweight", "bold")
        self.fig.text((self.left + c * self.col_w) / self.W, (self._y(r) - 0.5 * self.head) / self.H, text,
                      va="center", ha="left", **kw)

    def suptitle(self, text, **kw):
        kw.setdefault("fontsize", 11)
        self.fig.text(0.5, 1 - 0.1 / self.H, text, ha="center", va="top", **kw)


def colorbar(fig, mappable, cax, unit, vmax, extend="neither", name=None, nticks=5):
    """A vertical colour bar labelled '[unit]' (or 'name [unit]') with at most nticks
    ticks inside [0, vmax]; below 0.01 or from 1e4 on, the ticks count in a power
    of ten named in the label ('[10^-4 N/m]')."""
    import matplotlib.ticker as mticker

    cb = fig.colorbar(mappable, cax=cax, extend=extend)
    ticks = [t for t in mticker.MaxNLocator(nticks - 1).tick_values(0, vmax)
             if -1e-12 <= t <= vmax * (1 + 1e-9)]
    cb.set_ticks(ticks)
    e = int(math.floor(math.log10(vmax))) if vmax > 0 and (vmax < 0.01 or vmax >= 1e4) else 0
    scale = 10.0 ** e
    cb.ax.yaxis.set_major_formatter(mticker.FuncFormatter(lambda v, _: f"{v / scale:.3g}"))
    cb.ax.tick_params(labelsize=8)
    unit_text = f"$10^{{{e}}}$ {unit}" if e else unit
    cb.set_label(f"{name} [{unit_text}]" if name else f"[{unit_text}]", fontsize=9)
    return cb


def setup_map(ax, window_mm, ymax_mm, xlabel=True, ylabel=True):
    ax.set_xlim(*window_mm)
    ax.set_ylim(-ymax_mm, ymax_mm)
    ax.set_aspect("equal")
    ax.tick_params(labelsize=8)
    if xlabel:
        ax.set_xlabel("x [mm]", fontsize=9)
    if ylabel:
        ax.set_ylabel("y [mm]", fontsize=9)


def extent_mm(g):
    """(first, last) cell edge [mm] of cell-centred grid coordinates g [m]."""
    half = 0.5 * (g[1] - g[0])
    return ((g[0] - half) * 1e3, (g[-1] + half) * 1e3)


def default_window(geo, margin=0.01):
    """The sinus and `margin` [m] either side, clipped to the period [m]."""
    return (max(0.0, geo["x_root"] - margin), min(geo["length"], geo["x_sinus_end"] + margin))


def parse_window(text, geo):
    """'x0,x1' [mm] -> (x0, x1) [m] within the period; None -> default_window."""
    if text is None:
        return default_window(geo)
    try:
        a, b = (float(s) * 1e-3 for s in text.split(","))
    except ValueError:
        vc.fail(f"--window {text!r}: expected x0,x1 in mm")
    if not b > a:
        vc.fail(f"--window {text!r}: x1 must exceed x0")
    if a < -1e-9 or b > geo["length"] * (1 + 1e-9):
        vc.fail(f"--window {text!r}: must lie within the period 0 .. {geo['length'] * 1e3:g} mm")
    return a, b


def parse_times(text):
    """'t1,t2,...' [s] -> [t1, t2, ...]."""
    try:
        times = [float(s) for s in text.split(",") if s.strip()]
    except ValueError:
        vc.fail(f"--times {text!r}: expected t1[,t2,...] in s")
    if not times:
        vc.fail(f"--times {text!r}: no time")
    return times


def run_title(outdir, info):
    """The run's parameters as they were (vein_common.case_title: run.json's options,
    else vein.csv's comment and nu from vein-summary.csv)."""
    return vc.case_title(info, outdir)


def inlet_at(cols, t):
    """(inlet velocity [m/s], its column name) at the row nearest t."""
    u, name = vc.inlet_velocity(cols)
    i = int(np.argmin(np.abs(cols["t"] - t)))
    return float(u[i]), name


def phase(cols, t):
    """'forward' or 'backward' (the inlet velocity's sign at the row nearest t)."""
    u, _ = inlet_at(cols, t)
    return "backward" if u < 0 else "forward"


def requested_times(times, time, cols, T):
    """[(t, why)]: --times (comma-separated), else --time, else default_times."""
    if times is not None:
        return [(t, "--times") for t in parse_times(times)]
    if time is not None:
        return [(time, "--time")]
    return default_times(cols, T)


def default_times(cols, T, backward_fraction=0.05):
    """[(t, why)]: the first cycle's row of the largest inlet velocity and, when the
    flow reverses (its most negative value beyond backward_fraction of the forward
    peak), the row of the most negative one. Rows of the whole run when T is unknown."""
    u, name = vc.inlet_velocity(cols)
    t = cols["t"]
    first = (t <= T * (1 + 1e-6)) if (T and math.isfinite(T) and T > 0) else np.ones(t.size, bool)
    first &= np.isfinite(u)
    if not first.any():
        vc.fail(f"vein.csv: no finite {name} in the first cycle")
    ti, ui = t[first], u[first]
    out = []
    i = int(np.argmax(ui))
    out.append((float(ti[i]), f"peak forward {name}"))
    j = int(np.argmin(ui))
    if ui[j] < 0 and -ui[j] > backward_fraction * max(ui[i], 0.0):
        why = f"peak backward {name}"
        if T and math.isfinite(T) and t[-1] < T * (1 - 1e-6):
            why += f" so far (cycle 1 runs to t = {T:g} s, rows to {t[-1]:.3g} s)"
        out.append((float(ti[j]), why))
    return sorted(out)


def colour_cap(field, pct=99.5):
    """(vmax, extend): the pct-th percentile of the unmasked values, and 'max'
    when larger values exist."""
    a = np.ma.compressed(field)
    a = a[np.isfinite(a)]
    if a.size == 0:
        return 1.0, "neither"
    vmax = float(np.percentile(a, pct))
    if not vmax > 0:
        vmax = float(a.max()) if a.max() > 0 else 1.0
    return vmax, ("max" if a.max() > vmax else "neither")
