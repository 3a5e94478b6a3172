"""flexure.beam: one load by the tool's `beam` command (without a command line where the keywords
allow), or many loads at once."""
import os

from . import _command, _core

_VECTOR = ("n", "alpha2", "mu", "theta0", "b_over_l")
_GIVEN = ("alpha2", "theta0", "b_over_l")
# A value of the given quantity that passes the tool's checks, used once to validate the other
# options of a vectorised call (every load is checked again on its own).
_PLACEHOLDER = {"alpha2": 1.0, "theta0": 0.5, "b_over_l": 0.1}


_NOT_ARRAYS = (type(None), float, int, str, bool)


def _is_array(value):
    if type(value) in _NOT_ARRAYS:  # the scalar call, without asking numpy
        return False
    try:
        import numpy
    except ImportError:
        return False
    return not isinstance(value, str) and numpy.ndim(value) > 0


def beam(n=None, alpha2=None, mu=None, theta0=None, b_over_l=None, *, method=None, tol=None,
         shape=None, boundary=None, tip_x=None, tip_y=None, tip_angle=None, follower=None,
         elements=None, increments=None, chain_variant=None, integrator=None, chain=None,
         constants=None, slenderness=None, length=None, E=None, I=None, width=None,
         thickness=None, Fx=None, Fy=None, M=None, yield_strength=None, stable=False, stability=None,
         material=None, cycle=None, surface_finish=None, reliability=None,
         Kf=None, fatigue_factor=None, ultimate_strength=None, endurance_limit=None,
         threads=None, plate=None, nu=None, qx=None, qy=None, q_follower=None, density=None,
         g=None, extensible=False, shear_coefficient=None, curvature=None, width_tip=None,
         thickness_tip=None):
    """Solves an initially straight cantilever with an end load: `flexure beam` (docs/cli.md).

    Howell's nondimensional loads (give exactly one of alpha2, theta0, b_over_l):
      n         load ratio: horizontal load n P, n > 0 compressive (default 0)
      alpha2    P l^2/EI, the vertical tip load
      mu        end moment M l/EI, counter-clockwise positive (default 0)
      theta0    inverse problem: the tip angle to reach, rad (or a string with a unit, '30deg')
      b_over_l  inverse problem: the tip deflection b/l to reach, in [-1, 1]
    Any of n, alpha2, mu, theta0, b_over_l may be a numpy array (or anything numpy.asarray takes):
    they broadcast, and every key of the result is an array of the broadcast shape, plus
    `status` (0 converged, 1 no converged solution, 2 invalid input at that load; `message` says
    why) and the boolean `converged`. One failed load never raises. The loads are solved in C++
    on `threads` worker threads (default: all cores) while other Python threads run.

    Method and end conditions (the tool's defaults when None):
      method      'auto' | 'elliptic' | 'shooting' | 'chain' | 'prbm', or a cheaper model of the
                  ladder: 'linear' | 'prbm3r' | 'bcm' | 'cbcm' (default 'auto'; docs/models.md)
      tol         auto only: the relative error allowed (default 1e-6)
      shape       also return the deflected shape at this many points (scalar loads only)
      boundary    'free' | 'guided' | 'pinned' | 'slider' | 'fixed'; tip_x, tip_y, tip_angle
                  prescribe the tip; follower: a follower force F l^2/EI
      elements, increments, chain_variant: the chain algorithm; integrator: shooting's
                  ('rk8pd', 'cvodes', 'dormand-prince'); elements is also the chained BCM's N
      constants   prbm3r: 'su' (default) | 'su-moment' | 'su-force' | 'flexure'
      slenderness bcm, cbcm: L/t of the segment, axial stiffness 12 (L/t)^2 (default: a chain
                  segment's EA, else inextensible)
      chain       a segment chain TOML file (docs/chain-toml.md)
      stability   'on' (default) or 'off': the stability verdict of every answer (off: faster,
                  stability 'not_checked')
      stable      True: when the equilibrium reached by proportional loading is unstable or
                  critical, return a stable equilibrium found from it (key stable_search says
                  what was done; NoConvergence when none is found); given loads only
    A physical cantilever (SI numbers, or strings with units: '50mm', '200GPa', '5N'):
      length, E, I (or width and thickness), Fx, Fy, M, yield_strength, material (a name of
      flexure.materials(): E and S_y); cycle 'reversed' | 'repeated' checks the beam in fatigue
      (surface_finish, reliability, Kf, fatigue_factor, ultimate_strength, endurance_limit;
      docs/fatigue.md); plate 'off' | 'on' | 'auto' the bending modulus E or E/(1 - nu^2) of a
      wide strip with nu Poisson's ratio (default the material's; docs/plate-modulus.md: keys
      modulus_rule, effective_E, modulus); qx, qy (dead load per unit length, N/m), q_follower
      (pressure along the deflected normal, N/m), density and g (self-weight), extensible=True
      with nu and shear_coefficient (Reissner's beam), curvature (stress-free, 1/m), width_tip
      and thickness_tip (a linear taper from the clamp's width and thickness); boundary with
      tip_x, tip_y in metres (docs/cli.md, "Physical beams")
      Any of these physical values may be a numpy array (or a list: SI numbers, never text):
      they broadcast, the beam is solved at every entry, and the result holds an array of the
      broadcast shape for every numeric key, plus `status`, `converged` and `message` as for
      arrays of Howell's loads (one failed entry never raises). Each entry is one in-process run
      of the command (about 0.1-10 ms), not the threaded solve of Howell's loads.

    Returns the dict `flexure beam --json` prints: method, method_reason, expected_error,
    expected_error_per_length (the ladder's models on the map, docs/models.md), n,
    alpha2, mu, a_over_l, b_over_l, theta0 (rad), iterations, converged, branch,
    inflection_points, root_moment, limit_points, target_residual, first_limit_load_factor,
    family, message, termination, boundary, reactions {Fx, Fy, M}, the stability verdict
    (stability: 'stable' | 'unstable' | 'critical' | 'not_conservative' | 'not_checked',
    stability_index and stability_margin, None where not judged, stability_message,
    stable_search, warnings), and per method or input more (shape as columns s, x, y, theta; the
    SI keys of a physical beam). An unstable answer is returned (it is the proportional-loading
    answer, labelled) with a FlexureWarning. Raises InvalidInput (a ValueError) for input the tool
    refuses and NoConvergence (a RuntimeError, with .reached) when a scalar load does not
    converge.

    Example:
      >>> import flexure, numpy as np
      >>> flexure.beam(alpha2=2.0)["theta0"]                        # doctest: +ELLIPSIS
      0.6...
      >>> r = flexure.beam(n=np.array([[0.0], [1.0]]), alpha2=np.linspace(0.5, 5, 10))
      >>> r["theta0"].shape, bool(r["converged"].all())
      ((2, 10), True)
    """
    # Physical values, any of which may be an array (solved entry by entry).
    physical = {"length": length, "E": E, "I": I, "width": width, "thickness": thickness,
                "Fx": Fx, "Fy": Fy, "M": M, "yield_strength": yield_strength, "nu": nu,
                "qx": qx, "qy": qy, "q_follower": q_follower, "density": density, "g": g,
                "shear_coefficient": shear_coefficient, "curvature": curvature,
                "width_tip": width_tip, "thickness_tip": thickness_tip}
    if (threads is None and tol is None and chain is None and constants is None
            and all(v is None for v in physical.values()) and extensible is False
            and plate is None
            and slenderness is None and length is None and E is None and I is None
            and width is None and thickness is None and Fx is None and Fy is None and M is None
            and yield_strength is None and material is None and cycle is None
            and surface_finish is None and reliability is None and Kf is None
            and fatigue_factor is None and ultimate_strength is None
            and endurance_limit is None and not _is_array(n) and not _is_array(alpha2)
            and not _is_array(mu) and not _is_array(theta0) and not _is_array(b_over_l)):
        values = _fast_values((("n", n), ("alpha2", alpha2), ("mu", mu), ("theta0", theta0),
                               ("b_over_l", b_over_l), ("method", method), ("shape", shape),
                               ("boundary", boundary), ("tip_x", tip_x), ("tip_y", tip_y),
                               ("tip_angle", tip_angle), ("follower", follower),
                               ("elements", elements), ("increments", increments),
                               ("chain_variant", chain_variant), ("integrator", integrator),
                               ("stable", stable), ("stability", stability)))
        if values is not None:
            # One load by the command's own checks and JSON object, without a command line
            # (the library's BeamRequest, solve_beam and beam/beam_keys.h): the same dict, messages and
            # warnings.
            kind, payload, texts, _ = _core.beam(**values)
            if texts:
                _command.emit(texts, stacklevel=2)
            if kind != "ok":
                _command.raise_for(kind, payload)
            return payload
    loads = {"n": n, "alpha2": alpha2, "mu": mu, "theta0": theta0, "b_over_l": b_over_l}
    options = {"method": method, "tol": tol, "shape": shape, "boundary": boundary,
               "tip_x": tip_x, "tip_y": tip_y, "tip_angle": tip_angle, "follower": follower,
               "elements": elements, "increments": increments, "chain_variant": chain_variant,
               "integrator": integrator, "chain": chain, "constants": constants,
               "slenderness": slenderness, "length": length, "E": E, "I": I,
               "width": width, "thickness": thickness, "Fx": Fx, "Fy": Fy, "M": M,
               "yield_strength": yield_strength, "stable": stable, "stability": stability,
               "material": material, "cycle": cycle,
               "surface_finish": surface_finish, "reliability": reliability, "Kf": Kf,
               "fatigue_factor": fatigue_factor, "ultimate_strength": ultimate_strength,
               "endurance_limit": endurance_limit, "plate": plate, "nu": nu, "qx": qx,
               "qy": qy, "q_follower": q_follower, "density": density, "g": g,
               "extensible": extensible or None, "shear_coefficient": shear_coefficient,
               "curvature": curvature, "width_tip": width_tip, "thickness_tip": thickness_tip}
    many_physical = [k for k, v in {**physical, "tip_x": tip_x, "tip_y": tip_y}.items()
                     if _is_sequence(v)]
    if many_physical:
        if any(_is_array(loads[k]) for k in _VECTOR):
            raise _command.InvalidInput(
                f"arrays of physical values ({', '.join(many_physical)}) and of Howell's loads "
                f"(n, alpha2, mu, theta0, b_over_l) cannot be mixed in one call")
        return _physical_many(options, many_physical)
    if threads is not None and (not isinstance(threads, int) or isinstance(threads, bool)
                                or threads < 1):
        raise _command.InvalidInput(f"threads = {threads!r}: expected an integer >= 1")
    if not any(_is_array(loads[k]) for k in _VECTOR):
        return _command.run(["beam"], {**loads, **options}, switches={"stable", "extensible"})
    return _beam_many(loads, options, threads or os.cpu_count() or 1)


# The keywords _core.beam takes (the rest go through the command line), by kind of value.
_FAST_FLOAT = frozenset(("n", "mu", "alpha2", "b_over_l", "tip_x", "tip_y", "follower", "tol",
                         "slenderness"))
_FAST_ANGLE = frozenset(("theta0", "tip_angle"))
_FAST_INT = frozenset(("shape", "elements", "increments"))
# The names the command's parser accepts (case-insensitively), as it stores them.
_FAST_NAMES = {
    "method": frozenset(("auto", "elliptic", "shooting", "chain", "prbm", "linear", "prbm3r",
                         "bcm", "cbcm")),
    "boundary": frozenset(("free", "guided", "pinned", "slider", "fixed")),
    "integrator": frozenset(("rk8pd", "cvodes", "dormand-prince")),
    "chain_variant": frozenset(("howell", "corrected")),
    "stability": frozenset(("on", "off")),
    "constants": frozenset(("su", "su-moment", "su-force", "flexure")),
}
# The keywords that describe a physical beam or a chain file: one load at a time.
_WHOLE_BEAM = ("chain", "length", "E", "I", "width", "thickness", "Fx", "Fy", "M",
               "yield_strength", "material", "cycle", "surface_finish", "reliability", "Kf",
               "fatigue_factor", "ultimate_strength", "endurance_limit", "plate", "nu", "qx", "qy",
               "q_follower", "density", "g", "extensible", "shear_coefficient", "curvature",
               "width_tip", "thickness_tip")


def _fast_values(pairs):
    """The keyword values for _core.beam from (keyword, value) pairs, or None where only the
    command line gives the tool's exact answer (a value of another type, a name the parser would
    refuse, a switch not a bool): that call then runs the command, whose parser words the
    refusal."""
    values = {}
    for key, value in pairs:
        if value is None:
            continue
        kind = type(value)
        if key in _FAST_FLOAT:
            if kind is int and -2**53 <= value <= 2**53:
                value = float(value)
            elif not isinstance(value, float):
                return None
            values[key] = float(value)
        elif key in _FAST_ANGLE:
            if kind is str:
                values[key] = value
            elif kind is int or isinstance(value, float):
                values[key] = _command.flag_value(key, value)
            else:
                return None
        elif key in _FAST_INT:
            if kind is not int or not -2**31 <= value < 2**31:
                return None
            values[key] = value
        elif key in _FAST_NAMES:
            if kind is not str or value.lower() not in _FAST_NAMES[key]:
                return None
            values[key] = value.lower()
        elif key == "stable":
            if kind is not bool:
                return None
            values[key] = value
        else:
            return None
    return values


def _beam_many(loads, options, threads):
    import numpy
    given = [k for k in _GIVEN if loads[k] is not None]
    arrays = {}
    for k in _VECTOR:
        if loads[k] is None:
            continue
        try:
            arrays[k] = numpy.asarray(loads[k], dtype=numpy.float64)
        except (TypeError, ValueError) as e:
            raise _command.InvalidInput(
                f"{k}: expected numbers (an array of float64), got {loads[k]!r:.60}: {e}") from None
    try:
        broadcast = numpy.broadcast_arrays(*arrays.values())
    except ValueError:
        shapes = ", ".join(f"{k} {a.shape}" for k, a in arrays.items())
        raise _command.InvalidInput(
            f"the load arrays do not broadcast to one shape: {shapes}") from None
    arrays = dict(zip(arrays, broadcast))
    shape = broadcast[0].shape
    # The options are checked once by the library with the tool's names, with a valid placeholder
    # load. (Two given quantities are refused by the tool, naming them.)
    scalar = {k: _PLACEHOLDER[k] for k in given}
    size = int(numpy.prod(shape)) if shape else 1
    zeros = numpy.zeros(size)

    def flat(name):
        return numpy.ascontiguousarray(arrays[name].reshape(-1)) if name in arrays else zeros

    if not given:  # the tool's own message: one of --alpha2, --theta0, --b-over-l is required
        _command.run(["beam"], options, switches={"stable"})
    whole = [k for k in _WHOLE_BEAM if options.get(k) not in (None, False)]
    values = None if whole else _fast_values(tuple({**scalar, **options}.items()))
    if values is None:
        # A physical beam, a chain file, a value of another type or a name the parser refuses:
        # the tool's own checks word the refusal (one run with the placeholder load).
        _command.run(["beam"], {**scalar, **options}, switches={"stable", "extensible"})
        if whole:
            raise _command.InvalidInput(
                "arrays of loads are for Howell's nondimensional beam (n, alpha2, mu, theta0, "
                "b_over_l); solve a physical beam or a chain file one load at a time")
        odd = [k for k, v in options.items() if v is not None
               and _fast_values(((k, v),)) is None]
        raise _command.InvalidInput(
            f"{', '.join(odd) or 'an option'}: give a number or a name of the documented type "
            f"with arrays of loads")
    try:
        result = _core.beam_many(values, flat("n"), flat("mu"), flat(given[0]), list(shape),
                                 threads)
    except ValueError as e:
        raise _command.InvalidInput(str(e)) from None
    unstable = result["converged"] & (result["stability"] == "unstable")
    if unstable.any():
        # One warning for the call, where the scalar call warns at each load.
        _command.emit([f"{int(unstable.sum())} of {unstable.size} loads have an UNSTABLE answer "
                       f"(stability 'unstable'): the equilibrium reached by proportional loading, "
                       f"which the beam cannot hold under those loads; stable=True returns a "
                       f"stable equilibrium"], stacklevel=3)
    if "within_validity" in result:
        # One warning for the call, where the scalar call warns at each load.
        outside = (result["method"] == "prbm") & result["converged"] & ~result["within_validity"]
        if outside.any():
            _command.emit([f"{int(outside.sum())} of {outside.size} loads solved by the PRBM lie "
                           f"outside its validity limits (within_validity False): their PRBM tip "
                           f"and force are not trusted (method='elliptic' or 'shooting' is "
                           f"exact)"], stacklevel=3)
        beyond = (result["method"] == "bcm") & result["converged"] & ~result["within_validity"]
        if beyond.any():
            _command.emit([f"{int(beyond.sum())} of {beyond.size} loads solved by the BCM deflect "
                           f"its element beyond its stated range |y| <= 0.1 l "
                           f"(max_element_deflection): method='cbcm' follows larger "
                           f"deflections"], stacklevel=3)
    return result


def _is_sequence(value):
    """A list, tuple or numpy array (of any dimension but 0): many values, never one text."""
    if type(value) in _NOT_ARRAYS:
        return False
    if isinstance(value, (list, tuple)):
        return True
    return _is_array(value)


def _physical_many(options, keys):
    """The physical beam at every entry of the broadcast arrays `keys` of `options` (SI numbers):
    one run of the command per entry; numeric keys become arrays of the broadcast shape, with
    status (0 converged, 1 no converged solution, 2 invalid input), converged and message."""
    import math
    import numpy
    arrays = {}
    for k in keys:
        try:
            arrays[k] = numpy.asarray(options[k], dtype=numpy.float64)
        except (TypeError, ValueError) as e:
            raise _command.InvalidInput(
                f"{k}: an array of physical values holds SI numbers (float64), got "
                f"{options[k]!r:.60}: {e}") from None
    try:
        broadcast = numpy.broadcast_arrays(*arrays.values())
    except ValueError:
        shapes = ", ".join(f"{k} {a.shape}" for k, a in arrays.items())
        raise _command.InvalidInput(
            f"the physical arrays do not broadcast to one shape: {shapes}") from None
    shape = broadcast[0].shape
    flat = {k: a.reshape(-1) for k, a in zip(arrays, broadcast)}
    size = int(numpy.prod(shape)) if shape else 1
    if options.get("shape") is not None:
        raise _command.InvalidInput("shape: the deflected shape is returned for one beam at a "
                                    "time (call flexure.beam per entry)")
    results, status, messages = [], numpy.zeros(size, dtype=numpy.int32), []
    import warnings
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for i in range(size):
            one = dict(options)
            for k in keys:
                one[k] = float(flat[k][i])
            try:
                results.append(_command.run(["beam"], one, switches={"stable", "extensible"}))
                messages.append(results[-1].get("message", ""))
            except _command.NoConvergence as e:
                status[i] = 1
                results.append(None)
                messages.append(str(e))
            except _command.InvalidInput as e:
                status[i] = 2
                results.append(None)
                messages.append(str(e))
    texts = sorted({str(w.message) for w in caught})
    if texts:
        _command.emit(texts, stacklevel=3)
    out = {}
    names = []
    for r in results:
        if r is not None:
            names = [k for k, v in r.items()
                     if v is None or (isinstance(v, (int, float)) and not isinstance(v, bool))]
            break
    for name in names:
        column = numpy.full(size, math.nan)
        for i, r in enumerate(results):
            v = None if r is None else r.get(name)
            if isinstance(v, (int, float)) and not isinstance(v, bool):
                column[i] = v
        out[name] = column.reshape(shape)
    for name in ("method", "stability", "units", "boundary"):
        out[name] = numpy.array([("" if r is None else str(r.get(name))) for r in results],
                                dtype=object).reshape(shape)
    out["status"] = status.reshape(shape)
    out["converged"] = (status == 0).reshape(shape)
    out["message"] = numpy.array(messages, dtype=object).reshape(shape)
    for k in keys:
        out.setdefault(k, flat[k].reshape(shape))
    return out
