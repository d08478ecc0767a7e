#!/bin/bash
# Restart equivalence of one scene, across rank counts: a run to T_END on
# NP_REF ranks (A) against a run to T_END/2 on NP_FIRST ranks that checkpoints
# at its end, restarted in the same directory on NP_SECOND ranks to T_END (B).
# Every output must agree: each snapshot and the final checkpoint bitwise
# (particles matched by gid), particles.xdmf, every CSV (the diagnostics, the
# profiles, the gid-sorted -dump_final) apart from wall-clock columns.
# With --past, the first run checkpoints at T_END/2 and goes on to 3/4 T_END,
# as a run killed after its last checkpoint: the restart must replace what it
# wrote after the checkpoint (snapshots, CSV rows).
# Usage: restart_scene.sh DMHS PYTHON MPIRUN... -- [--past] WORKDIR NP_REF NP_FIRST NP_SECOND T_END OPTIONS...
set -euo pipefail
EXE=$1 PY=$2; shift 2
MPI=()
while [ "$1" != "--" ]; do MPI+=("$1"); shift; done
shift
PAST=0
if [ "$1" = "--past" ]; then PAST=1; shift; fi
W=$1 NP_REF=$2 NP_FIRST=$3 NP_SECOND=$4 T_END=$5; shift 5
OPTS=("$@" -quiet)
HERE=$(cd "$(dirname "$0")" && pwd)
die() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$W" && mkdir -p "$W"
HALF=$("$PY" -c "print($T_END / 2)")
run() { # LOG NP ARGS...
  local log=$1 np=$2; shift 2
  local rc=0
  "${MPI[@]}" -n "$np" "$EXE" "${OPTS[@]}" "$@" > "$W/$log" 2>&1 || rc=$?
  [ $rc -eq 0 ] || { tail -5 "$W/$log"; die "$log: exit status $rc"; }
}
run a.log "$NP_REF" -t_end "$T_END" -output_dir "$W/a" -dump_final "$W/a/final.csv"
if [ $PAST = 1 ]; then
  run b1.log "$NP_FIRST" -t_end "$("$PY" -c "print(0.75 * $T_END)")" -checkpoint_interval "$HALF" \
    -checkpoint_at_end false -output_dir "$W/b"
else
  run b1.log "$NP_FIRST" -t_end "$HALF" -output_dir "$W/b"
fi
run b2.log "$NP_SECOND" -t_end "$T_END" -output_dir "$W/b" -restart "$W/b/checkpoint.h5" -dump_final "$W/b/final.csv"
grep -q "Restarted from $W/b/checkpoint.h5" "$W/b2.log" || die "no restart message"
grep -q '"status": "completed"' "$W/b/run.json" || die "b/run.json does not say completed"
echo "== $NP_REF ranks to t = $T_END s against $NP_FIRST ranks to $HALF s + restart on $NP_SECOND ranks" \
  "$([ $PAST = 1 ] && echo "(the first run went on past its checkpoint)")"
. "$HERE/compare_dirs.sh"
compare_dirs "$W/a" "$W/b"
echo "restart equivalence ($NP_FIRST -> $NP_SECOND ranks): OK"
