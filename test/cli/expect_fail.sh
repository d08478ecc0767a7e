#!/usr/bin/env bash
# Runs a command that must fail cleanly: exit status 1 (dmhs's error exit; a
# crash, an abort or a signal gives another status and fails the check), and
# output matching a regex.
#   expect_fail.sh '<regex>' [--no-nan DIR] [--lines N] [--status S] -- command args...
# With --no-nan, no CSV value or HDF5 dataset in DIR may be non-finite (no NaN reaches an output file).
# With --lines, the output may have at most N lines (an error is one line, not a traceback).
# With --status, the exit status must be S instead of 1 (S > 0).
set -u
regex="$1"; shift
nan_dir="" max_lines="" want=1
while [ "${1:-}" = "--no-nan" ] || [ "${1:-}" = "--lines" ] || [ "${1:-}" = "--status" ]; do
  case "$1" in
    --no-nan) nan_dir="$2" ;;
    --lines) max_lines="$2" ;;
    --status) want="$2" ;;
  esac
  shift 2
done
[ "${1:-}" = "--" ] && shift
[ -n "$regex" ] || { echo "FAIL: empty regex (it would match anything)"; exit 1; }
[ "$want" -gt 0 ] 2>/dev/null || { echo "FAIL: --status $want is not a failure status"; exit 1; }
out=$("$@" 2>&1); status=$?
tail -n 20 <<<"$out"
if [ $status -eq 0 ]; then echo "FAIL: command succeeded, expected an error"; exit 1; fi
if [ $status -ne "$want" ]; then
  echo "FAIL: exit status $status, expected $want (the clean error exit; >= 128 is a signal: a crash or abort)"
  exit 1
fi
# the regex may span lines: match against the output joined into one line (here-strings:
# grep -q leaving early cannot kill a writer by SIGPIPE)
rc=0; grep -Eq -- "$regex" <<<"$(tr '\n' ' ' <<<"$out")" || rc=$?
if [ $rc -ne 0 ]; then
  [ $rc -eq 1 ] && echo "FAIL: output does not match /$regex/" || echo "FAIL: grep -E rejects /$regex/"
  exit 1
fi
lines=$(wc -l <<<"$out")
if [ -n "$max_lines" ] && [ "$lines" -gt "$max_lines" ]; then echo "FAIL: $lines lines of output, at most $max_lines expected"; exit 1; fi
if [ -n "$nan_dir" ] && ! /usr/bin/python3 "$(dirname "$0")/check_finite.py" "$nan_dir"; then
  echo "FAIL: a non-finite value reached an output file in $nan_dir"; exit 1
fi
echo "OK: failed with status $status and the expected message"
