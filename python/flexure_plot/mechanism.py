"""Mechanism files: `flexure mechanism analyze --out` (the stroke: slider force of the PRBM and of
the exact model, the PRBM's force error, the stress of every flexure against the yield strength,
the stretch outside the PRBM's validity shaded; the deformed half mechanism at rest and at several
stroke points where the file holds the exact model's shapes, /shapes, and their animation),
`mechanism validate --out` (the table of designs)
and `mechanism tolerance --out` (distributions over the sampled designs; docs/tolerance.md)."""
import math

import numpy as np

from ._common import PlotError, attr, display, finite, label, legend_beside, unit


def _flag(f, name):
    v = f.attrs.get(name)
    return v is not None and int(v) != 0


def _pcf_note(f, model):
    if _flag(f, f"force_changes_sign_{model}"):
        return " (force changes sign)"
    if _flag(f, f"force_vanishes_{model}"):
        return " (force vanishes)"
    return ""


def draw_analyze(f, plt, rec, stress=True):
    dx_ds = f["displacement"]
    dx = dx_ds[()]
    length_scale, length_unit = display(dx_ds, "m")
    force_scale, force_unit = display(f["force_prbm"], "N")
    force_of = attr(f, "force_of", "one half")  # files before the attribute: one half
    exact = f["force_exact"][()] if "force_exact" in f else None
    stresses = [(p, m) for p in (1, 2, 3) for m in ("prbm", "exact")
                if f"stress_{m}_pivot{p}" in f]
    stress_panel = stress and bool(stresses)
    panels = 1 + (exact is not None) + stress_panel
    has_shapes = "shapes/x" in f
    fig = plt.figure(figsize=(16.5 if has_shapes else 8.5, 2.0 + 3.0 * max(panels, 2 if has_shapes
                                                                          else 1)))
    grid = fig.add_gridspec(panels, 2 if has_shapes else 1,
                            width_ratios=(1.0, 0.9) if has_shapes else None)
    axes = [fig.add_subplot(grid[0, 0])]
    for r in range(1, panels):
        axes.append(fig.add_subplot(grid[r, 0], sharex=axes[0]))
    for a in axes[:-1]:
        a.tick_params(labelbottom=False)
    ax = axes[0]
    k = np.arange(len(dx))
    rec.line(ax, dx, f["force_prbm"][()], "o-", ms=3, label="PRBM", x_src=("displacement", k),
             y_src=("force_prbm", k), x_scale=length_scale, y_scale=force_scale, panel="force")
    if exact is not None:
        rec.line(ax, dx, exact, "s-", ms=3, label="exact (elastica)", x_src=("displacement", k),
                 y_src=("force_exact", k), x_scale=length_scale, y_scale=force_scale,
                 panel="force")
    ax.set_ylabel(label(f"slider force F, {force_of}", force_unit))
    ax.grid(True, alpha=0.3)
    row = 1
    if exact is not None:
        err = 100.0 * (f["force_prbm"][()] - exact) / exact
        rec.line(axes[row], dx, err, "o-", ms=3, color="C2", x_src=("displacement", k),
                 x_scale=length_scale, panel="force_error", label="PRBM - exact")
        axes[row].axhline(0.0, color="0.5", lw=0.8)
        axes[row].set_ylabel(label("PRBM force error", "%"))
        axes[row].grid(True, alpha=0.3)
        row += 1
    if stress_panel:
        sa = axes[row]
        s_scale, s_unit = display(f[f"stress_{stresses[0][1]}_pivot{stresses[0][0]}"], "Pa")
        for pivot, model in stresses:
            name = f"stress_{model}_pivot{pivot}"
            rec.line(sa, dx, f[name][()], "--" if model == "prbm" else "-",
                     color=f"C{pivot - 1}", label=f"pivot {pivot} {model.upper() if model == 'prbm' else model}",
                     x_src=("displacement", k), y_src=(name, k), x_scale=length_scale,
                     y_scale=s_scale, panel="stress")
        if "design/yield_strength" in f:
            sa.axhline(float(f["design/yield_strength"][()]) * s_scale, color="k", ls=":",
                       lw=1.2, label="yield strength")
        sa.set_ylabel(label("largest stress", s_unit))
        sa.grid(True, alpha=0.3)
        legend_beside(sa)
    inside = f["prbm_within_validity"][()] if "prbm_within_validity" in f else None
    if inside is not None and (inside == 0).any() and len(dx) > 1:
        d = dx * length_scale
        edges = np.concatenate([[d[0] - 0.5 * (d[1] - d[0])], 0.5 * (d[:-1] + d[1:]),
                                [d[-1] + 0.5 * (d[-1] - d[-2])]])
        for a in axes:
            for i, flag in enumerate(inside):
                if int(flag) == 0:
                    a.axvspan(edges[i], edges[i + 1], color="C3", alpha=0.12, lw=0)
        text = "PRBM outside Howell Table 5.1"
        error = f.attrs.get("prbm_force_error_at_validity_limit")
        if error is not None and math.isfinite(float(error)):
            text += f"\n(force error there {100 * float(error):.1f} %)"
        axes[0].fill_between([], [], color="C3", alpha=0.12, label=text)
    legend_beside(axes[0])
    axes[-1].set_xlabel(label("slider displacement Delta x", length_unit))
    if has_shapes:
        _draw_shapes(f, plt, rec, fig.add_subplot(grid[:min(panels, 2), 1]), force_of)
    pcf = ""
    if "percent_constant_force_prbm" in f.attrs:
        pcf = f"PRBM {float(f.attrs['percent_constant_force_prbm']):.2f} %{_pcf_note(f, 'prbm')}"
    if "percent_constant_force_exact" in f.attrs:
        pcf += (f", exact {float(f.attrs['percent_constant_force_exact']):.2f} %"
                f"{_pcf_note(f, 'exact')}")
    config = attr(f, "config", "")
    fig.suptitle(f"{attr(f, 'mechanism', '')}{' (' + config + ')' if config else ''}: "
                 f"percent constant force {pcf}", fontsize=11)
    fig.tight_layout()
    return fig


def _shape_rows(count, wanted=5):
    return np.unique(np.linspace(0, count - 1, min(count, wanted)).round().astype(int))


def _draw_shapes(f, plt, rec, ax, force_of):
    """The half mechanism at rest and at up to five stored stroke points (the last: the end of
    the stroke), each the exact model's centreline from the ground to the slider (/shapes)."""
    x, y = f["shapes/x"][()], f["shapes/y"][()]
    dx = f["shapes/displacement"][()]
    rows = f["shapes/point_index"][()]
    scale, shown = display(f["shapes/x"], "m")
    k = np.arange(x.shape[1])
    rec.line(ax, f["shapes/rest_x"][()], f["shapes/rest_y"][()], "-", color="0.6", lw=1.5,
             label="at rest", x_src=("shapes/rest_x", k), y_src=("shapes/rest_y", k),
             x_scale=scale, y_scale=scale, panel="shapes:rest")
    force = f["force_exact"][()] if "force_exact" in f else None
    f_scale, f_unit = display(f["force_exact"], "N") if force is not None else (1.0, "N")
    cmap = plt.get_cmap("viridis")
    picks = _shape_rows(len(dx))
    for n, r in enumerate(picks):
        flat = r * x.shape[1] + k
        text = f"Delta x = {dx[r] * scale:.4g} {shown}"
        if force is not None:
            text += f", F = {force[rows[r]] * f_scale:.4g} {f_unit}"
        rec.line(ax, x[r], y[r], "-", lw=2.0, color=cmap(n / max(1, len(picks) - 1)),
                 label=text, x_src=("shapes/x", flat), y_src=("shapes/y", flat), x_scale=scale,
                 y_scale=scale, panel="shapes")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(label("x along the slider axis", shown))
    ax.set_ylabel(label("y", shown))
    ax.set_title(f"half mechanism, exact model (F of {force_of})")
    ax.grid(True, alpha=0.3)
    legend_beside(ax)


def animate_analyze(f, plt, out):
    """One frame at rest and one per stored stroke point: the half mechanism's exact shapes."""
    if "shapes/x" not in f:
        why = ("it holds no exact model (written with --method prbm, --method auto chose the "
               "PRBM alone, or the configuration has none): run `flexure mechanism analyze ... "
               "--method exact --out FILE.h5`") if "force_exact" not in f else (
            "it was written by a flexure older than /shapes, or the exact stroke converged at "
            "no point: write it again with `flexure mechanism analyze ... --out FILE.h5`")
        note = attr(f, "shapes_note")
        if note:
            why = note
        raise PlotError(f"plot: --animate needs deformed shapes; {f.filename} (mechanism "
                        f"analyze) has no /shapes group (the exact model's shape at every "
                        f"stroke point): {why}")
    from matplotlib import animation

    x, y = f["shapes/x"][()], f["shapes/y"][()]
    rest_x, rest_y = f["shapes/rest_x"][()], f["shapes/rest_y"][()]
    dx = f["shapes/displacement"][()]
    rows = f["shapes/point_index"][()]
    force = f["force_exact"][()] if "force_exact" in f else None
    scale, shown = display(f["shapes/x"], "m")
    frames_x = np.vstack([rest_x[None, :], x]) * scale
    frames_y = np.vstack([rest_y[None, :], y]) * scale
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ok = np.isfinite(frames_x) & np.isfinite(frames_y)
    pad = 0.05 * (np.ptp(frames_x[ok]) + 1e-12)
    ax.set_xlim(frames_x[ok].min() - pad, frames_x[ok].max() + pad)
    ax.set_ylim(frames_y[ok].min() - pad, frames_y[ok].max() + pad)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(label("x along the slider axis", shown))
    ax.set_ylabel(label("y", shown))
    ax.grid(True, alpha=0.3)
    ax.plot(rest_x * scale, rest_y * scale, "-", color="0.75", lw=1.2)
    (line,) = ax.plot([], [], "-", color="C0", lw=2)
    title = ax.set_title("")
    f_scale, f_unit = display(f["force_exact"], "N") if force is not None else (1.0, "N")

    def frame(k):
        line.set_data(frames_x[k], frames_y[k])
        if k == 0:
            title.set_text("at rest")
        else:
            text = f"Delta x = {dx[k - 1] * scale:.4g} {shown} (point {k} of {len(dx)})"
            if force is not None:
                text += f", exact F = {force[rows[k - 1]] * f_scale:.4g} {f_unit}"
            title.set_text(text)
        return line, title

    anim = animation.FuncAnimation(fig, frame, frames=len(dx) + 1, blit=False)
    anim.save(out, writer=animation.PillowWriter(fps=6))
    plt.close(fig)
    return len(dx) + 1


def draw_validate(f, plt, rec):
    names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["name"][()]]
    rows = np.arange(len(names))
    fig, axes = plt.subplots(1, 3, figsize=(15, max(4.0, 0.25 * len(names) + 1.5)), sharey=True)
    for key, lab, colour in (("percent_constant_force", "PRBM", "C0"),
                             ("percent_constant_force_exact", "exact", "C1")):
        rec.line(axes[0], f[key][()], rows, "o", ls="none", color=colour, label=lab,
                 x_src=(key, rows), panel="pcf")
    axes[0].set_xlabel(label("percent constant force Xi'", unit(f["percent_constant_force"])))
    rec.line(axes[1], 100 * f["max_force_error"][()], rows, "o", ls="none", color="C2",
             label="largest PRBM force error", panel="force_error")
    axes[1].set_xlabel(label("largest PRBM force error", "%"))
    rec.line(axes[2], f["safety_factor"][()], rows, "o", ls="none", color="C4",
             x_src=("safety_factor", rows), panel="safety_factor", label="static")
    axes[2].axvline(1.0, color="k", ls=":", lw=1)
    axes[2].set_xlabel(label("safety factor", unit(f["safety_factor"])))
    axes[0].set_yticks(rows)
    axes[0].set_yticklabels(names, fontsize=9)
    axes[0].invert_yaxis()
    for ax in axes:
        ax.grid(True, alpha=0.3)
    legend_beside(axes[0])
    fig.suptitle(f"mechanism validate ({attr(f, 'designs', '')}, {attr(f, 'points', '')} "
                 "stroke points)", fontsize=11)
    fig.tight_layout()
    return fig


def draw_tolerance(f, plt, rec):
    quantities = [q for q in ("mean_force_prbm", "mean_force_exact", "percent_constant_force_prbm",
                              "percent_constant_force_exact", "safety_factor")
                  if q + "/values" in f]
    params = [p.decode() if isinstance(p, bytes) else str(p) for p in f["parameters"][()]]
    # Which force the mean forces are (one half or the whole symmetric mechanism); files before
    # the attribute: one half, as mechanism analyze reported then.
    force_of = attr(f, "force_of", "one half")
    fig, axes = plt.subplots(2, len(quantities), figsize=(4.2 * len(quantities), 8),
                             squeeze=False)
    for col, q in enumerate(quantities):
        g = f[q]
        values = g["values"][()]
        scale, shown = display(g["values"])
        ax = axes[0, col]
        ok = finite(values)
        name = _quantity_name(f, q)
        if q.startswith("mean_force"):
            name += f" ({force_of})"
        rec.values(q, values, src=q + "/values", label=name)
        if len(ok):
            ax.hist(ok * scale, bins=max(5, min(40, int(math.sqrt(len(ok))) + 1)), color="C0",
                    alpha=0.7)
        for stat, colour, ls in (("nominal", "k", "-"), ("mean", "C1", "--"), ("p05", "C2", ":"),
                                 ("p95", "C2", ":")):
            if stat in g:
                ax.axvline(float(g[stat][()]) * scale, color=colour, ls=ls, lw=1.3,
                           label={"p05": "p05, p95", "p95": None}.get(stat, stat))
        ax.set_xlabel(label(name, shown))
        ax.set_ylabel("samples")
        std = float(g["std"][()]) * scale if "std" in g else float("nan")
        fo = float(g["first_order_std"][()]) * scale if "first_order_std" in g else float("nan")
        ax.set_title(f"std {std:.3g}, first order {fo:.3g}", fontsize=9)
        sens = g["parameter_sensitivity"][()]
        bx = axes[1, col]
        rec.values(q + ":sensitivity", sens, src=q + "/parameter_sensitivity")
        bx.barh(np.arange(len(params)), sens * scale, color="C0")
        bx.set_yticks(np.arange(len(params)))
        bx.set_yticklabels(params if col == 0 else [""] * len(params), fontsize=9)
        bx.invert_yaxis()
        bx.set_xlabel(label("sensitivity: change per relative change", shown))
        bx.grid(True, alpha=0.3, axis="x")
    legend_beside(axes[0, -1])
    spreads = ", ".join(f"{k[7:]} {100 * float(f.attrs[k]):g} %" for k in
                        ("spread_thickness", "spread_width", "spread_length", "spread_E")
                        if k in f.attrs)
    fig.suptitle(f"tolerance study of {attr(f, 'mechanism', '')}: {attr(f, 'samples', '')} "
                 f"{attr(f, 'distribution', '')} samples ({spreads}); forces of {force_of}",
                 fontsize=11)
    fig.tight_layout()
    return fig


def _quantity_name(f, q):
    names = {"mean_force_prbm": "mean force, PRBM", "mean_force_exact": "mean force, exact",
             "percent_constant_force_prbm": "Xi', PRBM", "percent_constant_force_exact":
             "Xi', exact", "safety_factor": "safety factor"}
    return names.get(q, q)


def _general_scale(unit_name):
    """Display scale and unit of a general mechanism's input or load: degrees for rad, mm for m,
    N mm for N m."""
    return {"rad": (180.0 / math.pi, "deg"), "m": (1e3, "mm")}.get(unit_name, (1.0, unit_name))


def draw_general(f, plt, rec):
    """`mechanism analyze FILE.toml --out` (general form, io/general_mechanism_file.h): the input
    load against the input for every model solved (points unstable with the input held drawn
    hollow, limit points x), the unloaded mechanism's equilibria on the zero line (filled: stable,
    hollow: unstable), and for a built-in design in its general form the slider force against the
    stroke, as `mechanism analyze` reports it."""
    design = "displacement" in f and "force" in f
    models = [m for m in f["models"]]
    first = attr(f, "first_model", models[0])
    models.sort(key=lambda m: m != first)
    has_energy = any(np.isfinite(f[f"models/{m}/energy"][()]).any() for m in models)
    has_shapes = "geometry" in f and any("bodies" in f["models"][m] for m in models)
    panels = 1 + design + has_energy + has_shapes
    fig, axes = plt.subplots(panels, 1, figsize=(8.5, 2.2 + 3.0 * panels + 2.0 * has_shapes),
                             squeeze=False)
    axes = list(axes[:, 0])
    ax = axes[0]
    xs, xu = _general_scale(unit(f["input"]))
    ys, yu = _general_scale(unit(f["input_load"]))
    if yu == "N m":
        ys, yu = 1e3, "N mm"
    coordinate = attr(f, "input_coordinate", "x")
    body = attr(f, "input_body", "")
    for k, m in enumerate(models):
        g = f["models"][m]
        x, y = g["input"][()], g["input_load"][()]
        idx = np.arange(len(x))
        colour = f"C{k}"
        rec.line(ax, x, y, "-", color=colour, label=m if m != "prbm" else "PRBM",
                 x_src=(f"models/{m}/input", idx), y_src=(f"models/{m}/input_load", idx),
                 x_scale=xs, y_scale=ys, panel="input_load:" + m)
        unstable = g["stability_displacement_control"][()] == 1
        if unstable.any():
            rec.line(ax, x[unstable], y[unstable], "o", ms=4, mfc="none", color=colour, ls="none",
                     label=f"{m}: unstable, input held", x_src=(f"models/{m}/input",
                                                                idx[unstable]),
                     y_src=(f"models/{m}/input_load", idx[unstable]), x_scale=xs, y_scale=ys,
                     panel="unstable:" + m)
        lim = g["limit_points"]
        if len(lim["input"]):
            n = np.arange(len(lim["input"]))
            rec.line(ax, lim["input"][()], lim["input_load"][()], "x", ms=8, mew=2, color=colour,
                     ls="none", label=f"{m}: limit points",
                     x_src=(f"models/{m}/limit_points/input", n),
                     y_src=(f"models/{m}/limit_points/input_load", n), x_scale=xs, y_scale=ys,
                     panel="limit:" + m)
        eq = g["equilibria"]
        if len(eq["input"]):
            code = eq["stability_force_control"][()]
            e = eq["input"][()]
            # 0 stable, 1 unstable, 2 critical, 4 not checked (the exact model judges none).
            for mask, fill, word in ((code == 0, colour, "stable"),
                                     ((code == 1) | (code == 2), "none", "unstable"),
                                     (code >= 3, "0.6", "not judged")):
                if mask.any():
                    rec.line(ax, e[mask], np.zeros(int(mask.sum())), "D", ms=6, mfc=fill,
                             color=colour, ls="none", label=f"{m}: {word} equilibrium",
                             x_src=(f"models/{m}/equilibria/input", np.arange(len(e))[mask]),
                             x_scale=xs, panel=f"equilibria:{m}:{word}")
    ax.axhline(0.0, color="0.5", lw=0.8)
    what = "angle" if coordinate == "angle" else coordinate
    ax.set_xlabel(label(f"input {what} of {body}", xu))
    ax.set_ylabel(label("input " + ("moment" if coordinate == "angle" else "force")
                        + f" ({attr(f, 'control', 'displacement')} control)", yu))
    ax.set_title(f"{attr(f, 'mechanism', '')}: model {attr(f, 'model', '')}")
    ax.grid(True, alpha=0.3)
    legend_beside(ax)
    row = 1
    if design:
        da = axes[row]
        ls_, lu = display(f["displacement"], "m")
        fs_, fu = display(f["force"], "N")
        idx = np.arange(len(f["displacement"]))
        rec.line(da, f["displacement"][()], f["force"][()], "o-", ms=3, color="C0",
                 label=first, x_src=("displacement", idx), y_src=("force", idx), x_scale=ls_,
                 y_scale=fs_, panel="force")
        da.set_xlabel(label("slider displacement Delta x", lu))
        da.set_ylabel(label(f"slider force F, {attr(f, 'force_of', 'one half')}", fu))
        da.grid(True, alpha=0.3)
        legend_beside(da)
        row += 1
    if has_energy:
        ea = axes[row]
        for k, m in enumerate(models):
            g = f["models"][m]
            idx = np.arange(len(g["input"]))
            rec.line(ea, g["input"][()], g["energy"][()], "-", color=f"C{k}", label=m,
                     x_src=(f"models/{m}/input", idx), y_src=(f"models/{m}/energy", idx),
                     x_scale=xs, panel="energy:" + m)
        ea.set_xlabel(label(f"input {what} of {body}", xu))
        ea.set_ylabel(label("potential energy", "J"))
        ea.grid(True, alpha=0.3)
        legend_beside(ea)
        row += 1
    if has_shapes:
        _draw_general_shapes(axes[row], f, models, rec, xs, xu)
    fig.tight_layout()
    return fig


def shape_points(n, count=5):
    """The point indices whose shapes are drawn: `count` spread evenly over the path."""
    return sorted(set(int(round(v)) for v in np.linspace(0, n - 1, min(count, n))))


def general_geometry(f):
    """The described configuration of a general mechanism's file (/geometry): for each body its
    named points (k x 2, in the order drawn: by angle about their centroid, so that the outline
    does not cross itself), each moving body's pose reference, and the flexures' ends."""
    g = f["geometry"]
    text = lambda d: [v.decode() if isinstance(v, bytes) else str(v) for v in d[()]]
    body_of, xy = text(g["points/body"]), np.column_stack([g["points/x"][()], g["points/y"][()]])
    bodies = {}
    for name in dict.fromkeys(body_of):
        pts = xy[[k for k, b in enumerate(body_of) if b == name]]
        c = pts.mean(axis=0)
        bodies[name] = pts[np.argsort(np.arctan2(pts[:, 1] - c[1], pts[:, 0] - c[0]))]
    refs = {n: np.array([x, y]) for n, x, y in zip(text(g["bodies/name"]),
                                                   g["bodies/reference_x"][()],
                                                   g["bodies/reference_y"][()])}
    fl = g["flexures"]
    flexures = [dict(name=n, a=a, b=b, end=e, pa=np.array(p), pb=np.array(q), length=l)
                for n, a, b, e, p, q, l in zip(
                    text(fl["name"]), text(fl["body_a"]), text(fl["body_b"]), text(fl["end_b"]),
                    zip(fl["a_x"][()], fl["a_y"][()]), zip(fl["b_x"][()], fl["b_y"][()]),
                    fl["length"][()])]
    return bodies, refs, flexures


def posed(points, ref, pose):
    """Points of a body moved by its pose (x, y, phi) about its reference point."""
    x, y, phi = pose
    c, s = math.cos(phi), math.sin(phi)
    d = np.atleast_2d(points) - ref
    return ref + np.array([x, y]) + np.column_stack([c * d[:, 0] - s * d[:, 1],
                                                     s * d[:, 0] + c * d[:, 1]])


def flexure_curve(pa, pb, ta, tb, length, samples=41):
    """A flexure drawn between its posed ends: the cubic of linear beam theory (a beam loaded at
    its ends only bends into a cubic) as a Hermite curve with the end tangents of the bodies it is
    clamped into (length `length`); a pinned far end takes no moment, so its curvature vanishes
    there and its tangent follows (P''(1) = 0). Not the elastica's shape: the file holds the bodies'
    poses, and the flexure's own shape is the model's."""
    t = np.linspace(0.0, 1.0, samples)[:, None]
    m0 = length * ta
    m1 = length * tb if tb is not None else 1.5 * (pb - pa) - 0.5 * m0
    h00, h10, h01, h11 = 2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t, -2 * t**3 + 3 * t**2, \
        t**3 - t**2
    return h00 * pa + h10 * m0 + h01 * pb + h11 * m1


def _draw_general_shapes(ax, f, models, rec, xs, xu):
    """The mechanism at a few inputs: every body as the outline through its named points (the
    ground grey, at rest), every flexure as the curve of flexure_curve; one colour per input, the
    first model solid, a further model dashed."""
    bodies, refs, flexures = general_geometry(f)
    ls_, lu = 1e3, "mm"
    cmap = __import__("matplotlib").colormaps["viridis"]

    def outline(pts):
        return np.vstack([pts, pts[:1]]) if len(pts) > 2 else pts

    if "ground" in bodies:
        g = outline(bodies["ground"])
        rec.line(ax, g[:, 0], g[:, 1], "s-", color="0.5", lw=2.5, ms=4, x_scale=ls_,
                 y_scale=ls_, label="ground", panel="shape:ground")
    for k, m in enumerate(models):
        gm = f["models"][m]
        if "bodies" not in gm:
            continue
        names = [v.decode() if isinstance(v, bytes) else str(v) for v in gm["bodies/name"][()]]
        bx, by, bphi = gm["bodies/x"][()], gm["bodies/y"][()], gm["bodies/phi"][()]
        picks = shape_points(len(bx))
        for j, i in enumerate(picks):
            colour = cmap(j / max(1, len(picks) - 1))
            style = "-" if k == 0 else "--"
            pose = {n: (bx[i, c], by[i, c], bphi[i, c]) for c, n in enumerate(names)}
            tag = (f"{m}, input {gm['input'][i] * xs:.4g} {xu}" if k == 0 or j == 0 else None)
            for name, pts in bodies.items():
                if name == "ground" or name not in pose:
                    continue
                q = outline(posed(pts, refs[name], pose[name]))
                rec.line(ax, q[:, 0], q[:, 1], "o" + style, color=colour, ms=3, lw=1.5,
                         x_scale=ls_, y_scale=ls_, label=tag or "_nolegend_",
                         panel=f"shape:{m}:{i}:body:{name}")
                tag = None
            for fx in flexures:
                ends = []
                for body, p in ((fx["a"], fx["pa"]), (fx["b"], fx["pb"])):
                    pz = pose.get(body, (0.0, 0.0, 0.0))
                    ends.append((posed(p, refs.get(body, p), pz)[0], pz[2]))
                u = (fx["pb"] - fx["pa"]) / fx["length"]
                rot = lambda phi: np.array([math.cos(phi) * u[0] - math.sin(phi) * u[1],
                                            math.sin(phi) * u[0] + math.cos(phi) * u[1]])
                tb = rot(ends[1][1]) if fx["end"] == "clamped" else None
                curve = flexure_curve(ends[0][0], ends[1][0], rot(ends[0][1]), tb, fx["length"])
                rec.line(ax, curve[:, 0], curve[:, 1], style, color=colour, lw=1.0,
                         x_scale=ls_, y_scale=ls_, label="_nolegend_",
                         panel=f"shape:{m}:{i}:flexure:{fx['name']}")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(label("x", lu))
    ax.set_ylabel(label("y", lu))
    ax.set_title("bodies through their named points and flexures (cubic between the bodies' "
                 "poses) at a few inputs", fontsize=9)
    ax.grid(True, alpha=0.3)
    legend_beside(ax)
