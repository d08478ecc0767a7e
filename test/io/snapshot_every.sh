#!/bin/bash
# -snapshot_every N: a snapshot at every Nth output time and at the run's last
# step, every diagnostics row still written; a run stopped and continued from
# its checkpoint keeps the cadence (its stop adds the stop's own snapshot).
# Usage: snapshot_every.sh DMHS PYTHON WORKDIR INPUT_DIR
set -uo pipefail
EXE=$1 PY=$2 W=$3 INPUT=$4
source "$(dirname "$0")/common.sh"
rm -rf "$W" && mkdir -p "$W"
opts=(-options_file "$INPUT/vein-quick.opts" -output_interval 0.005 -snapshot_every 3 -quiet)

# times of the snapshots particles.xdmf lists, after checking the index
snap_times() {
  "$PY" "$HERE/check_xdmf.py" "$1" 1 > /dev/null || die "$1: particles.xdmf inconsistent"
  "$PY" - "$1" <<'PY'
import glob, sys, h5py
for f in sorted(glob.glob(sys.argv[1] + "/snap_*.h5")):
    print("%.4f" % h5py.File(f, "r").attrs["time"][0])
PY
}
expect() { # dir, expected times
  local got
  got=$(snap_times "$1" | tr '\n' ' ')
  [ "$got" = "$2" ] || die "$1: snapshots at t = $got, expected $2"
  echo "$1: snapshots at t = $got"
}

"$EXE" "${opts[@]}" -t_end 0.035 -output_dir "$W/whole" > "$W/whole.log" 2>&1 ||
  { tail -5 "$W/whole.log"; die "the run failed"; }
# outputs 0 ... 7 at 0.005 s: snapshots at 0, 3 and 6, and at the last step (7)
expect "$W/whole" "0.0000 0.0150 0.0300 0.0350 "
rows=$(grep -c "^[0-9]" "$W/whole/vein.csv")
[ "$rows" = 8 ] || die "vein.csv has $rows rows, expected one per output time (8)"

"$EXE" "${opts[@]}" -t_end 0.02 -output_dir "$W/split" > "$W/split.log" 2>&1 ||
  { tail -5 "$W/split.log"; die "the first part failed"; }
"$EXE" "${opts[@]}" -t_end 0.035 -output_dir "$W/split" -restart "$W/split/checkpoint.h5" \
  >> "$W/split.log" 2>&1 || { tail -5 "$W/split.log"; die "the continued part failed"; }
expect "$W/split" "0.0000 0.0150 0.0200 0.0300 0.0350 "
cmp -s "$W/whole/vein.csv" "$W/split/vein.csv" || die "the continued run's vein.csv differs"
echo "snapshot_every: OK"
