#!/bin/bash
# A full disk (a 1 MB tmpfs; needs root and mount, else skipped with 77):
# the run stops with the file named and status 1, leaves no *.tmp, run.json
# says "error" with the message, and the last checkpoint is intact and restarts.
# Usage: diskfull.sh DMHS PYTHON WORKDIR
set -uo pipefail
EXE=$1 PY=$2 W=$3
source "$(dirname "$0")/common.sh"
rm -rf "$W" && mkdir -p "$W/mnt"
mount -t tmpfs -o size=1m tmpfs "$W/mnt" 2>/dev/null || { echo "SKIP: cannot mount a tmpfs here"; exit 77; }
trap 'umount "$W/mnt"' EXIT
O=$W/mnt/out
rc=0
"$EXE" "${QUICK[@]}" -t_end 1 -output_interval 0.0005 -checkpoint_interval 0.005 -output_dir "$O" > "$W/run.log" 2>&1 ||
  rc=$?
tail -2 "$W/run.log"
[ $rc -eq 1 ] || die "exit status $rc on a full disk, expected 1"
grep -q "dmhs: error: .*$O/" "$W/run.log" || die "the error does not name the file"
ls "$O"/*.tmp 2>/dev/null && die "*.tmp files left on the full disk"
grep -q '"status": "error"' "$O/run.json" || { cat "$O/run.json"; die "run.json does not say error"; }
grep -q '"message": ".*failed' "$O/run.json" || die "run.json lacks the message"
"$PY" -c "import json,sys; json.load(open(sys.argv[1]))" "$O/run.json" || die "run.json is not valid JSON"
cp "$O/checkpoint.h5" "$W/last.h5" || die "no checkpoint survived"
t=$(h5attr "$W/last.h5" t) && [ -n "$t" ] || die "cannot read t from the last checkpoint"
"$EXE" "${QUICK[@]}" -t_end "$("$PY" -c "print($t + 0.0025)")" -restart "$W/last.h5" -output_dir "$W/again" \
  > "$W/again.log" 2>&1 || { tail -3 "$W/again.log"; die "the last checkpoint (t = $t s) does not restart"; }
echo "full disk: stopped cleanly, checkpoint at t = $t s restarts: OK"
