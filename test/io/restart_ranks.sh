#!/bin/bash
# Restart on another rank count: 1000 steps on one rank in one go (A) against
# 500 steps on 2 ranks + restart on 3 ranks + 500 (B) and + restart on 1 rank
# + 500 (C). Particles matched by gid; the rows' order differs with the ranks.
# dmhs sums in an order fixed by (cell, gid), so the states agree bitwise.
# Usage: restart_ranks.sh DMHS PYTHON MPIRUN... -- WORKDIR
set -euo pipefail
EXE=$1 PY=$2; shift 2
MPI=()
while [ "$1" != "--" ]; do MPI+=("$1"); shift; done
W=$2
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
rm -rf "$W" && mkdir -p "$W"
"$EXE" "${QUICK[@]}" -t_end 0.025 -output_dir "$W/a" > "$W/a.log"
for d in b c; do
  "${MPI[@]}" -n 2 "$EXE" "${QUICK[@]}" -t_end 0.0125 -output_dir "$W/$d" > "$W/$d.1.log"
done
"${MPI[@]}" -n 3 "$EXE" "${QUICK[@]}" -t_end 0.025 -output_dir "$W/b" -restart "$W/b/checkpoint.h5" > "$W/b.2.log"
"$EXE" "${QUICK[@]}" -t_end 0.025 -output_dir "$W/c" -restart "$W/c/checkpoint.h5" > "$W/c.2.log"
grep -q "Restarted from $W/b/checkpoint.h5 at step 500" "$W/b.2.log" || die "restart message missing"
"$PY" "$HERE/compare_by_gid.py" "$W/a/snap_000005.h5" "$W/b/snap_000005.h5" | tail -1
"$PY" "$HERE/compare_by_gid.py" "$W/a/snap_000005.h5" "$W/c/snap_000005.h5" | tail -1
echo "restart on another rank count: OK"
