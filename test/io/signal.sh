#!/bin/bash
# Signal-triggered checkpoint: a long run gets SIGUSR1 (or SIGTERM), must write
# a checkpoint and exit 0 with run.json status "signal-checkpoint"; the
# checkpoint must restart.
# Usage: signal.sh DMHS PYTHON WORKDIR [SIGNAL]
set -uo pipefail
EXE=$1 PY=$2 W=$3 SIG=${4:-USR1}
source "$(dirname "$0")/common.sh"
rm -rf "$W" && mkdir -p "$W"
"$EXE" "${QUICK[@]}" -t_end 100 -output_dir "$W/run" > "$W/run.log" 2>&1 &
pid=$!
# the handlers are in place once the step loop writes its first snapshot after t = 0
for _ in $(seq 1 600); do [ -f "$W/run/snap_000001.h5" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.05; done
[ -f "$W/run/snap_000001.h5" ] || { kill -9 $pid 2>/dev/null; cat "$W/run.log"; die "the run did not start"; }
kill -"$SIG" $pid
rc=0; wait $pid || rc=$?
cat "$W/run.log" | tail -3
[ $rc -eq 0 ] || die "exit status $rc after SIG$SIG"
grep -q "received SIG$SIG" "$W/run.log" || die "no message about SIG$SIG"
grep -q '"status": "signal-checkpoint"' "$W/run/run.json" || die "run.json status"
t=$(h5attr "$W/run/checkpoint.h5" t)
step=$(h5attr "$W/run/checkpoint.h5" step)
echo "checkpoint at step $step, t = $t s"
t_end=$("$PY" -c "print($t + 0.0025)")
"$EXE" "${QUICK[@]}" -t_end "$t_end" -output_dir "$W/run" -restart "$W/run/checkpoint.h5" > "$W/restart.log" 2>&1 ||
  { cat "$W/restart.log"; die "restart from the signal checkpoint failed"; }
grep -q '"status": "completed"' "$W/run/run.json" || die "run.json after restart"
[ "$(h5attr "$W/run/checkpoint.h5" step)" = $((step + 100)) ] || die "restart did not run 100 steps"
"$PY" "$HERE/check_xdmf.py" "$W/run" 2
echo "signal checkpoint (SIG$SIG): OK"
