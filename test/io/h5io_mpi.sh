#!/bin/bash
# Parallel row layout on 3 ranks with uneven and empty row counts: h5io_mpi
# writes and reads back (C side), then h5py checks the file.
# Usage: h5io_mpi.sh H5IO_MPI PYTHON WORKDIR MPIRUN [MPIRUN ARGS...]
set -euo pipefail
EXE=$1 PY=$2 W=$3
shift 3
rm -rf "$W" && mkdir -p "$W"
"$@" -n 3 "$EXE" "$W"
"$PY" - "$W/rows.h5" <<'PYEOF'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    x, g = f["x"][()], f["gid"][()]
n = len(g)
assert n == 3 + 7 and (g == np.arange(n)).all(), g           # ranks own 3, 0, 7 rows
assert x.shape == (n, 3) and (x[:, 0] == 0.5 * g).all() and (x[:, 1] == -1.0 * g).all() and (x[:, 2] == 0).all()
print("h5py: rows in rank order, 2D vector padded to 3: OK")
PYEOF
