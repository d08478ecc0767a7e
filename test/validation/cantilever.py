#!/usr/bin/python3
"""Cantilever validation (doc/theory.md, "Mass-spring leaflets as Timoshenko beams").

Runs `dmhs -scene cantilever` and compares with the beam theory computed here
from the raw parameters (an implementation of the mapping independent of the C one):
  k_s = U''(r0) of the layer bonds, EI = k_s r0^3/2 + 2 k_a r0, kGA = 8 k_a/r0,
  mu = 2 m/r0, L = (n - n_clamp) r0.
static:    tip deflection after damping out the motion vs F L^3/(3 EI) + F L/(kGA)
frequency: undamped step load; period of the tip oscillation vs
           1/w1^2 = 1/wb^2 + 1/ws^2, wb = 1.8751^2 sqrt(EI/(mu L^4)), ws = (pi/2) sqrt(kGA/(mu L^2))
Exit status 0 when the relative error is within --tol.
"""
import argparse, math, os, subprocess, sys
import numpy as np

p = argparse.ArgumentParser()
p.add_argument("--exe", required=True)
p.add_argument("--outdir", required=True)
p.add_argument("--mode", choices=["static", "frequency"], default="static")
p.add_argument("--n", type=int, default=21, help="columns incl. the clamped one")
p.add_argument("--ka", type=float, default=0.01, help="angle stiffness k_a [J]")
p.add_argument("--K", type=float, default=1e6, help="harmonic bond K [J/m^2]")
p.add_argument("--tol", type=float, required=True, help="relative tolerance")
p.add_argument("--deflection", type=float, default=0.01, help="target tip deflection / L")
p.add_argument("--extra", default="", help="more dmhs options (one string), e.g. the sub-steps")
p.add_argument("--energy-tol", type=float, default=0.0,
               help="frequency mode: also require |E(t) - E(0)| <= this x max potential energy, with "
                    "E = kinetic + potential - work of the tip load")
a = p.parse_args()

r0, m, n_clamp = 1e-4, 2e-5, 1
k_s = 2 * a.K
EI = 0.5 * k_s * r0**3 + 2 * a.ka * r0
kGA = 8 * a.ka / r0
mu = 2 * m / r0
L = (a.n - n_clamp) * r0
wb = 1.8751**2 * math.sqrt(EI / (mu * L**4))
ws = 0.5 * math.pi * math.sqrt(kGA / (mu * L**2))
w1_beam = 1 / math.sqrt(1 / wb**2 + 1 / ws**2)
# the lattice lumps a whole column (2m) at the tip where the continuous beam has
# half a cell (m): an extra tip mass m on the modal mass 0.2427 mu L of mode 1
w1 = w1_beam / math.sqrt(1 + m / (0.2427 * mu * L))
bend, shear = L**3 / (3 * EI), L / kGA
F = a.deflection * L / (bend + shear)

os.makedirs(a.outdir, exist_ok=True)
if a.mode == "static":
    gamma = w1  # every underdamped mode decays as exp(-gamma t/2)
    t_end = 30 / gamma
    out_dt = t_end / 200
else:
    gamma = 0.0
    t_end = 6 * 2 * math.pi / w1
    out_dt = (2 * math.pi / w1) / 200
cmd = [a.exe, "-scene", "cantilever", "-cantilever_n", str(a.n), "-bond_k", repr(a.K), "-bond_r0", repr(r0),
       "-angle_k", repr(a.ka), "-cantilever_mass", repr(m), "-solid_load_force", f"0,{-F!r}",
       "-solid_damping", repr(gamma), "-t_end", repr(t_end), "-output_interval", repr(out_dt),
       "-output_dir", a.outdir, "-quiet"] + a.extra.split()
print(" ".join(cmd))
subprocess.run(cmd, check=True)

with open(os.path.join(a.outdir, "cantilever.csv")) as f:
    lines = [l for l in f if not l.startswith("#")]
data = np.genfromtxt(lines, delimiter=",", names=True)
t, w = data["t"], -data["tip_dy"]
if a.mode == "static":
    expect = F * (bend + shear)
    got = w[-1]
    tail = w[len(w) * 9 // 10:]
    print(f"n = {a.n}, L = {L:g} m, k_a = {a.ka:g} J: EI = {EI:.4g} N m^2 (layers {0.5*k_s*r0**3:.3g}, angles "
          f"{2*a.ka*r0:.3g}), kGA = {kGA:.4g} N")
    print(f"tip deflection: measured {got:.6g} m, Timoshenko {expect:.6g} m (bending {F*bend:.4g}, shear "
          f"{F*shear:.4g}: shear share {shear/(bend+shear):.1%}); relative error {(got-expect)/expect:+.3%}; "
          f"settled to {np.ptp(tail)/got:.1e}; tolerance {a.tol:.1%}")
    ok = abs(got - expect) <= a.tol * expect and np.ptp(tail) <= 1e-3 * got
else:
    # period from upward crossings of the mean (linear interpolation between samples)
    x = w - w.mean()
    up = [t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i]) for i in range(len(x) - 1) if x[i] < 0 <= x[i + 1]]
    periods = np.diff(up)
    got = 2 * math.pi / periods.mean()
    print(f"n = {a.n}, L = {L:g} m, k_a = {a.ka:g} J: first frequency measured {got:.6g} rad/s "
          f"({len(periods)} periods), beam theory {w1:.6g} rad/s (Dunkerley {w1_beam:.6g} of Euler-Bernoulli {wb:.6g} and shear beam {ws:.6g}, with the lumped tip mass); "
          f"relative error {(got-w1)/w1:+.3%}; tolerance {a.tol:.1%}")
    ok = abs(got - w1) <= a.tol * w1 and len(periods) >= 3
    if a.energy_tol > 0:
        # the load's work is in the potential (solid_load): E = kinetic + potential is conserved
        E = data["kinetic"] + data["potential"]
        scale = np.max(np.abs(data["kinetic"]))
        drift = np.max(np.abs(E - E[0])) / scale
        print(f"energy: max|E(t) - E(0)| = {drift:.3e} of the largest kinetic energy {scale:.4g} J over "
              f"{t[-1]:.4g} s; tolerance {a.energy_tol:.1e}")
        ok = ok and np.all(np.isfinite(E)) and scale > 0 and drift <= a.energy_tol
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
