#!/usr/bin/python3
"""plot_vein_convergence.py's stretch table, on two made-up runs whose values it
must reproduce: a coarse run (dx 0.4 mm, to t = 1 s) and a finer one (dx 0.2 mm,
stopped at t = 0.5 s, short of the cycle T = 4 s). The coarse inlet velocity is
0.75x the fine one's, its opening 1 mm more, so every difference is known.
  vein_stretch_check.py SCRIPT WORKDIR
Exit 0 when the table's rows, differences and stretch peak are those expected."""
import csv
import os
import subprocess
import sys

HEAD = ("t,u_mean,u_flux,tip_upper_x,tip_upper_y,tip_lower_x,tip_lower_y,gap,"
        "probe_stress,probe_disp")


def write_run(d, dx, t_last, u_scale, open_extra):
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "vein.csv"), "w") as f:
        f.write(f"# vein: leaflet 0.0256 m, g0 0.1 m/s^2, k_a 0.01 J (at dx = 1e-4 m), T 4. s, "
                f"dx {dx} m, rest gap 0.0012 m\n{HEAD}\n")
        n = int(round(t_last / 0.02))
        for k in range(1, n + 1):
            t = 0.02 * k
            u = u_scale * 0.04 * t
            gap = 2 * dx + 1e-3 * (1 + 4 * t) + open_extra
            f.write(f"{t:.6g},{u:.9g},{u:.9g},0.05,{gap / 2:.9g},0.05,{-gap / 2:.9g},{gap:.9g},,\n")


def main():
    script, work = sys.argv[1], sys.argv[2]
    coarse, fine = os.path.join(work, "coarse"), os.path.join(work, "fine")
    write_run(coarse, 4e-4, 1.0, 0.75, 1e-3)
    write_run(fine, 2e-4, 0.5, 1.0, 0.0)
    table = os.path.join(work, "stretch.csv")
    out = subprocess.run([sys.executable, script, coarse, fine, "--out", os.path.join(work, "c.png"),
                          "--stretch-csv", table, "--every", "0.1"],
                         capture_output=True, text=True)
    bad = []
    if out.returncode != 0:
        print(out.stdout + out.stderr)
        sys.exit(f"FAIL: {script} exited {out.returncode}")
    rows = list(csv.DictReader(open(table)))
    if [r["t"] for r in rows] != ["0.1", "0.2", "0.3", "0.4", "0.5"]:
        bad.append(f"sample times {[r['t'] for r in rows]}, expected 0.1 .. 0.5 (the shorter run's end)")
    for r in rows:
        t = float(r["t"])
        checks = (("u_dx0.0004", 0.75 * 0.04 * t), ("u_dx0.0002", 0.04 * t),
                  ("open_dx0.0004", 1e-3 * (2 + 4 * t)), ("open_dx0.0002", 1e-3 * (1 + 4 * t)))
        for key, want in checks:
            got = float(r.get(key, "nan"))
            if not abs(got - want) <= 1e-6 * max(abs(want), 1e-9) + 1e-12:
                bad.append(f"t = {t}: {key} = {got}, expected {want:.6g}")
    if "0.0060 (-25%)" not in out.stdout:
        bad.append("no '0.0060 (-25%)' (coarse inlet velocity at 0.2 s, 25 % below the fine one)")
    if "dx 0.2 mm: 0.0200 m/s at t = 0.500 s" not in out.stdout:
        bad.append("the fine run's stretch peak (0.0200 m/s at t = 0.5 s) not printed")
    if "dx 0.4 mm: 0.0150 m/s at t = 0.500 s" not in out.stdout:
        bad.append("the coarse run's stretch peak is not taken over the shorter run's stretch")
    if bad:
        print(out.stdout)
        sys.exit("FAIL:\n  " + "\n  ".join(bad))
    print("vein stretch table: 5 rows, values, differences and peaks as expected")


if __name__ == "__main__":
    main()
