#!/usr/bin/python3
"""Charts from a `flexure models map` file (schema: docs/hdf5-schema.md "flexure models map").

Usage (Debian's matplotlib and h5py):
  /usr/bin/python3 scripts/plot_models.py FILE.h5 [--out-dir DIR] [--prefix NAME] [--n N] [--table]
  /usr/bin/python3 scripts/plot_models.py FILE.h5 --out FIG.png    # = flexure plot FILE.h5 --out FIG.png

Figures written to --out-dir (default: the folder of FILE.h5), each path printed:
  <prefix>_error_maps.png   per model, log10 of the tip position error per length over the load
                            plane, with the 1 %, 0.1 % and 0.01 % contours; x marks a point with
                            no answer (status 1 not converged, 2 not representable). The plane is
                            alpha2 x mu (free end) or alpha2 x tip_angle (guided) at the n closest
                            to --n (default 0); with one value on that axis, alpha2 x n.
  <prefix>_error_time.png   every model's error against its time per solve: one small point per
                            load and a large marker at the medians.
<prefix> defaults to the file's name without .h5. Every axis names its quantity and its unit in
brackets, read from the datasets' `units` attributes. --table prints a Markdown table per model
(docs/models.md): points answered, the share within 1 %, 0.1 % and 0.01 % of the length, the
largest and median error, the median time.
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# The figures are drawn by the package behind `flexure plot` (python/flexure_plot), as the maps of
# `flexure plot FILE.h5`; this script adds the error-against-time chart and the table.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from flexure_plot import studies  # noqa: E402
from flexure_plot._common import Recorder, save_figure, style  # noqa: E402


def models(f):
    """The model groups of the file in the ladder's order (any unknown one last)."""
    return studies._model_groups(f)


def print_table(f):
    print("| model | settings | answered | within 1 % | within 0.1 % | within 0.01 % | "
          "max error/l | median error/l | median time |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name in models(f):
        g = f[name]
        status = g["status"][:]
        error = g["position_error"][:][status == 0]
        total = status.size
        settings = g.attrs.get("settings", "")
        settings = settings.decode() if isinstance(settings, bytes) else settings
        if not len(error):
            print(f"| {name} | {settings} | 0 / {total} | | | | | | |")
            continue
        share = [f"{100.0 * np.mean(error <= v):.0f} %" for v in (1e-2, 1e-3, 1e-4)]
        seconds = np.median(g["seconds"][:][status == 0])
        print(f"| {name} | {settings} | {len(error)} / {total} | {share[0]} | {share[1]} | "
              f"{share[2]} | {error.max():.2g} | {np.median(error):.2g} | {seconds:.2g} s |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file")
    ap.add_argument("--out-dir", default=None, help="folder for the figures (default: FILE's)")
    ap.add_argument("--out", default=None,
                    help="one figure file (.png, .pdf, .svg): that of `flexure plot FILE`")
    ap.add_argument("--prefix", default=None, help="figure name prefix (default: FILE's stem)")
    ap.add_argument("--n", type=float, default=None,
                    help="the load ratio of the maps' plane (default: the file's n nearest 0)")
    ap.add_argument("--table", action="store_true")
    args = ap.parse_args()
    if args.out:
        # --out is a figure file, as for every plot script and `flexure plot` (docs/cli.md).
        if os.path.isdir(args.out):
            print(f"plot_models.py: error: --out {args.out} is a folder; --out names one figure "
                  "file (.png, .pdf, .svg), --out-dir the folder of the figures", file=sys.stderr)
            return 2
        from flexure_plot import PlotError, plot_file
        try:
            result = plot_file(args.file, args.out, n_value=args.n, expect_kind="models-map")
        except PlotError as e:
            print(f"plot_models.py: error: {e}", file=sys.stderr)
            return e.exit_code
        print(f"wrote {os.path.realpath(result['out'])}")
        return 0
    with h5py.File(args.file, "r") as f:
        if not str(f.attrs.get("schema", "")).startswith("flexure-models-map"):
            print(f"{args.file}: not a `flexure models map` file (no schema "
                  f"'flexure-models-map')", file=sys.stderr)
            return 2
        out = args.out_dir or os.path.dirname(os.path.abspath(args.file))
        os.makedirs(out, exist_ok=True)
        prefix = args.prefix or os.path.splitext(os.path.basename(args.file))[0]
        maps = os.path.join(out, f"{prefix}_error_maps.png")
        chart = os.path.join(out, f"{prefix}_error_time.png")
        style(plt)
        try:
            maps_figure = studies.draw_models(f, plt, Recorder(), args.n)
        except studies.PlotError as e:
            print(f"plot_models.py: error: {e}", file=sys.stderr)
            return e.exit_code
        save_figure(maps_figure, maps)
        save_figure(studies.draw_models_error_time(f, plt, Recorder()), chart)
        plt.close("all")
        print(f"wrote {maps}")
        print(f"wrote {chart}")
        if args.table:
            print_table(f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
