#!/usr/bin/env bash
# The LAMMPS vein twin's converter (bench/lammps/vein_data.py) on a coarse vein
# (dx = 5e-4 m, one step): the data file has every particle of the t = 0 snapshot
# with its position, density and the mass of its type, every bond and angle of
# the checkpoint, bonds at their rest length and right angles at rest; the
# parameter file has the run's values. No LAMMPS needed.
#   lammps_vein_data.sh DMHS_EXE PYTHON OUT_DIR
set -euo pipefail
exe="$1"
py="$2"
out="$3"
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
rm -rf "$out"
mkdir -p "$out"
"$exe" -options_file "$repo/input/vein.opts" -vein_dx 5e-4 -t_end 1e-7 -dt 1e-7 -quiet \
  -output_dir "$out/run" > "$out/dmhs.log"
"$py" "$repo/bench/lammps/vein_data.py" "$out/run" --out "$out/vein"
"$py" - "$out" <<'PY'
import math, re, sys
import h5py, numpy as np
out = sys.argv[1]
lines = open(f"{out}/vein.data").read().splitlines()
def section(name):
    i = next(k for k, l in enumerate(lines) if l.split("#")[0].strip() == name) + 2
    rows = []
    while i < len(lines) and lines[i].strip():
        rows.append(lines[i].split("#")[0].split())
        i += 1
    return rows
masses = {int(r[0]): float(r[1]) for r in section("Masses")}
atoms = np.array(section("Atoms"), dtype=float)
bonds = np.array(section("Bonds"), dtype=int)
angles = np.array(section("Angles"), dtype=int)
with h5py.File(f"{out}/run/snap_000000.h5") as s, h5py.File(f"{out}/run/checkpoint.h5") as c:
    P = s["particles"]
    o = np.argsort(P["gid"][:])
    x, rho, mass, typ, body = (P[k][:][o] for k in ("x", "rho", "mass", "type", "body"))
    nb, na = len(c["topology/bond_gid"]), len(c["topology/angle_gid"])
atoms = atoms[np.argsort(atoms[:, 0])]
assert len(atoms) == len(x), (len(atoms), len(x))
assert np.array_equal(atoms[:, 0].astype(int), np.arange(1, len(x) + 1))
assert np.abs(atoms[:, 2:4] - x[:, :2]).max() == 0 and np.abs(atoms[:, 6] - rho).max() == 0
lt = atoms[:, 1].astype(int)
want = {(0, 0): 1, (1, 0): 2, (2, 1): 3, (2, 2): 4, (1, 1): 5, (1, 2): 6}
assert all(want[(t, b)] == l for t, b, l in zip(typ, body, lt)), "types"
assert all(masses[l] == m for l, m in zip(lt, mass)), "masses"
assert len(bonds) == nb and len(angles) == na and nb > 0 and na > 0
p = {m.group(1): float(m.group(2)) for m in
     (re.match(r"variable\s+(\S+)\s+equal\s+(\S+)", l) for l in open(f"{out}/vein.params.in")) if m}
X = atoms[:, 2:4]
r = np.hypot(*(X[bonds[:, 2] - 1] - X[bonds[:, 3] - 1]).T)
assert np.abs(r / p["bond_r01"] - 1).max() < 1e-9, "bond lengths"
a, b = X[angles[:, 2] - 1] - X[angles[:, 3] - 1], X[angles[:, 4] - 1] - X[angles[:, 3] - 1]
th = np.degrees(np.arctan2(np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]), (a * b).sum(axis=1)))
assert np.abs(th - p["angle_theta01"]).max() < 1e-6, "angles"
# reference values scaled to dx = 5e-4 m (src/scenes/vein/vein.c): h = 2.5 dx, K_bond 1e6/125, r* = dx
r5 = 5.0
assert math.isclose(p["h"], 2.5 * 5e-4) and math.isclose(p["bond_k1"], 1e6 / r5**3)
assert math.isclose(p["rep_rstar"], 5e-4) and math.isclose(p["mu"], 1056 * 1e-5)
assert math.isclose(p["rep_eps"], 4e-4 * r5**2 * 2 / 8) and math.isclose(p["period"], 4)
for k in (1, 2):  # the tips: the leaflet's last column
    ids = [int(p[f"tip{k}_a"]), int(p[f"tip{k}_b"])]
    assert all(lt[i - 1] == 2 + k for i in ids) and max(np.nonzero(lt == 2 + k)[0] + 1) == ids[1]
print(f"vein_data.py: {len(x)} atoms, {nb} bonds, {na} angles checked")
PY
