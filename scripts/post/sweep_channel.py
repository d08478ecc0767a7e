#!/usr/bin/python3
"""Error against run time: Poiseuille (or Couette) over resolution and time step.

  scripts/post/sweep_channel.py [--dmhs build/dmhs] [--case poiseuille] [--t-end 1]
                                [--work output/sweep] [--out DIR] [--table FILE]

Runs dmhs at 10x20, 20x40 and 40x80 liquid particles (h = 3 dx) with dt at
0.25, 0.5 and 0.9 of the viscous limit 0.125 (h/2)^2/nu, to --t-end, and
records the L2 error at the end and the wall-clock of the step loop. Writes
sweep_<case>.png (error against wall-clock, one line per resolution) into
--out (default: the --work directory, where the runs go; `--out doc/img`
replaces the figure of doc/validation.md) and prints a Markdown table (--table
also writes it to a file). Wall-clock is noisy on a shared machine: compare
ratios.
"""
import argparse
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

RESOLUTIONS = [(10, 20), (20, 40), (40, 80)]
DT_FRACTIONS = [0.25, 0.5, 0.9]
WIDTH, LENGTH, NU = 1e-3, 5e-4, 1e-6


def run(args, nx, ny, frac):
    dx = WIDTH / ny
    h = 3 * dx
    dt = frac * 0.125 * (h / 2) ** 2 / NU
    out = os.path.join(args.work, f"{args.case}_{nx}x{ny}_dt{frac}")
    cmd = [args.dmhs, "-options_file", f"input/{args.case}.opts", "-channel_nx", str(nx), "-channel_ny", str(ny),
           "-sph_h", repr(h), "-dt", repr(dt), "-t_end", repr(args.t_end), "-quiet", "-output_dir", out,
           "-output_interval", repr(args.t_end / 10), "-output_snapshots", "false", "-checkpoint_at_end", "false"]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "error.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    last = rows[-1]
    early = min(rows, key=lambda r: abs(float(r["t"]) - args.t_end / 10))
    return dict(nx=nx, ny=ny, dx=dx, dt=dt, frac=frac, l2=float(last["l2"]), linf=float(last["linf"]),
                wall=float(last["wall_s"]), steps=int(last["step"]), l2_early=float(early["l2"]),
                wall_early=float(early["wall_s"]))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dmhs", default="build/dmhs")
    ap.add_argument("--case", default="poiseuille", choices=["poiseuille", "couette"])
    ap.add_argument("--t-end", type=float, default=1.0)
    ap.add_argument("--work", default="output/sweep", help="directory of the runs (default: output/sweep)")
    ap.add_argument("--out", default=None, help="directory of sweep_<case>.png (default: the --work directory)")
    ap.add_argument("--table", default=None, help="write the Markdown table here (default: print only)")
    args = ap.parse_args()
    if args.out is None:
        args.out = args.work
    os.makedirs(args.out, exist_ok=True)
    results = []
    for nx, ny in RESOLUTIONS:
        for frac in DT_FRACTIONS:
            r = run(args, nx, ny, frac)
            print(f"{nx}x{ny} dt={r['dt']:.3g} ({frac} of limit): L2 {100 * r['l2']:.3g} %  wall {r['wall']:.2f} s",
                  file=sys.stderr)
            results.append(r)

    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key, wkey, t in ((axes[0], "l2_early", "wall_early", args.t_end / 10), (axes[1], "l2", "wall", args.t_end)):
        for nx, ny in RESOLUTIONS:
            rs = [r for r in results if r["nx"] == nx]
            ax.loglog([r[wkey] for r in rs], [100 * r[key] for r in rs], "o-", label=f"{nx} x {ny}")
            for r in rs:
                ax.annotate(f"{r['frac']}", (r[wkey], 100 * r[key]), fontsize=7, xytext=(3, 3),
                            textcoords="offset points")
        ax.set_xlabel(f"wall-clock to t = {t:g} s [s]")
        ax.set_ylabel(f"L2 error at t = {t:g} s [% of v_ref]")
        ax.legend()
    fig.suptitle(f"{args.case}: error against run time (labels: dt / viscous limit)")
    fig.tight_layout()
    png = os.path.join(args.out, f"sweep_{args.case}.png")
    fig.savefig(png, dpi=120)

    te, tl = f"{args.t_end / 10:g}", f"{args.t_end:g}"
    lines = [f"| particles | dx [m] | dt [s] | dt / limit | steps | L2 at {te} s [%] | wall to {te} s [s] | "
             f"L2 at {tl} s [%] | Linf at {tl} s [%] | wall to {tl} s [s] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        # 3 significant digits: the steady errors are now far below 1e-4 %
        lines.append(f"| {r['nx']} x {r['ny']} | {r['dx']:.3g} | {r['dt']:.3g} | {r['frac']} | {r['steps']} | "
                     f"{100 * r['l2_early']:.3g} | {r['wall_early']:.2f} | "
                     f"{100 * r['l2']:.3g} | {100 * r['linf']:.3g} | {r['wall']:.2f} |")
    table = "\n".join(lines) + "\n"
    print(table)
    if args.table:
        with open(args.table, "w") as f:
            f.write(f"# Error against run time: the {args.case} sweep\n\n"
                    f"Every run of `scripts/post/sweep_channel.py --case {args.case}` (resolution, dt as a "
                    f"fraction of its stability limit), its error against the series solution and its wall "
                    f"time; the figure and what it shows: [validation.md](validation.md#error-against-run-time).\n\n")
            f.write(table)
    print(f"plot: {png}", file=sys.stderr)


if __name__ == "__main__":
    main()
