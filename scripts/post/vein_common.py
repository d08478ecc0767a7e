"""Readers shared by the plot_vein_*.py scripts (scene vein, doc/guide/scene-vein.md).

  read_csv(path, need)       vein.csv / vein-sinus.csv: columns as float arrays (an
                             empty cell is NaN), and the '# vein: ...' comment as a dict
  read_summary(path, need)   vein-summary.csv: key -> float (empty -> NaN)
  snapshots(run_dir)         [(time, path)] of snap_*.h5, sorted by time
  nearest_snapshot(run_dir, t)
  read_snapshot(path, names) {'time': t, name: array} from /particles (and 'bonds')
  masks(snapshot)            fluid, wall and leaflet (body > 0) masks
  run_options(run_dir)       run.json's options as {name: value} (None without run.json)
  run_params(run_dir, info)  the run's actual L, g0, k_a, T, dx, nu: run.json's options
                             over the scene's defaults, else the vein.csv comment
  case_title(info, run_dir)  'vein: L = 25.6 mm, g0 = 0.1 m/s², k_a = 0.01 J, ...'
  title_parts(run_dir, info) its parts, ['L = 25.6 mm', 'g0 = 0.1 m/s²', ...]
  shared_parts(run_dirs)     the parts every run has (a multi-run figure's title)

Every reader calls fail() with a one-line message naming the file when it is
missing, empty or lacks a column or dataset; fail() exits with status 1.
"""
import csv
import math
import os
import re
import sys

import numpy as np

from snapshot_files import marker_size, snapshot_files  # noqa: F401 (marker_size: vc.marker_size)

PROG = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else "plot_vein"
FLUID, WALL, SOLID = 0, 1, 2


def fail(msg):
    sys.exit(f"{PROG}: {msg}")


def _number(cell):
    cell = cell.strip()
    if cell == "":
        return math.nan
    try:
        return float(cell)
    except ValueError:
        return None


def parse_comment(line):
    """'# vein: leaflet 0.0255 m, g0 0.5 m/s^2, k_a 0.01 J (at dx = 1e-4 m), T 0.5 s, ...'
    -> {'leaflet': 0.0255, 'g0': 0.5, 'k_a': 0.01, 'T': 0.5, 'dx': 0.0005, 'rest gap': 0.003}."""
    text = re.sub(r"\([^)]*\)", "", line.lstrip("#").strip())
    text = text.split(":", 1)[1] if ":" in text else text
    info = {}
    for part in text.split(","):
        m = re.match(r"\s*([A-Za-z_][A-Za-z_0-9 ]*?)\s+([-+]?[0-9.]+(?:[eE][-+]?[0-9]+)?)\b", part)
        if m:
            info[m.group(1)] = float(m.group(2))
    return info


def read_csv(path, need=()):
    """Returns (columns, comment): columns maps each header name to a float array."""
    if not os.path.isfile(path):
        fail(f"{path}: no such file")
    with open(path, newline="") as f:
        lines = f.read().splitlines()
    comment = {}
    while lines and lines[0].startswith("#"):
        comment.update(parse_comment(lines.pop(0)))
    lines = [ln for ln in lines if ln.strip()]
    if len(lines) < 2:
        fail(f"{path}: empty (no header or no data rows)")
    rows = list(csv.reader(lines))
    header = [h.strip() for h in rows[0]]
    missing = [c for c in need if c not in header]
    if missing:
        fail(f"{path}: no column {', '.join(missing)} (header: {','.join(header)})")
    data = {h: np.full(len(rows) - 1, math.nan) for h in header}
    for k, row in enumerate(rows[1:]):
        for h, cell in zip(header, row):
            value = _number(cell)
            if value is None:
                fail(f"{path}:{k + 2}: column {h}: not a number: {cell!r}")
            data[h][k] = value
    return data, comment


def read_summary(path, need=()):
    """vein-summary.csv as {key: float}; an empty value is NaN."""
    if not os.path.isfile(path):
        fail(f"{path}: no such file")
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    if rows and rows[0][:1] == ["key"]:
        rows = rows[1:]
    if not rows:
        fail(f"{path}: empty (no key,value rows)")
    out = {}
    for r in rows:
        value = _number(r[1] if len(r) > 1 else "")
        if value is None:
            fail(f"{path}: {r[0]}: not a number: {r[1]!r}")
        out[r[0].strip()] = value
    missing = [k for k in need if k not in out]
    if missing:
        fail(f"{path}: no key {', '.join(missing)}")
    return out


def snapshots(run_dir):
    return snapshot_files(run_dir, fail)


def nearest_snapshot(run_dir, t):
    """(time, path) of the snapshot closest to t."""
    snaps = snapshots(run_dir)
    return min(snaps, key=lambda s: abs(s[0] - t))


def read_snapshot(path, names=("x", "type")):
    """{'time': t, 'scene': str, name: array} for the /particles datasets named (x as n x 2);
    'bonds' gives /bonds/rows."""
    import h5py

    try:
        f = h5py.File(path, "r")
    except OSError as e:
        fail(f"{path}: cannot open ({e})")
    with f:
        out = {"time": float(np.ravel(f.attrs.get("time", [math.nan]))[0])}
        scene = f.attrs.get("scene", b"")
        out["scene"] = scene.decode() if isinstance(scene, bytes) else str(scene)
        for name in names:
            key = "bonds/rows" if name == "bonds" else f"particles/{name}"
            if key not in f:
                fail(f"{path}: no dataset /{key}")
            a = f[key][()]
            out[name] = a[:, :2] if name in ("x", "x0", "v", "a") else a
    return out


def masks(d):
    """(fluid, wall, leaflet) masks of a snapshot read with 'type' and 'body': a
    leaflet is every particle of body 1 or 2, its clamped root column included."""
    leaflet = d["body"] > 0 if "body" in d else d["type"] == SOLID
    return d["type"] == FLUID, (d["type"] == WALL) & ~leaflet, leaflet


# src/scenes/vein/vein.c's defaults for the parameters a title shows (the reference case)
VEIN_DEFAULTS = {"vein_leaflet_length": 0.0256, "body_force_amplitude": 0.1, "vein_leaflet_ka": 0.01,
                 "body_force_period": 4.0, "vein_dx": 1e-4, "sph_nu": 3.3e-6}
DX_REF = 1e-4  # the spacing -vein_leaflet_ka is stated at [m]


def run_options(run_dir):
    """The options a run ran with, from run_dir/run.json (its 'options': every option
    of the command line and the options files), as {name without the dash: value};
    None when there is no readable run.json."""
    import json

    import sph_grid

    path = os.path.join(run_dir, "run.json")
    try:
        with open(path) as f:
            text = json.load(f).get("options", "")
    except (OSError, ValueError):
        return None
    return sph_grid.parse_options(text)


def _option_number(text):
    """An option's (first) value as a number, or None."""
    try:
        return float(str(text).split(",")[0])
    except ValueError:
        return None


def run_params(run_dir=None, info=None):
    """The parameters a vein plot's title shows, as the run had them: {'leaflet' [m],
    'g0' [m/s^2], 'k_a' [J, at dx = 1e-4 m], 'T' [s], 'dx' [m], 'nu' [m^2/s],
    'k_a_note' (how k_a was set when not by -vein_leaflet_ka)}. From run_dir/run.json's
    options over the scene's defaults; -angle_k given explicitly is the angle stiffness
    at the run's dx, so k_a = angle_k dx / 1e-4 m. Without run.json: the vein.csv
    comment (info) and nu from vein-summary.csv."""
    opts = run_options(run_dir) if run_dir else None
    if opts is None:
        out = {}
        for key, names in (("leaflet", ("leaflet", "leaflet_length")), ("g0", ("g0",)),
                           ("k_a", ("k_a", "ka_ref")), ("T", ("T", "period")), ("dx", ("dx",)),
                           ("nu", ("nu",))):
            for k in names:
                if info and k in info and not math.isnan(info[k]):
                    out[key] = info[k]
                    break
        summary = os.path.join(run_dir, "vein-summary.csv") if run_dir else ""
        if "nu" not in out and summary and os.path.isfile(summary):
            nu = read_summary(summary).get("nu", math.nan)
            if math.isfinite(nu):
                out["nu"] = nu
        return out

    def get(name):
        v = _option_number(opts[name]) if opts.get(name) else None
        return VEIN_DEFAULTS[name] if v is None else v

    out = {"leaflet": get("vein_leaflet_length"), "g0": get("body_force_amplitude"),
           "k_a": get("vein_leaflet_ka"), "T": get("body_force_period"), "dx": get("vein_dx"),
           "nu": get("sph_nu")}
    angle_k = _option_number(opts["angle_k"]) if opts.get("angle_k") else None
    if angle_k is not None:
        out["k_a"] = angle_k * out["dx"] / DX_REF
        out["k_a_note"] = f"-angle_k {angle_k:g} J at dx = {out['dx'] * 1e3:g} mm"
    return out


def title_parts(run_dir=None, info=None):
    """The run's parameters as title parts: 'L = 25.6 mm', 'g0 = 0.1 m/s²', 'k_a = 0.01 J',
    'T = 4 s', 'dx = 0.4 mm', 'ν = 1e-05 m²/s' (those known; run_params)."""
    p = run_params(run_dir, info)
    parts = []
    if "leaflet" in p:
        parts.append(f"L = {p['leaflet'] * 1e3:g} mm")
    if "g0" in p:
        parts.append(f"g0 = {p['g0']:g} m/s²")
    if "k_a" in p:
        parts.append(f"k_a = {p['k_a']:g} J" + (f" ({p['k_a_note']})" if "k_a_note" in p else ""))
    if "T" in p:
        parts.append(f"T = {p['T']:g} s")
    if "dx" in p:
        parts.append(f"dx = {p['dx'] * 1e3:g} mm")
    if "nu" in p:
        parts.append(f"ν = {p['nu']:g} m²/s")
    return parts


def case_title(info, run_dir=None):
    """A short name of the case: the run's parameters (run_params: run.json's
    options when run_dir has one, else the CSV comment or summary keys in info)."""
    return "vein: " + ", ".join(title_parts(run_dir, info))


def shared_parts(run_dirs, infos=None):
    """The title parts (title_parts) that every run of run_dirs has, in order."""
    infos = infos or [None] * len(run_dirs)
    parts_of = [title_parts(d, i) for d, i in zip(run_dirs, infos)]
    return [p for p in parts_of[0] if all(p in q for q in parts_of[1:])]


def output_path(out, default_dir, name):
    """--out given: a .png path, or a directory for `name`; otherwise default_dir/name."""
    if out and out.lower().endswith(".png"):
        path = out
    else:
        path = os.path.join(out or default_dir, name)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    return path


def require_dir(path):
    if not os.path.isdir(path):
        fail(f"{path}: no such directory")


def inlet_velocity(cols):
    """The inlet velocity a study compares: u_flux (the volume flux over the width,
    free of the slab's sampling noise) when vein.csv has it, else u_mean."""
    if "u_flux" in cols and np.isfinite(cols["u_flux"]).any():
        return cols["u_flux"], "u_flux"
    return cols["u_mean"], "u_mean"


CYCLE_METRICS = (
    ("u_peak", "peak inlet velocity [m/s]"),
    ("open_max", "largest clear opening between the tips, gap - 2 dx [m]"),
    ("open_min", "smallest clear opening between the tips, gap - 2 dx [m]"),
    ("disp_mean", "measurement point's time-averaged displacement [m]"),
    ("stress_peak", "measurement point's peak total stress [Pa]"),
)


def clear_opening(cols, dx):
    """The tips' clear opening: their mid-plane gap less the two leaflets' half
    thicknesses (a leaflet is two layers, 2 dx thick), the quantity the scene
    keeps at every dx."""
    return cols["gap"] - 2 * dx


def cycle_metrics(cols, T, dx):
    """Per completed drive cycle k (rows with k T < t <= (k+1) T): a list of dicts
    with the CYCLE_METRICS keys (NaN where the measurement point is not chosen yet)
    and 'cycle' (1-based). A cycle counts as completed when the rows reach its end."""
    t = cols["t"]
    u, _ = inlet_velocity(cols)
    out = []
    if not (T > 0) or t.size == 0:
        return out
    n = int(math.floor(t[-1] / T + 1e-6))
    for k in range(n):
        m = (t > k * T + 1e-9 * T) & (t <= (k + 1) * T + 1e-6 * T)
        if not m.any():
            continue
        opening = clear_opening(cols, dx)[m]
        row = {"cycle": k + 1, "u_peak": float(np.nanmax(np.abs(u[m]))),
               "open_max": float(np.nanmax(opening)), "open_min": float(np.nanmin(opening))}
        disp, stress = cols["probe_disp"][m], cols["probe_stress"][m]
        row["disp_mean"] = float(np.nanmean(disp)) if np.isfinite(disp).any() else math.nan
        row["stress_peak"] = float(np.nanmax(stress)) if np.isfinite(stress).any() else math.nan
        out.append(row)
    return out
