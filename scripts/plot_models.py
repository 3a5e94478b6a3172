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
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

LEVELS = (1e-4, 1e-3, 1e-2)  # 0.01 %, 0.1 %, 1 % of the length
LABELS = {1e-4: "0.01 %", 1e-3: "0.1 %", 1e-2: "1 %"}
COLOURS = {1e-4: "white", 1e-3: "orange", 1e-2: "red"}


def unit(dataset):
    value = dataset.attrs.get("units", "1")
    return value.decode() if isinstance(value, bytes) else str(value)


def label(f, name, text):
    return f"{text} [{unit(f[name])}]"


# The ladder's order, cheapest model first (docs/models.md).
LADDER = ("linear", "prbm", "prbm3r", "bcm", "cbcm", "chain", "shooting", "elliptic")


def models(f):
    """The model groups of the file in the ladder's order (any unknown one last)."""
    names = [name for name in f if isinstance(f[name], h5py.Group) and name != "reference"]
    return sorted(names, key=lambda n: LADDER.index(n) if n in LADDER else len(LADDER))


def plane(f, n_value):
    """(x name, y name, index function): the 2-D slice of the grid the maps show."""
    third = "tip_angle" if "tip_angle" in f else "mu"
    n = f["n"][:]
    if len(f[third]) > 1 or len(n) == 1:
        i = int(np.argmin(np.abs(n - n_value)))
        return "alpha2", third, (lambda a: a[i, :, :]), f"n = {n[i]:g}"
    return "alpha2", "n", (lambda a: a[:, :, 0].T), f"{third} = {f[third][0]:g}"


def plot_error_maps(f, path, n_value):
    names = models(f)
    xname, yname, take, fixed = plane(f, n_value)
    x, y = f[xname][:], f[yname][:]
    columns = min(3, len(names))
    rows = math.ceil(len(names) / columns)
    fig, axes = plt.subplots(rows, columns, figsize=(4.2 * columns, 3.6 * rows), squeeze=False)
    for ax in axes.flat[len(names):]:
        ax.set_visible(False)
    for ax, name in zip(axes.flat, names):
        g = f[name]
        error = take(g["position_error"][:]).T  # rows: y, columns: x
        status = take(g["status"][:]).T
        with np.errstate(divide="ignore"):
            logged = np.log10(np.where(error > 0, error, 1e-16))
        logged = np.where(status == 0, logged, np.nan)
        if len(x) > 1 and len(y) > 1:
            mesh = ax.pcolormesh(x, y, logged, shading="nearest", cmap="viridis", vmin=-8, vmax=0)
            finite = np.isfinite(logged)
            inside = [v for v in LEVELS
                      if finite.any() and np.nanmin(logged) < math.log10(v) < np.nanmax(logged)]
            if finite.sum() > 3 and inside:
                contours = ax.contour(x, y, np.where(finite, logged, 1.0),
                                      levels=[math.log10(v) for v in inside],
                                      colors=[COLOURS[v] for v in inside], linewidths=1.0)
                ax.clabel(contours, fmt={math.log10(v): LABELS[v] for v in inside}, fontsize=7)
            bad = np.argwhere(status != 0)
            if len(bad):
                ax.plot(x[bad[:, 1]], y[bad[:, 0]], "x", color="black", markersize=3)
            cb = fig.colorbar(mesh, ax=ax)
            cb.set_label("log10 position error per length [1]")
        settings = g.attrs.get("settings", "")
        settings = settings.decode() if isinstance(settings, bytes) else settings
        ax.set_title(f"{name} {settings}".strip(), fontsize=9)
        ax.set_xlabel(label(f, xname, xname))
        ax.set_ylabel(label(f, yname, yname))
    fig.suptitle(f"tip position error against the exact solution ({fixed}, "
                 f"{f.attrs['boundary']} end)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_error_time(f, path):
    fig, ax = plt.subplots(figsize=(7, 5))
    for k, name in enumerate(models(f)):
        g = f[name]
        ok = g["status"][:] == 0
        error = np.maximum(g["position_error"][:][ok], 1e-16)
        seconds = g["seconds"][:][ok]
        if not len(error):
            continue
        colour = f"C{k % 10}"
        ax.scatter(seconds, error, s=3, alpha=0.25, color=colour)
        ax.scatter([np.median(seconds)], [np.median(error)], s=80, color=colour,
                   edgecolor="black", label=name, zorder=3)
    for v in LEVELS:
        ax.axhline(v, color="grey", linewidth=0.6, linestyle=":")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(f"time per solve [{unit(f[models(f)[0] + '/seconds'])}]")
    ax.set_ylabel("tip position error per length [1]")
    ax.set_title(f"error against time ({f.attrs['boundary']} end; large markers: medians)",
                 fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


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
    ap.add_argument("--n", type=float, default=0.0, help="the load ratio of the maps' plane")
    ap.add_argument("--table", action="store_true")
    args = ap.parse_args()
    if args.out:
        # --out is a figure file, as for every plot script and `flexure plot` (docs/cli.md).
        if os.path.isdir(args.out):
            print(f"plot_models.py: error: --out {args.out} is a folder; --out names one figure "
                  "file (.png, .pdf, .svg), --out-dir the folder of the figures", file=sys.stderr)
            return 2
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                        "python"))
        from flexure_plot import PlotError, plot_file
        try:
            result = plot_file(args.file, args.out, expect_kind="models-map")
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
        plot_error_maps(f, maps, args.n)
        plot_error_time(f, chart)
        print(f"wrote {maps}")
        print(f"wrote {chart}")
        if args.table:
            print_table(f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
