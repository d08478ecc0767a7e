#!/bin/bash
# Progress lines that tell the truth (src/driver/progress.c, include/dmhs/progress.h):
#  1. -progress_wall_interval 0: the lines of -progress_interval only (4 in 400 steps) and,
#     after the step-100 line, the projection with the exact step count of a fixed dt;
#  2. a wall interval shorter than a step: a line after every step, the simulated-time
#     lines and the projection among them;
#  3. the automatic dt of the quick colon, which grows over its first 12 steps: the
#     projected step count is the count the run takes (within 0.5 %; a projection from the
#     mean dt so far, 1612 against 1572, would be 2.5 % off);
#  4. -quiet: no line at all, the summary still there.
# Usage: progress.sh DMHS INPUT_DIR WORKDIR
set -euo pipefail
EXE=$1 INPUT=$2 W=$3
rm -rf "$W" && mkdir -p "$W"
fail() { echo "FAIL: $*"; exit 1; }
# 400 steps of 2.5e-5 s, about 0.1 ms each (test/io/common.sh's channel)
QUICK=(-scene poiseuille -channel_width 1e-3 -channel_length 5e-4 -channel_nx 10 -channel_ny 20
       -sph_h 1.5e-4 -body_force 2e-4,0 -dt 2.5e-5 -t_end 0.01 -progress_interval 0.0025
       -output_snapshots false -checkpoint_at_end false)
status_lines() { grep -c '^step ' "$1" || true; }

"$EXE" "${QUICK[@]}" -progress_wall_interval 0 -output_dir "$W/a" > "$W/a.log"
steps=$(grep '^step ' "$W/a.log" | awk '{print $2}' | tr '\n' ' ')
[ "$steps" = "100 200 300 400 " ] || fail "-progress_wall_interval 0: lines at steps '$steps', expected 100 200 300 400"
grep -A1 '^step  *100 ' "$W/a.log" | grep -q '^projection after 100 steps: 400 steps to t_end = 0.01 s, .* of wall time (.* to go at .* s per step), ending about [0-9]\{4\}-[0-9][0-9]-[0-9][0-9] [0-9][0-9]:[0-9][0-9] local time$' ||
  fail "no projection line with 400 steps after the step-100 line: $(grep projection "$W/a.log")"
[ "$(grep -c '^projection' "$W/a.log")" = 1 ] || fail "more than one projection line"
grep -q '^step  *400 .* ETA 0.0 s ([0-9-]* [0-9:]*) ' "$W/a.log" || fail "the last line's ETA is not 0.0 s with its end time"
echo "1. simulated-time lines at steps $steps and the projection: OK"

"$EXE" "${QUICK[@]}" -progress_wall_interval 1e-9 -output_dir "$W/b" > "$W/b.log"
n=$(status_lines "$W/b.log")
[ "$n" -ge 399 ] || fail "-progress_wall_interval 1e-9: $n status lines in 400 steps, expected one a step"
[ "$(grep -c '^projection after 100 steps: 400 steps' "$W/b.log")" = 1 ] || fail "wall-clock lines: no projection"
echo "2. a line after every step with a tiny wall interval ($n lines): OK"

"$EXE" -options_file "$INPUT/intestine-quick.opts" -t_end 0.02 -progress_wall_interval 0 -output_snapshots false \
  -checkpoint_at_end false -output_dir "$W/c" > "$W/c.log"
projected=$(sed -n 's/^projection after 100 steps: \([0-9]*\) steps to t_end.*the automatic dt changes.*/\1/p' "$W/c.log")
taken=$(sed -n 's/^dmhs summary: .*, \([0-9]*\) steps to t = .*/\1/p' "$W/c.log")
[ -n "$projected" ] && [ -n "$taken" ] || fail "automatic dt: no projection ('$projected') or summary ('$taken')"
awk -v p="$projected" -v n="$taken" 'BEGIN { d = p - n; if (d < 0) d = -d; exit !(d <= 0.005 * n) }' ||
  fail "automatic dt: $projected steps projected, $taken taken"
echo "3. automatic dt: $projected steps projected, $taken taken: OK"

"$EXE" "${QUICK[@]}" -progress_wall_interval 1e-9 -quiet -output_dir "$W/d" > "$W/d.log"
[ "$(status_lines "$W/d.log")" = 0 ] && ! grep -q '^projection' "$W/d.log" || fail "-quiet printed progress lines"
grep -q '^dmhs summary: .* 400 steps' "$W/d.log" || fail "-quiet: no summary"
echo "4. -quiet: OK"
echo "progress lines: OK"
