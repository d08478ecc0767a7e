#!/usr/bin/env bash
# Runs a command that must succeed: exit 0, output matching a regex, and no
# non-finite value in any CSV or HDF5 file of the output directory.
#   expect_ok.sh '<regex>' OUTDIR -- command args...
set -u
regex="$1"; dir="$2"; shift 2
[ "${1:-}" = "--" ] && shift
[ -n "$regex" ] || { echo "FAIL: empty regex (it would match anything)"; exit 1; }
out=$("$@" 2>&1); status=$?
tail -n 8 <<<"$out"
if [ $status -ne 0 ]; then echo "FAIL: exit status $status"; exit 1; fi
# here-strings, not printf | grep -q (SIGPIPE under pipefail)
rc=0; grep -Eq -- "$regex" <<<"$(tr '\n' ' ' <<<"$out")" || rc=$?
if [ $rc -ne 0 ]; then
  [ $rc -eq 1 ] && echo "FAIL: output does not match /$regex/" || echo "FAIL: grep -E rejects /$regex/"
  exit 1
fi
/usr/bin/python3 "$(dirname "$0")/check_finite.py" "$dir" || exit 1
echo "OK"
