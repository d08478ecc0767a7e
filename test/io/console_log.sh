#!/bin/bash
# <output_dir>/dmhs.log, the copy of the console (src/io/console_log.c):
#  1. a fresh run: the opening line, then exactly what the run printed on stdout (the
#     configuration, the stability report, the progress lines, the summary);
#  2. its restart into the same directory appends: its own opening line naming the
#     checkpoint, then its output; the file is both runs' consoles;
#  3. an error after the directory exists ends the log with the error line;
#  4. a fresh run into the same directory starts the log anew;
#  5. a run killed by SIGKILL leaves a log that is its console up to the last line printed.
# Usage: console_log.sh DMHS PYTHON WORKDIR
set -euo pipefail
EXE=$1 PY=$2 W=$3
source "$(dirname "$0")/common.sh"
rm -rf "$W" && mkdir -p "$W"
LOUD=()
for o in "${QUICK[@]}"; do [ "$o" = -quiet ] || LOUD+=("$o"); done # the progress lines wanted
run() { "$EXE" "${LOUD[@]}" -output_snapshots false "$@"; }
opening='^==== \(fresh run\|restart from [^ ]*\) at [0-9]\{4\}-[0-9][0-9]-[0-9][0-9]T[0-9:]\{8\}Z (dmhs [^,]*, commit [^,]*, host [^,]*, pid [0-9]*) ====$'
body() { grep -v '^==== ' "$1"; }

run -t_end 0.0125 -output_dir "$W/a" > "$W/a.out" 2> "$W/a.err"
log=$W/a/dmhs.log
[ -s "$log" ] || die "no $log"
head -n 1 "$log" | grep -q "$opening" || die "first line of $log: $(head -n 1 "$log")"
head -n 1 "$log" | grep -q "^==== fresh run " || die "a fresh run's log does not say so"
[ ! -s "$W/a.err" ] || die "the run wrote to stderr: $(cat "$W/a.err")"
cmp <(body "$log") "$W/a.out" || die "dmhs.log is not the console's output"
for what in '^Stability report' '^step .* ETA ' '^projection after 100 steps' '^dmhs summary'; do
  grep -q "$what" "$log" || die "no line /$what/ in $log"
done
echo "1. fresh run: the opening line and the console, line for line ($(wc -l < "$log") lines): OK"

run -t_end 0.025 -restart "$W/a/checkpoint.h5" -output_dir "$W/a" > "$W/b.out" 2> "$W/b.err"
[ "$(grep -c '^==== ' "$log")" = 2 ] || die "after the restart: $(grep -c '^==== ' "$log") opening lines, expected 2"
grep '^==== ' "$log" | tail -n 1 | grep -q "^==== restart from $W/a/checkpoint.h5 at " ||
  die "the restart's opening line: $(grep '^==== ' "$log" | tail -n 1)"
cmp <(body "$log") <(cat "$W/a.out" "$W/b.out") || die "dmhs.log is not both consoles, in order"
grep -q "^Restarted from $W/a/checkpoint.h5 at step 500" "$log" || die "no restart line in the log"
echo "2. restart: appended after its own opening line: OK"

cp -r "$W/a" "$W/c"
rc=0
run -t_end 0.01 -restart "$W/c/checkpoint.h5" -output_dir "$W/c" > "$W/c.out" 2>&1 || rc=$?
[ $rc = 1 ] || die "a restart to an earlier -t_end exited with $rc, expected 1"
tail -n 1 "$W/c/dmhs.log" | grep -q '^dmhs: error: -t_end 0.01 s is not after the time of the checkpoint' ||
  die "the log does not end with the error: $(tail -n 1 "$W/c/dmhs.log")"
echo "3. an error is the log's last line: OK"

run -t_end 0.0025 -output_dir "$W/a" > "$W/d.out"
[ "$(grep -c '^==== ' "$log")" = 1 ] && cmp <(body "$log") "$W/d.out" || die "a fresh run did not start the log anew"
echo "4. a fresh run starts the log anew: OK"

# SIGKILL once the log holds a few progress lines: every line it holds is whole and is the
# console's (the console may hold one more: it is written first)
"$EXE" "${LOUD[@]}" -output_snapshots false -t_end 10 -progress_wall_interval 0.05 -output_dir "$W/e" \
  > "$W/e.out" &
pid=$! # dmhs itself (a shell function run with & would be a subshell around it)
lines() { if [ -f "$W/e/dmhs.log" ]; then grep -c '^step ' "$W/e/dmhs.log" || true; else echo 0; fi; }
for _ in $(seq 300); do
  [ "$(lines)" -ge 3 ] && break
  sleep 0.1
done
kill -KILL "$pid"
wait "$pid" 2>/dev/null || true
[ "$(lines)" -ge 3 ] || die "no progress lines in 30 s"
[ -z "$(tail -c 1 "$W/e/dmhs.log")" ] || die "the killed run's log ends in a partial line"
n=$(body "$W/e/dmhs.log" | wc -l)
cmp <(body "$W/e/dmhs.log") <(head -n "$n" "$W/e.out") || die "the killed run's log is not its console"
echo "5. SIGKILL: the log is the console up to its last line ($n lines): OK"
echo "console log: OK"
