#!/usr/bin/env python3
"""One row of the stiff and extreme matrix (doc/stability.md).

  stiff_matrix.py --exe DMHS --outdir DIR --name NAME [--table FILE] [--expect REGEX] -- dmhs options...

1. The case with the automatic time step (-dt 0) must run to its end: exit 0,
   the summary line, no non-finite value in any CSV or HDF5 file.
2. The stability report of that run names the smallest limit L at t = 0; the
   same case at the fixed dt = 1.02 L must stop before step 0 with exit
   status 1 (dmhs's error exit; a crash or an abort is not a refusal), the
   report marking that limit EXCEEDED and the pre-flight error, and no
   non-finite value in its outputs.
With --table, appends "name,limit,value_s,dt_auto_s,dt_changes,steps,wall_s"
(the automatic run's figures) to FILE.
"""
import argparse
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
CHECK_FINITE = os.path.join(HERE, "..", "cli", "check_finite.py")


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def finite(outdir):
    r = subprocess.run([sys.executable, CHECK_FINITE, outdir], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"a non-finite value in {outdir}: {r.stdout.strip()} {r.stderr.strip()}")


def report_limits(out):
    """(name, value) of every line of the stability report"""
    limits = []
    for line in out.splitlines():
        m = re.match(r"^  (\S.{17}) (.*?)\s+([0-9.]+e[-+][0-9]+) s  dt/limit", line)
        if m:
            limits.append((m.group(1).strip(), float(m.group(3))))
    return limits


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--outdir", required=True)
    ap.add_argument("--name", required=True)
    ap.add_argument("--table")
    ap.add_argument("--expect", help="a regex the automatic run's output must match (e.g. no crossings)")
    ap.add_argument("opts", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    opts = [o for o in a.opts if o != "--"]

    auto = os.path.join(a.outdir, "auto")
    start = time.time()
    r = subprocess.run([a.exe] + opts + ["-dt", "0", "-quiet", "-output_dir", auto], capture_output=True, text=True)
    wall = time.time() - start
    out = r.stdout + r.stderr
    if r.returncode != 0 or "dmhs summary" not in out:
        print(out[-3000:])
        fail(f"{a.name}: the automatic-dt run did not reach its end (exit {r.returncode})")
    finite(auto)
    if a.expect and not re.search(a.expect, out.replace("\n", " ")):
        print(out[-3000:])
        fail(f"{a.name}: the automatic-dt run's output does not match /{a.expect}/")
    limits = report_limits(out)
    if not limits:
        fail(f"{a.name}: no stability report in the output")
    name, value = min(limits, key=lambda nv: nv[1])
    m = re.search(r"dt = ([0-9.e+-]+) s chosen automatically", out)
    steps = re.search(r", (\d+) steps to t = ", out)
    if not m or not steps:
        fail(f"{a.name}: no automatic dt or step count in the output")
    with open(os.path.join(auto, "dt.csv")) as f:
        changes = sum(1 for _ in f) - 2
    print(f"{a.name}: -dt 0 ran to the end in {wall:.1f} s, {steps.group(1)} steps; smallest limit at t = 0: "
          f"{name} {value:.4g} s; first dt {m.group(1)} s, {changes} changes (dt.csv)")

    fixed = os.path.join(a.outdir, "fixed")
    dt = 1.02 * value
    r = subprocess.run([a.exe] + opts + ["-dt", repr(dt), "-quiet", "-output_dir", fixed], capture_output=True,
                       text=True)
    out2 = r.stdout + r.stderr
    exceeded = [ln for ln in out2.splitlines() if ln.startswith("  " + name) and "EXCEEDED" in ln]
    if r.returncode != 1 or not exceeded or "pre-flight check failed" not in out2:
        print(out2[-3000:])
        fail(f"{a.name}: -dt {dt:.4g} (1.02 x the {name} limit) did not stop before step 0 naming it "
             f"(exit {r.returncode}, expected 1)")
    if os.path.isdir(fixed):
        finite(fixed)
    print(f"{a.name}: -dt {dt:.4g} s stopped before step 0: {exceeded[0].strip()}")
    if a.table:
        new = not os.path.exists(a.table)
        with open(a.table, "a") as f:
            if new:
                f.write("name,limit,value_s,dt_auto_s,dt_changes,steps,wall_s\n")
            f.write(f"{a.name},{name},{value:.6g},{m.group(1)},{changes},{steps.group(1)},{wall:.2f}\n")
    print("PASS")


if __name__ == "__main__":
    main()
