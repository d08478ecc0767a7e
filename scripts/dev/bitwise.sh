#!/usr/bin/env bash
# Are two builds' results the same bit for bit? Runs every quick input over a
# short stretch with binary A and binary B, on 1 and 2 ranks and as a run
# stopped half-way and continued from its checkpoint, and compares every CSV,
# snapshot, checkpoint and XDMF index by its bytes (bitwise_compare.py: only
# the wall-clock times, wall_s, are left out; run.json and the log hold times
# and commits, so they are not compared). Both sides run in the same
# directory, moved aside afterwards: the snapshots record the options.
#   scripts/dev/bitwise.sh OLD_BIN NEW_BIN [case ...]
# A case is an input name without .opts, or one of the variants below
# (default: every quick input and every variant).
# Exit 0 when every file is identical; otherwise the differing files are
# listed and the exit status is 1. Work files go to $BITWISE_DIR (default: a
# new temporary directory, removed when everything agrees).
set -euo pipefail

if [ $# -lt 2 ]; then
  echo "usage: $0 OLD_BIN NEW_BIN [case ...]" >&2
  exit 2
fi
old=$(readlink -f "$1")
new=$(readlink -f "$2")
shift 2
for b in "$old" "$new"; do
  [ -x "$b" ] || { echo "bitwise: $b is not an executable" >&2; exit 2; }
done
root=$(cd "$(dirname "$0")/../.." && pwd)
mpirun=(mpirun --oversubscribe --allow-run-as-root)

# case: t_end of the short stretch [s] and its output interval [s]; the
# restart stops at half of t_end
declare -A t_end=(
  [vein-quick+multirate]=0.02 [poiseuille-quick]=0.02 [couette-quick]=0.02 [womersley-quick]=0.0206
  [flap-quick]=0.02 [cantilever]=0.004 [peristaltic_channel-quick]=4
  [intestine-quick]=0.02 [vein-quick]=0.02 [vein-clot-quick]=0.02
)
declare -A interval=(
  [vein-quick+multirate]=0.002 [poiseuille-quick]=0.002 [couette-quick]=0.002 [womersley-quick]=0.00206
  [flap-quick]=0.002 [cantilever]=0.0004 [peristaltic_channel-quick]=0.4
  [intestine-quick]=0.002 [vein-quick]=0.002 [vein-clot-quick]=0.002
)
# variants: an input with options of its own
declare -A input=([vein-quick+multirate]=vein-quick)
declare -A extra=([vein-quick+multirate]="-solid_substeps 0 -repulsion_substeps -solid_substeps_scheme respa")
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(poiseuille-quick couette-quick womersley-quick flap-quick
  cantilever peristaltic_channel-quick intestine-quick vein-quick vein-clot-quick
  vein-quick+multirate)

work=${BITWISE_DIR:-$(mktemp -d)}
mkdir -p "$work"
differ=0

# run BIN DIR RANKS T_END [extra options]
run() {
  local bin=$1 dir=$2 ranks=$3 tend=$4
  shift 4
  # shellcheck disable=SC2086 # the variant's options are words
  (cd "$root" && "${mpirun[@]}" -n "$ranks" "$bin" -options_file "input/${input[$c]:-$c}.opts" \
    ${extra[$c]:-} -t_end "$tend" -output_interval "${interval[$c]}" -output_dir "$dir" -quiet "$@" \
    >> "$work/$c.log" 2>&1) || { echo "bitwise: $c failed, see $work/$c.log" >&2; exit 1; }
}

compare() {
  /usr/bin/python3 "$root/scripts/dev/bitwise_compare.py" "$1" "$2" || differ=1
}

for c in "${cases[@]}"; do
  [ -n "${t_end[$c]:-}" ] || { echo "bitwise: no stretch known for case $c" >&2; exit 2; }
  [ -f "$root/input/${input[$c]:-$c}.opts" ] || { echo "bitwise: no input/${input[$c]:-$c}.opts" >&2; exit 2; }
  half=$(/usr/bin/python3 -c "print(${t_end[$c]} / 2)")
  for ranks in 1 2; do
    for side in old new; do
      bin=$old
      [ $side = new ] && bin=$new
      run "$bin" "$work/$c" "$ranks" "${t_end[$c]}"
      mv "$work/$c" "$work/$c-$ranks-$side"
    done
    echo "$c on $ranks rank(s):"
    compare "$work/$c-$ranks-old" "$work/$c-$ranks-new"
  done
  for side in old new; do
    bin=$old
    [ $side = new ] && bin=$new
    d="$work/$c"
    run "$bin" "$d" 2 "$half"
    run "$bin" "$d" 2 "${t_end[$c]}" -restart "$d/checkpoint.h5"
    mv "$d" "$work/$c-restart-$side"
  done
  echo "$c, stopped at t = $half s and continued, on 2 ranks:"
  compare "$work/$c-restart-old" "$work/$c-restart-new"
done

if [ $differ = 0 ]; then
  echo "bitwise: every file identical"
  [ -n "${BITWISE_DIR:-}" ] || rm -rf "$work"
else
  echo "bitwise: files differ (work files in $work)"
  exit 1
fi
