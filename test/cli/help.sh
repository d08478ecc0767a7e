#!/bin/bash
# -help: each option once, sections once, with the values the chosen scene's
# run would use, arrays in full, none of PETSc's banner or "(None)" clutter.
# Usage: help.sh DMHS INPUT_DIR
set -uo pipefail
EXE=$1 IN=$2
die() { echo "FAIL: $*"; exit 1; }
check() { # NAME OUTPUT: common properties
  local name=$1 out=$2
  [ -n "$out" ] || die "$name: no output"
  dup=$(printf '%s\n' "$out" | grep -oE '^  -[a-z0-9_]+ <' | sort | uniq -d)
  [ -z "$dup" ] || die "$name: listed more than once: $dup"
  dup=$(printf '%s\n' "$out" | grep -E '^[A-Z].*:$' | sort | uniq -d)
  [ -z "$dup" ] || die "$name: sections repeated: $dup"
  # here-strings, not printf | grep -q: with pipefail, grep -q leaving at its first
  # match kills printf by SIGPIPE on a long listing, and the pipeline then fails
  grep -qE '\(None\)|PETSc Release|Options for all PETSc programs|formerly' <<<"$out" &&
    die "$name: PETSc clutter in the listing"
  echo "$name: $(printf '%s\n' "$out" | grep -cE '^  -') options, each once"
}
has() { grep -qE -- "$3" <<<"$2" || die "$1: no line matching /$3/"; }

out=$("$EXE" -help 2>&1) || die "-help failed"
check default "$out"
has default "$out" '^  -scene <poiseuille> '
has default "$out" '^  -body_force <0.0002,0> +Body acceleration Fx,Fy \[m/s\^2\]'
has default "$out" '^  -error_report_times <0.01,0.1,1> '
has default "$out" '^  -sph_h <3.75e-05> +Kernel support radius h \[m\]'
has default "$out" '^  -sph_kernel_correction <true> +Corrected operators \[1\]'
has default "$out" '^  -sph_wall_extrapolation <quadratic> +Wall velocity of the viscous term \[1\]'
has default "$out" '^Scene couette .*:$'
has default "$out" '^  -bond_rmax <'
has default "$out" '^  -repulsion_rstar <'

out=$("$EXE" -options_file "$IN/intestine-quick.opts" -help 2>&1) || die "intestine -help failed"
check intestine "$out"
has intestine "$out" '^  -scene <intestine> '
has intestine "$out" '^  -sph_h <0.00125> '
has intestine "$out" '^  -sph_c0 <5> '
has intestine "$out" '^  -sph_delta <0.1> '
has intestine "$out" '^  -sph_nu <1e-05> '
has intestine "$out" '^  -gravity <9.81> '
has intestine "$out" '^  -dt <0> '
has intestine "$out" '^  -bond_style <nonlinear> '
has intestine "$out" '^  -sph_kernel_correction <false> '
has intestine "$out" '^  -sph_wall_extrapolation <adami> '
has intestine "$out" '^Scene flap .*\(not used by scene intestine\):$'

out=$("$EXE" -options_file "$IN/flap-quick.opts" -sph_c0 2 -help 2>&1) || die "flap -help failed"
check flap "$out"
has flap "$out" '^  -sph_c0 <2> '
has flap "$out" '^  -sph_h <0.00025> '
has flap "$out" '^  -body_force <0.5,0> '
echo "help: OK"
