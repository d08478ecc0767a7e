#!/bin/bash
# scripts/slurm/vein-study.sbatch without Slurm (srun stands in as a plain
# exec), task 7 of the array = run 19 at a coarse, tiny size: it runs to its
# end, a second submission skips the completed run, and one stopped by a
# signal (run.json "signal-checkpoint") continues from its checkpoint.
# Usage: vein_study.sh REPO DMHS WORKDIR
set -euo pipefail
repo=$1 exe=$2 W=$3
rm -rf "$W" && mkdir -p "$W/bin"
printf '#!/bin/bash\nexec "$@"\n' > "$W/bin/srun" && chmod +x "$W/bin/srun"
run() { (cd "$repo" && PATH="$W/bin:$PATH" SLURM_SUBMIT_DIR="$repo" SLURM_ARRAY_TASK_ID=7 DMHS_EXE="$exe" \
  bash scripts/slurm/vein-study.sbatch -vein_dx 5e-4 -vein_length 0.06 -quiet -output_dir "$W/out" "$@"); }
run -t_end 2e-4 > "$W/1.log" 2>&1 || { cat "$W/1.log"; echo "FAIL: first run"; exit 1; }
grep -q '"status": "completed"' "$W/out/run.json" || { echo "FAIL: first run not completed"; exit 1; }
grep -q "vein: leaflets of 0.0175 m" "$W/1.log" || { cat "$W/1.log"; echo "FAIL: task 7 is not run 19 (L = 0.0175 m)"; exit 1; }
run -t_end 4e-4 > "$W/2.log" 2>&1
grep -q "already completed" "$W/2.log" || { cat "$W/2.log"; echo "FAIL: a completed run was not skipped"; exit 1; }
sed -i 's/"status": "completed"/"status": "signal-checkpoint"/' "$W/out/run.json"
run -t_end 4e-4 > "$W/3.log" 2>&1 || { cat "$W/3.log"; echo "FAIL: continued run"; exit 1; }
grep -q "continues from $W/out/checkpoint.h5" "$W/3.log" || { cat "$W/3.log"; echo "FAIL: not continued"; exit 1; }
grep -q '"status": "completed"' "$W/out/run.json" || { echo "FAIL: continued run not completed"; exit 1; }
echo "vein study script: OK"
