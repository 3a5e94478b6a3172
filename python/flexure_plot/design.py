"""Design files: `flexure map cfm` (design-space maps of Xi' and Phi with contours over R and the
stroke d; docs/design.md "Design-space maps"), `flexure design cfm --out` (the search's
convergence history) and `design cfm --all-subclasses --out` (the table of sub-classes)."""
import numpy as np

from ._common import attr, label, legend_beside, unit


def _axis_pick(f, name):
    """Index of the middle of an axis that the map does not show."""
    n = len(f[name])
    return n // 2


def draw_cfm_map(f, plt, rec):
    R, d, K1, K2 = (f[a][()] for a in ("R", "d", "K1", "K2"))
    i1, i2 = _axis_pick(f, "K1"), _axis_pick(f, "K2")
    quantities = [("percent_constant_force", "PRBM Xi'"), ("Phi", "PRBM mean Phi = F r2/k1")]
    if "percent_constant_force_exact" in f:
        quantities += [("percent_constant_force_exact", "exact Xi'"),
                       ("max_force_error", "largest PRBM force error")]
    rows = (len(quantities) + 1) // 2
    fig, axes = plt.subplots(rows, 2, figsize=(11.5, 4.6 * rows), squeeze=False)
    axes = axes.reshape(1, -1)
    shape = f["Phi"].shape
    status = f["status"][:, :, i1, i2]
    for ax, (q, name) in zip(axes[0], quantities):
        z = f[q][:, :, i1, i2]  # [R, d]
        flat = (np.arange(shape[0])[:, None] * shape[1] + np.arange(shape[1])[None, :]) \
            * shape[2] * shape[3] + i1 * shape[3] + i2
        shown = np.where(status == 0, z, np.nan).T  # rows: d, columns: R
        rec.grid(q, R, d, z.T, x_src="R", y_src="d", z_src=(q, flat.T), label=name)
        if len(R) > 1 and len(d) > 1:
            mesh = ax.pcolormesh(R, d, shown, shading="nearest", cmap="viridis")
            cb = fig.colorbar(mesh, ax=ax)
            cb.set_label(label(name, unit(f[q])))
            if np.isfinite(shown).sum() > 3 and np.nanmax(shown) > np.nanmin(shown):
                c = ax.contour(R, d, np.where(np.isfinite(shown), shown, np.nanmin(shown)),
                               levels=6, colors="white", linewidths=0.8)
                ax.clabel(c, fontsize=9, fmt="%.3g")
            bad = np.argwhere(status.T != 0)
            if len(bad):
                ax.plot(R[bad[:, 1]], d[bad[:, 0]], "x", color="C3", ms=5, label="no answer")
        else:
            x, xn = (R, "R") if len(R) > 1 else (d, "d")
            ax.plot(x, shown.ravel(), "o-")
        ax.set_xlabel(label("R = r3/r2", unit(f["R"])))
        ax.set_ylabel(label("design stroke d", unit(f["d"]) + " of r2 + r3"))
        ax.set_title(name)
    fixed = []
    if len(K1) > 1 or K1[0] != 0:
        fixed.append(f"K1 = {K1[i1]:g}")
    if len(K2) > 1 or K2[0] != 0:
        fixed.append(f"K2 = {K2[i2]:g}")
    fig.suptitle(f"map cfm {attr(f, 'config', '')} ({attr(f, 'model', '')})"
                 f"{': ' + ', '.join(fixed) if fixed else ''}", fontsize=11)
    fig.tight_layout()
    return fig


def draw_history(f, plt, rec):
    g = f["history"]
    obj = g["objective"][()]
    feasible = g["feasible"][()]
    full = g["full_sampling"][()]
    k = np.arange(len(obj))
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.5))
    ax = axes[0]
    ok = k[feasible == 1]
    rec.line(ax, ok, obj[ok], "o", ms=3, ls="none", color="C0", label="feasible",
             y_src=("history/objective", ok), panel="objective")
    no = k[(feasible == 0) & (g["valid"][()] == 1)]
    rec.line(ax, no, obj[no], "x", ms=3, ls="none", color="0.6", label="infeasible",
             y_src=("history/objective", no), panel="objective")
    best = ok[full[ok] == 1]
    if len(best):
        objective = attr(f, "objective", "")
        sense = np.nanargmin if objective.startswith("min") else np.nanargmax
        b = best[sense(obj[best])]
        ax.plot([b], [obj[b]], "*", color="C3", ms=14, label="reported optimum")
    ax.set_xlabel("model evaluation (in order)")
    ax.set_ylabel(label(f"objective {attr(f, 'objective', '')}", unit(g["objective"])))
    ax.grid(True, alpha=0.3)
    legend_beside(ax)
    bx = axes[1]
    for key, colour in (("R", "C0"), ("K1", "C1"), ("K2", "C2")):
        v = g[key][()]
        if np.any(v != 0):
            rec.line(bx, ok, v[ok], "o", ms=3, ls="none", color=colour, label=key,
                     y_src=("history/" + key, ok), panel="design")
    bx.set_xlabel("model evaluation (in order)")
    bx.set_ylabel(label("design variable (feasible points)", "1"))
    bx.grid(True, alpha=0.3)
    legend_beside(bx)
    fig.suptitle(f"design cfm {attr(f, 'config', '')} at d = {attr(f, 'stroke_percent', '')} % "
                 f"of r2 + r3: the search ({len(obj)} evaluations)", fontsize=11)
    fig.tight_layout()
    return fig


def draw_table(f, plt, rec):
    names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["name"][()]]
    rows = np.arange(len(names))
    fig, axes = plt.subplots(1, 2, figsize=(13, max(4.0, 0.24 * len(names) + 1.5)), sharey=True)
    rec.line(axes[0], f["percent_constant_force"][()], rows, "o", ls="none", color="C0",
             label="PRBM optimum", x_src=("percent_constant_force", rows), panel="pcf")
    if "percent_constant_force_exact" in f:
        rec.line(axes[0], f["percent_constant_force_exact"][()], rows, "s", ls="none",
                 color="C1", label="exact optimum", x_src=("percent_constant_force_exact", rows),
                 panel="pcf")
    axes[0].set_xlabel(label("percent constant force Xi'", unit(f["percent_constant_force"])))
    for key, colour in (("R", "C0"), ("K1", "C1"), ("K2", "C2")):
        rec.line(axes[1], f[key][()], rows, "o", ls="none", color=colour, label=key,
                 x_src=(key, rows), panel="design")
    axes[1].set_xlabel(label("R, K1, K2", "1"))
    axes[0].set_yticks(rows)
    axes[0].set_yticklabels(names, fontsize=9)
    axes[0].invert_yaxis()
    for ax in axes:
        ax.grid(True, alpha=0.3)
        legend_beside(ax)
    fig.suptitle(f"design cfm --all-subclasses ({attr(f, 'model', '')}): {len(names)} sub-classes",
                 fontsize=11)
    fig.tight_layout()
    return fig
