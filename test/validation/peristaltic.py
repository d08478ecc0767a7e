#!/usr/bin/python3
"""Peristaltic channel against Shapiro, Jaffrin & Weinberg's flux
(test/validation/peristaltic.cmake, doc/validation.md).

  peristaltic.py --exe DMHS --opts OPTS --outdir DIR [--extra "OPTIONS"]
                 [--ranks N --mpirun "CMD"] [--compare REF_DIR] [--tol 0.05]
                 [--max-rho-dev 0.05] [--max-mach 0.1]
runs dmhs into DIR and asserts: it exits 0; DIR/flux.csv exists, is not
empty, has exactly the header cycle,t,Q_mean,Q_theory, at least one row (a
completed wave period), rows numbered 1, 2, ... with increasing t, every value
finite, Q_theory > 0; the last period's |Q_mean/Q_theory - 1| <= --tol; the
run's final report gives max |rho/rho0 - 1| <= --max-rho-dev and Mach <=
--max-mach. With --compare, DIR/flux.csv must be byte for byte REF_DIR's.
  peristaltic.py --check FLUX_CSV [--tol T]   only the file checks above.
  peristaltic.py --selftest                   the checks fail on bad files.
Exit status 0 on success, 1 on any failure.
"""
import argparse, filecmp, math, os, re, subprocess, sys, tempfile

HEADER = "cycle,t,Q_mean,Q_theory"


class CheckError(Exception):
    pass


def check_flux(path, tol):
    """The rows of flux.csv as floats; raises CheckError on any defect."""
    if not os.path.isfile(path):
        raise CheckError(f"{path}: missing")
    with open(path) as f:
        lines = f.read().splitlines()
    if not lines:
        raise CheckError(f"{path}: empty")
    if lines[0] != HEADER:
        raise CheckError(f"{path}: header {lines[0]!r}, expected {HEADER!r}")
    rows = []
    for n, line in enumerate(lines[1:], start=2):
        cells = line.split(",")
        if len(cells) != 4:
            raise CheckError(f"{path}:{n}: {len(cells)} values, expected 4")
        try:
            r = [float(c) for c in cells]
        except ValueError:
            raise CheckError(f"{path}:{n}: not a number: {line!r}")
        if not all(math.isfinite(v) for v in r):
            raise CheckError(f"{path}:{n}: non-finite value: {line!r}")
        rows.append(r)
    if not rows:
        raise CheckError(f"{path}: no completed wave period (no row)")
    for k, r in enumerate(rows, start=1):
        if r[0] != k:
            raise CheckError(f"{path}: row {k} is cycle {r[0]:g}")
        if k > 1 and not r[1] > rows[k - 2][1]:
            raise CheckError(f"{path}: t does not increase at cycle {k}")
        if not r[3] > 0:
            raise CheckError(f"{path}: Q_theory = {r[3]:g} at cycle {k}")
    last = rows[-1]
    err = last[2] / last[3] - 1.0
    print(f"{path}: period {int(last[0])} (t = {last[1]:g} s): Q_mean = {last[2]:.6g}, "
          f"Q_theory = {last[3]:.6g} m^2/s, relative error {100 * err:+.2f} % (tolerance {100 * tol:g} %)")
    if not abs(err) <= tol:
        raise CheckError(f"{path}: |Q_mean/Q_theory - 1| = {abs(err):.4g} > {tol:g}")
    return rows


def check_bounds(log, max_rho_dev, max_mach):
    m = re.search(r"max \|rho/rho0 - 1\| = (\S+), max Mach = (\S+)", log)
    if not m:
        raise CheckError("the run printed no density / Mach report")
    rho_dev, mach = float(m.group(1).rstrip(",")), float(m.group(2))
    print(f"over the run: max |rho/rho0 - 1| = {rho_dev:.3g} (<= {max_rho_dev:g}), "
          f"max Mach = {mach:.3g} (<= {max_mach:g})")
    if not (math.isfinite(rho_dev) and rho_dev <= max_rho_dev):
        raise CheckError(f"density deviation {rho_dev:g} > {max_rho_dev:g}")
    if not (math.isfinite(mach) and mach <= max_mach):
        raise CheckError(f"Mach number {mach:g} > {max_mach:g}")


def selftest():
    good = HEADER + "\n1,40,6.5e-07,6.666666667e-07\n"
    cases = {"missing": None, "empty": "", "header": "cycle,t,Q,Q_theory\n1,40,1,1\n",
             "no period": HEADER + "\n", "nan": HEADER + "\n1,40,nan,6.6e-07\n",
             "inf": HEADER + "\n1,40,6.5e-07,inf\n", "short row": HEADER + "\n1,40,6.5e-07\n",
             "text": HEADER + "\n1,40,abc,6.6e-07\n", "off": HEADER + "\n1,40,5e-07,6.666666667e-07\n",
             "cycle order": HEADER + "\n2,40,6.5e-07,6.666666667e-07\n"}
    with tempfile.TemporaryDirectory() as d:
        p = os.path.join(d, "flux.csv")
        with open(p, "w") as f:
            f.write(good)
        check_flux(p, 0.05)  # must pass
        for name, text in cases.items():
            if os.path.exists(p):
                os.remove(p)
            if text is not None:
                with open(p, "w") as f:
                    f.write(text)
            try:
                check_flux(p, 0.05)
            except CheckError as e:
                print(f"selftest {name}: refused as it should be ({e})")
                continue
            raise CheckError(f"selftest {name}: the check accepted a bad file")
        try:
            check_bounds("no report here", 0.05, 0.1)
            raise CheckError("selftest: a log without the report was accepted")
        except CheckError as e:
            if "selftest" in str(e):
                raise
    print("selftest: OK")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe")
    ap.add_argument("--opts")
    ap.add_argument("--outdir")
    ap.add_argument("--extra", default="")
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--compare")
    ap.add_argument("--tol", type=float, default=0.05)
    ap.add_argument("--max-rho-dev", type=float, default=0.05)
    ap.add_argument("--max-mach", type=float, default=0.1)
    ap.add_argument("--check")
    ap.add_argument("--selftest", action="store_true")
    a = ap.parse_args()
    if a.selftest:
        selftest()
        return
    if a.check:
        check_flux(a.check, a.tol)
        return
    if not (a.exe and a.opts and a.outdir):
        raise CheckError("give --exe, --opts and --outdir (or --check, --selftest)")
    os.makedirs(a.outdir, exist_ok=True)
    flux = os.path.join(a.outdir, "flux.csv")
    if os.path.exists(flux):
        os.remove(flux)  # a file of an earlier run would pass for this one's
    cmd = [a.exe, "-options_file", a.opts, "-output_dir", a.outdir, "-quiet"] + a.extra.split()
    if a.ranks > 1:
        cmd = a.mpirun.split() + ["-n", str(a.ranks)] + cmd
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(a.outdir, "run.log"), "w") as f:
        f.write(p.stdout)
    print(p.stdout[-2000:])
    if p.returncode != 0:
        raise CheckError(f"dmhs exited with {p.returncode}: {' '.join(cmd)}")
    check_flux(flux, a.tol)
    check_bounds(p.stdout, a.max_rho_dev, a.max_mach)
    if a.compare:
        ref = os.path.join(a.compare, "flux.csv")
        if not os.path.isfile(ref):
            raise CheckError(f"{ref}: missing (the reference run)")
        if not filecmp.cmp(flux, ref, shallow=False):
            raise CheckError(f"{flux} differs from {ref} (the rank count changed the result)")
        print(f"{flux}: identical to {ref}")
    print("OK")


if __name__ == "__main__":
    try:
        main()
    except CheckError as e:
        print("FAIL:", e)
        sys.exit(1)
