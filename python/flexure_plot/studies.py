"""Study files: `flexure models map` (each model's error map over the load plane with the 1 %,
0.1 % and 0.01 % contours; docs/models.md), `flexure bench` (each method's worst error against
its time per solve, per problem; the cfm_stroke force; docs/benchmarks.md) and `flexure dynamics`
(the input force against the drive frequency and its history over one period; docs/dynamics.md)."""
import math

import numpy as np

from ._common import PlotError, attr, display, label, legend_beside, unit

LEVELS = (1e-4, 1e-3, 1e-2)
LEVEL_TEXT = {1e-4: "0.01 %", 1e-3: "0.1 %", 1e-2: "1 %"}
LADDER = ("linear", "prbm", "prbm3r", "bcm", "cbcm", "chain", "shooting", "elliptic")


def _model_groups(f):
    names = [n for n in f if hasattr(f[n], "keys") and n != "reference"]
    return sorted(names, key=lambda n: LADDER.index(n) if n in LADDER else len(LADDER))


def draw_models(f, plt, rec, n_value=None):
    """The maps over alpha2 x mu (free end) or alpha2 x tip_angle (guided) at the load ratio
    `n_value` (one of the file's n; None: the n nearest 0), or over alpha2 x n when the file has
    one mu or tip angle (then `n_value` is refused: the plane has every n)."""
    names = _model_groups(f)
    third = "tip_angle" if "tip_angle" in f else "mu"
    n = f["n"][()]
    shape = f[names[0] + "/position_error"].shape
    if n_value is not None and not np.isfinite(n_value):
        raise PlotError(f"plot: --n must be a finite number, got {n_value}")
    if len(f[third]) > 1 or len(n) == 1:
        i = int(np.argmin(np.abs(n - (0.0 if n_value is None else n_value))))
        if n_value is not None and abs(n[i] - n_value) > 1e-9 * max(1.0, abs(n_value)):
            raise PlotError(f"plot: --n {n_value:g} is not a load ratio of the map; its n: "
                            + ", ".join(f"{v:g}" for v in n))
        xname, yname = "alpha2", third
        flat = i * shape[1] * shape[2] + np.arange(shape[1])[None, :] * shape[2] \
            + np.arange(shape[2])[:, None]  # [y = third, x = alpha2]
        fixed = f"n = {n[i]:g}"
    elif n_value is not None:
        raise PlotError(f"plot: --n {n_value:g}: this map has one {third} ({f[third][0]:g}) and "
                        f"is drawn over alpha2 x n, every n at once; --n picks a plane only in a "
                        f"map with several {third} values")
    else:
        xname, yname = "alpha2", "n"
        flat = np.arange(shape[0])[:, None] * shape[1] * shape[2] \
            + np.arange(shape[1])[None, :] * shape[2]  # [y = n, x = alpha2], third index 0
        fixed = f"{third} = {f[third][0]:g}"
    x, y = f[xname][()], f[yname][()]
    columns = min(3, len(names))
    rows = math.ceil(len(names) / columns)
    fig, axes = plt.subplots(rows, columns, figsize=(5.2 * columns, 4.2 * rows), squeeze=False)
    for ax in axes.flat[len(names):]:
        ax.set_visible(False)
    for ax, name in zip(axes.flat, names):
        g = f[name]
        error = g["position_error"][()].ravel()[flat]
        status = g["status"][()].ravel()[flat]
        rec.grid(name, x, y, error, x_src=xname, y_src=yname,
                 z_src=(name + "/position_error", flat), label=name)
        with np.errstate(divide="ignore"):
            logged = np.log10(np.where(error > 0, error, 1e-16))
        logged = np.where(status == 0, logged, np.nan)
        if len(x) > 1 and len(y) > 1:
            mesh = ax.pcolormesh(x, y, logged, shading="nearest", cmap="viridis", vmin=-8, vmax=0)
            ok = np.isfinite(logged)
            inside = [v for v in LEVELS
                      if ok.any() and np.nanmin(logged) < math.log10(v) < np.nanmax(logged)]
            if ok.sum() > 3 and inside:
                c = ax.contour(x, y, np.where(ok, logged, 1.0),
                               levels=[math.log10(v) for v in inside], colors="white",
                               linewidths=1.0)
                ax.clabel(c, fmt={math.log10(v): LEVEL_TEXT[v] for v in inside}, fontsize=9)
            cb = fig.colorbar(mesh, ax=ax)
            cb.set_label(label("log10 position error per length", "1"))
        else:
            ax.semilogy(x if len(x) > 1 else y, np.where(status == 0, error, np.nan).ravel(), "o-")
        bad = np.argwhere(status != 0)
        if len(bad) and len(x) > 1 and len(y) > 1:
            ax.plot(x[bad[:, 1]], y[bad[:, 0]], "x", color="k", ms=4)
        ax.set_title(f"{name} {attr(g, 'settings', '')}".strip())
        ax.set_xlabel(label("alpha2 = P l²/EI", unit(f[xname])))
        ax.set_ylabel(label({"mu": "mu = M l/EI", "n": "load ratio n",
                             "tip_angle": "guided tip angle"}[yname], unit(f[yname])))
    fig.suptitle(f"tip position error against the exact solution ({fixed}, "
                 f"{attr(f, 'boundary', '')} end; x: no answer)", fontsize=11)
    fig.tight_layout()
    return fig



def draw_models_error_time(f, plt, rec):
    """Every model's tip error against its time per solve: a small point per load, a large marker
    at each model's medians (docs/models.md; scripts/plot_models.py writes it beside the maps)."""
    names = _model_groups(f)
    fig, ax = plt.subplots(figsize=(7, 5))
    for k, name in enumerate(names):
        g = f[name]
        ok = g["status"][()].ravel() == 0
        error = np.maximum(g["position_error"][()].ravel()[ok], 1e-16)
        seconds = g["seconds"][()].ravel()[ok]
        if not len(error):
            continue
        colour = f"C{k % 10}"
        ax.scatter(seconds, error, s=3, alpha=0.25, color=colour)
        medians = [float(np.median(seconds)), float(np.median(error))]
        ax.scatter([medians[0]], [medians[1]], s=80, color=colour, edgecolor="black", label=name,
                   zorder=3)
        rec.values(name, medians, label="median time per solve, median tip error per length")
    for v in LEVELS:
        ax.axhline(v, color="grey", linewidth=0.6, linestyle=":")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(label("time per solve", unit(f[names[0] + "/seconds"])))
    ax.set_ylabel(label("tip position error per length", "1"))
    ax.set_title(f"error against time ({attr(f, 'boundary', '')} end; large markers: medians)")
    legend_beside(ax)
    fig.tight_layout()
    return fig


def _family_colour(method):
    for k, fam in enumerate(("elliptic", "shooting_rk8pd", "shooting_cvodes", "shooting_dopri",
                             "chain", "prbm", "exact", "calculix")):
        if method.startswith(fam):
            return f"C{k}"
    return "0.3"


def draw_bench(f, plt, rec):
    problems = [p for p in f if hasattr(f[p], "keys")]
    panels = problems + (["cfm_stroke:force"] if "cfm_stroke" in problems else [])
    cols = min(3, len(panels))
    rows = math.ceil(len(panels) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(5.4 * cols, 4.2 * rows), squeeze=False)
    for ax in axes.flat[len(panels):]:
        ax.axis("off")
    for ax, panel in zip(axes.flat, panels):
        if panel == "cfm_stroke:force":
            g = f["cfm_stroke"]
            for k, method in enumerate(m for m in g if m != "reference"):
                d, force = g[method]["displacement"], g[method]["force"]
                xs, shown_x = display(d, "m")
                ys, shown_y = display(force, "N")
                idx = np.arange(len(d))
                rec.line(ax, d[()], force[()], "o-", ms=4, color=f"C{k}", label=method,
                         x_src=(f"cfm_stroke/{method}/displacement", idx),
                         y_src=(f"cfm_stroke/{method}/force", idx), x_scale=xs, y_scale=ys,
                         panel=panel)
                ax.set_xlabel(label("slider displacement Delta x", shown_x))
                ax.set_ylabel(label("slider force, one half", shown_y))
            ax.set_title(f"cfm_stroke: {attr(g, 'mechanism', '')}")
            ax.grid(True, alpha=0.3)
            legend_beside(ax)
            continue
        g = f[panel]
        for method in g:
            if method == "reference":
                continue
            m = g[method]
            ok = np.isin(m["status"][()], (0, 3)) & np.isfinite(m["error_relative"][()])
            if not ok.any():
                continue
            worst = max(float(np.nanmax(m["error_relative"][()][ok])), 1e-16)
            t = float(np.median(m["seconds"][()]))
            rec.line(ax, [t], [worst], "o", ms=6, color=_family_colour(method), ls="none",
                     label=method, panel=panel)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(panel)
        quantity = "force" if panel == "cfm_stroke" else "tip"
        ax.set_xlabel(label("median time per solve", "s"))
        ax.set_ylabel(label(f"worst relative {quantity} error", "1"))
        ax.grid(True, alpha=0.3)
        legend_beside(ax, fontsize=9)
    fig.suptitle("bench: accuracy against time per method" +
                 (" (quick set)" if int(f.attrs.get("quick", 0)) else ""), fontsize=11)
    fig.tight_layout()
    return fig


def draw_dynamics(files, plt, rec):
    """`files`: [(h5py.File, label)] with forces of the same thing (one half or the whole)."""
    f0 = files[0][0]
    force_of = attr(f0, "force_of", "whole symmetric mechanism")
    for f, _ in files[1:]:  # one force axis: every file's forces of the same thing
        other = attr(f, "force_of", "whole symmetric mechanism")
        if other != force_of:
            raise PlotError(f"plot: {f0.filename} has forces of the {force_of}, {f.filename} of "
                            f"the {other}: write them with the same --force-of")
    has_history = "history" in f0 and len(f0["history"]) > 0 and len(files) == 1
    fig, axes = plt.subplots(2 if has_history else 1, 3, figsize=(15, 8.5 if has_history else 4.5),
                             squeeze=False)
    fs, fu = display(f0["mean_force"], "N")
    quantities = (("mean_force", "mean force"), ("peak_to_peak_force", "peak-to-peak force"),
                  ("percent_constant_force", "percent constant force"))
    for ax, (key, name) in zip(axes[0], quantities):
        for k, (f, lab) in enumerate(files):
            idx = np.arange(len(f["omega"]))
            scale = 1.0 if key == "percent_constant_force" else fs
            rec.line(ax, f["omega"][()], f[key][()], "o-", ms=3, color=f"C{k}", label=lab,
                     x_src=("omega", idx), y_src=(key, idx), y_scale=scale, panel=key)
        ax.set_xlabel(label("drive frequency omega", unit(f0["omega"], "rad/s")))
        shown = "%" if key == "percent_constant_force" else fu
        ax.set_ylabel(label(name if key == "percent_constant_force" else f"{name}, {force_of}",
                            shown))
        ax.grid(True, alpha=0.3)
    if "static_nominal_force" in f0.attrs:
        axes[0, 0].axhline(float(f0.attrs["static_nominal_force"]) * fs, color="k", ls=":",
                           label="static nominal force")
    legend_beside(axes[0, 2])
    if len(files) > 1 or "static_nominal_force" in f0.attrs:
        legend_beside(axes[0, 0])
    if has_history:
        names = sorted(f0["history"], key=int)
        for ax, name in zip(axes[1], names[:3]):
            g = f0["history"][name]
            t = g["t"][()]
            period = t[-1] + (t[1] - t[0]) if len(t) > 1 else 1.0
            idx = np.arange(len(t))
            rec.line(ax, t / period, g["force"][()], "-", color="C0", label="dynamic",
                     y_src=(f"history/{name}/force", idx), y_scale=fs, panel="history" + name)
            rec.line(ax, t / period, g["static_force"][()], "--", color="C1", label="static",
                     y_src=(f"history/{name}/static_force", idx), y_scale=fs,
                     panel="history" + name)
            ax.set_title(f"omega = {float(g.attrs['omega']):.4g} rad/s")
            ax.set_xlabel(label("phase t / period", "1"))
            ax.set_ylabel(label(f"input force, {force_of}", fu))
            ax.grid(True, alpha=0.3)
        legend_beside(axes[1, min(2, len(names) - 1)])
        for ax in axes[1, len(names):]:
            ax.axis("off")
    fig.suptitle(f"dynamics of {attr(f0, 'mechanism', '')}: forces of the {force_of}",
                 fontsize=11)
    fig.tight_layout()
    return fig
