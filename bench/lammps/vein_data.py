#!/usr/bin/python3
"""Turns a dmhs vein run's initial state into the input of the LAMMPS twin
bench/lammps/vein.in: a data file (atoms with types, masses, densities and
velocities, bonds, angles) and an include file of the physics parameters.

  build/dmhs -options_file input/vein.opts [-vein_dx 4e-4 ...] -t_end 1e-7 -dt 1e-7 \\
      -output_dir DIR
  /usr/bin/python3 bench/lammps/vein_data.py DIR [--snapshot snap_000000.h5 | --state-from-checkpoint]
      [--evaluation-density] [--out PREFIX]

Writes PREFIX.data and PREFIX.params.in (PREFIX = DIR/vein by default).

Where each piece comes from (dmhs writes no single file with all of it):
  * the particles (gid, type, body, x, v, mass, rho) from the snapshot, by default
    DIR/snap_000000.h5, the state at t = 0 (src/io/snapshot.c), or from the
    checkpoint's /particles (the state at the end of the run, for a twin that
    continues it: the include file's t0 is that state's time);
  * the bonds and angles by particle gid from the checkpoint DIR/checkpoint.h5,
    group /topology (src/io/topology_checkpoint.c), written at the end of the run.
    The vein's topology never changes (no clots): the checkpoint's is that of
    t = 0. The snapshot's /bonds/rows (the bonds as pairs of its rows) must name
    the same bonds: checked. Angles are only in the checkpoint;
  * every physics value from the checkpoint's attribute physics_options (every
    option of the run with its value, defaults included).

LAMMPS atom types (dmhs has a type and a body per particle; LAMMPS keys masses,
pair coefficients and groups to types):
  1 liquid (type 0)                 4 lower leaflet, free (type 2, body 2)
  2 wall (type 1, body 0)           5 upper leaflet's clamp (type 1, body 1)
  3 upper leaflet, free (type 2, body 1)   6 lower leaflet's clamp (type 1, body 2)
Every particle of a LAMMPS type must have the same mass (LAMMPS' atom_style
sph has per-type masses only): checked.
"""
import argparse
import math
import os
import sys

import h5py
import numpy as np

# (dmhs type, body) -> LAMMPS type; bodies: 0 walls/liquid, 1 upper leaflet, 2 lower
LMP_TYPE = {(0, 0): 1, (1, 0): 2, (2, 1): 3, (2, 2): 4, (1, 1): 5, (1, 2): 6}
TYPE_NAME = {1: "liquid", 2: "wall", 3: "leaflet 1", 4: "leaflet 2", 5: "clamp 1", 6: "clamp 2"}


def physics_options(ck):
    """The checkpoint's physics_options: '-name value' lines -> {name: value}."""
    raw = ck.attrs["physics_options"]
    text = raw.decode() if isinstance(raw, bytes) else str(raw)
    opts = {}
    for line in text.splitlines():
        parts = line.strip().split(None, 1)
        if len(parts) == 2 and parts[0].startswith("-"):
            opts[parts[0][1:]] = parts[1].strip()
    return opts


def num(opts, name):
    return float(opts[name])


def first_of_list(opts, name, k):
    return float(opts[name].split(",")[k])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", help="dmhs output directory of the vein run (snapshot and checkpoint)")
    ap.add_argument("--snapshot", default="snap_000000.h5",
                    help="snapshot (in DIR) whose particle state is written (default: t = 0)")
    ap.add_argument("--state-from-checkpoint", action="store_true",
                    help="write the checkpoint's particle state (the end of the run) instead of a "
                    "snapshot's: a twin that continues a dmhs run (its time goes to t0)")
    ap.add_argument("--checkpoint", default="checkpoint.h5", help="checkpoint in DIR (the topology)")
    ap.add_argument("--out", default=None, help="output prefix (default DIR/vein)")
    ap.add_argument("--evaluation-density", action="store_true",
                    help="write the density the snapshot's last force evaluation saw, rho - dt/2 "
                    "drho for the integrated particles (the half-step density of a run with "
                    "-sph_density_predict false), instead of rho: for a force-by-force check "
                    "(bench/lammps/vein_forces.py)")
    a = ap.parse_args()
    out = a.out or os.path.join(a.dir, "vein")

    state = a.checkpoint if a.state_from_checkpoint else a.snapshot
    with h5py.File(os.path.join(a.dir, state), "r") as sn, \
            h5py.File(os.path.join(a.dir, a.checkpoint), "r") as ck:
        scene = sn.attrs["scene"]
        scene = scene.decode() if isinstance(scene, bytes) else str(scene)
        if scene != "vein":
            sys.exit(f"{state}: scene {scene}, not vein")
        time = float(sn.attrs["t" if a.state_from_checkpoint else "time"][0])
        P = sn["particles"]
        gid = P["gid"][:].astype(np.int64)
        ptype = P["type"][:].astype(np.int64)
        body = P["body"][:].astype(np.int64)
        x = P["x"][:, :2]
        v = P["v"][:, :2]
        mass = P["mass"][:]
        rho = P["rho"][:]
        drho = P["drho"][:]
        dt_snap = float(sn.attrs["dt"][0])
        # the snapshot's bonds as pairs of its rows (a checkpoint has none: its own topology is used)
        rows = sn["bonds/rows"][:] if "bonds" in sn else None
        opts = physics_options(ck)
        T = ck["topology"]
        bond_gid = T["bond_gid"][:] if "bond_gid" in T else np.zeros((0, 2), dtype=np.int64)
        bond_type = T["bond_type"][:] if "bond_type" in T else np.zeros(0, dtype=np.int64)
        bond_r0 = T["bond_r0"][:] if "bond_r0" in T else np.zeros(0)
        angle_gid = T["angle_gid"][:] if "angle_gid" in T else np.zeros((0, 3), dtype=np.int64)
        angle_type = T["angle_type"][:] if "angle_type" in T else np.zeros(0, dtype=np.int64)

    n = len(gid)
    order = np.argsort(gid)
    gid, ptype, body, x, v, mass, rho, drho = (q[order] for q in (gid, ptype, body, x, v, mass, rho, drho))
    inv = np.empty(n, dtype=np.int64)
    inv[order] = np.arange(n)
    if not np.array_equal(gid, np.arange(n)):
        sys.exit("the snapshot's gids are not 0 .. n-1")

    # the topology: the checkpoint's, checked against the snapshot's bonds
    if np.any(bond_r0 != 0) or np.any(bond_type != 0) or np.any(angle_type != 0):
        sys.exit("the checkpoint holds bonds of their own rest length or of other types than the "
                 "scene's (clot bonds?): this converter handles the vein without clots")
    snap_bonds = {tuple(sorted(p)) for p in gid[inv[rows]].tolist()} if rows is not None else None
    ck_bonds = {tuple(sorted(p)) for p in bond_gid.tolist()}
    if snap_bonds is not None and snap_bonds != ck_bonds:
        sys.exit(f"the snapshot names {len(snap_bonds)} bonds, the checkpoint {len(ck_bonds)}, "
                 f"{len(snap_bonds ^ ck_bonds)} differ: not the same run?")

    # LAMMPS types and per-type masses
    ltype = np.array([LMP_TYPE.get((t, b), 0) for t, b in zip(ptype.tolist(), body.tolist())])
    if np.any(ltype == 0):
        bad = np.nonzero(ltype == 0)[0][0]
        sys.exit(f"particle gid {gid[bad]}: type {ptype[bad]} body {body[bad]} has no LAMMPS type")
    masses = {}
    for t in range(1, 7):
        m = np.unique(mass[ltype == t])
        if len(m) != 1:
            sys.exit(f"LAMMPS type {t} ({TYPE_NAME[t]}): {len(m)} different masses {m[:4]}")
        masses[t] = m[0]

    if a.evaluation_density:
        if opts.get("sph_density_predict") != "false":
            sys.exit("--evaluation-density: the run must have -sph_density_predict false (the "
                     "predicted density's first rate is not in the snapshot)")
        # walls (type 1) take an extrapolated density in the evaluation itself: kept as written
        moving = ptype != 1
        rho = np.where(moving, rho - 0.5 * dt_snap * drho, rho)

    # physics
    dx = num(opts, "vein_dx")
    length = num(opts, "vein_length")
    h = num(opts, "sph_h")
    rho0, c0, nu = num(opts, "sph_rho0"), num(opts, "sph_c0"), num(opts, "sph_nu")
    for name, want in (("sph_kernel", "lucy"), ("sph_eos", "tait"), ("sph_density", "continuity"),
                       ("bond_style", "harmonic"), ("sph_kernel_correction", "false"),
                       ("special_bonds_include", "false"), ("repulsion_bodies", "true"),
                       ("body_force_types", "(default)")):
        if opts.get(name) != want:
            sys.exit(f"-{name} {opts.get(name)}: the twin has {want} only")
    if num(opts, "sph_p_background") != 0 or num(opts, "gravity") != 0 or num(opts, "sph_tensile_eps") != 0:
        sys.exit("-sph_p_background, -gravity and -sph_tensile_eps must be 0 for the twin")
    fx, fy = (float(q) for q in opts["body_force"].split(","))
    period = num(opts, "body_force_period")
    n_btypes = int(bond_type.max()) + 1 if len(bond_type) else 1
    n_atypes = int(angle_type.max()) + 1 if len(angle_type) else 1
    bond_k = [first_of_list(opts, "bond_k", k) for k in range(n_btypes)]
    bond_r0s = [first_of_list(opts, "bond_r0", k) for k in range(n_btypes)]
    angle_k = [first_of_list(opts, "angle_k", k) for k in range(n_atypes)]
    angle_t0 = [first_of_list(opts, "angle_theta0", k) for k in range(n_atypes)]
    K, rs = num(opts, "repulsion_k"), num(opts, "repulsion_rstar")
    p1, p2 = int(num(opts, "repulsion_p1")), int(num(opts, "repulsion_p2"))
    # dmhs's U = K[(s^p1 - 1)/p1 - (s^p2 - 1)/p2], s = r*/r < 1, is LAMMPS' Mie potential cut and
    # shifted at its minimum r*: epsilon = K (p1 - p2)/(p1 p2), sigma = r* (p2/p1)^(1/(p1 - p2))
    # (doc/lammps.md; bench/lammps/check_potentials.py compares the tables)
    eps = K * (p1 - p2) / (p1 * p2)
    sigma = rs * (p2 / p1) ** (1.0 / (p1 - p2))
    # dmhs's neighbour skin is -neighbour_skin times the longest reach of its modules: here the
    # angles' ghost reach, twice 1.5 r0 (doc/theory.md, "Topology"), beyond h and r*
    reach = max(h, rs, 3.0 * max(bond_r0s))
    skin = num(opts, "neighbour_skin") * reach

    ylo, yhi = x[:, 1].min() - 4 * dx, x[:, 1].max() + 4 * dx
    if x[:, 0].min() < 0 or x[:, 0].max() >= length:
        sys.exit("a particle lies outside [0, vein_length) in x")

    with open(out + ".data", "w") as f:
        f.write(f"LAMMPS data file: dmhs vein twin, {a.dir}/{state} (t = {time:.17g} s), "
                f"dx = {dx:g} m (bench/lammps/vein_data.py)\n\n")
        f.write(f"{n} atoms\n6 atom types\n{len(bond_gid)} bonds\n{n_btypes} bond types\n"
                f"{len(angle_gid)} angles\n{n_atypes} angle types\n\n")
        f.write(f"0 {length:.17g} xlo xhi\n{ylo:.17g} {yhi:.17g} ylo yhi\n"
                f"{-0.5 * dx:.17g} {0.5 * dx:.17g} zlo zhi\n\n")
        f.write("Masses\n\n")
        for t in range(1, 7):
            f.write(f"{t} {masses[t]:.17g}  # {TYPE_NAME[t]}\n")
        # atom_style hybrid angle sph: id type x y z | molecule | rho esph cv
        f.write("\nAtoms  # hybrid\n\n")
        for i in range(n):
            f.write(f"{gid[i] + 1} {ltype[i]} {x[i, 0]:.17g} {x[i, 1]:.17g} 0 {body[i]} "
                    f"{rho[i]:.17g} 0 1\n")
        f.write("\nVelocities\n\n")
        for i in range(n):
            f.write(f"{gid[i] + 1} {v[i, 0]:.17g} {v[i, 1]:.17g} 0\n")
        if len(bond_gid):
            f.write("\nBonds\n\n")
            for k, (b, t) in enumerate(zip(bond_gid.tolist(), bond_type.tolist())):
                f.write(f"{k + 1} {t + 1} {b[0] + 1} {b[1] + 1}\n")
        if len(angle_gid):
            # dmhs stores (i, j centre, k), LAMMPS atom1 atom2 (centre) atom3
            f.write("\nAngles\n\n")
            for k, (g3, t) in enumerate(zip(angle_gid.tolist(), angle_type.tolist())):
                f.write(f"{k + 1} {t + 1} {g3[0] + 1} {g3[1] + 1} {g3[2] + 1}\n")

    tips = {}
    for b in (1, 2):
        ids = gid[(ptype == 2) & (body == b)]
        # the tip column: the leaflet's two largest gids (layers 0 and 1), as 1-based LAMMPS ids
        tips[b] = (int(ids.max() - 1) + 1, int(ids.max()) + 1)
    with open(out + ".params.in", "w") as f:
        f.write(f"# dmhs vein run {a.dir} (bench/lammps/vein_data.py): its physics options as "
                "LAMMPS variables and coefficients\n")
        f.write(f"variable t0 equal {time:.17g}  # the state's time: the twin starts there\n")
        f.write(f"variable dx equal {dx:.17g}\n")
        f.write(f"variable length equal {length:.17g}\n")
        f.write(f"variable h equal {h:.17g}\n")
        f.write(f"variable rho0 equal {rho0:.17g}\n")
        f.write(f"variable c0 equal {c0:.17g}\n")
        f.write(f"variable nu equal {nu:.17g}\n")
        f.write(f"variable mu equal {rho0 * nu:.17g}  # dynamic viscosity rho0 nu [Pa s]\n")
        f.write(f"variable g0 equal {math.hypot(fx, fy):.17g}\n")
        f.write(f"variable gx equal {fx / math.hypot(fx, fy) if (fx or fy) else 1.0:.17g}\n")
        f.write(f"variable gy equal {fy / math.hypot(fx, fy) if (fx or fy) else 0.0:.17g}\n")
        f.write(f"variable period equal {period:.17g}  # 0: a constant drive\n")
        f.write(f"variable rep_eps equal {eps:.17g}  # repulsion K = {K:g} J, r* = {rs:g} m, "
                f"(p1, p2) = ({p1}, {p2})\n")
        f.write(f"variable rep_sigma equal {sigma:.17g}\n")
        f.write(f"variable rep_rstar equal {rs:.17g}\n")
        f.write(f"variable rep_p1 equal {p1}\n")
        f.write(f"variable rep_p2 equal {p2}\n")
        f.write(f"variable skin equal {skin:.17g}\n")
        f.write(f"variable tip1_a equal {tips[1][0]}\nvariable tip1_b equal {tips[1][1]}\n")
        f.write(f"variable tip2_a equal {tips[2][0]}\nvariable tip2_b equal {tips[2][1]}\n")
        for k in range(n_btypes):
            f.write(f"variable bond_k{k + 1} equal {bond_k[k]:.17g}\n")
            f.write(f"variable bond_r0{k + 1} equal {bond_r0s[k]:.17g}\n")
        for k in range(n_atypes):
            f.write(f"variable angle_k{k + 1} equal {angle_k[k]:.17g}\n")
            f.write(f"variable angle_theta0{k + 1} equal {angle_t0[k]:.17g}\n")
        f.write(f"variable n_bond_types equal {n_btypes}\nvariable n_angle_types equal {n_atypes}\n")
        # dmhs options LAMMPS' SPH package has no counterpart of (reported, not applied)
        extra = []
        if num(opts, "sph_delta") != 0:
            extra.append(f"-sph_delta {opts['sph_delta']}")
        if opts.get("sph_density_predict") == "true":
            extra.append("-sph_density_predict true")
        if num(opts, "sph_av_alpha") != 0 or num(opts, "sph_av_beta") != 0:
            extra.append(f"-sph_av_alpha {opts['sph_av_alpha']} -sph_av_beta {opts['sph_av_beta']}")
        if int(num(opts, "solid_substeps")) != 1:
            extra.append(f"-solid_substeps {opts['solid_substeps']}")
        f.write(f"# not in the twin (LAMMPS has no counterpart): {' '.join(extra) or 'none'}; and "
                f"dmhs's walls take the liquid's extrapolated pressure and velocity (-sph_wall_"
                f"extrapolation {opts.get('sph_wall_extrapolation')})\n")
    counts = ", ".join(f"{TYPE_NAME[t]} {np.count_nonzero(ltype == t)}" for t in range(1, 7))
    print(f"{out}.data: {n} atoms ({counts}), {len(bond_gid)} bonds, {len(angle_gid)} angles, "
          f"t = {time:g} s; {out}.params.in: dx = {dx:g} m, h = {h:g} m")
    if extra:
        print(f"dmhs options without a LAMMPS counterpart (not in the twin): {' '.join(extra)}")


if __name__ == "__main__":
    main()
