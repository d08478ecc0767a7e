#!/bin/bash
# Bad input: truncated, foreign, wrong-version, incomplete, mismatched,
# bit-flipped (checksums) and duplicated-gid checkpoints, a missing one, an output directory that cannot be created, and a
# checkpoint write that fails. Each must stop with exit status 1 (no crash) and
# a message naming the file; a failed checkpoint write leaves the previous
# checkpoint intact.
# Usage: corrupt.sh DMHS PYTHON WORKDIR
set -uo pipefail
EXE=$1 PY=$2 W=$3
source "$(dirname "$0")/common.sh"
rm -rf "$W" && mkdir -p "$W"
"$EXE" "${QUICK[@]}" -t_end 0.0025 -output_dir "$W/good" > "$W/good.log" 2>&1 || die "the reference run failed"
GOOD=$W/good/checkpoint.h5

# expect_fail NAME PATTERN ARGS...: exit status 1 and PATTERN on stderr
expect_fail() {
  local name=$1 pattern=$2; shift 2
  local rc=0
  "$EXE" "${QUICK[@]}" -t_end 0.005 "$@" > "$W/$name.out" 2> "$W/$name.err" || rc=$?
  [ $rc -eq 1 ] || { cat "$W/$name.err"; die "$name: exit status $rc, expected 1"; }
  grep -qF -- "$pattern" "$W/$name.err" || { cat "$W/$name.err"; die "$name: message lacks '$pattern'"; }
  echo "$name: $(head -1 "$W/$name.err")"
}

head -c $(( $(stat -c %s "$GOOD") / 2 )) "$GOOD" > "$W/truncated.h5"
expect_fail truncated "$W/truncated.h5" -output_dir "$W/o1" -restart "$W/truncated.h5"
grep -q '"status": "error"' "$W/o1/run.json" || die "run.json does not record the error"

echo "not HDF5 at all" > "$W/foreign.txt"
expect_fail foreign "$W/foreign.txt" -output_dir "$W/o2" -restart "$W/foreign.txt"
expect_fail snapshot_as_checkpoint "not a dmhs checkpoint" -output_dir "$W/o3" -restart "$W/good/snap_000000.h5"
expect_fail missing "cannot read $W/nope.h5" -output_dir "$W/o4" -restart "$W/nope.h5"

cp "$GOOD" "$W/version.h5"
"$PY" -c "import h5py,numpy; f=h5py.File('$W/version.h5','r+'); f.attrs['format_version']=numpy.array([99],dtype='i8')"
expect_fail version "format version 99" -output_dir "$W/o5" -restart "$W/version.h5"

cp "$GOOD" "$W/magic.h5"
"$PY" -c "import h5py,numpy; f=h5py.File('$W/magic.h5','r+'); f.attrs['magic']=numpy.bytes_('SOMETHING-ELSE')"
expect_fail magic "not a dmhs checkpoint (magic 'SOMETHING-ELSE'" -output_dir "$W/o6" -restart "$W/magic.h5"

cp "$GOOD" "$W/incomplete.h5"
"$PY" -c "import h5py; f=h5py.File('$W/incomplete.h5','r+'); del f['particles/rho']"
expect_fail incomplete "$W/incomplete.h5 lacks the dataset rho" -output_dir "$W/o7" -restart "$W/incomplete.h5"

cp "$GOOD" "$W/count.h5"
"$PY" -c "import h5py,numpy; f=h5py.File('$W/count.h5','r+'); f.attrs['n_particles']=numpy.array([300],dtype='i8')"
expect_fail count "holds 300 particles but scene 'poiseuille' built 260" -output_dir "$W/o8" -restart "$W/count.h5"

cp "$GOOD" "$W/rows.h5"
"$PY" -c "
import h5py
f = h5py.File('$W/rows.h5', 'r+'); v = f['particles/v'][()]; del f['particles/v']; f['particles/v'] = v[:200]"
expect_fail rows "dataset v in $W/rows.h5 is 200 x 2" -output_dir "$W/o9" -restart "$W/rows.h5"

expect_fail options "-channel_length 0.0005 in the checkpoint, 0.0006 now; -channel_nx 10 in the checkpoint, 12 now" \
  -output_dir "$W/o10" -restart "$GOOD" -channel_nx 12 -channel_length 6e-4
expect_fail options_allowed "holds 260 particles but scene 'poiseuille' built 312" -output_dir "$W/o10" \
  -restart "$GOOD" -channel_nx 12 -channel_length 6e-4 -restart_allow_change

# flipped bytes in the raw data (HDF5 itself does not notice): each dataset's checksum does
flip() { # FILE DATASET: xor one byte in the middle of the dataset's storage
  "$PY" - "$1" "$2" << 'PYEOF'
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    d = f[sys.argv[2]]
    at = d.id.get_offset() + d.id.get_storage_size() // 2
with open(sys.argv[1], "r+b") as raw:
    raw.seek(at)
    b = raw.read(1)
    raw.seek(at)
    raw.write(bytes([b[0] ^ 0x10]))
PYEOF
}
cp "$GOOD" "$W/flipped.h5" && flip "$W/flipped.h5" particles/v
expect_fail flipped "checkpoint $W/flipped.h5 is corrupt: dataset /particles/v fails its checksum" \
  -output_dir "$W/o11" -restart "$W/flipped.h5"
cp "$GOOD" "$W/flipped_state.h5" && flip "$W/flipped_state.h5" diagnostics/errors/errors_next_report
expect_fail flipped_state "dataset /diagnostics/errors/errors_next_report fails its checksum" -output_dir "$W/o12" \
  -restart "$W/flipped_state.h5"
cp "$GOOD" "$W/dup.h5"
"$PY" -c "import h5py; f=h5py.File('$W/dup.h5','r+'); g=f['particles/gid']; v=g[()]; v[3]=v[4]; g[...]=v"
expect_fail duplicate_gid "checkpoint $W/dup.h5 is corrupt: dataset /particles/gid holds gid" \
  -output_dir "$W/o13" -restart "$W/dup.h5"

expect_fail output_dir "/dev/null/sub" -output_dir /dev/null/sub

# a checkpoint write that fails (its temporary name is taken by a directory)
# stops the run and leaves the previous checkpoint as it was
cp -r "$W/good" "$W/keep"
before=$(md5sum < "$W/keep/checkpoint.h5")
mkdir "$W/keep/checkpoint.h5.tmp"
expect_fail failed_write "$W/keep/checkpoint.h5.tmp" -output_dir "$W/keep" -checkpoint_interval 0.00125
[ "$(md5sum < "$W/keep/checkpoint.h5")" = "$before" ] || die "the previous checkpoint was changed"
echo "bad input: OK"
