#!/bin/bash
# run.json tells a live run from a dead one (src/io/io.c, scripts/run_state.sh):
#  1. while a run goes, run.json holds the commit it was built from, the host, the pid of
#     the process and a heartbeat (ISO 8601 UTC) that advances; run_state.sh says running;
#  2. scripts/vein_study.sh does not start a run that is running again;
#  3. stopped (SIGSTOP) past two heartbeat intervals: stalled;
#  4. killed (SIGKILL): died, also in vein_study.sh --status;
#  5. run on another host (no pid to look at): running while the heartbeat is fresh, died
#     once it is older than two intervals; a completed run and an empty directory;
#  6. a copy of the program under another name (run.json's executable): running, and
#     vein_study.sh leaves it alone; without run.json's executable, a name not dmhs*: died.
# Usage: run_state.sh REPO DMHS PYTHON WORKDIR
set -euo pipefail
repo=$1 EXE=$2 PY=$3 W=$4
rm -rf "$W" && mkdir -p "$W"
pid=""
fail() { echo "FAIL: $*"; [ -n "$pid" ] && kill -KILL "$pid" 2>/dev/null; exit 1; }
state() { bash "$repo/scripts/run_state.sh" --state "$1"; }
QUICK=(-scene poiseuille -channel_width 1e-3 -channel_length 5e-4 -channel_nx 10 -channel_ny 20
       -sph_h 1.5e-4 -body_force 2e-4,0 -dt 2.5e-5 -output_snapshots false -checkpoint_at_end false)
run=$W/study/run4 # where scripts/vein_study.sh --ids 4 --out $W/study looks
mkdir -p "$W/study"

"$EXE" "${QUICK[@]}" -t_end 100 -progress_wall_interval 0.5 -output_dir "$run" > "$W/run.log" 2>&1 &
pid=$!
# the heartbeat must move on from the start time (whole seconds)
for _ in $(seq 100); do
  if [ -f "$run/run.json" ] && "$PY" - "$run/run.json" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
sys.exit(0 if r["heartbeat"] > r["start"] else 1)
EOF
  then break; fi
  sleep 0.1
done
"$PY" - "$run/run.json" "$pid" "$repo" <<'EOF' || fail "run.json of the live run"
import datetime, json, re, socket, subprocess, sys
r = json.load(open(sys.argv[1]))
problems = []
want = "unknown"
if subprocess.run(["git", "-C", sys.argv[3], "rev-parse"], capture_output=True).returncode == 0:
    want = subprocess.run(["git", "-C", sys.argv[3], "describe", "--always"], capture_output=True,
                          text=True).stdout.strip()
if r.get("commit", "").removesuffix("-dirty") != want:
    problems.append(f"commit {r.get('commit')!r}, expected {want!r} (with or without -dirty)")
if r.get("host") != socket.gethostname():
    problems.append(f"host {r.get('host')!r}, expected {socket.gethostname()!r}")
if r.get("pid") != int(sys.argv[2]):
    problems.append(f"pid {r.get('pid')!r}, expected {sys.argv[2]}")
iso = "%Y-%m-%dT%H:%M:%SZ"
now = datetime.datetime.now(datetime.timezone.utc).replace(tzinfo=None)
try:
    beat = datetime.datetime.strptime(r["heartbeat"], iso)
    start = datetime.datetime.strptime(r["start"], iso)
    if not start < beat <= now + datetime.timedelta(seconds=1):
        problems.append(f"heartbeat {r['heartbeat']} not after start {r['start']} and by now")
except (KeyError, ValueError) as e:
    problems.append(f"heartbeat or start not ISO 8601 UTC: {e}")
if r.get("heartbeat_interval") != 0.5 or r.get("status") != "running" or r.get("end") is not None:
    problems.append(f"heartbeat_interval {r.get('heartbeat_interval')!r}, status {r.get('status')!r}, "
                    f"end {r.get('end')!r}: expected 0.5, running, null")
print("\n".join(problems) or f"run.json: commit {r['commit']}, host {r['host']}, pid {r['pid']}, "
      f"heartbeat {r['heartbeat']} (start {r['start']})")
sys.exit(1 if problems else 0)
EOF
[ "$(state "$run")" = running ] || fail "a live run: '$(state "$run")', expected running"
echo "1. live run: run.json's commit, host, pid and heartbeat; running: OK"

rc=0
DMHS_EXE="$EXE" bash "$repo/scripts/vein_study.sh" --ids 4 --study none --out "$W/study" > "$W/study.log" 2>&1 || rc=$?
grep -q "run4 is running, not started again" "$W/study.log" || fail "vein_study.sh: $(cat "$W/study.log")"
[ $rc = 1 ] && [ "$(grep -c '^==== ' "$run/dmhs.log")" = 1 ] || fail "vein_study.sh started the running run again"
echo "2. vein_study.sh leaves the running run alone: OK"

kill -STOP "$pid"
sleep 3.5 # two intervals of 0.5 s and the heartbeat's resolution, 1 s
s=$(state "$run")
kill -CONT "$pid"
[ "$s" = stalled ] || fail "a stopped run: '$s', expected stalled"
echo "3. stopped: stalled: OK"

kill -KILL "$pid"
wait "$pid" 2>/dev/null || true
pid=""
[ "$(state "$run")" = died ] || fail "a killed run: '$(state "$run")', expected died"
bash "$repo/scripts/vein_study.sh" --ids 4 --out "$W/study" --status > "$W/status.log"
grep -q "^$run: died (step [0-9]*, t = .*; heartbeat .*; pid [0-9]* on " "$W/status.log" ||
  fail "vein_study.sh --status: $(cat "$W/status.log")"
echo "4. killed: died: OK"

elsewhere() { # run.json as written on another host, with this heartbeat
  sed -e "s/^  \"host\": .*/  \"host\": \"elsewhere.invalid\",/" -e "s/^  \"heartbeat\": .*/  \"heartbeat\": \"$1\",/" \
    "$run/run.json" > "$W/other/run.json"
}
mkdir -p "$W/other"
elsewhere "$(date -u +%Y-%m-%dT%H:%M:%SZ)"
[ "$(state "$W/other")" = running ] || fail "another host, fresh heartbeat: '$(state "$W/other")'"
elsewhere 2000-01-01T00:00:00Z
[ "$(state "$W/other")" = died ] || fail "another host, old heartbeat: '$(state "$W/other")'"
"$EXE" "${QUICK[@]}" -t_end 0.0025 -output_dir "$W/done" > "$W/done.log"
[ "$(state "$W/done")" = completed ] || fail "a completed run: '$(state "$W/done")'"
mkdir -p "$W/empty"
[ "$(state "$W/empty")" = "not started" ] || fail "an empty directory: '$(state "$W/empty")'"
echo "5. another host, completed, not started: OK"

cp "$EXE" "$W/solver-copy"
run=$W/study/run5
"$W/solver-copy" "${QUICK[@]}" -t_end 100 -progress_wall_interval 0.5 -output_dir "$run" > "$W/copy.log" 2>&1 &
pid=$!
for _ in $(seq 100); do [ -f "$run/run.json" ] && break; sleep 0.1; done
grep -qF "\"executable\": \"$W/solver-copy\"," "$run/run.json" || fail "run.json's executable: $(grep executable "$run/run.json")"
[ "$(state "$run")" = running ] || fail "a live run of a renamed copy: '$(state "$run")', expected running"
rc=0
DMHS_EXE="$W/solver-copy" bash "$repo/scripts/vein_study.sh" --ids 5 --study none --out "$W/study" > "$W/study5.log" 2>&1 || rc=$?
grep -q "run5 is running, not started again" "$W/study5.log" || fail "vein_study.sh on the copy: $(cat "$W/study5.log")"
mkdir -p "$W/legacy" && grep -v '^  "executable": ' "$run/run.json" > "$W/legacy/run.json"
[ "$(state "$W/legacy")" = died ] || fail "run.json without executable, a program not named dmhs*: '$(state "$W/legacy")'"
kill -KILL "$pid"
wait "$pid" 2>/dev/null || true
pid=""
echo "6. a renamed copy: running, left alone: OK"
echo "run state: OK"
