"""Kernel interpolation of a vein snapshot's liquid onto a regular grid, and the
drawing helpers shared by the plot_vein_*.py field maps (scene vein).

  geometry(snap_path, info)   the scene's lengths [m] from the snapshot's 'options'
                              attribute (defaults of src/scenes/vein.c otherwise)
  interpolate(...)            Shepard-normalised SPH sums at arbitrary points
  liquid_grid(...)            liquid fields on a regular grid, masked outside the liquid
  draw_solids(ax, d, geo)     walls (grey) and leaflets (black), x and y in mm
  leaflets(d)                 each leaflet's two particle layers, sorted root to tip
  PanelGrid, colorbar, setup_map   the map figures' layout (in inches), colour bars
  run_title(outdir, info)     'vein: L = 25.6 mm, g0 = 0.1 m/s², k_a = 0.01 J, T = 4 s,
                              dx = 0.4 mm, ν = 1e-05 m²/s'
  phase(cols, t)              'forward' / 'backward' from the inlet velocity at t
  default_times(cols, T)      the first cycle's forward and backward peaks

Interpolation (the scene's kernel, Lucy in 2D, support radius h = 2.5 dx):
    W(q) = 5 / (pi h^2) (1 + 3q) (1 - q)^3,  q = r/h < 1,
    f(x) = sum_j f_j V_j W(x - x_j) / sum_j V_j W(x - x_j),  V_j = m_j / rho_j,
over the liquid particles only, minimum image in the periodic x. The kernel sum
S(x) = sum_j V_j W is ~1 inside the liquid and falls to ~0.5 at its free edge
(half the kernel covered); grid points with S < 0.5 (inside walls and leaflets,
beyond the domain) are masked. Neighbours come from a cell list of cells at
least h wide: each grid point looks at the particles of its 3 x 3 cells, in
vectorised chunks of grid points (a padded cell -> particle table), so that
1e5 particles onto a 1000 x 200 grid take seconds.
"""
import math
import os
import re

import numpy as np

import vein_common as vc

# src/scenes/vein.c's defaults (the reference case, run 1 of the study)
DEFAULTS = {"length": 0.09, "width": 0.008, "sinus_diameter": 0.014, "sinus_length": 0.04,
            "leaflet_length": 0.0256, "leaflet_gap": 1e-3, "dx": 1e-4, "wall_layers": 3}
CLOT, CLOT_COLOR = 3, "#8b1a1a"
H_OVER_DX = 2.5
MASK_THRESHOLD = 0.5


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
        run = os.path.join(os.path.dirname(path), "run.json")
        if os.path.isfile(run):
            import json

            try:
                with open(run) as f:
                    text = json.load(f).get("options", "")
            except (OSError, ValueError):
                text = ""
    out, key = {}, None
    for tok in text.split():
        if re.match(r"^-[A-Za-z_]", tok):
            key = tok[1:]
            out[key] = ""
        elif key is not None:
            out[key] = tok
            key = None
    return out


def geometry(snap_path, info=None):
    """{'length', 'width', 'sinus_diameter', 'sinus_length', 'leaflet_length', 'dx',
    'h', 'x_root', 'x_sinus_end', 'wall_layers'} [m] of the run that wrote snap_path:
    the -vein_* options it ran with, the vein.csv comment's dx (info), else the
    scene's defaults."""
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
    geo["x_root"] = 0.5 * geo["length"] - 0.5 * geo["sinus_length"]
    geo["x_sinus_end"] = 0.5 * geo["length"] + 0.5 * geo["sinus_length"]
    return geo


def lucy(q, h):
    """The 2D Lucy kernel W(q) [1/m^2], q = r/h (0 for q >= 1)."""
    q = np.minimum(q, 1.0)
    return (5.0 / (math.pi * h * h)) * (1.0 + 3.0 * q) * (1.0 - q) ** 3


def interpolate(px, py, vol, values, qx, qy, h, period=None, chunk=20000):
    """Shepard-normalised kernel sums at the points (qx, qy) [m].

    px, py, vol: the particles' positions [m] and volumes m/rho [m^2]; values: an
    (n, k) array of particle fields; period: the x period [m] (minimum image) or
    None. Returns (f, S): f (m, k) the normalised fields (NaN where S = 0) and S (m,)
    the kernel sum sum_j V_j W."""
    px = np.asarray(px, float)
    py = np.asarray(py, float)
    vol = np.asarray(vol, float)
    values = np.asarray(values, float)
    if values.ndim == 1:
        values = values[:, None]
    qx = np.asarray(qx, float).ravel()
    qy = np.asarray(qy, float).ravel()
    n, k = values.shape
    m = qx.size
    f = np.full((m, k), math.nan)
    S = np.zeros(m)
    if n == 0 or m == 0:
        return f, S

    # cells at least h wide; in a periodic x the period is a whole number of cells
    if period:
        ncx = max(1, int(math.floor(period / h)))
        cwx, x_lo = period / ncx, 0.0
        px = np.mod(px, period)
    else:
        x_lo = px.min() - 1e-12
        cwx = h
        ncx = int(math.floor((px.max() - x_lo) / cwx)) + 1
    y_lo = py.min() - 1e-12
    ncy = int(math.floor((py.max() - y_lo) / h)) + 1
    cx = np.minimum((px - x_lo) // cwx, ncx - 1).astype(np.int64)
    cy = np.minimum((py - y_lo) // h, ncy - 1).astype(np.int64)
    # padded grid of cells: an empty ring around it (for queries beyond the particles)
    pad_x = 0 if period else 1
    NX, NY = ncx + 2 * pad_x, ncy + 2
    cell = (cx + pad_x) * NY + (cy + 1)
    order = np.argsort(cell, kind="stable")
    counts = np.bincount(cell, minlength=NX * NY)
    start = np.concatenate(([0], np.cumsum(counts)[:-1]))
    M = int(counts.max())
    table = np.full((NX * NY, M), n, dtype=np.int64)  # n: a dummy of zero volume
    sorted_cell = cell[order]
    table[sorted_cell, np.arange(n) - start[sorted_cell]] = order
    PX = np.append(px, 0.0)
    PY = np.append(py, 0.0)
    PV = np.append(vol, 0.0)
    PF = np.vstack([values, np.zeros((1, k))])

    offsets = [(ox, oy) for ox in (-1, 0, 1) for oy in (-1, 0, 1)]
    for a in range(0, m, chunk):
        b = min(m, a + chunk)
        x = qx[a:b]
        y = qy[a:b]
        xw = np.mod(x, period) if period else x
        qcx = np.floor((xw - x_lo) / cwx).astype(np.int64)
        qcy = np.floor((y - y_lo) / h).astype(np.int64)
        qcx = np.clip(qcx, 0, ncx - 1) if period else np.clip(qcx, -1, ncx)
        qcy = np.clip(qcy, -1, ncy)
        cols = []
        for ox, oy in offsets:
            ix = np.mod(qcx + ox, ncx) if period else qcx + ox + pad_x
            iy = qcy + oy + 1
            ok = (ix >= 0) & (ix < NX) & (iy >= 0) & (iy < NY)
            idx = table[np.where(ok, ix * NY + iy, 0)]
            idx[~ok] = n
            cols.append(idx)
        idx = np.concatenate(cols, axis=1)  # (chunk, 9 M) candidate neighbours
        ddx = x[:, None] - PX[idx]
        if period:
            ddx -= period * np.round(ddx / period)
        r2 = ddx * ddx + (y[:, None] - PY[idx]) ** 2
        row, col = np.nonzero(r2 < h * h)  # the pairs within the support only
        j = idx[row, col]
        w = lucy(np.sqrt(r2[row, col]) / h, h) * PV[j]
        s = np.bincount(row, weights=w, minlength=b - a)
        S[a:b] = s
        with np.errstate(invalid="ignore", divide="ignore"):
            for c in range(k):
                acc = np.bincount(row, weights=w * PF[j, c], minlength=b - a)
                f[a:b, c] = np.where(s > 0, acc / s, math.nan)
    return f, S


def grid_axes(x0, x1, y0, y1, spacing):
    """Cell-centred grid coordinates [m] over [x0, x1] x [y0, y1]."""
    nx = max(2, int(round((x1 - x0) / spacing)))
    ny = max(2, int(round((y1 - y0) / spacing)))
    return (x0 + (np.arange(nx) + 0.5) * (x1 - x0) / nx, y0 + (np.arange(ny) + 0.5) * (y1 - y0) / ny)


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
                       geo["h"], period=geo["length"])
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
    """|y| of the wall surface [m] at x [m] (src/scenes/vein.c: W/2, and the
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
    """The run's parameters: vein.csv's comment, and nu from vein-summary.csv when
    there is one."""
    title = vc.case_title(info)
    path = os.path.join(outdir, "vein-summary.csv")
    if os.path.isfile(path):
        nu = vc.read_summary(path).get("nu", math.nan)
        if math.isfinite(nu):
            title += f", ν = {nu:g} m²/s"
    return title


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
