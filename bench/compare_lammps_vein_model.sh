#!/usr/bin/env bash
# Is the LAMMPS vein twin (bench/lammps/vein.in) the same model as dmhs's vein?
# A coarse vein (dx = 4e-4 m, ~6.8k particles), in two parts.
# A. Dynamics from rest, the same fixed dt in both codes:
#   1. dmhs writes its t = 0 state; bench/lammps/vein_data.py turns it into the
#      twin's data and parameter files;
#   2. LAMMPS runs the twin to T_END (every particle dumped every T_OUT);
#   3. dmhs runs the case as shipped ("dmhs": density diffusion, the predicted
#      density, artificial viscosity, extrapolated walls) and with what LAMMPS
#      lacks switched off ("dmhs-plain": -sph_delta 0 -sph_density_predict false
#      -sph_av_alpha 0; the walls stay extrapolated, no option turns that off);
#   4. bench/lammps/vein_compare.py prints at every T_OUT the liquid's kinetic
#      energy, mean x velocity, inlet-station velocity, density error and the
#      leaflet tips of the three runs, and the particle-by-particle differences.
# B. Forces on a developed state (the flow and the leaflets in motion):
#   5. dmhs runs the case as shipped to FORCE_AT (at WARM_DT), then one step more
#      with the plain options from its checkpoint; vein_data.py writes that step's
#      state (the density its force evaluation saw), LAMMPS computes its forces
#      there (run 0) and bench/lammps/vein_forces.py compares them with dmhs's,
#      particle by particle, grouped by neighbourhood.
#   bench/compare_lammps_vein_model.sh [A|B]          (default both)
# Environment (defaults): DX (4e-4 m), DT (2e-7 s), T_END (0.1 s), T_OUT (0.01 s),
# FORCE_AT (0.5 s), WARM_DT (4e-6 s), OUT (output/lammps-vein), DMHS (build/dmhs),
# LMP (a LAMMPS binary with the SPH and MOLECULE packages, default lmp on PATH;
# bench/compare_lammps_vein.sh's header says how to get one).
# Why a small DT: at 2e-6 s both LAMMPS's twin and dmhs-plain blow up from rest
# within ~0.1 s at this dx: the continuity density's acoustic noise grows at a
# rate proportional to dt (doc/theory.md, "Time integration"; doc/lammps.md, "The
# vein twin"); dmhs as shipped does not. A restarted dmhs run keeps its
# checkpoint's dt, hence part A starts from rest.
# Cost at the defaults, one core each: LAMMPS ~20-25 min (500k steps), each dmhs
# run ~10-15 min, part B ~5 min.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
parts="${1:-AB}"
dx="${DX:-4e-4}"
dt="${DT:-2e-7}"
t_end="${T_END:-0.1}"
t_out="${T_OUT:-0.01}"
force_at="${FORCE_AT:-0.5}"
warm_dt="${WARM_DT:-4e-6}"
dmhs="${DMHS:-build/dmhs}"
lmp="${LMP:-lmp}"
cd "$repo"
out="${OUT:-output/lammps-vein}"
plain="-sph_delta 0 -sph_density_predict false -sph_av_alpha 0"
mkdir -p "$out"

if [[ "$parts" == *A* ]]; then
  every=$(awk -v a="$t_out" -v b="$dt" 'BEGIN{printf "%d", a / b + 0.5}')
  echo "A. dx = $dx m, from rest to t = $t_end s at dt = $dt s in both, output every $t_out s"
  rm -rf "$out/init" "$out/lammps" "$out/dmhs" "$out/dmhs-plain"
  mkdir -p "$out/lammps"
  "$dmhs" -options_file input/vein.opts -vein_dx "$dx" -t_end "$dt" -dt "$dt" -quiet \
    -output_dir "$out/init" > "$out/init.log"
  /usr/bin/python3 bench/lammps/vein_data.py "$out/init" --out "$out/vein"
  echo "LAMMPS: bench/lammps/vein.in"
  $lmp -in bench/lammps/vein.in -var data "$out/vein.data" -var params "$out/vein.params.in" \
    -var dt "$dt" -var t_end "$t_end" -var dump_every "$every" -var thermo_every "$every" \
    -var out "$out/lammps" -log "$out/lammps/log.lammps" -screen none
  for run in dmhs dmhs-plain; do
    extra=""
    [ "$run" = dmhs-plain ] && extra="$plain"
    echo "$run: input/vein.opts -vein_dx $dx -dt $dt $extra"
    # shellcheck disable=SC2086
    "$dmhs" -options_file input/vein.opts -vein_dx "$dx" -dt "$dt" -t_end "$t_end" $extra \
      -output_interval "$t_out" -checkpoint_interval 1e9 -checkpoint_at_end false -quiet \
      -output_dir "$out/$run" > "$out/$run.log"
  done
  /usr/bin/python3 bench/lammps/vein_compare.py --lammps "$out/lammps" --dt "$dt" \
    --params "$out/vein.params.in" --data "$out/vein.data" \
    --dmhs "dmhs=$out/dmhs" --dmhs "dmhs-plain=$out/dmhs-plain"
fi

if [[ "$parts" == *B* ]]; then
  echo
  echo "B. dx = $dx m: dmhs as shipped to t = $force_at s at dt = $warm_dt s, one plain step, LAMMPS's forces there"
  rm -rf "$out/warm" "$out/step" "$out/forces-lammps"
  "$dmhs" -options_file input/vein.opts -vein_dx "$dx" -dt "$warm_dt" -t_end "$force_at" \
    -output_interval "$force_at" -output_snapshots false -checkpoint_interval 1e9 -quiet \
    -output_dir "$out/warm" > "$out/warm.log"
  # one step with the plain options (its final snapshot and checkpoint: the state, dmhs's
  # accelerations there, the run's options and the topology)
  # shellcheck disable=SC2086
  "$dmhs" -options_file input/vein.opts -vein_dx "$dx" -dt "$warm_dt" $plain \
    -t_end "$(awk -v a="$force_at" -v b="$warm_dt" 'BEGIN{printf "%.17g", a + b}')" \
    -restart "$out/warm/checkpoint.h5" -restart_allow_change -output_interval "$force_at" \
    -checkpoint_interval 1e9 -quiet -output_dir "$out/step" > "$out/step.log" 2>&1
  snap=$(cd "$out/step" && ls snap_*.h5 | tail -1)
  /usr/bin/python3 bench/lammps/vein_data.py "$out/step" --snapshot "$snap" --evaluation-density \
    --out "$out/forces" > /dev/null
  mkdir -p "$out/forces-lammps"
  $lmp -in bench/lammps/vein.in -var data "$out/forces.data" -var params "$out/forces.params.in" \
    -var t_end 0 -var dump_every 1 -var out "$out/forces-lammps" \
    -log "$out/forces-lammps/log.lammps" -screen none
  /usr/bin/python3 bench/lammps/vein_forces.py --snapshot "$out/step/$snap" \
    --dump "$out/forces-lammps/vein.0.dump" --data "$out/forces.data" --params "$out/forces.params.in"
fi
