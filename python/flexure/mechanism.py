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


def analyze(mechanism, *, points=None, method=None, tol=None, out=None, prbm_only=False,
            spring_rule=None, force_of=None):
    """Force curve of a constant-force mechanism over its stroke: `flexure mechanism analyze`.

    mechanism   a built-in name ('1A-lpp', '2B-lplm', a thesis sub-class 'lpp-b', an inversion
                "1A-lpp'"), a TOML file path (docs/mechanisms.md), or a dict with the keys of
                such a file
    points      stroke points (default 50); method 'auto' | 'prbm' | 'exact'; tol for auto
    out         also write the curves to this HDF5 file; spring_rule, force_of ('half' | 'whole')
    Returns the dict `flexure mechanism analyze --json` prints (curves as numpy arrays in N, m),
    with the stability of every stroke point in `stability_displacement_control` and
    `stability_force_control` ({"prbm": ..., "exact": ...}: `stability`, `stability_index`,
    `stability_margin` per point; docs/stability.md "Mechanisms").

    Example:
      >>> r = flexure.mechanism.analyze("1A-lpp", points=20, method="exact")   # doctest: +SKIP
      >>> r["percent_constant_force_exact"]                                     # doctest: +SKIP
    """
    argument, temporary = _design_argument(mechanism)
    try:
        return _command.run(["mechanism", "analyze"],
                            dict(points=points, method=method, tol=tol, out=out,
                                 prbm_only=prbm_only, spring_rule=spring_rule, force_of=force_of),
                            positional=[argument], switches={"prbm_only"})
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


__all__ = ["list", "analyze", "validate"]
