#!/usr/bin/env bash
# Poiseuille at 10x20, 20x40 and 40x80 particles (h = 3 dx, dt = 0.57 of the
# viscous limit) to t = 0.1 s: the L2 error there must fall by at least 2x at
# each refinement (second order gives ~4x). A missing or non-numeric t = 0.1 s
# row fails.
#   convergence.sh <dmhs> <input dir> <output dir>
set -euo pipefail
dmhs="$1"; input="$2"; out="$3"
prev=""
for r in "10 20 1.5e-4 4e-4" "20 40 7.5e-5 1e-4" "40 80 3.75e-5 2.5e-5"; do
  set -- $r
  "$dmhs" -options_file "$input/poiseuille.opts" -channel_nx "$1" -channel_ny "$2" -sph_h "$3" -dt "$4" \
    -t_end 0.1 -quiet -output_dir "$out/n$1" > "$out-n$1.log"
  l2=$(awk -F, '$2 > 0.0999 && $2 < 0.1001 {print $4}' "$out/n$1/error.csv")
  # exactly one row, and a number: an empty value would compare as 0 below and pass
  if ! [[ "$l2" =~ ^[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$ ]]; then
    echo "FAIL: $out/n$1/error.csv has no single numeric L2 at t = 0.1 s (got '$l2')"; exit 1
  fi
  echo "nx x ny = $1 x $2: L2(t = 0.1 s) = $l2"
  if [ -n "$prev" ] && ! awk -v a="$l2" -v b="$prev" 'BEGIN{exit !(a * 2 <= b)}'; then
    echo "FAIL: error did not fall by 2x ($prev -> $l2)"; exit 1
  fi
  prev="$l2"
done
echo "OK: the error falls with resolution"
