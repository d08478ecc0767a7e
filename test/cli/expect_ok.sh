#!/usr/bin/env bash
# Runs a command that must succeed: exit 0, output matching a regex, and no
# non-finite value in any CSV or HDF5 file of the output directory.
#   expect_ok.sh '<regex>' OUTDIR -- command args...
set -u
regex="$1"; dir="$2"; shift 2
[ "${1:-}" = "--" ] && shift
out=$("$@" 2>&1); status=$?
printf '%s\n' "$out" | tail -n 8
if [ $status -ne 0 ]; then echo "FAIL: exit status $status"; exit 1; fi
if ! printf '%s\n' "$out" | tr '\n' ' ' | grep -Eq -- "$regex"; then echo "FAIL: output does not match /$regex/"; exit 1; fi
/usr/bin/python3 "$(dirname "$0")/check_finite.py" "$dir" || exit 1
echo "OK"
