#!/bin/bash
# -restart compares the checkpoint's physics options with this run's: a changed
# kernel or body force is refused naming the option and both values, unless
# -restart_allow_change (then run.json lists the change); run-control options
# (-t_end, -output_*, -checkpoint_*, -progress_interval, -quiet) may change; a
# -t_end at or before the checkpoint's time is refused.
# Usage: restart_options.sh DMHS PYTHON WORKDIR
set -uo pipefail
EXE=$1 PY=$2 W=$3
source "$(dirname "$0")/common.sh"
rm -rf "$W" && mkdir -p "$W"
"$EXE" "${QUICK[@]}" -t_end 0.0025 -output_dir "$W/good" > "$W/good.log" 2>&1 || die "the reference run failed"
GOOD=$W/good/checkpoint.h5

# expect_fail NAME PATTERN ARGS...: exit status 1 and PATTERN on stderr
expect_fail() {
  local name=$1 pattern=$2; shift 2
  local rc=0
  "$EXE" "${QUICK[@]}" -t_end 0.005 -restart "$GOOD" -output_dir "$W/$name" "$@" > "$W/$name.out" 2> "$W/$name.err" ||
    rc=$?
  [ $rc -eq 1 ] || { cat "$W/$name.err"; die "$name: exit status $rc, expected 1"; }
  grep -qF -- "$pattern" "$W/$name.err" || { cat "$W/$name.err"; die "$name: message lacks '$pattern'"; }
  echo "$name: $(head -1 "$W/$name.err")"
}
expect_fail kernel "1 physics option(s) differ from the run that wrote it: -sph_kernel lucy in the checkpoint, cubic now" \
  -sph_kernel cubic
expect_fail body_force "-body_force 0.0002,0 in the checkpoint, 0.0003,0 now" -body_force 3e-4,0
expect_fail two "2 physics option(s) differ" -sph_nu 2e-6 -sph_c0 0.02
expect_fail t_end_at "-t_end 0.0025 s is not after the time of the checkpoint $GOOD (t = 0.0025 s, step 100)" \
  -t_end 0.0025
expect_fail t_end_before "nothing to run; give a later -t_end" -t_end 0.001

# run control may change
"$EXE" "${QUICK[@]}" -t_end 0.004 -restart "$GOOD" -output_dir "$W/control" -output_interval 0.001 \
  -checkpoint_interval 0.003 -checkpoint_at_end false -progress_interval 0.0005 -output_snapshots false \
  > "$W/control.log" 2>&1 || { tail -3 "$W/control.log"; die "a run-control change was refused"; }
grep -q '"restart_changes": null' "$W/control/run.json" || die "control/run.json should list no change"

# -restart_allow_change: continues, says so, and run.json records it
"$EXE" "${QUICK[@]}" -t_end 0.005 -restart "$GOOD" -output_dir "$W/allowed" -sph_kernel cubic -restart_allow_change \
  > "$W/allowed.log" 2>&1 || { tail -3 "$W/allowed.log"; die "-restart_allow_change did not continue"; }
grep -q "WARNING: -restart_allow_change: continuing $GOOD with 1 changed physics option(s): -sph_kernel" \
  "$W/allowed.log" || die "no warning about the changed option"
grep -q '"restart_allow_change": true' "$W/allowed/run.json" || die "run.json lacks restart_allow_change"
grep -q '"restart_changes": "-sph_kernel lucy in the checkpoint, cubic now"' "$W/allowed/run.json" ||
  die "run.json lacks the change"
grep -q '"status": "completed"' "$W/allowed/run.json" || die "allowed/run.json status"
echo "restart option checks: OK"
