#!/bin/bash
# The progress lines change nothing but the console: the quick colon (automatic dt,
# membrane bonds) on 2 ranks without wall-clock lines (A) and with a line, a heartbeat and
# the projection after every step (B, rank 0's clock deciding for both ranks), to the same
# outputs: every snapshot, checkpoint and CSV compared (test/io/compare_dirs.sh).
# Usage: progress_bitwise.sh DMHS PYTHON MPIRUN... -- WORKDIR
set -euo pipefail
EXE=$1 PY=$2; shift 2
MPI=()
while [ "$1" != "--" ]; do MPI+=("$1"); shift; done
W=$2
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
rm -rf "$W" && mkdir -p "$W"
INPUT=$HERE/../../input
run() { # NAME OPTIONS...
  local name=$1; shift
  "${MPI[@]}" -n 2 "$EXE" -options_file "$INPUT/intestine-quick.opts" -t_end 0.01 -output_interval 0.0025 \
    -output_dir "$W/$name" "$@" > "$W/$name.log" 2>&1 || { tail -5 "$W/$name.log"; die "$name: exit status"; }
}
run a -progress_wall_interval 0
run b -progress_wall_interval 1e-9
lines_a=$(grep -c '^step ' "$W/a.log" || true) lines_b=$(grep -c '^step ' "$W/b.log" || true)
steps=$(sed -n 's/^dmhs summary: .*, \([0-9]*\) steps to t = .*/\1/p' "$W/b.log")
[ "$lines_b" -ge "$steps" ] && [ "$lines_b" -gt "$lines_a" ] ||
  die "B printed $lines_b lines in $steps steps (A: $lines_a): the wall-clock lines did not come"
echo "== 2 ranks, $steps steps: $lines_a progress lines against $lines_b"
. "$HERE/compare_dirs.sh"
compare_dirs "$W/a" "$W/b"
echo "progress lines change no output: OK"
