"""Kernel interpolation of snapshot particles onto points and grids, for any scene:
the one implementation behind scripts/post/plot_fields.py and the vein's field maps
(vein_grid.py).

  kernel_w(kind, q, h)         the 2D kernels of src/physics/sph_kernel.h: lucy, cubic,
                               wendland; q = r/h, support radius h (W = 0 for q >= 1)
  interpolate(...)             Shepard-normalised SPH sums at arbitrary points, across
                               periodic boundaries in x and/or y
  grid_axes(x0, x1, y0, y1, spacing)   cell-centred grid coordinates
  snapshot_meta(f)             what a snapshot says about its run: time, step, scene,
                               options, box, periodicity, rest spacing, kernel and h
  parse_options(text)          '-a 1 -b -c x' -> {'a': '1', 'b': '', 'c': 'x'}

Interpolation:
    f(x) = sum_j f_j V_j W(x - x_j) / sum_j V_j W(x - x_j),  V_j = m_j / rho_j,
with the minimum image along periodic directions. The kernel sum S(x) = sum_j V_j W
is ~1 inside the particles and falls to ~0.5 at a free edge (half the kernel
covered); callers mask where S < 0.5 (MASK_THRESHOLD). Neighbours come from a cell
list of cells at least h wide (in a periodic direction the period is a whole number
of cells): each point looks at the particles of its 3 x 3 cells, in vectorised
chunks of points (a padded cell -> particle table), so that 1e5 particles onto a
1000 x 200 grid take seconds.
"""
import math
import re

import numpy as np

MASK_THRESHOLD = 0.5
KERNELS = ("lucy", "cubic", "wendland")


def kernel_w(kind, q, h):
    """W [1/m^2] of the 2D kernel `kind` at q = r/h (0 for q >= 1), normalised as in
    src/physics/sph_kernel.h (support radius h)."""
    q = np.minimum(np.asarray(q, float), 1.0)
    m = 1.0 - q
    if kind == "lucy":
        return (5.0 / (math.pi * h * h)) * (1.0 + 3.0 * q) * m ** 3
    if kind == "wendland":
        return (7.0 / (math.pi * h * h)) * m ** 4 * (1.0 + 4.0 * q)
    if kind == "cubic":  # B-spline with smoothing length s = h/2, u = r/s = 2q
        s = 0.5 * h
        u = 2.0 * q
        inner = 1.0 - 1.5 * u * u + 0.75 * u ** 3
        outer = 0.25 * np.maximum(2.0 - u, 0.0) ** 3
        return (10.0 / (7.0 * math.pi * s * s)) * np.where(u < 1.0, inner, outer)
    raise ValueError(f"unknown kernel {kind!r} (one of {', '.join(KERNELS)})")


def lucy(q, h):
    """The 2D Lucy kernel W(q) [1/m^2], q = r/h (0 for q >= 1)."""
    return kernel_w("lucy", q, h)


class _Axis:
    """The cell list along one direction: periodic (period P from lo) or bounded by
    the particles (with an empty cell either side for points beyond them)."""

    def __init__(self, p, h, period, lo):
        self.period = period if period else None
        if self.period:
            self.n = max(1, int(math.floor(self.period / h)))
            self.w, self.lo, self.pad = self.period / self.n, lo, 0
            p = np.mod(p - lo, self.period) + lo
            # distinct neighbour offsets: with 1 or 2 cells, -1 and +1 are the same cell
            self.offsets = sorted({o % self.n for o in (-1, 0, 1)})
            self.offsets = [o - self.n if o > 1 else o for o in self.offsets]
        else:
            self.lo = p.min() - 1e-12 if p.size else 0.0
            self.w, self.pad = h, 1
            self.n = int(math.floor(((p.max() if p.size else 0.0) - self.lo) / h)) + 1
            self.offsets = [-1, 0, 1]
        self.N = self.n + 2 * self.pad  # padded cell count
        self.p = p
        self.cell = np.minimum((p - self.lo) // self.w, self.n - 1).astype(np.int64) + self.pad

    def query(self, q):
        """The padded cell of each point q."""
        if self.period:
            qw = np.mod(q - self.lo, self.period)
            return np.clip(np.floor(qw / self.w).astype(np.int64), 0, self.n - 1)
        return np.clip(np.floor((q - self.lo) / self.w).astype(np.int64), -1, self.n) + self.pad

    def neighbour(self, qc, o):
        """(cell index, valid) of the cell o away from qc."""
        if self.period:
            return np.mod(qc + o, self.n), np.ones(qc.shape, bool)
        c = qc + o
        return c, (c >= 0) & (c < self.N)

    def separation(self, d):
        """d with the minimum image along a periodic direction."""
        if self.period:
            d -= self.period * np.round(d / self.period)
        return d


def _periods(period):
    """period: None, a number (x only) or (Px, Py) with None for a bounded direction."""
    if period is None:
        return None, None
    if np.isscalar(period):
        return (float(period) or None), None
    px, py = period
    return (px or None), (py or None)


def interpolate(px, py, vol, values, qx, qy, h, period=None, origin=(0.0, 0.0), kernel="lucy",
                chunk=None):
    """Shepard-normalised kernel sums at the points (qx, qy) [m].

    px, py, vol: the particles' positions [m] and volumes m/rho [m^2]; values: an (n, k)
    (or (n,)) array of particle fields; h: the kernel's support radius [m]; period: None,
    the x period [m], or (Px, Py) with None where the box is bounded; origin: the box's
    lower corner [m] (where a periodic direction starts); kernel: lucy, cubic or
    wendland. Returns (f, S): f (m, k) the normalised fields (NaN where S = 0) and S
    (m,) the kernel sum sum_j V_j W."""
    px = np.asarray(px, float).ravel()
    py = np.asarray(py, float).ravel()
    vol = np.asarray(vol, float).ravel()
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
    Px, Py = _periods(period)
    ax = _Axis(px, h, Px, origin[0])
    ay = _Axis(py, h, Py, origin[1])
    cell = ax.cell * ay.N + ay.cell
    order = np.argsort(cell, kind="stable")
    counts = np.bincount(cell, minlength=ax.N * ay.N)
    start = np.concatenate(([0], np.cumsum(counts)[:-1]))
    M = int(counts.max())
    table = np.full((ax.N * ay.N, M), n, dtype=np.int64)  # n: a dummy of zero volume
    sorted_cell = cell[order]
    table[sorted_cell, np.arange(n) - start[sorted_cell]] = order
    PX = np.append(ax.p, 0.0)
    PY = np.append(ay.p, 0.0)
    PV = np.append(vol, 0.0)
    PF = np.vstack([values, np.zeros((1, k))])
    offsets = [(ox, oy) for ox in ax.offsets for oy in ay.offsets]
    if chunk is None:  # about 4e6 candidate pairs at a time
        chunk = max(256, int(4e6 // (len(offsets) * M)))
    h2 = h * h
    for a in range(0, m, chunk):
        b = min(m, a + chunk)
        x, y = qx[a:b], qy[a:b]
        qcx, qcy = ax.query(x), ay.query(y)
        cols = []
        for ox, oy in offsets:
            ix, okx = ax.neighbour(qcx, ox)
            iy, oky = ay.neighbour(qcy, oy)
            ok = okx & oky
            idx = table[np.where(ok, ix * ay.N + iy, 0)]
            idx[~ok] = n
            cols.append(idx)
        idx = np.concatenate(cols, axis=1)  # (chunk, 9 M) candidate neighbours
        ddx = ax.separation(x[:, None] - PX[idx])
        ddy = ay.separation(y[:, None] - PY[idx])
        r2 = ddx * ddx + ddy * ddy
        row, col = np.nonzero(r2 < h2)  # the pairs within the support only
        j = idx[row, col]
        w = kernel_w(kernel, np.sqrt(r2[row, col]) / h, h) * PV[j]
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


def _attr(attrs, name, default=None):
    if name not in attrs:
        return default
    v = attrs[name]
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, str):
        return v
    a = np.ravel(v)
    return a if a.size > 1 else a[0]


def snapshot_meta(f):
    """What an open snapshot (h5py.File) says about its run: {'time', 'step', 'scene',
    'options', 'box_lo', 'box_hi' (arrays [m] or None), 'periodic' ((bool, bool) or None),
    'dx', 'h' [m] or None, 'kernel' (or None)}. Box, periodicity, dx, h and kernel are
    None in snapshots without them (SPH's only with the sph module)."""
    a = f.attrs
    periodic = _attr(a, "periodic")
    return {
        "time": float(_attr(a, "time", math.nan)),
        "step": int(_attr(a, "step", -1)),
        "scene": _attr(a, "scene", ""),
        "options": _attr(a, "options", ""),
        "box_lo": None if "box_lo" not in a else np.ravel(a["box_lo"]).astype(float),
        "box_hi": None if "box_hi" not in a else np.ravel(a["box_hi"]).astype(float),
        "periodic": None if periodic is None else tuple(bool(p) for p in np.ravel(periodic)),
        "dx": None if "dx" not in a else float(_attr(a, "dx")),
        "h": None if "sph_h" not in a else float(_attr(a, "sph_h")),
        "kernel": _attr(a, "sph_kernel"),
    }


def parse_options(text):
    """A command line of options ('-vein_dx 5e-4 -quiet -scene vein', as run.json and
    the snapshots record it) as {name without the dash: value}, '' for a flag; a
    later value wins, as in dmhs. Negative numbers are values, not options."""
    out, key = {}, None
    for tok in str(text).split():
        if re.match(r"^-[A-Za-z_]", tok):
            key = tok[1:]
            out[key] = ""
        elif key is not None:
            out[key] = tok
            key = None
    return out
