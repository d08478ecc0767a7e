#!/bin/bash
# XDMF / HDF5 consistency of a run's output directory (check_xdmf.py), the
# snapshot metadata, and -output_snapshots false writing none.
# Usage: consistency.sh DMHS PYTHON WORKDIR
set -euo pipefail
EXE=$1 PY=$2 W=$3
source "$(dirname "$0")/common.sh"
rm -rf "$W" && mkdir -p "$W"
"$EXE" "${QUICK[@]}" -t_end 0.02 -output_dir "$W/run" > "$W/run.log"
"$PY" "$HERE/check_xdmf.py" "$W/run" 5
"$PY" - "$W/run" <<'PYEOF'
import json, os, sys, h5py
d = sys.argv[1]
with h5py.File(os.path.join(d, "snap_000004.h5"), "r") as f:
    a = f.attrs
    assert abs(a["time"][0] - 0.02) < 1e-15 and a["step"][0] == 800 and a["dt"][0] == 2.5e-5, dict(a)
    assert a["dmhs_version"].decode() and a["scene"] == b"poiseuille", dict(a)
    assert b"-channel_nx 10" in a["options"], a["options"]
    assert f["particles/x"].shape == (260, 3) and (f["particles/x"][:, 2] == 0).all()
    assert sorted(f["particles/gid"][()]) == list(range(260))
    # the box and the kernel, for post-processing (scripts/post/sph_grid.py): periodic along the
    # channel (x in [0, 5e-4] m), bounded across it, dx = 1e-3 m / 20 rows, h as given
    assert list(a["box_lo"]) == [0, a["box_lo"][1]] and a["box_lo"][1] < 0, dict(a)
    assert a["box_hi"][0] == 5e-4 and a["box_hi"][1] > 1e-3, dict(a)
    assert list(a["periodic"]) == [1, 0], dict(a)
    assert abs(a["dx"][0] - 5e-5) < 1e-18 and a["sph_h"][0] == 1.5e-4, dict(a)
    assert a["sph_kernel"] == b"lucy", dict(a)
run = json.load(open(os.path.join(d, "run.json")))
for k in ("dmhs_version", "options", "ranks", "start", "end", "status"):
    assert k in run, k
assert run["status"] == "completed" and run["ranks"] == 1 and run["end"], run
print("snapshot attributes and run.json: OK")
PYEOF
"$EXE" "${QUICK[@]}" -t_end 0.01 -output_snapshots false -output_dir "$W/off" > "$W/off.log"
# a listing, then a here-string: '! ls | grep -q' passed when ls failed (no directory) and,
# under pipefail, when grep -q's early exit killed ls by SIGPIPE
listing=$(ls "$W/off") || die "-output_snapshots false: no output directory $W/off"
grep -q '"status": "completed"' "$W/off/run.json" || die "-output_snapshots false: the run did not complete"
if grep -q -e '^snap_' -e xdmf <<<"$listing"; then die "-output_snapshots false still wrote snapshots"; fi
echo "consistency: OK"
