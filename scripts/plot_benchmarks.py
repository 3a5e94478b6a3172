#!/usr/bin/python3
"""Charts from a `flexure bench` results file (schema: docs/hdf5-schema.md).

Usage (Debian's matplotlib and h5py):
  /usr/bin/python3 scripts/plot_benchmarks.py FILE.h5 [--out-dir DIR] [--table]
  /usr/bin/python3 scripts/plot_benchmarks.py FILE.h5 --out FIG.png    # = flexure plot FILE.h5 --out FIG.png
  /usr/bin/python3 scripts/plot_benchmarks.py FILE.h5 --print-prbm-map

Figures written to --out-dir (default: a folder bench_figures beside FILE.h5; the committed figures
in docs/figures are replaced only when that folder is named), each path printed:
  bench_pareto.png     accuracy against time per problem, one point per method and resolution
                       (worst relative error over the converged loads against the median time per
                       solve); the Pareto front (no other method both faster and more accurate)
                       is joined by a line.
  bench_stability.png  stability maps over the load plane (n, alpha2) of cantilever_force: colour
                       = log10 relative error, x = no converged solution (status 1 or 2).
  bench_column.png     post_buckled_column: error of every method along the load path (a
                       method that lands on the mirror-image branch shows an error near 1).
  bench_prbm_map.png   PRBM relative error over (n, alpha2) with the validity limit
                       Theta = Theta_max (Howell Table 5.1) drawn as a line.
The figures are drawn by the package behind `flexure plot` (python/flexure_plot/bench.py); this
script keeps only its options and the tables. Every axis names its quantity and its unit in
brackets, read from the datasets' `units` attributes ([–]: dimensionless). --table prints a Markdown table per problem (docs/benchmarks.md);
--print-prbm-map prints the
rows of the accuracy map used by `--method auto`, in the format of data/method_auto_error_map.csv
(the header row and one row per load; the file's comment block stays as it is).
"""
import argparse
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from flexure_plot import bench  # noqa: E402
from flexure_plot._common import Recorder, save_figure, style  # noqa: E402

FIGURES = (("bench_pareto.png", bench.draw_pareto), ("bench_stability.png", bench.draw_stability),
           ("bench_prbm_map.png", bench.draw_prbm_map), ("bench_column.png", bench.draw_column))


def print_table(f):
    for problem in f:
        print(f"\n**{problem}** ({f[problem].attrs['description']})\n")
        print("| method | converged | worst rel. error | median time [s] |")
        print("|---|---|---|---|")
        for method in f[problem]:
            conv, total, worst, t = bench.summary(f[problem][method])
            w = "n/a" if not math.isfinite(worst) else f"{worst:.1e}"
            print(f"| {method} | {conv}/{total} | {w} | {t:.2e} |")


def print_prbm_map(f):
    g = f["cantilever_force"]["prbm"]
    ns, als, err, _, _ = bench.load_plane(g)

    def up(x):  # round UP to two significant digits: the map never understates the error
        p = 10 ** (math.floor(math.log10(x)) - 1)
        return math.ceil(x / p) * p

    print("n,alpha2,error")
    for i, n in enumerate(ns):
        for j, a in enumerate(als):
            print(f"{n:g},{a:g},{up(err[i, j]):.2g}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file")
    ap.add_argument("--out-dir", default=None,
                    help="folder for the figures (default: bench_figures beside FILE)")
    ap.add_argument("--out", default=None,
                    help="one figure file (.png, .pdf, .svg): that of `flexure plot FILE`")
    ap.add_argument("--table", action="store_true")
    ap.add_argument("--print-prbm-map", action="store_true")
    args = ap.parse_args()
    if args.out:
        # --out is a figure file, as for every plot script and `flexure plot` (docs/cli.md).
        if os.path.isdir(args.out):
            print(f"plot_benchmarks.py: error: --out {args.out} is a folder; --out names one figure "
                  "file (.png, .pdf, .svg), --out-dir the folder of the figures", file=sys.stderr)
            return 2
        from flexure_plot import PlotError, plot_file
        try:
            result = plot_file(args.file, args.out, expect_kind="bench")
        except PlotError as e:
            print(f"plot_benchmarks.py: error: {e}", file=sys.stderr)
            return e.exit_code
        print(f"wrote {os.path.realpath(result['out'])}")
        return 0
    with h5py.File(args.file, "r") as f:
        if args.print_prbm_map:
            print_prbm_map(f)
            return 0
        out = args.out_dir or os.path.join(os.path.dirname(os.path.abspath(args.file)),
                                       "bench_figures")
        os.makedirs(out, exist_ok=True)
        style(plt)
        for name, draw in FIGURES:
            fig = draw(f, plt, Recorder())
            if fig is None:  # the file lacks the problem this figure shows
                continue
            path = os.path.join(out, name)
            save_figure(fig, path)
            plt.close(fig)
            print(f"wrote {path}")
        if args.table:
            print_table(f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
