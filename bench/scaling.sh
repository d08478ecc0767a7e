#!/usr/bin/env bash
# Strong scaling of bench/box.opts, 1 -> 2 ranks, alternating runs (the VM is
# shared: side-by-side runs keep the comparison fair). Prints one line per run
# and keeps the -log_view output in $out.
#   bench/scaling.sh [repeats] [out_dir]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
reps="${1:-3}"
out="${2:-$repo/output/bench-scaling}"
exe="${DMHS_EXE:-$repo/build/dmhs}"
mkdir -p "$out"
for r in $(seq 1 "$reps"); do
  for n in 1 2; do
    log="$out/np${n}_rep${r}.txt"
    mpirun --oversubscribe --allow-run-as-root -n "$n" "$exe" -options_file "$repo/bench/box.opts" \
      -quiet -log_view -output_dir "$out/run" >"$log" 2>&1
    rate=$(grep -o 'particle-steps/s: [0-9.e+]*' "$log" | awk '{print $2}')
    loop=$(grep -o 'step loop [0-9.]* s' "$log" | awk '{print $3}')
    echo "ranks $n rep $r step_loop_s $loop particle_steps_per_s $rate"
  done
done
