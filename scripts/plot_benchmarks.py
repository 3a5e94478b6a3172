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
Every axis names its quantity and its unit in brackets, read from the datasets' `units` attributes
([1]: dimensionless). --table prints a Markdown table per problem (docs/benchmarks.md);
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
import numpy as np  # noqa: E402

CONVERGED = 0


def unit(g, name, default="1"):
    """The `units` attribute of dataset `name` in group `g` (`default` for files written before
    flexure stored units)."""
    if name not in g:
        return default
    value = g[name].attrs.get("units", default)
    return value.decode() if isinstance(value, bytes) else str(value)


def first_group(f, problem):
    """Any method group of `problem` (all groups of a problem have the same datasets)."""
    return next(iter(f[problem].values()))


def validity(g):
    """Per-load PRBM validity (1 within, 0 outside, -1 not a PRBM); before schema 2 the dataset
    was called inside_validity."""
    return g["within_validity"] if "within_validity" in g else g["inside_validity"]


def groups(f):
    for problem in f:
        for method in f[problem]:
            yield problem, method, f[problem][method]


def summary(g):
    """(converged, total, worst relative error, median seconds) of one group."""
    status = g["status"][:]
    err = g["error_relative"][:]
    ok = status == CONVERGED
    worst = float(np.max(err[ok])) if ok.any() else math.nan
    return int(ok.sum()), len(status), worst, float(np.median(g["seconds"][:]))


def family_style(method):
    if method.startswith("elliptic"):
        return "tab:blue", "o"
    if method.startswith("shooting_cvodes"):
        return "tab:orange", "s"
    if method.startswith("shooting_dopri"):
        return "tab:red", "D"
    if method.startswith("shooting_rk8pd"):
        return "tab:brown", "v"
    if method.startswith("chain"):
        return "tab:green", "^"
    if method.startswith("prbm"):
        return "tab:purple", "P"
    if method.startswith("calculix"):
        return "black", "*"
    return "gray", "."


def plot_pareto(f, out):
    problems = list(f)
    cols = 3
    rows = math.ceil(len(problems) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(12, 3.6 * rows), squeeze=False)
    for ax, problem in zip(axes.flat, problems):
        pts = []
        for method in f[problem]:
            if method == "reference":
                continue
            conv, total, worst, t = summary(f[problem][method])
            if conv == 0 or not math.isfinite(worst):
                continue
            worst = max(worst, 1e-16)  # the reference itself has error 0
            color, marker = family_style(method)
            hollow = conv < total  # some loads failed
            ax.scatter(t, worst, color=color, marker=marker,
                       facecolors="none" if hollow else color, s=30)
            pts.append((t, worst, method))
        pts.sort()
        front, best = [], math.inf
        for t, e, m in pts:
            if e < best:
                front.append((t, e, m))
                best = e
        if front:
            ax.plot([p[0] for p in front], [p[1] for p in front], "k--", lw=0.8)
            for t, e, m in front:
                ax.annotate(m.replace("shooting_", "").replace("_rtol", " "), (t, e),
                            fontsize=6, xytext=(3, 3), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(problem, fontsize=9)
        g = first_group(f, problem)
        ax.set_xlabel(f"median time per solve [{unit(g, 'seconds', 's')}]", fontsize=8)
        # cfm_stroke measures the slider force of a mechanism, not a beam tip.
        quantity = "force" if problem == "cfm_stroke" else "tip"
        ax.set_ylabel(f"worst relative {quantity} error [{unit(g, 'error_relative')}]", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(True, which="major", alpha=0.3)
    for ax in axes.flat[len(problems):]:
        ax.axis("off")
    handles = [plt.Line2D([], [], color=c, marker=m, ls="") for c, m in
               [family_style(x) for x in ("elliptic", "shooting_rk8pd", "shooting_cvodes",
                                          "shooting_dopri", "chain", "prbm", "calculix")]]
    fig.legend(handles, ["elliptic", "shooting rk8pd", "shooting CVODES",
                         "shooting Dormand-Prince", "chain", "PRBM", "CalculiX"], loc="lower right", fontsize=8)
    fig.suptitle("Accuracy against time (hollow: some loads failed; dashed: Pareto front)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bench_pareto.png"), dpi=80)
    plt.close(fig)


def load_plane(g):
    n = g["load_ratio_n"][:]
    a = g["alpha2"][:]
    ns = np.unique(n)
    als = np.unique(a)
    err = np.full((len(ns), len(als)), np.nan)
    failed = np.zeros_like(err, dtype=bool)
    inside = np.zeros_like(err)
    for k in range(len(n)):
        i = np.searchsorted(ns, n[k])
        j = np.searchsorted(als, a[k])
        s = g["status"][k]
        if s == CONVERGED:
            err[i, j] = max(g["error_relative"][k], 1e-16)
        elif s in (1, 2):
            failed[i, j] = True
        inside[i, j] = validity(g)[k]
    return ns, als, err, failed, inside


def plot_stability(f, out, problem="cantilever_force"):
    if problem not in f:
        return
    wanted = [m for m in ("elliptic", "shooting_rk8pd_rtol1e-06", "shooting_cvodes_rtol1e-06",
                          "shooting_cvodes_rtol1e-09", "chain_N010_inc01", "chain_N010_inc20",
                          "chain_N050_inc05", "chain_N200_inc05", "prbm") if m in f[problem]]
    if not wanted:
        wanted = [m for m in f[problem] if m != "reference"][:9]
    cols = 3
    rows = math.ceil(len(wanted) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(11, 3.2 * rows), squeeze=False)
    fig.subplots_adjust(hspace=0.55, right=0.85)
    for ax, method in zip(axes.flat, wanted):
        ns, als, err, failed, _ = load_plane(f[problem][method])
        im = ax.pcolormesh(np.arange(len(als) + 1), np.arange(len(ns) + 1),
                           np.log10(err), vmin=-14, vmax=0, cmap="viridis", shading="flat")
        fi, fj = np.nonzero(failed)
        ax.scatter(fj + 0.5, fi + 0.5, marker="x", color="red", s=40)
        ax.set_xticks(np.arange(len(als)) + 0.5)
        ax.set_xticklabels([f"{a:g}" for a in als], fontsize=6)
        ax.set_yticks(np.arange(len(ns)) + 0.5)
        ax.set_yticklabels([f"{n:g}" for n in ns], fontsize=7)
        g = f[problem][method]
        ax.set_xlabel(f"alpha2 = P l^2/EI [{unit(g, 'alpha2')}]", fontsize=8)
        ax.set_ylabel(f"load ratio n [{unit(g, 'load_ratio_n')}]", fontsize=8)
        ax.set_title(method, fontsize=9)
    for ax in axes.flat[len(wanted):]:
        ax.axis("off")
    fig.colorbar(im, cax=fig.add_axes([0.88, 0.15, 0.02, 0.7]),
                 label="log10 of the relative tip error [1]")
    fig.suptitle(f"{problem}: error over the load plane (red x: failed)", fontsize=10)
    fig.savefig(os.path.join(out, "bench_stability.png"), dpi=80)
    plt.close(fig)


def plot_column(f, out, problem="post_buckled_column"):
    """Stability along the post-buckled column's load path: error against P = n alpha2."""
    if problem not in f:
        return
    fig, ax = plt.subplots(figsize=(7, 3.6))
    for method in f[problem]:
        if method == "reference":
            continue
        g = f[problem][method]
        P = g["load_ratio_n"][:] * g["alpha2"][:]
        err = np.maximum(g["error_relative"][:], 1e-16)
        status = g["status"][:]
        color, marker = family_style(method)
        ok = status == CONVERGED
        ax.plot(P[ok], err[ok], marker=marker, color=color, ms=3, lw=0.5, alpha=0.6)
        bad = (status == 1) | (status == 2)
        ax.scatter(P[bad], np.full(bad.sum(), 30.0), marker="x", color=color, s=25)
    ax.axvline(math.pi ** 2 / 4, color="gray", ls=":", lw=1)
    ax.text(math.pi ** 2 / 4, 1e-15, " Euler load", fontsize=7, color="gray")
    ax.set_yscale("log")
    ax.set_ylim(1e-16, 100)
    g = first_group(f, problem)
    ax.set_xlabel(f"axial compression n alpha2 = n P l^2/EI, n = 50 [{unit(g, 'alpha2')}]")
    ax.set_ylabel(f"relative tip error [{unit(g, 'error_relative')}]")
    ax.set_title("post-buckled column: error ~1 = another equilibrium branch; x at top = failed",
                 fontsize=9)
    handles = [plt.Line2D([], [], color=c, marker=m, ls="") for c, m in
               [family_style(x) for x in ("elliptic", "shooting_rk8pd", "shooting_cvodes",
                                          "shooting_dopri", "chain", "prbm")]]
    ax.legend(handles, ["elliptic", "shooting rk8pd", "shooting CVODES",
                        "shooting Dormand-Prince", "chain",
                        "PRBM"], fontsize=7, loc="center right")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bench_column.png"), dpi=80)
    plt.close(fig)


def plot_prbm_map(f, out, problem="cantilever_force"):
    if problem not in f or "prbm" not in f[problem]:
        return
    ns, als, err, failed, inside = load_plane(f[problem]["prbm"])
    fig, ax = plt.subplots(figsize=(7, 3.6))
    im = ax.pcolormesh(np.arange(len(als) + 1), np.arange(len(ns) + 1), 100 * err,
                       cmap="magma_r", vmin=0, vmax=10, shading="flat")
    for i in range(len(ns)):
        for j in range(len(als)):
            if np.isfinite(err[i, j]):
                ax.text(j + 0.5, i + 0.5, f"{100 * err[i, j]:.1f}", ha="center", va="center",
                        fontsize=6, color="white" if err[i, j] > 0.05 else "black")
        # Validity limit: the cell edge after the last load inside Theta_max.
        last = np.nonzero(inside[i] == 1)[0]
        edge = (last[-1] + 1) if len(last) else 0
        ax.plot([edge, edge], [i, i + 1], color="cyan", lw=2.5)
    ax.set_xticks(np.arange(len(als)) + 0.5)
    ax.set_xticklabels([f"{a:g}" for a in als], fontsize=7)
    ax.set_yticks(np.arange(len(ns)) + 0.5)
    ax.set_yticklabels([f"{n:g}" for n in ns], fontsize=7)
    g = f[problem]["prbm"]
    ax.set_xlabel(f"alpha2 = P l^2/EI [{unit(g, 'alpha2')}]")
    ax.set_ylabel(f"load ratio n [{unit(g, 'load_ratio_n')}]")
    fig.colorbar(im, ax=ax, label="relative tip error [%]")
    ax.set_title("PRBM fixed-pinned (Table 5.1): error [%]; cyan: Theta_max limit", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bench_prbm_map.png"), dpi=80)
    plt.close(fig)


def print_table(f):
    for problem in f:
        print(f"\n**{problem}** ({f[problem].attrs['description']})\n")
        print("| method | converged | worst rel. error | median time [s] |")
        print("|---|---|---|---|")
        for method in f[problem]:
            conv, total, worst, t = summary(f[problem][method])
            w = "n/a" if not math.isfinite(worst) else f"{worst:.1e}"
            print(f"| {method} | {conv}/{total} | {w} | {t:.2e} |")


def print_prbm_map(f):
    g = f["cantilever_force"]["prbm"]
    ns, als, err, _, _ = load_plane(g)

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
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                        "python"))
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
        plot_pareto(f, out)
        plot_stability(f, out)
        plot_prbm_map(f, out)
        plot_column(f, out)
        for name in ("bench_pareto.png", "bench_stability.png", "bench_prbm_map.png",
                     "bench_column.png"):
            path = os.path.join(out, name)
            if os.path.exists(path):
                print(f"wrote {path}")
        if args.table:
            print_table(f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
