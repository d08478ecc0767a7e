#!/usr/bin/env bash
# What the vein's additions to the LAMMPS model cost per step in dmhs: the case as
# shipped (input/vein.opts) and with each of density diffusion (-sph_delta 0),
# the artificial viscosity (-sph_av_alpha 0) and the predicted density
# (-sph_density_predict false) switched off, then all three ("plain", what LAMMPS's
# SPH package has), at a fixed dt, run in turn and repeated; medians of the
# -log_view events of the step stage per step: SphForce (the pair sweep: pressure,
# viscosity, continuity, and the diffusion and artificial viscosity inside it),
# Integrate (the kicks and drift: the predicted density's extra pass), SphWall (the
# walls' extrapolated pressure and velocity, which no option turns off), and the
# whole step loop.
#   bench/vein_feature_costs.sh [--dx 1e-4] [--steps 200] [--repeats 3] [--restart CHECKPOINT]
#     --restart  continue a checkpoint of input/vein.opts at that --dx (a developed flow:
#                the artificial viscosity acts on approaching pairs only, none at t = 0)
#                for --steps steps at its dt, each variant with -restart_allow_change
# Environment: DMHS (default build/dmhs), OUT (keep the logs there).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dx=1e-4
steps=200
repeats=3
restart=""
while [ $# -gt 0 ]; do
  case "$1" in
    --dx) dx="$2"; shift 2 ;;
    --steps) steps="$2"; shift 2 ;;
    --repeats) repeats="$2"; shift 2 ;;
    --restart) restart="$2"; shift 2 ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    *) echo "$0: unknown argument $1" >&2; exit 2 ;;
  esac
done
dmhs="${DMHS:-build/dmhs}"
cd "$repo"
if [ -n "${OUT:-}" ]; then tmp="$OUT"; mkdir -p "$tmp"; else tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT; fi
dt=1e-7
t_end=$(awk -v n="$steps" -v dt="$dt" 'BEGIN{print n * dt}')
cont=(-dt "$dt")
if [ -n "$restart" ]; then
  read -r t_ck dt <<< "$(/usr/bin/python3 -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r'); print(repr(float(f.attrs['t'][0])), repr(float(f.attrs['dt'][0])))" "$restart")"
  t_end=$(awk -v t="$t_ck" -v n="$steps" -v dt="$dt" 'BEGIN{printf "%.17g", t + (n - 0.25) * dt}')
  cont=(-restart "$restart" -restart_allow_change)
fi
names=(shipped no-delta no-av no-predict plain)
opts=("" "-sph_delta 0" "-sph_av_alpha 0" "-sph_density_predict false"
      "-sph_delta 0 -sph_av_alpha 0 -sph_density_predict false")
echo "vein, dx = $dx m, $steps steps at dt = $dt s${restart:+ from $restart (t = $t_ck s)}, $repeats repeat(s); ms a step (medians)"
for ((k = 1; k <= repeats; k++)); do
  for i in "${!names[@]}"; do
    log="$tmp/${names[$i]}.$k.log"
    # shellcheck disable=SC2086
    rm -rf "$tmp/run"
    "$dmhs" -options_file input/vein.opts -vein_dx "$dx" "${cont[@]}" -t_end "$t_end" ${opts[$i]} -quiet \
      -log_view -output_snapshots false -checkpoint_at_end false -output_dir "$tmp/run" > "$log" 2>&1
    # the step stage's events (the "Event Stage 2" block of the log), seconds a step (the steps:
    # SphForce's count, one evaluation a step)
    awk -v name="${names[$i]}" '
      /--- Event Stage 2: dmhs steps/ {on = 1; next}
      /--- Event Stage/ {on = 0}
      on && ($1 == "SphForce" || $1 == "Integrate" || $1 == "SphWall") {t[$1] += $4}
      on && $1 == "SphForce" {n += $2}
      /step loop [0-9.]+ s/ {for (j = 1; j <= NF; j++) if ($j == "loop") loop = $(j + 1)}
      END {printf "%s %.6g %.6g %.6g %.6g\n", name, t["SphForce"] / n, t["Integrate"] / n, t["SphWall"] / n, loop / n}
    ' "$log" >> "$tmp/all"
  done
done
median() { sort -g | awk '{a[NR]=$1} END{print (NR%2)? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
printf '%-11s %10s %10s %10s %10s\n' run SphForce Integrate SphWall "step loop"
for name in "${names[@]}"; do
  row="$name"
  for c in 2 3 4 5; do
    row+=" $(awk -v n="$name" -v c="$c" '$1 == n {print $c * 1000}' "$tmp/all" | median)"
  done
  printf '%-11s %10.4g %10.4g %10.4g %10.4g\n' $row
done
