#!/usr/bin/env bash
# What a run is doing, from its output directory's run.json (doc/guide/output.md, "run.json"):
#
#   scripts/run_state.sh DIR...          # one line per directory, e.g.
#       output/vein: running (step 812000, t = 0.406 s; heartbeat 2026-12-05T14:32:10Z, 95 s ago;
#                    pid 4711 on node7)
#   scripts/run_state.sh --state DIR     # the state alone, for scripts
#
# The state is run.json's status (completed, error, signal-checkpoint), "not started" without
# a run.json, or for status "running":
#   running   its pid is a live dmhs on this host (the program run.json's "executable" names,
#             whatever its file is called; for a run.json without it, a program whose name
#             starts with dmhs); or, run on another host (where its pid cannot be looked
#             at), its heartbeat is younger than two heartbeat intervals
#   stalled   its pid is a live dmhs on this host but the heartbeat is older than two
#             intervals: hung, or stopped (kill -STOP)
#   died      its pid is gone from this host (or is another program now), or, run on another
#             host, no heartbeat for two intervals: killed, or its node failed; a restart
#             from its checkpoint continues it
# A run writes its heartbeat at every progress line (at least every -progress_wall_interval
# seconds, its heartbeat_interval) and every checkpoint, in whole seconds: "two intervals"
# allows one second more. Exit status 0, 2 on bad arguments.
set -euo pipefail
die() { echo "run_state: $*" >&2; exit 2; }
only_state=0
if [ "${1:-}" = "--state" ]; then only_state=1; shift; fi
[ $# -gt 0 ] || die "usage: run_state.sh [--state] DIR..."
[ "$only_state" = 0 ] || [ $# -eq 1 ] || die "--state takes one directory"

# A top-level value of DIR/run.json (dmhs writes one key a line, two spaces in), unquoted:
# field DIR KEY
field() {
  sed -n -e "s/^  \"$2\": \"\(.*\)\",\{0,1\}$/\1/p" -e "s/^  \"$2\": \([^\",]*\),\{0,1\}$/\1/p" \
    "$1/run.json" | head -n 1
}

state_of() {
  local dir=$1 status pid host heartbeat interval age="" now beat exe comm
  [ -f "$dir/run.json" ] || { echo "not started"; return; }
  status=$(field "$dir" status)
  [ "$status" = running ] || { echo "${status:-unknown}"; return; }
  pid=$(field "$dir" pid) host=$(field "$dir" host)
  heartbeat=$(field "$dir" heartbeat) interval=$(field "$dir" heartbeat_interval)
  now=$(date -u +%s)
  if [ -n "$heartbeat" ] && beat=$(date -u -d "$heartbeat" +%s 2>/dev/null); then age=$((now - beat)); fi
  # no heartbeat for two intervals and a second, the heartbeat's resolution (unknown without
  # an interval or a heartbeat)
  local stale=0
  if [ -n "$age" ] && [ -n "$interval" ] && [ "$interval" != null ] &&
     awk -v a="$age" -v i="$interval" 'BEGIN { exit !(a > 2 * i + 1) }'; then stale=1; fi
  if [ -n "$host" ] && [ "$host" = "$(hostname)" ] && [[ "$pid" =~ ^[0-9]+$ ]]; then
    # the kernel keeps a program's name to 15 characters (ps's comm)
    exe=$(field "$dir" executable) comm=$(ps -p "$pid" -o comm= 2>/dev/null || true)
    if [ -n "$exe" ] && [ "$exe" != null ]; then
      exe=$(basename -- "$exe") && exe=${exe:0:15}
    else
      exe="dmhs*" # written before run.json named it: a program called dmhs or dmhs-<something>
    fi
    # shellcheck disable=SC2053 # a pattern on purpose
    if [ -n "$comm" ] && [[ "$comm" == $exe ]]; then
      [ $stale = 1 ] && echo stalled || echo running
    else
      echo died
    fi
  else
    [ $stale = 1 ] && echo died || echo running
  fi
}

for dir in "$@"; do
  state=$(state_of "$dir")
  if [ "$only_state" = 1 ]; then echo "$state"; continue; fi
  case "$state" in
  "not started") echo "$dir: not started (no run.json)" ;;
  *)
    beat=$(field "$dir" heartbeat) ago=""
    if [ -n "$beat" ] && b=$(date -u -d "$beat" +%s 2>/dev/null); then ago=", $(($(date -u +%s) - b)) s ago"; fi
    echo "$dir: $state (step $(field "$dir" step), t = $(field "$dir" t) s; heartbeat ${beat:-none}$ago;" \
      "pid $(field "$dir" pid) on $(field "$dir" host))" ;;
  esac
done
