"""Beam files: `flexure sweep beam` (tip quantities against the load), `flexure path` (load factor
against the tip, stable and unstable stretches, limit and bifurcation points; the deformed shapes
at several load levels and their animation; under displacement control the support's force
against the moved coordinate with its zeros and extrema, docs/paths.md) and `flexure validate`
(docs/hdf5-schema.md)."""
import numpy as np

from ._common import PlotError, attr, display, label, legend_beside, unit

# Howell's nondimensional names (docs/units.md).
NAMES = {
    "alpha2": "alpha2 = P l²/EI",
    "load_ratio_n": "load ratio n",
    "mu": "mu = M l/EI",
    "theta0": "tip angle theta0",
    "b_over_l": "tip deflection b/l",
    "a_over_l": "tip coordinate a/l",
}


def _name(name):
    return NAMES.get(name, name)


def draw_sweep(f, plt, rec):
    axes_names = [a for a in str(attr(f, "axes", "")).split(",") if a]
    shape = f["b_over_l"].shape
    if len(shape) == 1:
        x_name = "alpha2"
        x_ds = f["alpha2"]
        columns = [(None, np.arange(shape[0]))]
    elif len(shape) == 2 and len(axes_names) == 2:
        x_name = axes_names[0]
        x_ds = f["axes/" + x_name]
        second = f["axes/" + axes_names[1]][()]
        picks = np.unique(np.linspace(0, len(second) - 1, min(len(second), 7)).round().astype(int))
        columns = [(second[j], np.arange(shape[0]) * shape[1] + j) for j in picks]
    else:
        raise PlotError("sweep with an unexpected shape " + str(shape))
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    x = x_ds[()]
    x_src = x_ds.name.lstrip("/")
    quantities = ("a_over_l", "b_over_l", "theta0")
    stability = f["stability"][()].ravel() if "stability" in f else None
    for ax, q in zip(axes, quantities):
        values = f[q][()].ravel()
        for k, (value, flat) in enumerate(columns):
            lab = "" if value is None else f"{_name(axes_names[1])} = {value:g}"
            rec.line(ax, x, values[flat], "o-", ms=3, color=f"C{k}", label=lab,
                     x_src=(x_src, np.arange(len(x))), y_src=(q, flat), panel=q)
            if stability is not None:
                bad = flat[stability[flat] == 1]
                if len(bad):
                    pos = bad if len(shape) == 1 else bad // shape[1]
                    ax.plot(x[pos], values[bad], "x", color="C3", ms=7, mew=1.5,
                            label="unstable" if k == 0 else None)
        ax.set_xlabel(label(_name(x_name), unit(x_ds)))
        ax.set_ylabel(label(_name(q), unit(f[q])))
        ax.grid(True, alpha=0.3)
    legend_beside(axes[-1])
    method = attr(f, "method", "")
    fixed = []
    for key in ("load_ratio_n", "mu"):
        if key in f.attrs and key not in axes_names:
            fixed.append(f"{_name(key)} = {float(f.attrs[key]):g}")
    fig.suptitle(f"sweep beam ({method}){': ' if fixed else ''}{', '.join(fixed)}; "
                 "P is the whole tip force", fontsize=11)
    fig.tight_layout()
    return fig


def _runs(codes):
    """Consecutive runs of the stability classes: stable (0), unstable (1), other (not judged,
    critical points alone belong to the stretch around them). Each run shares its first point
    with the previous run so the curve stays continuous."""
    cls = np.where(codes == 0, 0, np.where(codes == 1, 1, np.where(codes == 2, -1, 2)))
    # A critical point (2) takes the class of the point after it (or before, at the end).
    for i in range(len(cls) - 1, -1, -1):
        if cls[i] == -1:
            cls[i] = cls[i + 1] if i + 1 < len(cls) else (cls[i - 1] if i > 0 else 0)
    runs = []
    start = 0
    for i in range(1, len(cls) + 1):
        if i == len(cls) or cls[i] != cls[start]:
            runs.append((cls[start], max(0, start - 1) if runs else start, i))
            start = i
    return runs


STYLE = {0: ("-", "C0", "stable"), 1: ("--", "C3", "unstable"), 2: (":", "0.4", "not judged")}


def draw_path(f, plt, rec):
    if attr(f, "control", "load") in CONTROLLED:
        return draw_controlled_path(f, plt, rec)
    lam = f["load_factor"][()]
    codes = f["stability"][()] if "stability" in f else np.full(len(lam), 4)
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5))
    axes = axes.ravel()
    tips = ("tip_y", "tip_x", "tip_theta")
    names = {"tip_x": "tip x", "tip_y": "tip y", "tip_theta": "tip angle"}
    sp = f["special_points"]
    kinds = [k.decode() if isinstance(k, bytes) else str(k) for k in sp["kind"][()]] \
        if "kind" in sp else []
    for ax, q in zip(axes, tips):
        scale, shown = display(f[q])
        values = f[q][()]
        seen = set()
        for cls, a, b in _runs(codes):
            line, colour, lab = STYLE[cls]
            idx = np.arange(a, b)
            rec.line(ax, values[idx], lam[idx], line, color=colour, lw=1.8,
                     label=lab if cls not in seen else None, x_src=(q, idx),
                     y_src=("load_factor", idx), x_scale=scale, panel=q)
            seen.add(cls)
        for kind, marker, colour, lab in (("limit_point", "v", "C1", "limit point"),
                                          ("bifurcation", "D", "C2", "bifurcation")):
            pick = np.array([i for i, k in enumerate(kinds) if k == kind], dtype=int)
            if len(pick):
                rec.line(ax, sp[q][()][pick], sp["load_factor"][()][pick], marker, color=colour,
                         ms=8, ls="none", label=lab, x_src=("special_points/" + q, pick),
                         y_src=("special_points/load_factor", pick), x_scale=scale,
                         panel=q + ":" + kind)
        ax.set_xlabel(label(names[q], shown))
        ax.set_ylabel(label("load factor lambda", unit(f["load_factor"])))
        ax.grid(True, alpha=0.3)
    legend_beside(axes[0])
    _draw_shapes(f, plt, rec, axes[3], lambda r: f"lambda = {lam[r]:.3g}")
    units = attr(f, "units", "")
    loads = _full_load(f)
    fig.suptitle(f"path ({attr(f, 'method', '')}, {attr(f, 'boundary', '')} end, {units} units)"
                 f"{loads}: {attr(f, 'limit_points', 0)} limit point(s), "
                 f"{attr(f, 'bifurcation_points', 0)} bifurcation(s)", fontsize=11)
    fig.tight_layout()
    return fig


def _draw_shapes(f, plt, rec, shape_ax, level):
    """The deformed shapes at six path points (`level(row)` names each), or a note."""
    if "shapes/x" not in f:
        shape_ax.axis("off")
        shape_ax.text(0.0, 0.5, "no shapes stored (flexure path --shapes K)", fontsize=10)
        return
    lam = f["load_factor"][()]
    branch = f["branch"][()] if "branch" in f else np.zeros(len(lam), dtype=int)
    x, y = f["shapes/x"][()], f["shapes/y"][()]
    scale, shown = display(f["shapes/x"])
    cmap = plt.get_cmap("viridis")
    for r in _shape_rows(len(lam)):
        flat = r * x.shape[1] + np.arange(x.shape[1])
        rec.line(shape_ax, x[r], y[r], "-", color=cmap(r / max(1, len(lam) - 1)),
                 label=level(r) + (f" (branch {branch[r]})" if branch[r] else ""),
                 x_src=("shapes/x", flat), y_src=("shapes/y", flat), x_scale=scale,
                 y_scale=scale, panel="shapes")
    shape_ax.set_aspect("equal", adjustable="datalim")
    shape_ax.set_xlabel(label("x", shown))
    shape_ax.set_ylabel(label("y", shown))
    shape_ax.set_title("deformed shapes")
    shape_ax.grid(True, alpha=0.3)
    legend_beside(shape_ax)


# --control: the moved coordinate and the support's load conjugate to it (docs/paths.md).
CONTROLLED = {"tip-x": ("tip_x", "tip_Fx", "tip x", "Fx"),
              "tip-y": ("tip_y", "tip_Fy", "tip y", "Fy"),
              "tip-angle": ("tip_theta", "tip_M", "tip angle", "M")}

# Markers of /force_points: a zero of the force is an equilibrium with the coordinate released,
# stable where the force restores (df/dc > 0 with a stable displacement-controlled state,
# docs/paths.md "Force points"); an extremum is a limit point under force control.
FORCE_MARKS = (
    ("force_zero", lambda s: s > 0, "o", "C2", "force zero, df/dc > 0: stable when released"),
    ("force_zero", lambda s: s < 0, "o", "C3", "force zero, df/dc < 0: unstable when released"),
    ("force_zero", lambda s: ~np.isfinite(s) | (s == 0), "o", "0.5",
     "force zero, slope not computed"),
    ("force_maximum", None, "^", "C1", "force maximum (limit under force control)"),
    ("force_minimum", None, "v", "C1", "force minimum (limit under force control)"),
)


def draw_controlled_path(f, plt, rec):
    """A displacement-controlled path (`flexure path --control`): the support's load on the moved
    coordinate against that coordinate, the force points of /force_points marked, the located
    limit and bifurcation points of /special_points, and the deformed shapes where stored."""
    control = attr(f, "control")
    c_name, f_name, c_label, f_label = CONTROLLED[control]
    c_ds, f_ds = f[c_name], f[f_name]
    coordinate, force = c_ds[()], f_ds[()]
    lam = f["load_factor"][()]
    codes = f["stability"][()] if "stability" in f else np.full(len(lam), 4)
    has_shapes = "shapes/x" in f
    fig, axes = plt.subplots(1, 2 if has_shapes else 1, figsize=(15 if has_shapes else 9, 5.5),
                             squeeze=False)
    ax = axes[0, 0]
    c_scale, c_shown = display(c_ds)
    f_scale, f_shown = display(f_ds)
    seen = set()
    for cls, a, b in _runs(codes):
        line, colour, lab = STYLE[cls]
        if cls == 2:  # nothing judged (extensible chains): the curve itself, solid
            line, colour, lab = "-", "C0", "path (stability not checked)"
        idx = np.arange(a, b)
        rec.line(ax, coordinate[idx], force[idx], line, color=colour, lw=1.8,
                 label=lab if cls not in seen else None, x_src=(c_name, idx), y_src=(f_name, idx),
                 x_scale=c_scale, y_scale=f_scale, panel="force")
        seen.add(cls)
    ax.axhline(0.0, color="0.5", lw=0.8)
    sp = f["special_points"]
    sp_kinds = [k.decode() if isinstance(k, bytes) else str(k) for k in sp["kind"][()]] \
        if "kind" in sp else []
    # Drawn first, large and hollow: a force point at the same place (the force's corner at a
    # bifurcation where the path switched branch) stays visible inside.
    for kind, marker, colour, lab in (("limit_point", "s", "C4", "fold of the travel (limit point)"),
                                      ("bifurcation", "D", "C9", "bifurcation")):
        pick = np.array([i for i, k in enumerate(sp_kinds) if k == kind], dtype=int)
        if len(pick):
            rec.line(ax, sp[c_name][()][pick], sp[f_name][()][pick], marker, color=colour, ms=15,
                     mfc="none", mew=2.0, ls="none", label=lab,
                     x_src=("special_points/" + c_name, pick),
                     y_src=("special_points/" + f_name, pick), x_scale=c_scale, y_scale=f_scale,
                     panel="special_points:" + kind)
    fp = f["force_points"] if "force_points" in f else None
    if fp is not None and len(fp["kind"]):
        kinds = [k.decode() if isinstance(k, bytes) else str(k) for k in fp["kind"][()]]
        slope = fp["slope"][()]
        for kind, chooses, marker, colour, lab in FORCE_MARKS:
            ok = np.array([k == kind for k in kinds])
            if chooses is not None:
                ok &= chooses(slope)
            pick = np.flatnonzero(ok)
            if len(pick):
                rec.line(ax, fp["coordinate"][()][pick], fp["force"][()][pick], marker,
                         color=colour, ms=9, ls="none", mec="k", mew=0.8, label=lab,
                         x_src=("force_points/coordinate", pick),
                         y_src=("force_points/force", pick), x_scale=c_scale, y_scale=f_scale,
                         panel="force_points:" + kind)
    ax.set_xlabel(label(f"{c_label}, prescribed ({c_name})", c_shown))
    ax.set_ylabel(label(f"support's {f_label} on the tip ({f_name})", f_shown))
    ax.grid(True, alpha=0.3)
    _travel_axis(f, ax, coordinate, c_scale, c_shown)
    legend_beside(ax, markerscale=0.7)
    if has_shapes:
        _draw_shapes(f, plt, rec, axes[0, 1],
                     lambda r: f"{c_label} = {coordinate[r] * c_scale:.4g} {c_shown}")
    target = attr(f, "control_target")
    to = f" to {float(target) * c_scale:.4g} {c_shown}" if target is not None else ""
    zeros = sum(1 for k in (fp["kind"][()] if fp is not None else []) if
                (k.decode() if isinstance(k, bytes) else str(k)) == "force_zero")
    fig.suptitle(f"path under displacement control ({attr(f, 'method', '')}, "
                 f"{attr(f, 'boundary', '')} end): {c_label} moved{to}; the force changes sign "
                 f"{zeros} time(s)", fontsize=11)
    fig.tight_layout()
    return fig


def _travel_axis(f, ax, coordinate, scale, shown):
    """A second x axis on top: the travel d from the start of the moving stage toward the target
    (d = (c - c0) sign(c1 - c0)), the displacement a designer reads."""
    target = attr(f, "control_target")
    stage = f["stage"][()] if "stage" in f else np.ones(len(coordinate), dtype=int)
    moving = np.flatnonzero(stage == stage.max()) if len(stage) else []
    if target is None or not len(moving):
        return
    c0 = float(coordinate[moving[0]])
    sign = 1.0 if float(target) >= c0 else -1.0
    if sign < 0:
        ax.invert_xaxis()  # the travel grows to the right
    top = ax.secondary_xaxis("top", functions=(lambda c: sign * (c - c0 * scale),
                                               lambda d: c0 * scale + sign * d))
    top.set_xlabel(label("travel d from the start toward the target", shown))


def _full_load(f):
    """The full tip load (lambda = 1) from the last row of a completed path: whole forces on
    the one beam."""
    last = len(f["load_factor"]) - 1
    if last < 0 or "tip_Fx" not in f or float(f["load_factor"][last]) != 1.0:
        return ""
    parts = []
    for q in ("tip_Fx", "tip_Fy", "tip_M"):
        v = float(f[q][last])
        if np.isfinite(v) and v != 0.0:
            u = unit(f[q])
            parts.append(f"{q[4:]} = {v:.4g}" + ("" if u == "1" else " " + u))
    return "; full tip load " + ", ".join(parts) if parts else ""


def _shape_rows(count, wanted=6):
    return np.unique(np.linspace(0, count - 1, min(count, wanted)).round().astype(int))


def animate_path(f, plt, out):
    if "shapes/x" not in f:
        raise PlotError(f"{f.filename} holds no deformed shapes: write the path with "
                        "`flexure path ... --shapes K` to animate it")
    from matplotlib import animation

    x, y = f["shapes/x"][()], f["shapes/y"][()]
    lam = f["load_factor"][()]
    scale, shown = display(f["shapes/x"])
    fig, ax = plt.subplots(figsize=(6, 5))
    finite = np.isfinite(x) & np.isfinite(y)
    lo = min(x[finite].min(), y[finite].min()) * scale
    hi = max(x[finite].max(), y[finite].max()) * scale
    pad = 0.05 * (hi - lo + 1e-12)
    ax.set_xlim(lo - pad, hi + pad)
    ax.set_ylim(lo - pad, hi + pad)
    ax.set_aspect("equal")
    ax.set_xlabel(label("x", shown))
    ax.set_ylabel(label("y", shown))
    ax.grid(True, alpha=0.3)
    (line,) = ax.plot([], [], "-", color="C0", lw=2)
    title = ax.set_title("")

    moved = CONTROLLED.get(attr(f, "control", "load"))
    c_scale, c_shown = display(f[moved[0]]) if moved else (1.0, "")

    def frame(k):
        line.set_data(x[k] * scale, y[k] * scale)
        if moved:  # displacement control: the moved coordinate and the support's load
            c = f[moved[0]][k] * c_scale
            load = f[moved[1]][k] * display(f[moved[1]])[0]
            title.set_text(f"{moved[2]} = {c:.4g} {c_shown}, {moved[3]} = {load:.4g} "
                           f"{display(f[moved[1]])[1]} (point {k + 1} of {len(lam)})")
        else:
            title.set_text(f"load factor lambda = {lam[k]:.4g} (point {k + 1} of {len(lam)})")
        return line, title

    anim = animation.FuncAnimation(fig, frame, frames=len(lam), blit=False)
    anim.save(out, writer=animation.PillowWriter(fps=8))
    plt.close(fig)
    return len(lam)


def draw_validate(f, plt, rec):
    err = f["rel_error"][()]
    tol = f["tolerance"][()]
    methods = [m.decode() if isinstance(m, bytes) else str(m) for m in f["method"][()]]
    passed = f["passed"][()]
    fig, ax = plt.subplots(figsize=(12, 4.5))
    rows = np.arange(len(err))
    for k, m in enumerate(sorted(set(methods))):
        idx = np.array([i for i in rows if methods[i] == m])
        rec.line(ax, idx, err[idx], "o", ms=4, color=f"C{k}", ls="none", label=m,
                 y_src=("rel_error", idx), panel="rel_error")
    rec.line(ax, rows, tol, "_", color="k", ms=8, ls="none", label="tolerance",
             y_src=("tolerance", rows), panel="tolerance")
    bad = rows[passed == 0]
    if len(bad):
        ax.plot(bad, np.where(np.isfinite(err[bad]), err[bad], tol[bad]), "x", color="C3", ms=9,
                label="failed")
    ax.set_yscale("log")
    ax.set_xlabel("check (row of the file: problem x method x quantity)")
    ax.set_ylabel(label("relative error", unit(f["rel_error"])))
    ax.grid(True, alpha=0.3)
    legend_beside(ax)
    fig.suptitle(f"validate: {int(passed.sum())} of {len(passed)} checks passed", fontsize=11)
    fig.tight_layout()
    return fig
