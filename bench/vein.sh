#!/usr/bin/env bash
# Cost of the deep-vein reference case (input/vein.opts, ~95k particles at the
# published dx = 1e-4 m): a short piece of the run (-t_end, default 1e-4 s,
# ~200 steps at the automatic dt) on 1 and 2 ranks, alternating (the VM is
# shared: side-by-side runs keep the comparison fair). One line per run:
# step-loop seconds, particle-steps/s and the dt used; -log_view output in $out.
#   bench/vein.sh [repeats] [t_end] [out_dir]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
reps="${1:-2}"
tend="${2:-1e-4}"
out="${3:-$repo/output/bench-vein}"
exe="${DMHS_EXE:-$repo/build/dmhs}"
mkdir -p "$out"
cd "$repo"
for r in $(seq 1 "$reps"); do
  for n in 1 2; do
    log="$out/np${n}_rep${r}.txt"
    mpirun --oversubscribe --allow-run-as-root -n "$n" "$exe" -options_file input/vein.opts -t_end "$tend" \
      -quiet -log_view -output_snapshots false -checkpoint_at_end false -output_dir "$out/run" >"$log" 2>&1
    rate=$(grep -o 'particle-steps/s: [0-9.e+]*' "$log" | awk '{print $2}')
    loop=$(grep -o 'step loop [0-9.]* s' "$log" | awk '{print $3}')
    dt=$(grep -o '^dt = [0-9.e+-]*' "$log" | awk '{print $3}')
    echo "ranks $n rep $r step_loop_s $loop particle_steps_per_s $rate dt $dt"
  done
done
