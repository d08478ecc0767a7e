#!/bin/bash
# The output-directory policy (doc/guide/output.md, "Output directory"):
#  1. a fresh run into a directory an earlier, longer run used removes that
#     run's snapshots and particles.xdmf: only its own remain;
#  2. stale *.tmp files (interrupted writes) are removed by the next run;
#  3. a restart with an earlier -t_end than the interrupted run reached
#     removes the snapshots written after the checkpoint: files and index agree.
# Usage: outdir.sh DMHS PYTHON WORKDIR
set -uo pipefail
EXE=$1 PY=$2 W=$3
source "$(dirname "$0")/common.sh"
rm -rf "$W" && mkdir -p "$W"
snaps() { (cd "$1" && ls snap_*.h5 2>/dev/null | tr '\n' ' '); }

"$EXE" "${QUICK[@]}" -t_end 0.05 -output_dir "$W/d" > "$W/long.log" 2>&1 || die "the long run failed"
[ "$(snaps "$W/d")" = "$(printf 'snap_%06d.h5 ' $(seq 0 10))" ] || die "the long run wrote $(snaps "$W/d")"
touch "$W/d/snap_000003.h5.tmp" "$W/d/profile_t0.01.csv.tmp"
"$EXE" "${QUICK[@]}" -t_end 0.015 -output_dir "$W/d" > "$W/short.log" 2>&1 || die "the short run failed"
grep -q "output directory $W/d: removed 2 unfinished .tmp file(s) and 12 snapshot/index file(s) of an earlier run" \
  "$W/short.log" || { grep "output directory" "$W/short.log"; die "no message about the removed files"; }
[ "$(snaps "$W/d")" = "snap_000000.h5 snap_000001.h5 snap_000002.h5 snap_000003.h5 " ] ||
  die "after the short run: $(snaps "$W/d")"
ls "$W/d"/*.tmp 2>/dev/null && die "stale .tmp files remain"
"$PY" "$HERE/check_xdmf.py" "$W/d" 4 || die "index and snapshots disagree after the short run"

# 3. checkpoint at 0.025 s, the run goes on to 0.04 s (snapshots 0..8), then a restart to 0.03 s
"$EXE" "${QUICK[@]}" -t_end 0.04 -checkpoint_interval 0.025 -checkpoint_at_end false -output_dir "$W/r" \
  > "$W/r1.log" 2>&1 || die "the interrupted run failed"
"$EXE" "${QUICK[@]}" -t_end 0.03 -restart "$W/r/checkpoint.h5" -output_dir "$W/r" > "$W/r2.log" 2>&1 ||
  die "the restart failed"
grep -q "removed 3 snapshot file(s) written after the checkpoint" "$W/r2.log" || die "no message after the restart"
[ "$(snaps "$W/r")" = "$(printf 'snap_%06d.h5 ' $(seq 0 6))" ] || die "after the restart: $(snaps "$W/r")"
"$PY" "$HERE/check_xdmf.py" "$W/r" 7 || die "index and snapshots disagree after the restart"
echo "output directory policy: OK"
