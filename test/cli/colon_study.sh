#!/bin/bash
# scripts/slurm/colon-study.sbatch in its dry-run mode (no Slurm, nothing
# run): task ids 0 and 99 are the grid's corners (L = 0.0046 m, nu = 1e-6
# m^2/s, V_w = 1.45 cm/s and L = 0.0157 m, nu = 5e-4 m^2/s, V_w = 26 cm/s),
# t_w = (N+1) b / ((2N+5) V_w) is 0.6 s to 3 digits at V_w = 1.45 cm/s, task
# 37 is (0.0081 m, 5e-4 m^2/s, 5.8 cm/s) with --dry-run as well as
# DMHS_DRY_RUN=1; ids 100, -1 and "x" and a missing id fail; a completed run
# is skipped and one with a checkpoint continues from it (-restart); the
# fast waves (V_w = 13 and 26 cm/s) get -sph_c0 100 U_m/3 and
# -sph_av_alpha 0.1, the slow ones neither.
# Usage: colon_study.sh REPO WORKDIR
set -euo pipefail
repo=$1 W=$2
rm -rf "$W" && mkdir -p "$W"
sb="$repo/scripts/slurm/colon-study.sbatch"
fail() { echo "FAIL: $*"; exit 1; }
dry() { # dry ID [extra args]: the task's output in $W/ID.log
  local id=$1; shift
  (cd "$repo" && SLURM_ARRAY_TASK_ID=$id SLURM_SUBMIT_DIR="$repo" DMHS_EXE=/nonexistent/dmhs \
    bash "$sb" --dry-run "$@") > "$W/$id.log" 2>&1 || { cat "$W/$id.log"; fail "task $id failed"; }
  cat "$W/$id.log"
}
value() { # value FILE OPTION: the value after OPTION on the dry-run command line (the last one)
  awk -v k="$2" '/dry run:/ { for (i = 1; i < NF; i++) if ($i == k) v = $(i + 1) } END { print v }' "$1"
}
expect() { # expect ID OPTION VALUE
  local got; got=$(value "$W/$1.log" "$2")
  [ "$got" = "$3" ] || fail "task $1: $2 is '$got', expected '$3'"
}
close() { # close ID OPTION VALUE RELTOL
  local got; got=$(value "$W/$1.log" "$2")
  awk -v g="$got" -v e="$3" -v r="$4" 'BEGIN { exit !(g != "" && (g - e) <= r * e && (e - g) <= r * e) }' ||
    fail "task $1: $2 is '$got', expected $3 within $4"
}

dry 0
grep -q "dry run: srun /nonexistent/dmhs -options_file input/intestine.opts " "$W/0.log" || fail "task 0: not the dmhs command"
expect 0 -intestine_level 0.0046
expect 0 -sph_nu 1e-6
expect 0 -output_dir output/colon-study/L0.0046_nu1e-6_Vw1.45
tw=$(value "$W/0.log" -peristalsis_tw)
[ "$(awk -v t="$tw" 'BEGIN { printf "%.3f", t }')" = 0.600 ] || fail "task 0: t_w = $tw s, expected 0.600 s to 3 digits"
grep -q "V_w = 1.45 cm/s: t_w = (N+1) b / ((2N+5) V_w) = $tw s (N+1 = 10, b = 0.02 m)" "$W/0.log" || fail "task 0: t_w not printed"
close 0 -t_end 138.03 1e-4                # delay 0.05 s + 10 waves of 23 t_w + one output interval
close 0 -output_interval 0.049975 1e-4    # t_w/12
close 0 -checkpoint_interval 13.7931 1e-4 # once per wave
[ -z "$(value "$W/0.log" -restart)" ] || fail "task 0: -restart without a checkpoint"

dry 99
expect 99 -intestine_level 0.0157
expect 99 -sph_nu 5e-4
expect 99 -output_dir output/colon-study/L0.0157_nu5e-4_Vw26
close 99 -peristalsis_tw 0.0334448 1e-5   # 0.2 m / (23 x 0.26 m/s)
close 99 -t_end 7.74509 1e-5
# the fast waves' calibration: c0 = 100 U_m/3, U_m = 1.5 (F/k_s)/(ramp t_w), and alpha 0.1
close 99 -sph_c0 14.95 5e-3             # U_m = 1.5 x 0.01 m / 0.0334 s = 0.449 m/s (3 digits)
expect 99 -sph_av_alpha 0.1
dry 3                                   # V_w = 13 cm/s: U_m = 0.224 m/s
close 3 -sph_c0 7.48 5e-3 
[ -z "$(value "$W/0.log" -sph_c0)$(value "$W/0.log" -sph_av_alpha)" ] ||
  fail "task 0 (V_w = 1.45 cm/s): the fast waves' calibration on a slow wave"

# 37 = 25 x 1 + 5 x 2 + 2, through DMHS_DRY_RUN=1, with extra options after the task's
(cd "$repo" && SLURM_ARRAY_TASK_ID=37 SLURM_SUBMIT_DIR="$repo" DMHS_DRY_RUN=1 bash "$sb" -quiet) > "$W/37.log" 2>&1 ||
  { cat "$W/37.log"; fail "task 37 (DMHS_DRY_RUN=1)"; }
cat "$W/37.log"
expect 37 -intestine_level 0.0081
expect 37 -sph_nu 5e-5
expect 37 -output_dir output/colon-study/L0.0081_nu5e-5_Vw5.8
close 37 -peristalsis_tw 0.149925 1e-5
grep -q -- "-output_dir output/colon-study/L0.0081_nu5e-5_Vw5.8 -quiet$" "$W/37.log" || fail "task 37: extra options not passed on"

for id in 100 -1 x; do
  if (cd "$repo" && SLURM_ARRAY_TASK_ID=$id bash "$sb" --dry-run) > "$W/bad.log" 2>&1; then
    cat "$W/bad.log"; fail "task id $id accepted"
  fi
  grep -q "task id '$id' is not in 0..99" "$W/bad.log" || { cat "$W/bad.log"; fail "task id $id: no message"; }
done
if (cd "$repo" && env -u SLURM_ARRAY_TASK_ID bash "$sb" --dry-run) > "$W/none.log" 2>&1; then
  fail "no task id accepted"
fi

# a completed run is skipped, a checkpointed one continues (its own -output_dir)
mkdir -p "$W/done" "$W/ckpt"
echo '{ "status": "completed" }' > "$W/done/run.json"
dry 5 -output_dir "$W/done" > /dev/null
grep -q "task 5 already completed ($W/done)" "$W/5.log" || { cat "$W/5.log"; fail "a completed run was not skipped"; }
grep -q "dry run:" "$W/5.log" && fail "a completed run would run again"
echo '{ "status": "signal-checkpoint" }' > "$W/ckpt/run.json" && : > "$W/ckpt/checkpoint.h5"
dry 6 -output_dir "$W/ckpt" > /dev/null
expect 6 -restart "$W/ckpt/checkpoint.h5"
grep -q "task 6 continues from $W/ckpt/checkpoint.h5" "$W/6.log" || { cat "$W/6.log"; fail "not continued"; }
echo "colon study script: OK"
