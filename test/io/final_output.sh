#!/bin/bash
# Output at the end: a run shortened with -t_end so that no output time falls
# after t = 0 must still write its final state as a snapshot listed in
# particles.xdmf (at the run's final t), a row of its diagnostics there, and an
# end report whose liquid bounds are the run's, not 0.
# Usage: final_output.sh DMHS PYTHON WORKDIR INPUT_DIR
set -uo pipefail
EXE=$1 PY=$2 W=$3 INPUT=$4
source "$(dirname "$0")/common.sh"
rm -rf "$W" && mkdir -p "$W"
# the quick vein outputs every 0.01 s: 0.005 s is 674 steps, none of them an output time
"$EXE" -options_file "$INPUT/vein-quick.opts" -t_end 0.005 -output_interval 0.01 -output_dir "$W/run" > "$W/run.log" 2>&1 ||
  { tail -5 "$W/run.log"; die "the run failed"; }
t=$(h5attr "$W/run/checkpoint.h5" t)
echo "final t = $t s"
[ -f "$W/run/snap_000001.h5" ] || die "no snapshot of the final state (snap_000001.h5)"
[ "$(h5attr "$W/run/snap_000001.h5" time)" = "$t" ] || die "snap_000001.h5 is not at the final t = $t s"
"$PY" "$HERE/check_xdmf.py" "$W/run" 2 || die "particles.xdmf does not index both snapshots"
grep -q "<Time Value=\"$t\"/>" "$W/run/particles.xdmf" ||
  grep -q "snap_000001.h5" "$W/run/particles.xdmf" || die "particles.xdmf does not list the final snapshot"
last=$(tail -1 "$W/run/vein.csv" | cut -d, -f1)
"$PY" -c "import sys; sys.exit(0 if abs($last - $t) < 1e-7 else 1)" ||
  die "vein.csv's last row is at t = $last s, not at the final t = $t s"
line=$(grep "max |rho/rho0 - 1|" "$W/run.log") || die "no end report with the liquid's bounds"
echo "$line"
"$PY" - "$line" <<'EOF' || die "the end report's bounds are not > 0"
import re, sys
m = re.search(r"max \|rho/rho0 - 1\| (\S+), max Mach (\S+)", sys.argv[1])
sys.exit(0 if m and float(m.group(1)) > 0 and float(m.group(2)) > 0 else 1)
EOF
echo "final output: snapshot, XDMF, diagnostics row and bounds at t = $t s: OK"
