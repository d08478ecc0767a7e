#!/usr/bin/env bash
# The deep-vein valve study on one machine: the runs of the thesis's table
# (input/vein-run<ID>.opts), a few at a time, each continued from its
# checkpoint when the driver is started again after an interruption.
#
#   scripts/vein_study.sh                       # all 14 runs, 2 at a time on 1 rank each
#   scripts/vein_study.sh --ids "1 2 3" --jobs 1 --ranks 2
#   scripts/vein_study.sh --collect bench/results/vein-study   # copy the finished runs' CSVs
#   scripts/vein_study.sh --ids "" --clot-seeds "1 2 3 4 5"     # Fig. 4.11: run 19 with clots
#   scripts/vein_study.sh --status                 # what each run is doing (scripts/run_state.sh)
#
# Options:
#   --ids "ID ..."    runs of the table (default: 1 2 3 4 5 6 8 19 24 25 29 30 31 32)
#   --clot-seeds "S ..."  also the clot case (input/vein-clot.opts: run 19 with agglomeration)
#                     once per RNG seed S (-agglomeration_seed S), into DIR/clot-seed<S>
#   --jobs J          runs at a time (default 2)
#   --ranks N         MPI ranks per run (default 1)
#   --out DIR         runs' output directories DIR/run<ID> (default $HOME/dmhs-runs/vein-study)
#   --study FILE      options file added after each run's input (default input/vein-study.opts:
#                     the study's spacing; give --study none for the published dx = 1e-4 m)
#   --collect DEST    no run: copy vein-summary.csv, vein.csv (every 5th row), vein-sinus.csv
#                     (cycle ends only) and run.json of every completed run into DEST/run<ID>/
#                     (and, for clot runs, clots.csv, into DEST/clot-seed<S>/)
#   --status          no run: one line per run with its state (scripts/run_state.sh: completed,
#                     running, stalled, died, signal-checkpoint, error, not started)
#   -- OPTIONS        further dmhs options for every run (e.g. -- -t_end 4)
# Environment: DMHS_BUILD_DIR (default build), DMHS_EXE (default <build>/dmhs).
#
# A run whose run.json says "completed" is skipped, and so is one that is
# still going (run_state.sh: "running" or "stalled", e.g. started by another
# driver); one with a checkpoint.h5 continues from it (-restart), also one
# that died (killed, its node lost: run.json still says running). Ctrl-C or SIGTERM asks every running run to
# checkpoint and stop (dmhs writes checkpoint.h5 on SIGTERM), then the driver
# exits; start it again with the same arguments to continue. Each run's
# terminal output goes to DIR/run<ID>.log. Run from anywhere: the inputs are
# read from the repository root.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ids="1 2 3 4 5 6 8 19 24 25 29 30 31 32"
seeds="" jobs=2 ranks=1 out="$HOME/dmhs-runs/vein-study" study="input/vein-study.opts" collect="" status_only=0
extra=()
die() { echo "vein_study: $*" >&2; exit 2; }
# the "status" of DIR/run.json (not "previous_status"), or nothing
run_status() { sed -n 's/^  "status": "\([a-z-]*\)".*/\1/p' "$1/run.json" 2>/dev/null | head -n 1; }
# the status with "running" told apart: running, stalled or died (scripts/run_state.sh)
run_state() { bash "$repo/scripts/run_state.sh" --state "$1"; }
while [ $# -gt 0 ]; do
  case "$1" in
    --ids) ids="${2?--ids needs a list}"; shift 2 ;;
    --clot-seeds) seeds="${2:?--clot-seeds needs a list}"; shift 2 ;;
    --jobs) jobs="${2:?--jobs needs a number}"; shift 2 ;;
    --ranks) ranks="${2:?--ranks needs a number}"; shift 2 ;;
    --out) out="${2:?--out needs a directory}"; shift 2 ;;
    --study) study="${2:?--study needs a file or none}"; shift 2 ;;
    --collect) collect="${2:?--collect needs a directory}"; shift 2 ;;
    --status) status_only=1; shift ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown argument '$1' (see --help)" ;;
  esac
done
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || die "--jobs '$jobs' is not a positive whole number"
[[ "$ranks" =~ ^[1-9][0-9]*$ ]] || die "--ranks '$ranks' is not a positive whole number"
for id in $ids; do
  [ -r "$repo/input/vein-run$id.opts" ] || die "--ids: no input/vein-run$id.opts for run '$id'"
done
for seed in $seeds; do
  [[ "$seed" =~ ^[0-9]+$ ]] || die "--clot-seeds: '$seed' is not a whole number"
done
# the runs by name: run<ID> (the table) and clot-seed<S>
names=()
for id in $ids; do names+=("run$id"); done
for seed in $seeds; do names+=("clot-seed$seed"); done
[ "${#names[@]}" -gt 0 ] || die "no run: --ids and --clot-seeds are both empty"
# a run's own options: its input file and, for a clot run, its seed
run_opts() {
  case "$1" in
    run*) echo "-options_file input/vein-$1.opts" ;;
    clot-seed*) echo "-options_file input/vein-clot.opts -agglomeration_seed ${1#clot-seed}" ;;
  esac
}

if [ "$status_only" = 1 ]; then
  for name in "${names[@]}"; do bash "$repo/scripts/run_state.sh" "$out/$name"; done
  exit 0
fi

if [ -n "$collect" ]; then
  n=0
  for name in "${names[@]}"; do
    dir="$out/$name"
    [ "$(run_status "$dir")" = completed ] || continue
    dest="$collect/$name"
    mkdir -p "$dest"
    cp "$dir/vein-summary.csv" "$dir/run.json" "$dest/"
    awk '/^#/ || NR <= 2 || (NR - 2) % 5 == 0' "$dir/vein.csv" > "$dest/vein.csv"
    # the sinus liquid at the end of each cycle (the rows of Fig. 4.4), as written
    cp "$dir/vein-sinus.csv" "$dest/"
    [ ! -f "$dir/clots.csv" ] || cp "$dir/clots.csv" "$dest/"
    n=$((n + 1))
  done
  echo "vein_study: collected $n completed run(s) of '${names[*]}' from $out into $collect"
  exit 0
fi

study_opts=()
if [ "$study" != none ]; then
  [ -r "$repo/$study" ] || [ -r "$study" ] || die "--study: cannot read '$study'"
  study_opts=(-options_file "$study")
fi
build="${DMHS_BUILD_DIR:-$repo/build}"
exe="${DMHS_EXE:-$build/dmhs}"
if [ -z "${DMHS_EXE:-}" ]; then
  "$repo/scripts/setup.sh"
fi
[ -x "$exe" ] || die "no dmhs executable at '$exe'"
# --bind-to none: Open MPI binds each job's rank 0 to core 0, so two runs side by side (--jobs 2,
# or two drivers) shared one core and left the other idle
mpirun_flags=(--oversubscribe --bind-to none)
[ "$(id -u)" -eq 0 ] && mpirun_flags+=(--allow-run-as-root)
mkdir -p "$out"

pids=() stopping=0
stop() {
  stopping=1
  echo "vein_study: stopping: each running run writes its checkpoint" >&2
  for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null || true; done
}
trap stop INT TERM

# One run, in its own session so that a Ctrl-C reaches it once, through the driver.
start_run() {
  local name=$1 dir="$out/$1" restart=() own state
  state=$(run_state "$dir")
  case "$state" in
  completed)
    echo "vein_study: $name already completed ($dir)"
    return 1 ;;
  running | stalled) # two runs in one directory would overwrite each other's files
    echo "vein_study: $name is $state, not started again: $(bash "$repo/scripts/run_state.sh" "$dir")"
    return 1 ;;
  died) echo "vein_study: $name died (its run.json still says running)" ;;
  esac
  if [ -f "$dir/checkpoint.h5" ]; then
    restart=(-restart "$dir/checkpoint.h5")
    echo "vein_study: $name continues from $dir/checkpoint.h5"
  else
    echo "vein_study: $name starts in $dir"
  fi
  read -r -a own <<< "$(run_opts "$name")"
  (cd "$repo" && exec setsid mpirun "${mpirun_flags[@]}" -n "$ranks" "$exe" \
     "${own[@]}" "${study_opts[@]}" -output_dir "$dir" \
     "${restart[@]}" "${extra[@]}") >> "$out/$name.log" 2>&1 &
  pids+=($!)
  return 0
}

failed=0
wait_one() {
  local rc=0
  wait -n || rc=$?
  # a trapped signal interrupts wait with a status above 128: wait again for the children
  local alive=()
  for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && alive+=("$p"); done
  pids=("${alive[@]}")
  if [ "$rc" -ne 0 ] && [ "$stopping" -eq 0 ]; then failed=$((failed + 1)); fi
}

for name in "${names[@]}"; do
  [ "$stopping" -eq 1 ] && break
  while [ "${#pids[@]}" -ge "$jobs" ]; do wait_one; done
  [ "$stopping" -eq 1 ] && break
  start_run "$name" || true
done
while [ "${#pids[@]}" -gt 0 ]; do wait_one; done

status=0
for name in "${names[@]}"; do
  dir="$out/$name"
  s=$(run_state "$dir")
  echo "vein_study: $name: $s ($dir)"
  [ "$s" = completed ] || status=1
done
[ "$failed" -eq 0 ] || echo "vein_study: $failed run(s) ended with an error: see $out/<run>.log" >&2
exit "$status"
