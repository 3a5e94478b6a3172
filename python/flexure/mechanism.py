"""flexure.mechanism: constant-force mechanisms (`flexure mechanism ...`, docs/mechanisms.md)."""
import json as _json
import os
import tempfile

from . import _command, _core


def list():  # noqa: A001 - the tool's name for it: `flexure mechanism list`
    """The built-in designs: `flexure mechanism list` (docs/mechanisms.md).

    Returns the dict `flexure mechanism list --json` prints: `mechanisms`, one entry per design
    (name, configuration, class, source), as a list of dicts.

    Example:
      >>> [m["name"] for m in flexure.mechanism.list()["mechanisms"]][:2]   # doctest: +SKIP
    """
    return _command.run(["mechanism", "list"], {})


def _plain(value):
    """numpy values in a design dict as plain numbers and lists."""
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError(f"{value!r} ({type(value).__name__}) has no TOML form")


def _design_argument(design):
    """A built-in name or a TOML path as is; a dict written to a temporary TOML file (returned so
    that the caller removes it)."""
    if isinstance(design, dict):
        try:
            text = _core.toml_text(_json.dumps(design, allow_nan=False, default=_plain))
        except (TypeError, ValueError) as e:
            raise _command.InvalidInput(f"mechanism dict: {e}") from None
        handle, path = tempfile.mkstemp(prefix="flexure-design-", suffix=".toml")
        with os.fdopen(handle, "w", encoding="utf-8") as f:
            f.write(text)
        return path, path
    if isinstance(design, (str, os.PathLike)):
        return os.fspath(design), None
    raise _command.InvalidInput(
        f"mechanism: expected a built-in name, a TOML file path or a dict, got "
        f"{type(design).__name__}")


def _flexure_model_text(flexure_models):
    """`--flexure-model`'s text for analyze's flexure_models: a model name or 'NAME=MODEL,...' as
    is, a dict {name: model} joined in its order."""
    if flexure_models is None or isinstance(flexure_models, str):
        return flexure_models
    if isinstance(flexure_models, dict):
        parts = []
        for name, model in flexure_models.items():
            if not isinstance(name, str) or not isinstance(model, str) or not name or not model:
                raise _command.InvalidInput(
                    f"flexure_models: expected {{flexure name: model name}} with text keys and "
                    f"values, got {name!r}: {model!r}")
            parts.append(f"{name}={model}")
        if not parts:
            raise _command.InvalidInput("flexure_models: the dict is empty; name a flexure's "
                                        "model, or give one model name for every flexure")
        return ",".join(parts)
    raise _command.InvalidInput(
        f"flexure_models: expected a model name, 'NAME=MODEL,...' or a dict, got "
        f"{type(flexure_models).__name__}")


def analyze(mechanism, *, points=None, method=None, tol=None, out=None, prbm_only=False,
            spring_rule=None, force_of=None, material=None, surface_finish=None,
            reliability=None, Kf=None, fatigue_factor=None, ultimate_strength=None,
            endurance_limit=None, plate=None, nu=None, stable=False, model=None,
            flexure_models=None, flexure_tol=None, check_flexures=False, input=None,
            progress=None):  # noqa: A002
    """Force curve of a constant-force mechanism over its stroke: `flexure mechanism analyze`.

    mechanism   a built-in name ('1A-lpp', '2B-lplm', a thesis sub-class 'lpp-b', an inversion
                "1A-lpp'"), a TOML file path (docs/mechanisms.md), or a dict with the keys of
                such a file
    points      stroke points (default 50); method 'auto' | 'prbm' | 'exact'; tol for auto
    out         also write the curves to this HDF5 file; spring_rule, force_of ('half' | 'whole')
    material    a name of flexure.materials(): replaces the design's E and S_y, gives S_ut and
                S_e' for the fatigue check (surface_finish, reliability, Kf, fatigue_factor,
                ultimate_strength, endurance_limit; docs/fatigue.md): fatigue_safety_factor,
                alternating_stress, mean_stress, endurance_limit, fatigue
    plate       'off' | 'on' | 'auto': the strips' bending modulus E or E/(1 - nu^2), nu
                Poisson's ratio (default the design's or material's; docs/plate-modulus.md)
    stable      True (`--stable`): where the exact stroke from the PRBM start is unstable with the
                slider held, follow a stable branch instead (serial chains; key `stable_search`
                says what was done; docs/stability.md "Mechanisms")
    Returns the dict `flexure mechanism analyze --json` prints (curves as numpy arrays in N, m),
    with the stability of every stroke point in `stability_displacement_control` and
    `stability_force_control` ({"prbm": ..., "exact": ...}: `stability`, `stability_index`,
    `stability_margin` per point; docs/stability.md "Mechanisms").

    General mechanisms ([[body]] files, docs/general-mechanisms.md) and the mixed model:
    model       'prbm' | 'exact' | 'both' | 'mixed' (`--model`; mixed: each flexure its own model
                of the ladder, docs/models.md; mixed also takes a built-in design)
    flexure_models  with model='mixed' (`--flexure-model`): one model for every flexure ('exact',
                'prbm', 'linear', 'bcm', 'prbm3r', 'cbcm', 'chain', 'auto'), or a dict {flexure name:
                model} (built-in designs: 'f1', 'f2', 'f3' by pivot), or the CLI's text
                'NAME=MODEL,...'
    flexure_tol auto's tolerance, the largest mapped tip error per length (`--flexure-tol`)
    check_flexures  True (`--check-flexures`): measure each flexure's model against the exact
                elastica under its loads (measured_error_per_length)
    input       the input range 'START:STOP:COUNT' with units ('-5deg:33deg:77'; `--input`)
    progress    progress(done, total) after each point of a constant-force mechanism's exact
                stroke (as analyze_mechanism's), or of a general mechanism's path (each model
                its own count, as solve_general_prbm's and solve_general_exact's); Ctrl-C or an
                exception it raises stops it (docs/python.md "Progress and Ctrl-C")

    Example:
      >>> r = flexure.mechanism.analyze("1A-lpp", points=20, method="exact")   # doctest: +SKIP
      >>> r = flexure.mechanism.analyze("3A-sss", model="mixed",                # doctest: +SKIP
      ...                               flexure_models={"f1": "cbcm", "f2": "exact"})
      >>> r["percent_constant_force_exact"]                                     # doctest: +SKIP
    """
    argument, temporary = _design_argument(mechanism)
    flexure_model = _flexure_model_text(flexure_models)
    try:
        return _command.run(["mechanism", "analyze"],
                            dict(points=points, method=method, tol=tol, out=out,
                                 prbm_only=prbm_only, spring_rule=spring_rule, force_of=force_of,
                                 material=material, surface_finish=surface_finish,
                                 reliability=reliability, Kf=Kf, fatigue_factor=fatigue_factor,
                                 ultimate_strength=ultimate_strength,
                                 endurance_limit=endurance_limit, plate=plate, nu=nu,
                                 stable=stable, model=model, flexure_model=flexure_model,
                                 flexure_tol=flexure_tol, check_flexures=check_flexures,
                                 input=input),
                            positional=[argument],
                            switches={"prbm_only", "stable", "check_flexures"},
                            progress=progress)
    finally:
        if temporary:
            os.unlink(temporary)


def validate(*, designs=None, points=None, toggle_fraction=None, spring_rule=None,
             spring_rules=False):
    """Every built-in design's PRBM against its exact model: `flexure mechanism validate`.

    designs 'builtin' | 'thesis' | 'modified' | 'howell' | 'inversions' | 'all'; points per
    stroke; toggle_fraction; spring_rule; spring_rules=True compares the spring rules instead.
    Returns the dict `flexure mechanism validate --json` prints; a failed check is reported in it
    (the tool's exit code 1), not raised.
    """
    return _command.run(["mechanism", "validate"],
                        dict(designs=designs, points=points, toggle_fraction=toggle_fraction,
                             spring_rule=spring_rule, spring_rules=spring_rules),
                        switches={"spring_rules"})


def tolerance(mechanism, *, thickness=None, width=None, length=None, E=None, samples=None,
              distribution=None, seed=None, method=None, points=None, force_of=None, out=None):
    """Manufacturing tolerances: `flexure mechanism tolerance` (docs/tolerance.md).

    mechanism as for analyze; thickness, width, length, E: relative spreads ('3%' or 0.03);
    samples, distribution ('normal' | 'uniform'), seed, method ('exact' | 'prbm'), points,
    force_of ('half' | 'whole': what the mean forces are the force of), out.
    Returns the dict `flexure mechanism tolerance --json` prints: per quantity of analyze
    (mean_force_exact, ...) {nominal, mean, std, p05, p50, p95, first_order_std, sensitivity}.
    """
    argument, temporary = _design_argument(mechanism)
    try:
        return _command.run(["mechanism", "tolerance"],
                            dict(thickness=thickness, width=width, length=length, E=E,
                                 samples=samples, distribution=distribution, seed=seed,
                                 method=method, points=points, force_of=force_of, out=out),
                            positional=[argument])
    finally:
        if temporary:
            os.unlink(temporary)


__all__ = ["list", "analyze", "validate", "tolerance"]
