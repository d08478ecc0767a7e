#!/bin/bash
# Restart equivalence, bitwise, on one rank:
#  1. 2N steps in one go (A) == N steps, checkpoint at the end, restart, N more (B).
#  2. A run that checkpoints at step N and goes on past it (as if killed later),
#     restarted from that checkpoint in the same directory (C): the same final
#     state, error.csv identical to A's (rows past the checkpoint replaced), and
#     the XDMF index consistent with the snapshot files.
# Usage: restart.sh DMHS PYTHON WORKDIR
set -euo pipefail
EXE=$1 PY=$2 W=$3
source "$(dirname "$0")/common.sh"
rm -rf "$W" && mkdir -p "$W"
run() { "$EXE" "${QUICK[@]}" "$@"; }

run -t_end 0.025 -output_dir "$W/a" > "$W/a.log"                       # 1000 steps
run -t_end 0.0125 -output_dir "$W/b" > "$W/b1.log"                      # 500 steps
run -t_end 0.025 -output_dir "$W/b" -restart "$W/b/checkpoint.h5" > "$W/b2.log"
grep -q "Restarted from $W/b/checkpoint.h5 at step 500" "$W/b2.log" || die "restart message missing"
echo "== 1000 steps vs 500 + restart + 500: final checkpoints"
"$PY" "$HERE/compare_h5.py" "$W/a/checkpoint.h5" "$W/b/checkpoint.h5"
echo "== final snapshots (t = 0.025 s)"
"$PY" "$HERE/compare_h5.py" "$W/a/snap_000005.h5" "$W/b/snap_000005.h5"

run -t_end 0.02 -checkpoint_interval 0.0125 -checkpoint_at_end false -output_dir "$W/c" > "$W/c1.log"
[ "$(h5attr "$W/c/checkpoint.h5" step)" = 500 ] || die "interval checkpoint not at step 500"
run -t_end 0.025 -output_dir "$W/c" -restart "$W/c/checkpoint.h5" > "$W/c2.log"
echo "== 800 steps with a checkpoint at 500, restarted from it to 1000"
"$PY" "$HERE/compare_h5.py" "$W/a/checkpoint.h5" "$W/c/checkpoint.h5"
for d in b c; do
  diff <(cut -d, -f1,2,4,5 "$W/a/error.csv") <(cut -d, -f1,2,4,5 "$W/$d/error.csv") ||
    die "error.csv of the restarted run $d differs from the uninterrupted one"
  "$PY" "$HERE/check_xdmf.py" "$W/$d" 6
  grep -q '"status": "completed"' "$W/$d/run.json" || die "$d/run.json status"
done
echo "restart equivalence: OK"
