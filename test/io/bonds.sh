#!/bin/bash
# Bonds in the snapshots (XDMF Polyline over the particles), on 2 ranks: the
# index must be consistent, and every /bonds/rows entry must join two solid
# (or clamped wall) particles at about the rest length r0 apart.
# Usage: bonds.sh DMHS PYTHON MPIRUN... -- WORKDIR
set -euo pipefail
EXE=$1 PY=$2; shift 2
MPI=()
while [ "$1" != "--" ]; do MPI+=("$1"); shift; done
W=$2
HERE=$(cd "$(dirname "$0")" && pwd)
rm -rf "$W" && mkdir -p "$W"
"${MPI[@]}" -n 2 "$EXE" -options_file "$HERE/../../input/flap-quick.opts" -t_end 0.01 -output_interval 0.005 \
  -quiet -output_dir "$W" > "$W.log"
"$PY" "$HERE/check_xdmf.py" "$W" 3
grep -q 'TopologyType="Polyline"' "$W/particles.xdmf" || { echo "FAIL: no Polyline grid in the index"; exit 1; }
"$PY" - "$W" <<'PY'
import sys, h5py, numpy as np
with h5py.File(f"{sys.argv[1]}/snap_000002.h5", "r") as f:
    rows, x, kind = f["bonds/rows"][()], f["particles/x"][()][:, :2], f["particles/type"][()]
length = np.linalg.norm(x[rows[:, 0]] - x[rows[:, 1]], axis=1)
print(f"{len(rows)} bonds, lengths {length.min():.4g} .. {length.max():.4g} m, types {sorted(set(kind[rows.ravel()]))}")
assert len(rows) > 0 and set(kind[rows.ravel()]) <= {1, 2}, "a bond joins a fluid particle"
assert np.all(abs(length - 1e-4) < 0.05e-4), "a bond is far from its rest length: rows point at the wrong particles"
print("bonds in snapshots: OK")
PY
