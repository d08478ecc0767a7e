#!/usr/bin/env bash
# Halo sizes against rank count and problem size: the box (bench/box.opts) at
# several sizes and the vein (input/vein.opts, 95k particles; and at a smaller
# dx, 4x and 10x the particles), a few steps each on 1..8 ranks (and up to 64
# for some), oversubscribed: these are counts (run.json's "halo": the last
# neighbour build's owned, ghost and remote rows and partner ranks over the
# ranks), not timings. One CSV row per run:
#   bench/halo_counts.sh [csv] [work_dir]
# default csv bench/results/halo_counts.csv. RANKS="1 2 4" overrides the rank
# counts of every case (a quick check).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
csv="${1:-$repo/bench/results/halo_counts.csv}"
work="${2:-$repo/output/bench-halo}"
exe="${DMHS_EXE:-$repo/build/dmhs}"
py=/usr/bin/python3
mkdir -p "$work" "$(dirname "$csv")"
cd "$repo"
echo "case,particles,ranks,dx,ghost_width,owned_min,owned_mean,owned_max,ghost_min,ghost_mean,ghost_max,remote_mean,remote_max,sent_mean,partners_mean,partners_max,ghost_bytes,forward_bytes_max" >"$csv"

# run <case> <ranks> <dx> <dmhs options...>
run() {
  local name="$1" n="$2" dx="$3"
  shift 3
  local out="$work/${name}_np$n"
  mpirun --oversubscribe --allow-run-as-root -n "$n" "$exe" "$@" -quiet -output_snapshots false \
    -checkpoint_at_end false -output_dir "$out" >"$out.log" 2>&1 ||
    { echo "FAIL: $name on $n ranks (see $out.log)" >&2; exit 1; }
  local width
  width=$(grep -o 'ghost width [0-9.e+-]* m' "$out.log" | awk '{print $3}')
  "$py" - "$out/run.json" "$name" "$n" "$dx" "$width" >>"$csv" <<'PY'
import json, sys
path, name, n, dx, width = sys.argv[1:]
h = json.load(open(path))["halo"]
m = lambda k, f: h[k][f]
print(",".join(str(v) for v in [
    name, m("owned", "total"), n, dx, width, m("owned", "min"), m("owned", "mean"),
    m("owned", "max"), m("ghost", "min"), m("ghost", "mean"), m("ghost", "max"),
    m("remote_ghost", "mean"), m("remote_ghost", "max"), m("sent", "mean"),
    m("partners", "mean"), m("partners", "max"), h["ghost_bytes"], m("forward_bytes", "max")]))
PY
  tail -1 "$csv"
}

# every rank builds the whole scene before the partition keeps its part: the
# larger cases stop at fewer ranks to stay within the memory of a small machine
ranks_small="${RANKS:-1 2 3 4 5 6 7 8}"
ranks_more="${RANKS:-1 2 3 4 5 6 7 8 16 32 64}"
ranks_4x="${RANKS:-1 2 3 4 5 6 7 8 16 32}"
ranks_10x="${RANKS:-2 4 8 16}"
# the box: 3 steps of bench/box.opts at side n (n^2 particles, dx = 1e-4 m)
for side in 100 200 316 632; do
  ranks="$ranks_small"
  [ "$side" = 316 ] && ranks="$ranks_more"
  for n in $ranks; do
    run "box$side" "$n" 1e-4 -options_file bench/box.opts -box_nx "$side" -box_ny "$side" -t_end 3e-7
  done
done
# the vein: 3 steps of the reference case (the automatic dt is about 5e-7 s)
for n in $ranks_more; do
  run vein "$n" 1e-4 -options_file input/vein.opts -t_end 1.2e-6
done
# the vein at dx / 2 (4x the particles) and 0.09 m / 2846 = dx / 3.162 (10x: -vein_length must
# be a whole number of dx), a few steps
for n in $ranks_4x; do
  run vein_dx5e-5 "$n" 5e-5 -options_file input/vein.opts -vein_dx 5e-5 -t_end 1e-7
done
for n in $ranks_10x; do
  run vein_dx3.16e-5 "$n" 3.1623e-5 -options_file input/vein.opts -vein_dx 3.1623330990864372e-05 -t_end 1e-7
done
