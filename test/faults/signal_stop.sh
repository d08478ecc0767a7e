#!/bin/bash
# Stops that always checkpoint: a run on 2 ranks under mpirun gets a stop signal
# the way users and batch systems send one, must write a checkpoint and say
# "signal-checkpoint" in run.json, and its restart must end with the outputs of
# an uninterrupted run: the -dump_final CSV byte for byte, every snapshot and the
# final checkpoint bitwise (by gid), particles.xdmf, every CSV but wall-clock columns.
#   group_term   SIGTERM to mpirun's process group and to each rank directly (a group that
#                holds the ranks too: timeout, kill -- -PGID, srun): each rank gets it twice,
#                directly and a second later through mpirun
#   group_int    the same with SIGINT (Ctrl-C; mpirun passes it on as SIGTERM)
#   double_term  SIGTERM twice to one rank only, half a second apart, while the other rank is
#                held (SIGSTOP) so that the first cannot have been acted on yet; then the held
#                rank goes on and learns of the signal at the next step
#   usr1_mpirun  SIGUSR1 to mpirun, which forwards it to every rank (Slurm's --signal)
# Usage: signal_stop.sh DMHS PYTHON WORKDIR CASE MPIRUN...
set -uo pipefail
EXE=$1 PY=$2 W=$3 CASE=$4
shift 4
MPI=("$@")
source "$(dirname "$0")/../io/common.sh"
rm -rf "$W" && mkdir -p "$W"

# the run to interrupt, in a session of its own: its process group id is its pid
setsid -w bash -c 'echo $$ > "$1/pgid"; shift; exec "$@"' _ "$W" "${MPI[@]}" -n 2 "$EXE" "${QUICK[@]}" \
  -t_end 100 -output_dir "$W/b" > "$W/b1.log" 2>&1 &
launcher=$!
stop_all() { [ -s "$W/pgid" ] && kill -KILL -- -"$(cat "$W/pgid")" 2>/dev/null; }
trap stop_all EXIT
# the step loop runs once the first snapshot after t = 0 is written
for _ in $(seq 1 1200); do [ -f "$W/b/snap_000001.h5" ] && break; kill -0 $launcher 2>/dev/null || break; sleep 0.05; done
[ -f "$W/b/snap_000001.h5" ] || { cat "$W/b1.log"; die "the run did not start"; }
pgid=$(cat "$W/pgid")
ranks=($(pgrep -s "$pgid" -x dmhs))
[ ${#ranks[@]} = 2 ] || die "expected 2 dmhs processes in session $pgid, found ${#ranks[@]}"
case $CASE in
group_term) kill -TERM -- -"$pgid" "${ranks[@]}"; want=SIGTERM ;;
group_int) kill -INT -- -"$pgid" "${ranks[@]}"; want=SIGINT ;;
double_term)
  kill -STOP "${ranks[0]}"
  kill -TERM "${ranks[1]}"
  sleep 0.5 # two signals pending at once would merge into one
  kill -TERM "${ranks[1]}"
  sleep 0.5
  kill -CONT "${ranks[0]}"
  want=SIGTERM
  ;;
usr1_mpirun) kill -USR1 "$pgid"; want=SIGUSR1 ;;
*) die "unknown case $CASE" ;;
esac
for _ in $(seq 1 1200); do kill -0 $launcher 2>/dev/null || break; sleep 0.05; done
kill -0 $launcher 2>/dev/null && { cat "$W/b1.log"; die "the run did not stop within 60 s"; }
trap - EXIT
tail -4 "$W/b1.log"
grep -Eq "dmhs: received $want: stopped at step" "$W/b1.log" || die "no 'received $want: stopped' message"
if grep -Eq "signal 9|Killed|exited on signal" "$W/b1.log"; then die "a rank was killed"; fi
grep -q '"status": "signal-checkpoint"' "$W/b/run.json" || die "run.json status: $(grep status "$W/b/run.json")"
[ -f "$W/b/checkpoint.h5" ] || die "no checkpoint"
t=$(h5attr "$W/b/checkpoint.h5" t)
echo "checkpoint at step $(h5attr "$W/b/checkpoint.h5" step), t = $t s"
# Open MPI's mpirun passes SIGTERM and SIGINT on a second later (then SIGKILL after one more):
# the stop falls anywhere, and both runs end 100 steps after it
T_FINAL=$("$PY" -c "print($t + 100 * 2.5e-5)")

run() { # LOG ARGS...
  local log=$1 rc=0
  shift
  "${MPI[@]}" -n 2 "$EXE" "${QUICK[@]}" -t_end $T_FINAL "$@" > "$W/$log" 2>&1 || rc=$?
  [ $rc -eq 0 ] || { tail -5 "$W/$log"; die "$log: exit status $rc"; }
}
run b2.log -output_dir "$W/b" -restart "$W/b/checkpoint.h5" -dump_final "$W/b/final.csv"
grep -q '"status": "completed"' "$W/b/run.json" || die "run.json after the restart"
run a.log -output_dir "$W/a" -dump_final "$W/a/final.csv"
cmp "$W/a/final.csv" "$W/b/final.csv" || die "the final state differs from the uninterrupted run's"
. "$(dirname "$0")/../io/compare_dirs.sh"
compare_dirs "$W/a" "$W/b"
echo "stop signal ($CASE): checkpoint, signal-checkpoint, bitwise restart: OK"
