#!/bin/bash
# scripts/vein_study.sh on a miniature: two tiny runs of the table (4 and 5, the
# short leaflets, at dx = 5e-4 m on a 0.06 m period) two at a time; SIGTERM to
# the driver stops both with a checkpoint; started again, the driver continues
# both and they complete; their vein.csv equals, byte for byte, that of an
# uninterrupted run; a third start skips them; --collect copies their CSVs; a
# tiny clot run by seed (--clot-seeds) runs with that seed and its clots.csv is collected.
# Usage: vein_study_driver.sh REPO DMHS WORKDIR
set -euo pipefail
repo=$1 exe=$2 W=$3
rm -rf "$W" && mkdir -p "$W"
tiny=(-vein_dx 5e-4 -vein_length 0.06 -t_end 0.1 -output_interval 0.01 -quiet)
drive() { DMHS_EXE="$exe" bash "$repo/scripts/vein_study.sh" --ids "4 5" --jobs 2 --study none "$@" -- "${tiny[@]}"; }
fail() { echo "FAIL: $*"; for f in "$W"/*.log "$W"/*/*.log; do [ -f "$f" ] && { echo "== $f"; tail -n 20 "$f"; }; done; exit 1; }

# the interrupted study: SIGTERM once both runs write their rows
(DMHS_EXE="$exe" exec bash "$repo/scripts/vein_study.sh" --ids "4 5" --jobs 2 --study none --out "$W/study" \
  -- "${tiny[@]}") > "$W/1.log" 2>&1 &
driver=$!
for _ in $(seq 600); do
  [ -s "$W/study/run4/vein.csv" ] && [ -s "$W/study/run5/vein.csv" ] && break
  sleep 0.1
done
# two runs side by side may use every core this test may: neither is bound to one of them
allowed=$(awk '/^Cpus_allowed_list/ {print $2}' /proc/self/status)
for id in 4 5; do
  pid=$(pgrep -f -- "-output_dir $W/study/run$id( |\$)" | while read -r p; do
    [ "$(cat /proc/"$p"/comm 2>/dev/null)" != mpirun ] && echo "$p"; done | head -n 1)
  [ -n "$pid" ] || continue # already done: nothing to check
  got=$(awk '/^Cpus_allowed_list/ {print $2}' /proc/"$pid"/status 2>/dev/null || true)
  [ -z "$got" ] || [ "$got" = "$allowed" ] || fail "run $id bound to cores $got, not $allowed"
done
kill -TERM "$driver"
rc=0; wait "$driver" || rc=$?
[ "$rc" -ne 0 ] || fail "an interrupted study exited with status 0"
for id in 4 5; do
  grep -q '^  "status": "signal-checkpoint"' "$W/study/run$id/run.json" || fail "run $id: not stopped with a checkpoint"
  [ -f "$W/study/run$id/checkpoint.h5" ] || fail "run $id: no checkpoint.h5"
done

# started again: both continue and complete
drive --out "$W/study" > "$W/2.log" 2>&1 || fail "the continued study failed"
for id in 4 5; do
  grep -q "run$id continues from $W/study/run$id/checkpoint.h5" "$W/2.log" || fail "run $id not continued"
  grep -q "run$id: completed" "$W/2.log" || fail "run $id not completed"
done

# the same runs without interruption: the same rows
drive --out "$W/ref" > "$W/3.log" 2>&1 || fail "the uninterrupted study failed"
for id in 4 5; do
  cmp "$W/study/run$id/vein.csv" "$W/ref/run$id/vein.csv" || fail "run $id: vein.csv differs after the interruption"
done

# a third start runs nothing; --collect copies the CSVs
drive --out "$W/study" > "$W/4.log" 2>&1 || fail "a completed study did not exit 0"
[ "$(grep -c "already completed" "$W/4.log")" = 2 ] || fail "completed runs were not skipped"
bash "$repo/scripts/vein_study.sh" --ids "4 5" --out "$W/study" --collect "$W/results" > "$W/5.log" 2>&1 \
  || fail "--collect failed"
for id in 4 5; do
  for f in vein-summary.csv vein.csv vein-sinus.csv run.json; do
    [ -s "$W/results/run$id/$f" ] || fail "--collect: no $f of run $id"
  done
done
# the clot case by seed: one tiny clot run, its clot files collected
clot=(-vein_dx 5e-4 -vein_length 0.06 -vein_leaflet_length 0.01 -t_end 0.06 -output_interval 0.01
      -agglomeration_start 0.02 -agglomeration_interval 0.01 -quiet)
DMHS_EXE="$exe" bash "$repo/scripts/vein_study.sh" --ids "" --clot-seeds 3 --study none --out "$W/study" \
  -- "${clot[@]}" > "$W/7.log" 2>&1 || fail "the clot run failed"
grep -q "clot-seed3: completed" "$W/7.log" || fail "clot-seed3 not completed"
grep -qE -- '-agglomeration_seed 3( |")' "$W/study/clot-seed3/run.json" \
  || fail "clot-seed3 did not run with seed 3"
bash "$repo/scripts/vein_study.sh" --ids "" --clot-seeds 3 --out "$W/study" --collect "$W/results" \
  > "$W/8.log" 2>&1 || fail "--collect of the clot run failed"
[ -s "$W/results/clot-seed3/clots.csv" ] || fail "--collect: no clots.csv of clot-seed3"
# bad arguments: a clear message and status 2
rc=0; bash "$repo/scripts/vein_study.sh" --ids "4 7" --out "$W/x" > "$W/6.log" 2>&1 || rc=$?
[ "$rc" = 2 ] && grep -q "no input/vein-run7.opts" "$W/6.log" || fail "an unknown run id was not refused"
rc=0; bash "$repo/scripts/vein_study.sh" --clot-seeds "1 x" --out "$W/x" > "$W/9.log" 2>&1 || rc=$?
[ "$rc" = 2 ] && grep -q "clot-seeds: 'x'" "$W/9.log" || fail "a bad seed was not refused"
echo "vein study driver: OK"
