"""The charts of a `flexure bench` file that docs/benchmarks.md shows (scripts/plot_benchmarks.py
writes them; `flexure plot FILE.h5` draws the one-page summary, studies.draw_bench):

  draw_pareto     accuracy against time per problem, one point per method and resolution (the
                  worst relative error over the converged loads against the median time per
                  solve; hollow where some loads failed), the Pareto front joined by a line;
  draw_stability  the error over the load plane (n, alpha2) of cantilever_force per method;
  draw_prbm_map   the PRBM's error over (n, alpha2) with its validity limit Theta_max (Howell
                  Table 5.1);
  draw_column     post_buckled_column: every method's error along the load path.

Each returns a figure, or None when the file lacks the problem. Every axis names its quantity and
its unit from the datasets' `units` attributes; text is 9 pt or more; legends sit beside the axes.
"""
import math

import numpy as np

from ._common import label, legend_beside

CONVERGED = 0

FAMILIES = (("elliptic", "tab:blue", "o", "elliptic"),
            ("shooting_rk8pd", "tab:brown", "v", "shooting rk8pd"),
            ("shooting_cvodes", "tab:orange", "s", "shooting CVODES"),
            ("shooting_dopri", "tab:red", "D", "shooting Dormand-Prince"),
            ("chain", "tab:green", "^", "chain"),
            ("prbm", "tab:purple", "P", "PRBM"),
            ("calculix", "black", "*", "CalculiX"))


def family_style(method):
    for prefix, colour, marker, _ in FAMILIES:
        if method.startswith(prefix):
            return colour, marker
    return "gray", "."


def unit_of(g, name, default="1"):
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


def summary(g):
    """(converged, total, worst relative error, median seconds) of one group."""
    status = g["status"][:]
    err = g["error_relative"][:]
    ok = status == CONVERGED
    worst = float(np.max(err[ok])) if ok.any() else math.nan
    return int(ok.sum()), len(status), worst, float(np.median(g["seconds"][:]))


def load_plane(g):
    """(n values, alpha2 values, error, failed, validity) of a group over the load plane."""
    n = g["load_ratio_n"][:]
    a = g["alpha2"][:]
    ns = np.unique(n)
    als = np.unique(a)
    err = np.full((len(ns), len(als)), np.nan)
    failed = np.zeros_like(err, dtype=bool)
    inside = np.zeros_like(err)
    status = g["status"][:]
    error = g["error_relative"][:]
    valid = validity(g)[:]
    for k in range(len(n)):
        i = np.searchsorted(ns, n[k])
        j = np.searchsorted(als, a[k])
        if status[k] == CONVERGED:
            err[i, j] = max(error[k], 1e-16)
        elif status[k] in (1, 2):
            failed[i, j] = True
        inside[i, j] = valid[k]
    return ns, als, err, failed, inside


def _family_legend(fig, plt, families=None):
    shown = [x for x in FAMILIES if families is None or x[0] in families]
    handles = [plt.Line2D([], [], color=c, marker=m, ls="") for _, c, m, _ in shown]
    fig.legend(handles, [name for *_, name in shown], loc="center left",
               bbox_to_anchor=(1.0, 0.5))


def draw_pareto(f, plt, rec):
    problems = list(f)
    cols = 3
    rows = math.ceil(len(problems) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(14, 4.2 * rows), squeeze=False)
    for ax, problem in zip(axes.flat, problems):
        pts = []
        for method in f[problem]:
            if method == "reference":
                continue
            conv, total, worst, t = summary(f[problem][method])
            if conv == 0 or not math.isfinite(worst):
                continue
            worst = max(worst, 1e-16)  # the reference itself has error 0
            colour, marker = family_style(method)
            hollow = conv < total  # some loads failed
            ax.scatter(t, worst, color=colour, marker=marker,
                       facecolors="none" if hollow else colour, s=36)
            rec.values(f"pareto:{problem}:{method}", [t, worst],
                       label="median time per solve, worst relative error")
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
                            fontsize=9, xytext=(3, 3), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(problem)
        g = first_group(f, problem)
        ax.set_xlabel(label("median time per solve", unit_of(g, "seconds", "s")))
        # cfm_stroke measures the slider force of a mechanism, not a beam tip.
        quantity = "force" if problem == "cfm_stroke" else "tip"
        ax.set_ylabel(label(f"worst relative {quantity} error", unit_of(g, "error_relative")))
        ax.grid(True, which="major", alpha=0.3)
    for ax in axes.flat[len(problems):]:
        ax.axis("off")
    _family_legend(fig, plt)
    fig.suptitle("Accuracy against time (hollow: some loads failed; dashed: Pareto front)")
    fig.tight_layout()
    return fig


def draw_stability(f, plt, rec, problem="cantilever_force"):
    if problem not in f:
        return None
    wanted = [m for m in ("elliptic", "shooting_rk8pd_rtol1e-06", "shooting_cvodes_rtol1e-06",
                          "shooting_cvodes_rtol1e-09", "chain_N010_inc01", "chain_N010_inc20",
                          "chain_N050_inc05", "chain_N200_inc05", "prbm") if m in f[problem]]
    if not wanted:
        wanted = [m for m in f[problem] if m != "reference"][:9]
    cols = 3
    rows = math.ceil(len(wanted) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(14, 4.0 * rows), squeeze=False)
    fig.subplots_adjust(hspace=0.6, wspace=0.35, right=0.85)
    im = None
    for ax, method in zip(axes.flat, wanted):
        g = f[problem][method]
        ns, als, err, failed, _ = load_plane(g)
        rec.grid(f"stability:{method}", als, ns, err, label=method)
        im = ax.pcolormesh(np.arange(len(als) + 1), np.arange(len(ns) + 1),
                           np.log10(err), vmin=-14, vmax=0, cmap="viridis", shading="flat")
        fi, fj = np.nonzero(failed)
        ax.scatter(fj + 0.5, fi + 0.5, marker="x", color="red", s=40)
        ax.set_xticks(np.arange(len(als)) + 0.5)
        ax.set_xticklabels([f"{a:g}" for a in als], rotation=90)
        ax.set_yticks(np.arange(len(ns)) + 0.5)
        ax.set_yticklabels([f"{n:g}" for n in ns])
        ax.set_xlabel(label("alpha2 = P l²/EI", unit_of(g, "alpha2")))
        ax.set_ylabel(label("load ratio n", unit_of(g, "load_ratio_n")))
        ax.set_title(method)
    for ax in axes.flat[len(wanted):]:
        ax.axis("off")
    if im is not None:
        fig.colorbar(im, cax=fig.add_axes([0.88, 0.15, 0.02, 0.7]),
                     label=label("log10 of the relative tip error", "1"))
    fig.suptitle(f"{problem}: error over the load plane (red x: failed)")
    return fig


def draw_column(f, plt, rec, problem="post_buckled_column"):
    """Stability along the post-buckled column's load path: error against P = n alpha2."""
    if problem not in f:
        return None
    fig, ax = plt.subplots(figsize=(9, 4.5))
    families = set()
    for method in f[problem]:
        if method == "reference":
            continue
        g = f[problem][method]
        P = g["load_ratio_n"][:] * g["alpha2"][:]
        err = np.maximum(g["error_relative"][:], 1e-16)
        status = g["status"][:]
        colour, marker = family_style(method)
        families.update(p for p, *_ in FAMILIES if method.startswith(p))
        ok = status == CONVERGED
        rec.line(ax, P[ok], err[ok], marker=marker, color=colour, ms=3, lw=0.5, alpha=0.6,
                 panel=f"column:{method}")
        bad = (status == 1) | (status == 2)
        ax.scatter(P[bad], np.full(bad.sum(), 30.0), marker="x", color=colour, s=25)
    ax.axvline(math.pi ** 2 / 4, color="gray", ls=":", lw=1)
    ax.text(math.pi ** 2 / 4, 1e-15, " Euler load", fontsize=9, color="gray")
    ax.set_yscale("log")
    ax.set_ylim(1e-16, 100)
    g = first_group(f, problem)
    ax.set_xlabel(label("axial compression n alpha2 = n P l²/EI, n = 50", unit_of(g, "alpha2")))
    ax.set_ylabel(label("relative tip error", unit_of(g, "error_relative")))
    ax.set_title("post-buckled column: error ~1 = another equilibrium branch; x at top = failed")
    _family_legend(fig, plt, families)
    fig.tight_layout()
    return fig


def draw_prbm_map(f, plt, rec, problem="cantilever_force"):
    if problem not in f or "prbm" not in f[problem]:
        return None
    g = f[problem]["prbm"]
    ns, als, err, failed, inside = load_plane(g)
    rec.grid("prbm_map", als, ns, err, label="prbm")
    fig, ax = plt.subplots(figsize=(11, 4.8))
    im = ax.pcolormesh(np.arange(len(als) + 1), np.arange(len(ns) + 1), 100 * err,
                       cmap="magma_r", vmin=0, vmax=10, shading="flat")
    for i in range(len(ns)):
        for j in range(len(als)):
            if np.isfinite(err[i, j]):
                ax.text(j + 0.5, i + 0.5, f"{100 * err[i, j]:.1f}", ha="center", va="center",
                        fontsize=9, color="white" if err[i, j] > 0.05 else "black")
        # Validity limit: the cell edge after the last load inside Theta_max.
        last = np.nonzero(inside[i] == 1)[0]
        edge = (last[-1] + 1) if len(last) else 0
        ax.plot([edge, edge], [i, i + 1], color="cyan", lw=2.5)
    ax.set_xticks(np.arange(len(als)) + 0.5)
    ax.set_xticklabels([f"{a:g}" for a in als])
    ax.set_yticks(np.arange(len(ns)) + 0.5)
    ax.set_yticklabels([f"{n:g}" for n in ns])
    ax.set_xlabel(label("alpha2 = P l²/EI", unit_of(g, "alpha2")))
    ax.set_ylabel(label("load ratio n", unit_of(g, "load_ratio_n")))
    fig.colorbar(im, ax=ax, label=label("relative tip error", "%"))
    ax.set_title("PRBM fixed-pinned (Table 5.1): error in %; cyan: Theta_max limit")
    fig.tight_layout()
    return fig
