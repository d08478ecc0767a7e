#!/usr/bin/env bash
# Runs one case end to end: installs what is missing, builds, runs dmhs on the
# options file, then makes the case's plots.
#   scripts/run.sh input/poiseuille.opts [more dmhs options]
# Environment: DMHS_NP (MPI ranks, default 1).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ $# -lt 1 ]; then
  echo "usage: scripts/run.sh <options-file> [dmhs options...]" >&2
  exit 2
fi
opts="$1"; shift
if [ ! -r "$opts" ]; then
  echo "run.sh: cannot read options file '$opts'" >&2
  exit 2
fi
"$repo/scripts/setup.sh"
build="${DMHS_BUILD_DIR:-$repo/build}"
np="${DMHS_NP:-1}"
# --bind-to none: Open MPI binds each job's rank 0 to core 0, so two cases run side by side
# would share one core
mpirun_flags=(--oversubscribe --bind-to none)
[ "$(id -u)" -eq 0 ] && mpirun_flags+=(--allow-run-as-root)
mpirun "${mpirun_flags[@]}" -n "$np" "$build/dmhs" -options_file "$opts" "$@"
# The output directory is the one the options chose; post-process what the scene wrote.
outdir=$(awk '$1=="-output_dir"{print $2}' "$opts" | tail -n 1)
for ((i = 1; i <= $#; i++)); do
  if [ "${!i}" = "-output_dir" ]; then j=$((i + 1)); outdir="${!j}"; fi
done
outdir="${outdir:-output}"
if [ -f "$outdir/error.csv" ]; then
  # a pulsatile drive (-body_force_period T > 0 in the run's options) has its own plots
  if grep -Eq -- '-body_force_period +[0-9.]*[1-9]' "$outdir/run.json" 2>/dev/null; then
    /usr/bin/python3 "$repo/scripts/post/plot_womersley.py" "$outdir"
  else
    /usr/bin/python3 "$repo/scripts/post/plot_channel.py" "$outdir"
  fi
fi
# the vein: geometry, fields at the peak flow, the sinus liquid per cycle, the
# measurement point / inlet / gap history; with clots, their growth
# the colon: x_F with u_F, alpha, lifts, N/N0 per pocket, the liquid's bounds
if [ -f "$outdir/intestine.csv" ]; then
  /usr/bin/python3 "$repo/scripts/post/plot_intestine.py" "$outdir"
fi
if [ -f "$outdir/vein.csv" ]; then
  for p in geometry fields sinus probe inlet; do
    /usr/bin/python3 "$repo/scripts/post/plot_vein_$p.py" "$outdir"
  done
  if [ -f "$outdir/clots.csv" ]; then
    /usr/bin/python3 "$repo/scripts/post/plot_clots.py" "$outdir"
  fi
fi
# solids: the cantilever's tip against beam theory; the flap's tip and slip
# against time and its settled flow
if [ -f "$outdir/cantilever.csv" ]; then
  /usr/bin/python3 "$repo/scripts/post/plot_cantilever.py" "$outdir"
fi
if [ -f "$outdir/flap.csv" ]; then
  /usr/bin/python3 "$repo/scripts/post/plot_flap.py" "$outdir"
fi
