#!/usr/bin/env bash
# The measured costs of the scaling model (doc/performance.md, "Past one
# node"): short -log_view runs of the box (bench/box.opts at three sizes) and
# the vein (input/vein.opts) on 1 and 2 ranks, alternating, and one CSV row per
# run with the step loop, the events of the stage "dmhs steps" (max over
# ranks) and the halo's sizes (run.json). Timings: run it on an otherwise idle
# machine (no build, no tests), and compare within a run or side by side.
#   bench/halo_costs.sh [repeats] [csv] [work_dir]
# default: 2 repeats, bench/results/halo_costs.csv.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
reps="${1:-2}"
csv="${2:-$repo/bench/results/halo_costs.csv}"
work="${3:-$repo/output/bench-halo-costs}"
exe="${DMHS_EXE:-$repo/build/dmhs}"
py=/usr/bin/python3
events="Integrate TimeStep Migrate HaloBuild HaloForward PairList SphDensity SphEos SphWall SphForce BodyForce Diagnostics CheckState Bond Angle Repulsion"
mkdir -p "$work" "$(dirname "$csv")"
cd "$repo"
{
  printf 'case,particles,ranks,rep,steps,loop_s,load_1min,owned_max,ghost_max,remote_max,partners_max,ghost_bytes,forwards'
  for e in $events; do printf ',%s_s' "$e"; done
  echo
} >"$csv"

# run <case> <ranks> <rep> <dmhs options...>
run() {
  local name="$1" n="$2" rep="$3"
  shift 3
  local out="$work/${name}_np${n}_rep$rep"
  local load
  load=$(cut -d' ' -f1 /proc/loadavg)
  mpirun --oversubscribe --allow-run-as-root -n "$n" "$exe" "$@" -quiet -log_view \
    -output_snapshots false -checkpoint_at_end false -output_dir "$out" >"$out.log" 2>&1 ||
    { echo "FAIL: $name on $n ranks (see $out.log)" >&2; exit 1; }
  "$py" - "$out.log" "$out/run.json" "$name" "$n" "$rep" "$load" $events >>"$csv" <<'PY'
import json, re, sys
log, run_json, name, n, rep, load, *events = sys.argv[1:]
text = open(log).read()
summary = re.search(r"dmhs summary: .*? (\d+) particles, .*? (\d+) steps .*?step loop ([0-9.]+) s", text)
stage = text.split("--- Event Stage 2: dmhs steps")[1].split("-----")[0]
row = {}
for line in stage.splitlines():
    f = line.split()
    if len(f) > 4 and f[0] in events:
        row[f[0]] = (int(f[1]), float(f[3]))  # count, max time over ranks
h = json.load(open(run_json))["halo"]
out = [name, summary.group(1), n, rep, summary.group(2), summary.group(3), load,
       h["owned"]["max"], h["ghost"]["max"], h["remote_ghost"]["max"], h["partners"]["max"],
       h["ghost_bytes"], row.get("HaloForward", (0, 0))[0]]
out += [row.get(e, (0, 0.0))[1] for e in events]
print(",".join(str(v) for v in out))
PY
  tail -1 "$csv" | cut -d, -f1-8
}

for r in $(seq 1 "$reps"); do
  for n in 1 2; do
    run box316 "$n" "$r" -options_file bench/box.opts -t_end 5e-5
    run vein "$n" "$r" -options_file input/vein.opts -t_end 1e-4
  done
  # the exchange's cost per ghost against its fixed cost per call: three sizes on 2 ranks
  run box100 2 "$r" -options_file bench/box.opts -box_nx 100 -box_ny 100 -t_end 1e-4
  run box632 2 "$r" -options_file bench/box.opts -box_nx 632 -box_ny 632 -t_end 2e-5
done
