#!/usr/bin/env bash
# Runs a command that must succeed: exit status 0 AND output matching a regex.
# (ctest's PASS_REGULAR_EXPRESSION alone ignores the exit status: a run that
# crashes after printing the expected text would pass.)
#   expect_output.sh '<regex>' [--reject '<regex>'] -- command args...
# The regexes (grep -E) are matched against stdout and stderr joined into one
# line, so a pattern may span lines. With --reject, output matching that regex
# fails. Here-strings, not printf | grep -q: under pipefail, grep -q leaving at
# its first match can kill printf by SIGPIPE and fail the pipeline.
set -u
usage() { echo "usage: expect_output.sh '<regex>' [--reject '<regex>'] -- command args..." >&2; exit 2; }
[ $# -ge 1 ] || usage
regex="$1"; shift
reject=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  case "$1" in
    --reject) [ $# -ge 2 ] || usage; reject="$2"; shift 2 ;;
    *) usage ;;
  esac
done
[ "${1:-}" = "--" ] && shift
[ $# -gt 0 ] || usage
[ -n "$regex" ] || { echo "FAIL: empty regex (it would match anything)"; exit 1; }

out=$("$@" 2>&1); status=$?
tail -n 20 <<<"$out"
joined=$(tr '\n' ' ' <<<"$out")
if [ $status -ne 0 ]; then echo "FAIL: exit status $status, expected 0"; exit 1; fi
rc=0; grep -Eq -- "$regex" <<<"$joined" || rc=$?
if [ $rc -ne 0 ]; then
  [ $rc -eq 1 ] && echo "FAIL: output does not match /$regex/" || echo "FAIL: grep -E rejects /$regex/"
  exit 1
fi
if [ -n "$reject" ]; then
  rc=0; grep -Eq -- "$reject" <<<"$joined" || rc=$?
  if [ $rc -ne 1 ]; then
    [ $rc -eq 0 ] && echo "FAIL: output matches /$reject/" || echo "FAIL: grep -E rejects /$reject/"
    exit 1
  fi
fi
echo "OK: exit status 0 and the expected output"
