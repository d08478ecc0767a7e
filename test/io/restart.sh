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
  # diff of two process substitutions ignores cut's status: a missing file on both sides compared equal
  for f in "$W/a/error.csv" "$W/$d/error.csv"; do
    [ "$(wc -l < "$f")" -ge 3 ] || die "$f is missing or has no rows"
  done
  diff <(cut -d, -f1,2,4,5 "$W/a/error.csv") <(cut -d, -f1,2,4,5 "$W/$d/error.csv") ||
    die "error.csv of the restarted run $d differs from the uninterrupted one"
  "$PY" "$HERE/check_xdmf.py" "$W/$d" 6
  grep -q '"status": "completed"' "$W/$d/run.json" || die "$d/run.json status"
done
# 3. Neighbour lists with a skin: the restart must rebuild ghosts and pairs from
#    the positions of the last build (x_build), not the current ones. A strong
#    vortex in a periodic box rebuilds at irregular steps; the checkpoint falls
#    between two builds (step 240; the run rebuilt at 237 and next after 241).
BOX=(-scene box -box_nx 30 -box_ny 30 -box_velocity 1 -dt 2e-6 -partition_interval 0 -neighbour_skin 0.1
     -output_snapshots false -quiet)
"$EXE" "${BOX[@]}" -t_end 1e-3 -output_dir "$W/e" > "$W/e.log"
"$EXE" "${BOX[@]}" -t_end 4.8e-4 -output_dir "$W/f" > "$W/f1.log"
"$EXE" "${BOX[@]}" -t_end 1e-3 -output_dir "$W/f" -restart "$W/f/checkpoint.h5" > "$W/f2.log"
builds=$(grep -o '[0-9]* neighbour-list builds' "$W/e.log" | cut -d' ' -f1)
[ "$builds" -ge 5 ] || die "the vortex run rebuilt its lists only $builds times: the case no longer tests the skin"
echo "== box vortex, $builds list builds in 500 steps: 500 vs 240 + restart + 260"
"$PY" "$HERE/compare_h5.py" "$W/e/checkpoint.h5" "$W/f/checkpoint.h5"
echo "restart equivalence: OK"
