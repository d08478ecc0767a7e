#!/usr/bin/env bash
# The vein's time to solution as simulated seconds per wall-clock hour: a short piece of
# run 1 (input/vein-run1.opts, from t = 0) with the plain step against the sub-stepped
# contact (-solid_substeps N -repulsion_substeps -solid_substeps_scheme respa,
# doc/stability.md "Multi-rate contact"), at each spacing and rank count, the settings
# alternated within every round (the VM is shared: side by side keeps the ratio fair).
# One line per run (setting, dx, ranks, round, steps, step-loop seconds, simulated s/h,
# dt) and, per spacing and rank count, the median ratio new/plain of the simulated s/h.
#   bench/vein_speed.sh [--rounds 3] [--dx "2e-4 1e-4"] [--ranks "1 2"] [--steps 400]
#                       [--substeps N] [--out DIR]
# --steps: the piece's length in steps of the plain step (each setting runs the same
#   simulated time). --substeps: the multi-rate step's -solid_substeps (default 0: chosen
#   automatically, which the solids' fastest-mode limit keeps stable; 3 was the old
#   fixed choice at 1e-4 m). Environment: DMHS_EXE (default build/dmhs; its commit is printed),
#   DMHS_EXE_PLAIN (default the same: an older build for the plain step, to compare builds).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rounds=3
dxs="2e-4 1e-4"
rankss="1 2"
steps=400
substeps=0
out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds="$2"; shift 2 ;;
    --dx) dxs="$2"; shift 2 ;;
    --ranks) rankss="$2"; shift 2 ;;
    --steps) steps="$2"; shift 2 ;;
    --substeps) substeps="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "$0: unknown argument $1" >&2; exit 2 ;;
  esac
done
case "$rounds$steps$substeps" in *[!0-9]*) echo "$0: --rounds, --steps and --substeps take whole numbers" >&2; exit 2 ;; esac
exe="${DMHS_EXE:-$repo/build/dmhs}"
exe_plain="${DMHS_EXE_PLAIN:-$exe}"
for e in "$exe" "$exe_plain"; do
  [ -x "$e" ] || { echo "$0: no executable $e (build first: scripts/setup.sh)" >&2; exit 2; }
done
if [ -z "$out" ]; then out=$(mktemp -d); trap 'rm -rf "$out"' EXIT; else mkdir -p "$out"; fi
cd "$repo"
# the plain step's dt at each spacing (input/vein.opts' automatic dt: the leaflets bind)
plain_dt() { case "$1" in 1e-4) echo 5.06e-7 ;; 2e-4) echo 2.72e-6 ;; 4e-4) echo 5.35e-6 ;;
  *) echo "$0: --dx $1: no plain dt known (1e-4, 2e-4, 4e-4)" >&2; exit 2 ;; esac; }
for dx in $dxs; do
  case "$dx" in 1e-4|2e-4|4e-4) ;; *) echo "$0: --dx $dx: no plain dt known (1e-4, 2e-4, 4e-4)" >&2; exit 2 ;; esac
done
echo "$(date -u +%FT%TZ) on $(hostname): multi-rate with $exe, plain with $exe_plain"
echo "setting dx ranks round steps loop_s sim_s_per_h dt"
results="$out/results.txt"
: > "$results"
for dx in $dxs; do
  t_end=$(awk -v n="$steps" -v dt="$(plain_dt "$dx")" 'BEGIN{printf "%.6g", n * dt}')
  for ranks in $rankss; do
    for ((r = 1; r <= rounds; r++)); do
      for setting in plain multirate; do
        if [ "$setting" = plain ]; then e="$exe_plain"; extra=(); else
          e="$exe"; extra=(-solid_substeps "$substeps" -repulsion_substeps -solid_substeps_scheme respa); fi
        log="$out/$setting-$dx-np$ranks-$r.log"
        mpirun --oversubscribe --allow-run-as-root -n "$ranks" "$e" -options_file input/vein-run1.opts \
          -vein_dx "$dx" -t_end "$t_end" "${extra[@]}" -output_snapshots false -checkpoint_at_end false \
          -output_dir "$out/run" > "$log" 2>&1 || { echo "$0: run failed, see $log" >&2; exit 1; }
        line=$(grep 'dmhs summary' "$log")
        n=$(sed -E 's/.* ([0-9]+) steps to t = .*/\1/' <<< "$line")
        loop=$(sed -E 's/.*step loop ([0-9.]+) s.*/\1/' <<< "$line")
        dt=$(grep -o '^dt = [0-9.e+-]*' "$log" | awk '{print $3}')
        rate=$(awk -v t="$t_end" -v l="$loop" 'BEGIN{printf "%.4g", t / l * 3600}')
        echo "$setting $dx $ranks $r $n $loop $rate ${dt:-fixed}" | tee -a "$results"
        grep -o 'dmhs [0-9.]* (commit [0-9a-z-]*)' "$log" | head -1 >> "$out/commits.txt" || true
      done
    done
  done
done
echo "builds: $(sort -u "$out/commits.txt" | paste -sd ';' -)"
echo "median ratio of simulated s/h, multi-rate / plain (per spacing and rank count):"
/usr/bin/python3 - "$results" <<'EOF'
import sys, statistics, collections
runs = collections.defaultdict(dict)
for line in open(sys.argv[1]):
    setting, dx, ranks, r, n, loop, rate, dt = line.split()
    runs[(dx, ranks, r)][setting] = float(rate)
ratios = collections.defaultdict(list)
for (dx, ranks, r), v in runs.items():
    if "plain" in v and "multirate" in v:
        ratios[(dx, ranks)].append(v["multirate"] / v["plain"])
for (dx, ranks), xs in sorted(ratios.items()):
    print(f"  dx {dx} m, {ranks} rank(s): {statistics.median(xs):.3g} (rounds: {', '.join(f'{x:.3g}' for x in xs)})")
EOF
