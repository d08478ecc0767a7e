#!/bin/bash
# scripts/slurm/dmhs.sbatch without Slurm (srun stands in as a plain exec):
# a run stopped by a signal (run.json "signal-checkpoint") is continued from its
# checkpoint when the script runs again; a completed one is not.
# Usage: slurm.sh REPO DMHS WORKDIR
set -euo pipefail
repo=$1 exe=$2 W=$3
rm -rf "$W" && mkdir -p "$W/bin"
printf '#!/bin/bash\nexec "$@"\n' > "$W/bin/srun" && chmod +x "$W/bin/srun"
run() { PATH="$W/bin:$PATH" SLURM_SUBMIT_DIR="$repo" DMHS_EXE="$exe" \
  bash "$repo/scripts/slurm/dmhs.sbatch" "$repo/input/poiseuille-quick.opts" -quiet -output_dir "$W/out" "$@"; }
run -t_end 0.01 > "$W/1.log"
grep -q '"status": "completed"' "$W/out/run.json" || { echo "FAIL: first run not completed"; exit 1; }
run -t_end 0.02 > "$W/2.log"
if grep -q "continuing" "$W/2.log"; then echo "FAIL: a completed run was continued"; exit 1; fi
# a run that a signal stopped: continue from its checkpoint
sed -i 's/"status": "completed"/"status": "signal-checkpoint"/' "$W/out/run.json"
run -t_end 0.03 > "$W/3.log"
grep -q "Restarted from $W/out/checkpoint.h5 at step 200" "$W/3.log" || { echo "FAIL: not continued"; cat "$W/3.log"; exit 1; }
# the message whose absence the second run checked: without it that check proves nothing
grep -q "dmhs.sbatch: continuing from $W/out/checkpoint.h5" "$W/3.log" ||
  { echo "FAIL: the script does not say it continues"; cat "$W/3.log"; exit 1; }
echo "slurm script: OK"
