#!/usr/bin/env bash
# Runs a command that must fail: non-zero exit, and output matching a regex.
#   expect_fail.sh '<regex>' [--no-nan DIR] -- command args...
# With --no-nan, no CSV value or HDF5 dataset in DIR may be non-finite (no NaN reaches an output file).
set -u
regex="$1"; shift
nan_dir=""
if [ "${1:-}" = "--no-nan" ]; then nan_dir="$2"; shift 2; fi
[ "${1:-}" = "--" ] && shift
out=$("$@" 2>&1); status=$?
printf '%s\n' "$out" | tail -n 20
if [ $status -eq 0 ]; then echo "FAIL: command succeeded, expected an error"; exit 1; fi
# the regex may span lines: match against the output joined into one line
if ! printf '%s\n' "$out" | tr '\n' ' ' | grep -Eq -- "$regex"; then echo "FAIL: output does not match /$regex/"; exit 1; fi
if [ -n "$nan_dir" ] && ! /usr/bin/python3 "$(dirname "$0")/check_finite.py" "$nan_dir"; then
  echo "FAIL: a non-finite value reached an output file in $nan_dir"; exit 1
fi
echo "OK: failed with status $status and the expected message"
