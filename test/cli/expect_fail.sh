#!/usr/bin/env bash
# Runs a command that must fail: non-zero exit, and output matching a regex.
#   expect_fail.sh '<regex>' [--no-nan DIR] [--lines N] -- command args...
# With --no-nan, no CSV value or HDF5 dataset in DIR may be non-finite (no NaN reaches an output file).
# With --lines, the output may have at most N lines (an error is one line, not a traceback).
set -u
regex="$1"; shift
nan_dir="" max_lines=""
while [ "${1:-}" = "--no-nan" ] || [ "${1:-}" = "--lines" ]; do
  if [ "$1" = "--no-nan" ]; then nan_dir="$2"; else max_lines="$2"; fi
  shift 2
done
[ "${1:-}" = "--" ] && shift
out=$("$@" 2>&1); status=$?
printf '%s\n' "$out" | tail -n 20
if [ $status -eq 0 ]; then echo "FAIL: command succeeded, expected an error"; exit 1; fi
# the regex may span lines: match against the output joined into one line
if ! printf '%s\n' "$out" | tr '\n' ' ' | grep -Eq -- "$regex"; then echo "FAIL: output does not match /$regex/"; exit 1; fi
lines=$(printf '%s\n' "$out" | wc -l)
if [ -n "$max_lines" ] && [ "$lines" -gt "$max_lines" ]; then echo "FAIL: $lines lines of output, at most $max_lines expected"; exit 1; fi
if [ -n "$nan_dir" ] && ! /usr/bin/python3 "$(dirname "$0")/check_finite.py" "$nan_dir"; then
  echo "FAIL: a non-finite value reached an output file in $nan_dir"; exit 1
fi
echo "OK: failed with status $status and the expected message"
