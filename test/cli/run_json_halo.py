#!/usr/bin/python3
"""run.json's "halo" object on the periodic box, at rest (-box_velocity 0: the
lattice stays put, so the counts are those of the lattice), on 1 and 2 ranks.

One rank: the ghosts are the periodic images, counted here from the lattice
and the ghost width the run prints: a particle within the width of a side has
an image across it, one within the width of a corner also one across the
corner. Two ranks: every field present and an integer, owned rows summing to
nx * ny, means equal to total / ranks, min <= mean <= max, each rank with a
partner, as many copies sent as ghosts received from other ranks, the bytes
of a refresh equal to those ghosts times the row size, and more ghosts than
on one rank (the images plus the copies across the cut).

  run_json_halo.py OUT_DIR MPIRUN... -- DMHS
"""
import json
import os
import re
import subprocess
import sys

NX, NY, DX = 40, 30, 1e-4
COUNTS = ["owned", "ghost", "remote_ghost", "sent", "partners", "forward_bytes"]


def run(mpirun, exe, ranks, out):
    cmd = mpirun + ["-n", str(ranks), exe, "-scene", "box", "-box_nx", str(NX), "-box_ny",
                    str(NY), "-box_dx", str(DX), "-box_velocity", "0", "-dt", "1e-6", "-t_end",
                    "5e-6", "-quiet", "-output_snapshots", "false", "-checkpoint_at_end",
                    "false", "-output_dir", out]
    text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    width = float(re.search(r"ghost width ([0-9.eE+-]+) m", text).group(1))
    with open(os.path.join(out, "run.json")) as f:
        return json.load(f)["halo"], width


def images(width):
    """Periodic images of the lattice (i + 0.5) dx in [0, NX dx] x [0, NY dx]."""
    def near(n):  # how many of the n lattice lines are within the width of each side
        lo = sum(1 for i in range(n) if (i + 0.5) * DX < width)
        hi = sum(1 for i in range(n) if n * DX - (i + 0.5) * DX <= width)
        return lo, hi
    xl, xh = near(NX)
    yl, yh = near(NY)
    return (xl + xh) * NY + (yl + yh) * NX + (xl + xh) * (yl + yh)


def check_fields(halo, ranks, problems):
    for name in COUNTS:
        c = halo.get(name)
        if not isinstance(c, dict):
            problems.append(f"{ranks} rank(s): no '{name}'")
            continue
        for k in ("min", "max", "total"):
            if not isinstance(c.get(k), int) or c[k] < 0:
                problems.append(f"{ranks} rank(s): {name}.{k} = {c.get(k)!r}, not an integer >= 0")
        if all(isinstance(c.get(k), int) for k in ("min", "max", "total")):
            mean = c.get("mean")
            if not isinstance(mean, (int, float)) or abs(mean - c["total"] / ranks) > 1e-6 * (1 + mean):
                problems.append(f"{ranks} rank(s): {name}.mean {mean!r} != total / ranks")
            elif not c["min"] - 1e-9 <= mean <= c["max"] + 1e-9:
                problems.append(f"{ranks} rank(s): {name}: not min <= mean <= max")
    if not isinstance(halo.get("ghost_bytes"), int) or halo["ghost_bytes"] <= 0:
        problems.append(f"{ranks} rank(s): ghost_bytes {halo.get('ghost_bytes')!r}")


def main():
    out = sys.argv[1]
    sep = sys.argv.index("--")
    mpirun, exe = sys.argv[2:sep], sys.argv[sep + 1]
    problems = []
    h1, width = run(mpirun, exe, 1, os.path.join(out, "np1"))
    h2, _ = run(mpirun, exe, 2, os.path.join(out, "np2"))
    check_fields(h1, 1, problems)
    check_fields(h2, 2, problems)
    if problems:
        print("\n".join(problems))
        return 1
    n = NX * NY
    want = images(width)
    if h1["owned"]["total"] != n or h1["ghost"]["total"] != want or h1["ghost"]["min"] != want:
        problems.append(f"1 rank: owned {h1['owned']}, ghost {h1['ghost']}: expected {n} owned, "
                        f"{want} periodic images (ghost width {width} m)")
    for name in ("remote_ghost", "sent", "partners", "forward_bytes"):
        if h1[name]["max"] != 0:
            problems.append(f"1 rank: {name} {h1[name]}, expected 0")
    if h2["owned"]["total"] != n:
        problems.append(f"2 ranks: owned total {h2['owned']['total']}, expected {n}")
    if h2["partners"]["min"] != 1 or h2["partners"]["max"] != 1:
        problems.append(f"2 ranks: partners {h2['partners']}, expected 1 on each rank")
    if h2["sent"]["total"] != h2["remote_ghost"]["total"] or h2["remote_ghost"]["min"] <= 0:
        problems.append(f"2 ranks: sent {h2['sent']} against remote {h2['remote_ghost']}")
    if h2["forward_bytes"]["total"] != h2["remote_ghost"]["total"] * h2["ghost_bytes"]:
        problems.append(f"2 ranks: forward_bytes {h2['forward_bytes']} != remote x ghost_bytes")
    if h2["ghost"]["total"] <= want:
        problems.append(f"2 ranks: {h2['ghost']['total']} ghosts, not more than the {want} images")
    print(f"1 rank: {h1['ghost']['total']} ghosts (expected {want}); 2 ranks: owned "
          f"{h2['owned']}, ghost {h2['ghost']}, remote {h2['remote_ghost']}")
    if problems:
        print("FAIL:\n" + "\n".join(problems))
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
