#!/usr/bin/python3
"""The upper leaflet against a static cantilever beam (doc/validation.md,
"Leaflet stiffness against a static beam").

  scripts/post/vein_beam.py RUNDIR [--times 0.10,0.15,0.22,0.30] [--ei 3e-6] [--check]

For each time (the nearest snapshot): q, the mean pressure of the liquid
within 2 dx of the upper leaflet on its axis side minus that on its sinus
side; the static tip deflection of a clamped beam under a uniform load,
q L^4 / (8 EI); and the measured one, the tip's displacement normal to the
rest leaflet, positive toward the sinus. L is the leaflet's rest length (root
to tip), dx the run's spacing (run.json). EI defaults to the
scene's bending stiffness, 3e-6 N m^2 at every dx (doc/theory.md). Prints a
Markdown table. --check: exit 1 unless at every time the load pushes the
leaflet toward the sinus (q > 0), the tip has moved that way, and the
measured deflection is within 10x of the static one either way (the same
beam: a leaflet 10x too stiff or too soft fails).
"""
import argparse

import numpy as np

import vein_common as vc


def upper_leaflet(d):
    """Indices of the leaflet body above the axis."""
    _, _, leaflet = vc.masks(d)
    bodies = [b for b in np.unique(d["body"][leaflet]) if b > 0]
    if not bodies:
        vc.fail("no leaflet body in the snapshot")
    return np.where(d["body"] == max(bodies, key=lambda b: d["x0"][d["body"] == b, 1].mean()))[0]


def row(path, ei, dx):
    d = vc.read_snapshot(path, ("x", "x0", "type", "body", "p"))
    idx = upper_leaflet(d)
    x0, x = d["x0"][idx], d["x"][idx]
    root, tip = np.argmin(x0[:, 0]), np.argmax(x0[:, 0])
    along = x0[tip] - x0[root]
    length = float(np.hypot(*along))
    along /= length
    to_axis = np.array([along[1], -along[0]])
    if to_axis[1] > 0:
        to_axis = -to_axis
    fluid, _, _ = vc.masks(d)
    fx, fp = d["x"][fluid], d["p"][fluid]
    dist = np.linalg.norm(fx[:, None, :] - x[None, :, :], axis=2)
    near = dist.min(axis=1) < 2 * dx
    side = np.einsum("ij,j->i", fx - x[dist.argmin(axis=1)], to_axis)
    axis_p, sinus_p = fp[near & (side > 0)], fp[near & (side < 0)]
    if axis_p.size == 0 or sinus_p.size == 0:
        vc.fail(f"{path}: no liquid within 2 dx on one side of the upper leaflet")
    q = float(axis_p.mean() - sinus_p.mean())
    static = q * length**4 / (8 * ei)
    measured = float(np.dot(x[tip] - x0[tip], -to_axis))
    return d["time"], q, static, measured


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--times", default="0.10,0.15,0.22,0.30", help="comma-separated times [s]")
    ap.add_argument("--ei", type=float, default=3e-6, help="bending stiffness [N m^2]")
    ap.add_argument("--check", action="store_true", help="fail unless the beam's order of magnitude holds")
    a = ap.parse_args()
    vc.require_dir(a.run_dir)
    if not a.ei > 0:
        vc.fail(f"--ei must be positive (got {a.ei})")
    try:
        times = [float(t) for t in a.times.split(",")]
    except ValueError:
        vc.fail(f"--times '{a.times}' is not a comma-separated list of numbers")
    dx = vc.run_params(a.run_dir).get("dx")
    if not dx:
        vc.fail(f"{a.run_dir}: no dx in run.json or vein.csv")
    print("| t [s] | q [Pa] | static q L^4/(8 EI) [mm] | measured [mm] |")
    print("|---|---|---|---|")
    bad = []
    for t in times:
        _, path = vc.nearest_snapshot(a.run_dir, t)
        ts, q, static, measured = row(path, a.ei, dx)
        print(f"| {ts:.2f} | {q:.2g} | {static * 1e3:.2g} | {measured * 1e3:.2f} |")
        if a.check and not (q > 0 and measured > 0 and 0.1 <= measured / static <= 10):
            bad.append(f"t = {ts:.2f} s: q {q:.3g} Pa, static {static:.3g} m, measured {measured:.3g} m")
    if bad:
        vc.fail("not the static beam's order of magnitude: " + "; ".join(bad))


if __name__ == "__main__":
    main()
