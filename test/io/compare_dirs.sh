# Sourced by the restart and stop-signal tests: compare_dirs A B compares every
# output file of run directory A with B's (run.json and the console's copy
# dmhs.log aside: times, hosts, restarts): the same set of
# files, HDF5 by gid, CSVs by value, the XDMF byte for byte. Needs PY (python)
# and die().
compare_dirs() {
  local here f
  here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
  files() { (cd "$1" && ls | grep -v -e '^run\.json$' -e '^dmhs\.log$' | sort); }
  [ "$(files "$1")" = "$(files "$2")" ] || { diff <(files "$1") <(files "$2"); die "different sets of output files"; }
  for f in $(files "$1"); do
    case $f in
    *.h5) "$PY" "$here/compare_by_gid.py" "$1/$f" "$2/$f" | tail -1 ;;
    *.csv) "$PY" "$here/compare_csv.py" "$1/$f" "$2/$f" ;;
    *.xdmf) cmp "$1/$f" "$2/$f" && echo "$f: identical" ;;
    *) die "unexpected output file $f" ;;
    esac || die "$f differs after the restart"
  done
}
