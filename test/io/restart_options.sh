#!/bin/bash
# -restart compares the checkpoint's physics options with this run's: a changed
# kernel or body force is refused naming the option and both values, unless
# -restart_allow_change (then run.json lists the change); run-control options
# (-t_end, -output_*, -checkpoint_*, -progress_interval, -quiet) may change; a
# -t_end at or before the checkpoint's time is refused. An option the
# checkpoint's dmhs did not have (here one struck from its record) continues at
# its default with a note (run.json: restart_new_options); given, it is a change.
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
# a checkpoint written by a dmhs without -sph_kernel: its record struck of that line
OLDER=$W/older.h5
cp "$GOOD" "$OLDER"
"$PY" - "$OLDER" <<'PYEOF' || die "cannot edit $OLDER"
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r+") as f:
    lines = f.attrs["physics_options"].decode().split("\n")
    kept = [l for l in lines if not l.startswith("-sph_kernel ")]
    assert len(kept) == len(lines) - 1, "no -sph_kernel line in physics_options"
    del f.attrs["physics_options"]
    f.attrs.create("physics_options", np.bytes_("\n".join(kept)))
PYEOF
"$EXE" "${QUICK[@]}" -t_end 0.005 -restart "$OLDER" -output_dir "$W/older" > "$W/older.log" 2>&1 ||
  { tail -3 "$W/older.log"; die "an option unknown to the checkpoint's dmhs, at its default, was refused"; }
grep -qF "note: -restart $OLDER: 1 option(s) unknown to the dmhs that wrote it, continued at this run's default(s): -sph_kernel lucy" \
  "$W/older.log" || die "no note about the option the checkpoint lacks"
grep -q '"restart_new_options": "-sph_kernel lucy"' "$W/older/run.json" || die "run.json lacks restart_new_options"
grep -q '"restart_changes": null' "$W/older/run.json" || die "older/run.json should list no change"
# the same rows as a restart from the unedited checkpoint
"$EXE" "${QUICK[@]}" -t_end 0.005 -restart "$GOOD" -output_dir "$W/same" > "$W/same.log" 2>&1 ||
  die "the restart from $GOOD failed"
cmp -s <(cut -d, -f1,2,4- "$W/older/error.csv") <(cut -d, -f1,2,4- "$W/same/error.csv") ||
  die "older/error.csv differs from same/error.csv (wall time aside)"
rc=0
"$EXE" "${QUICK[@]}" -t_end 0.005 -restart "$OLDER" -output_dir "$W/older_given" -sph_kernel lucy \
  > "$W/older_given.out" 2> "$W/older_given.err" || rc=$?
[ $rc -eq 1 ] || die "older_given: exit status $rc, expected 1 (an option given that the checkpoint lacks)"
grep -qF -- "-sph_kernel (not set) in the checkpoint, lucy now" "$W/older_given.err" ||
  { cat "$W/older_given.err"; die "older_given: message lacks the option"; }
echo "restart option checks: OK"
