#!/usr/bin/env python3
"""Clot agglomeration, quick case (input/vein-clot-quick.opts; doc/validation.md
"Clot agglomeration").

--mode run: runs dmhs on --ranks ranks into --outdir and checks clots.csv: the
header, one row at the seeding and one per event, both clots present from
the seeding, the totals consistent (each joined particle brings exactly one
bond: clot_bonds = clot_particles - seeds), the clots never shrink and grow
to more than twice the seeds, no NaN in clots.csv or vein.csv; in the last
snapshot, as many particles of type clot (3) as the last row says and the
bonds of /bonds/rows as the leaflets' plus the clot bonds, each clot bond
joining two clot particles. With --compare DIR, clots.csv and vein.csv equal
DIR's byte for byte.
--mode restart: runs to --t-stop (checkpoint), restarts from it on
--restart-ranks ranks to t_end, and compares with --compare.
"""
import argparse
import glob
import os

from case_common import compare, fail, opt_value, read_csv, run

CSVS = ["clots.csv", "vein.csv"]


def check_run(args):
    names, rows = read_csv(os.path.join(args.outdir, "clots.csv"))
    read_csv(os.path.join(args.outdir, "vein.csv"))
    if names[:4] != ["step", "t", "clot_particles", "clot_bonds"]:
        fail(f"clots.csv header {names[:4]}")
    seeds = [n for n in names[4:] if n.startswith("clot_")]
    if len(seeds) != 2:
        fail(f"clots.csv: {len(seeds)} seed columns, expected 2 (P1, P2)")
    t_end = float(opt_value(args.opts, "-t_end"))
    start = float(opt_value(args.opts, "-agglomeration_start"))
    interval = float(opt_value(args.opts, "-agglomeration_interval"))
    expect = int(round((t_end - start) / interval)) + 1
    if len(rows) != expect:
        fail(f"clots.csv has {len(rows)} rows, expected {expect} (the seeding and every event)")
    prev = None
    for r in rows:
        n, nb, per = int(r[2]), int(r[3]), [int(v) for v in r[4:]]
        if sum(per) != n or nb != n - len(seeds) or min(per) < 1:
            fail(f"clots.csv row {r}: clot sizes {per}, particles {n}, bonds {nb} inconsistent")
        if prev and any(a < b for a, b in zip(per, prev)):
            fail(f"a clot shrank: {prev} -> {per}")
        prev = per
    if rows[-1][2] <= 2 * len(seeds):
        fail(f"the clots did not grow: {int(rows[-1][2])} particles at the end")
    print(f"  clots.csv: {len(rows)} rows, final sizes {prev} ({int(rows[-1][2])} particles, "
          f"{int(rows[-1][3])} bonds)")
    # the snapshot check is part of the test: no snapshot, or none at the last row's time, fails
    snaps = sorted(glob.glob(os.path.join(args.outdir, "snap_*.h5")))
    if not snaps:
        fail(f"no snapshot in {args.outdir} to check clots.csv against")
    import h5py
    import numpy as np
    with h5py.File(snaps[-1], "r") as f:
        if abs(float(f.attrs["time"]) - rows[-1][1]) > 1e-6:
            fail(f"the last snapshot is at t = {float(f.attrs['time'])}, the last clots.csv row at {rows[-1][1]}")
        ty = np.asarray(f["particles/type"]).ravel()
        n_clot = int((ty == 3).sum())
        if n_clot != int(rows[-1][2]):
            fail(f"{snaps[-1]}: {n_clot} clot particles, clots.csv says {int(rows[-1][2])}")
        pairs = np.asarray(f["bonds/rows"])
        both = (ty[pairs[:, 0]] == 3) & (ty[pairs[:, 1]] == 3)
        if int(both.sum()) != int(rows[-1][3]):
            fail(f"{snaps[-1]}: {int(both.sum())} bonds between clot particles, clots.csv says {int(rows[-1][3])}")
        print(f"  {os.path.basename(snaps[-1])}: {n_clot} particles of type clot, {int(both.sum())} clot bonds "
              f"of {len(pairs)}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--exe", required=True)
    p.add_argument("--opts", required=True)
    p.add_argument("--outdir", required=True)
    p.add_argument("--mode", default="run", choices=["run", "restart"])
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--restart-ranks", type=int, default=1)
    p.add_argument("--t-stop", type=float, default=0.06)
    p.add_argument("--mpirun", default="mpirun --oversubscribe --allow-run-as-root")
    p.add_argument("--compare")
    args = p.parse_args()
    if args.mode == "run":
        run(args, args.outdir, [], args.ranks, tail=2000)
    else:
        run(args, args.outdir, ["-t_end", str(args.t_stop)], args.ranks)
        run(args, args.outdir, ["-restart", os.path.join(args.outdir, "checkpoint.h5")], args.restart_ranks)
    check_run(args)
    if args.compare:
        compare(args.outdir, args.compare, CSVS)
    print("PASS")


if __name__ == "__main__":
    main()
