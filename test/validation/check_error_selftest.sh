#!/usr/bin/env bash
# The error checkers must fail on a broken error.csv, never pass it:
#   - check_error.py on doctored copies of a good file (a row missing, an empty, NaN
#     or inf value, a short row, a bad header, no rows, a value over the limit) must
#     exit 1 with a FAIL line and no Python traceback, and pass the good file;
#   - convergence.sh, run with a stand-in for dmhs that writes error.csv, must fail
#     when the t = 0.1 s row is missing or empty, and pass when it is there.
#   check_error_selftest.sh <python> <check_error.py> <convergence.sh> <work dir>
set -euo pipefail
python="$1"; check="$2"; convergence="$3"; work="$4"
rm -rf "$work"; mkdir -p "$work"
failures=0
good="$work/good.csv"
{
  echo "step,t,wall_s,l2,linf"
  for k in 1 2 3 4 5; do echo "$((k * 100)),0.$k,0.$k,1.0e-03,3.0e-03"; done
} > "$good"
args=(--all 0.01 --interval 0.1 --t-end 0.5 --at 0.3:0.01)

expect() { # expect pass|fail <name> <csv> [args...]
  local want="$1" name="$2" csv="$3" rc=0; shift 3
  "$python" "$check" "$csv" "$@" > "$work/$name.log" 2>&1 || rc=$?
  if [ "$want" = pass ] && [ $rc -eq 0 ]; then echo "ok: $name passes"; return; fi
  if [ "$want" = fail ] && [ $rc -eq 1 ] && grep -q '^FAIL' "$work/$name.log" &&
     ! grep -q Traceback "$work/$name.log"; then
    echo "ok: $name fails: $(grep -m1 '^FAIL' "$work/$name.log")"; return
  fi
  echo "WRONG: $name should $want (exit $rc):"; cat "$work/$name.log"; failures=$((failures + 1))
}
doctor() { # doctor <name> <sed script>: a copy of the good file
  sed "$2" "$good" > "$work/$1.csv"
}

expect pass good "$good" "${args[@]}"
doctor missing_row '4d';               expect fail missing_row "$work/missing_row.csv" "${args[@]}"
doctor missing_last '$d';              expect fail missing_last "$work/missing_last.csv" "${args[@]}"
doctor empty_l2 '3s/,1.0e-03,/,,/';    expect fail empty_l2 "$work/empty_l2.csv" "${args[@]}"
doctor empty_l2_at '4s/,1.0e-03,/,,/'; expect fail empty_l2_at "$work/empty_l2_at.csv" --at 0.3:0.01
doctor nan_l2 '3s/1.0e-03/nan/';       expect fail nan_l2 "$work/nan_l2.csv" "${args[@]}"
doctor inf_linf '3s/3.0e-03/inf/';     expect fail inf_linf "$work/inf_linf.csv" --all 0.01
doctor empty_t '5s/,0.4,/,,/';         expect fail empty_t "$work/empty_t.csv" --all 0.01
doctor short_row '3s/,3.0e-03$//';     expect fail short_row "$work/short_row.csv" --all 0.01
doctor bad_header '1s/l2/L2/';         expect fail bad_header "$work/bad_header.csv" --all 0.01
doctor no_rows '2,$d';                 expect fail no_rows "$work/no_rows.csv" --all 0.01
doctor over_limit '3s/1.0e-03/2.0e-02/'; expect fail over_limit "$work/over_limit.csv" "${args[@]}"
doctor repeated '3p';                  expect fail repeated "$work/repeated.csv" --all 0.01
expect fail no_file "$work/absent.csv" --all 0.01

# convergence.sh with a stand-in dmhs: L2 falls 4x per refinement; STUB_ROW_01 is what
# it writes in the l2 column at t = 0.1 s ('drop' leaves the row out)
stub="$work/dmhs-stub"
cat > "$stub" <<'STUB'
#!/usr/bin/env bash
while [ $# -gt 0 ]; do
  case "$1" in -channel_nx) nx="$2";; -output_dir) out="$2";; esac; shift
done
mkdir -p "$out"
l2=$(awk -v n="$nx" 'BEGIN{printf "%.6e", 0.3 / (n * n)}')
{
  echo "step,t,wall_s,l2,linf"
  echo "1,0.05,0.1,$l2,$l2"
  case "$STUB_ROW_01" in
    drop) ;;
    value) echo "2,0.1,0.2,$l2,$l2" ;;
    *) echo "2,0.1,0.2,$STUB_ROW_01,$l2" ;;
  esac
} > "$out/error.csv"
STUB
chmod +x "$stub"
for row in value drop "" nan; do
  mkdir -p "$work/conv-$row"; rc=0
  STUB_ROW_01="$row" bash "$convergence" "$stub" /nonexistent "$work/conv-$row/out" \
    > "$work/conv-$row.log" 2>&1 || rc=$?
  want=1; [ "$row" = value ] && want=0
  if [ $rc -eq $want ]; then echo "ok: convergence.sh with t = 0.1 s row '${row:-empty}': exit $rc"
  else echo "WRONG: convergence.sh with t = 0.1 s row '${row:-empty}': exit $rc, want $want:"
    cat "$work/conv-$row.log"; failures=$((failures + 1)); fi
done

[ $failures -eq 0 ] && echo "OK: the checkers fail on every broken file" || { echo "FAIL: $failures"; exit 1; }
