#!/bin/bash
# Options files that include others, run from another directory
# (include/dmhs/options_files.h):
#  - a quick case through an absolute path to a file that names its base from
#    the project root (-options_file input/base.opts, as the shipped inputs do),
#    itself included by a file in another directory, started from a directory
#    under /tmp: the options in their order (the including file's and the
#    command line's override the base's);
#  - the shipped input/vein-run1.opts by its absolute path from there (-help);
#  - an include found nowhere: one line naming it, the file and line that include it.
# Usage: options_include.sh DMHS INPUT_DIR WORKDIR
set -uo pipefail
EXE=$(realpath "$1") INPUT=$(realpath "$2") W=$(realpath -m "$3")
die() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$W" && mkdir -p "$W/project/input" "$W/project/cases"
away=$(mktemp -d /tmp/dmhs-options-include.XXXXXX) || die "mktemp"
trap 'rm -rf "$away"' EXIT
cp "$INPUT/poiseuille-quick.opts" "$W/project/input/base.opts"
printf '# the base, named from the project root\n-options_file input/base.opts\n-t_end 0.002 # over the base\n-quiet\n' \
  > "$W/project/input/run.opts"
printf -- '-options_file input/run.opts\n-output_interval 0.001\n' > "$W/project/cases/deep.opts"
printf -- '-options_file base.opts\n' > "$W/project/input/sibling.opts"
printf '# a base that does not exist\n-options_file input/no-such-base.opts\n' > "$W/project/input/broken.opts"
cd "$away" || die "cd $away"

out=$("$EXE" -options_file "$W/project/cases/deep.opts" -output_dir "$W/deep" 2>&1) ||
  { echo "$out" | tail -5; die "the case through deep.opts failed"; }
grep -q "run: t_end = 0.002 s, output every 0.001 s" <<<"$out" || { echo "$out"; die "options not in their order"; }
grep -q "scene poiseuille, 920 particles" <<<"$out" || die "not the base's case"
out=$("$EXE" -options_file "$W/project/input/sibling.opts" -t_end 0.0005 -quiet -output_dir "$W/sibling" 2>&1) ||
  { echo "$out" | tail -5; die "the case through sibling.opts failed"; }
grep -q "run: t_end = 0.0005 s" <<<"$out" || die "the command line does not override the file"

out=$("$EXE" -options_file "$INPUT/vein-run1.opts" -help 2>&1) || { echo "$out" | tail -3; die "vein-run1.opts from $away"; }
grep -q -- "-scene <vein>" <<<"$out" || die "vein-run1.opts: not the vein"
grep -q -- "-output_dir <output/vein-run1>" <<<"$out" || die "vein-run1.opts: its own -output_dir does not override vein.opts's"

out=$("$EXE" -options_file "$W/project/input/broken.opts" 2>&1) && die "an include found nowhere was accepted"
echo "$out"
[ "$(wc -l <<<"$out")" = 1 ] || die "more than one line"
grep -Fq "dmhs: error: Unable to open options file input/no-such-base.opts (included by $W/project/input/broken.opts line 2; not found from the working directory $away" <<<"$out" ||
  die "the message does not name the including file and line"
echo "nested options files from another directory: OK"
