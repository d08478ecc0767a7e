#!/bin/bash
# Every Slurm script in scripts/slurm/ in its dry-run mode, outside Slurm: it
# prints the commands it would run (srun dmhs ..., and with RESUBMIT=1 the
# sbatch that would resubmit it), runs none of them (srun and sbatch on PATH
# here fail the test if called), continues a checkpointed run (-restart) and
# skips a completed one, refuses a bad task id or a missing options file in
# one line; and every script carries the site placeholders (commented
# --account and --partition lines, a marked module section) and says how to
# change its tasks and time.
# Usage: slurm_dry_run.sh REPO WORKDIR
set -euo pipefail
repo=$1 W=$2
rm -rf "$W" && mkdir -p "$W/bin"
for cmd in srun sbatch; do
  printf '#!/bin/bash\necho "%s $*" >> "%s/called"\nexit 1\n' "$cmd" "$W" > "$W/bin/$cmd"
  chmod +x "$W/bin/$cmd"
done
fail() { echo "FAIL: $*"; exit 1; }
exe=/nonexistent/dmhs
# run NAME SCRIPT [args]: the script from the repository root, outside Slurm (no SLURM_* but
# what the caller sets), its output in $W/NAME.log; must succeed
run() {
  local name=$1 script=$2; shift 2
  (cd "$repo" && env -u SLURM_JOB_ID -u SLURM_SUBMIT_DIR -u SLURM_NTASKS PATH="$W/bin:$PATH" DMHS_EXE=$exe \
    bash "scripts/slurm/$script" "$@") > "$W/$name.log" 2>&1 || { cat "$W/$name.log"; fail "$name: exit status $?"; }
  cat "$W/$name.log"
}
# refuse NAME REGEX SCRIPT [args]: must fail with exit status 1 and one line matching REGEX
refuse() {
  local name=$1 regex=$2 script=$3 status=0; shift 3
  (cd "$repo" && env -u SLURM_JOB_ID -u SLURM_SUBMIT_DIR PATH="$W/bin:$PATH" DMHS_EXE=$exe \
    bash "scripts/slurm/$script" "$@") > "$W/$name.log" 2>&1 || status=$?
  cat "$W/$name.log"
  [ "$status" = 1 ] || fail "$name: exit status $status, expected 1"
  [ "$(wc -l < "$W/$name.log")" = 1 ] || fail "$name: not one line"
  grep -Eq -- "$regex" "$W/$name.log" || fail "$name: no /$regex/"
}
has() { grep -qF -- "$2" "$W/$1.log" || fail "$1: no '$2'"; }
hasnt() { if grep -qF -- "$2" "$W/$1.log"; then fail "$1: '$2' (not expected)"; fi; }
mkdir -p "$W/ckpt" "$W/done"
echo '{ "status": "signal-checkpoint" }' > "$W/ckpt/run.json" && : > "$W/ckpt/checkpoint.h5"
echo '{ "status": "completed" }' > "$W/done/run.json" && : > "$W/done/checkpoint.h5"

# dmhs.sbatch: one run, its checkpoint interval, the restart, the resubmission
run d1 dmhs.sbatch --dry-run input/poiseuille-quick.opts -quiet
has d1 "dmhs.sbatch: dry run: srun $exe -options_file input/poiseuille-quick.opts -quiet"
hasnt d1 "sbatch "
DMHS_DRY_RUN=1 CHECKPOINT_INTERVAL=0.1 RESUBMIT=1 run d2 dmhs.sbatch input/poiseuille-quick.opts -output_dir "$W/ckpt"
has d2 "dmhs.sbatch: continuing from $W/ckpt/checkpoint.h5"
has d2 "dmhs.sbatch: dry run: srun $exe -options_file input/poiseuille-quick.opts -checkpoint_interval 0.1 -restart $W/ckpt/checkpoint.h5 -output_dir $W/ckpt"
has d2 "dmhs.sbatch: dry run: then, unless $W/ckpt/run.json says \"completed\": sbatch scripts/slurm/dmhs.sbatch input/poiseuille-quick.opts -output_dir $W/ckpt"
run d3 dmhs.sbatch --dry-run input/poiseuille-quick.opts -output_dir "$W/done"
hasnt d3 "-restart"
refuse d4 "dmhs.sbatch: cannot read the options file 'input/no-such.opts'" dmhs.sbatch --dry-run input/no-such.opts
status=0
(cd "$repo" && PATH="$W/bin:$PATH" bash scripts/slurm/dmhs.sbatch --dry-run) > "$W/d5.log" 2>&1 || status=$?
[ "$status" != 0 ] && grep -q "usage: sbatch scripts/slurm/dmhs.sbatch <options-file>" "$W/d5.log" ||
  { cat "$W/d5.log"; fail "no options file: not refused with the usage"; }

# vein-study.sbatch: task 7 is run 19; extra options passed on; ids checked; skip and continue
SLURM_ARRAY_TASK_ID=7 RESUBMIT=1 run v1 vein-study.sbatch --dry-run -options_file input/vein-study.opts
has v1 "vein-study: task 7 of 0..13: run 19 (input/vein-run19.opts) into output/vein-run19"
has v1 "vein-study: dry run: srun $exe -options_file input/vein-run19.opts -options_file input/vein-study.opts"
has v1 "vein-study: dry run: then, unless output/vein-run19/run.json says \"completed\": sbatch --array=7 scripts/slurm/vein-study.sbatch -options_file input/vein-study.opts"
SLURM_ARRAY_TASK_ID=0 DMHS_DRY_RUN=1 run v2 vein-study.sbatch -output_dir "$W/ckpt"
has v2 "vein-study: dry run: srun $exe -options_file input/vein-run1.opts -restart $W/ckpt/checkpoint.h5 -output_dir $W/ckpt"
SLURM_ARRAY_TASK_ID=13 run v3 vein-study.sbatch --dry-run -output_dir "$W/done"
has v3 "vein-study: run 32 already completed ($W/done)"
hasnt v3 "dry run:"
for id in 14 -1 x; do
  SLURM_ARRAY_TASK_ID=$id refuse "v_$id" "vein-study: task id '$id' is not in 0..13" vein-study.sbatch --dry-run
done
status=0
(cd "$repo" && env -u SLURM_ARRAY_TASK_ID bash scripts/slurm/vein-study.sbatch --dry-run) > "$W/v4.log" 2>&1 || status=$?
[ "$status" != 0 ] || fail "vein-study without a task id: accepted"

# colon-study.sbatch (its grid: test/cli/colon_study.sh): the command and the resubmission
SLURM_ARRAY_TASK_ID=0 RESUBMIT=1 run c1 colon-study.sbatch --dry-run
has c1 "colon-study: dry run: srun $exe -options_file input/intestine.opts -intestine_level 0.0046"
has c1 "colon-study: dry run: then, unless output/colon-study/L0.0046_nu1e-6_Vw1.45/run.json says \"completed\": sbatch --array=0 scripts/slurm/colon-study.sbatch"

[ ! -e "$W/called" ] || { cat "$W/called"; fail "a dry run called srun or sbatch"; }

# the site placeholders and the resources' how-to, in every script
for f in "$repo"/scripts/slurm/*.sbatch; do
  n=$(basename "$f")
  for want in "##SBATCH --account=<your-account>" "##SBATCH --partition=<partition>" \
              "# ---- site setup: the modules dmhs was built with" "# module load " \
              "# ---- end of site setup" "sbatch --ntasks=" "--dry-run"; do
    grep -qF -- "$want" "$f" || fail "$n: no '$want'"
  done
  # the resources' lines are the live ones, and each script says how to change them
  grep -q '^#SBATCH --ntasks=' "$f" && grep -q '^#SBATCH --time=' "$f" || fail "$n: no --ntasks/--time line"
  grep -q "Change them here, or at submission" "$f" || fail "$n: does not say how to change its resources"
done
echo "slurm dry runs: OK"
