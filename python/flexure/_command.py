"""Keyword arguments to the tool's flags, one command run in-process, the module's exceptions."""
import math
import os
import warnings

from . import _core


class InvalidInput(ValueError):
    """Input the tool refuses (its exit code 2): the message is the tool's, naming the flag."""


class NoConvergence(RuntimeError):
    """No converged solution (the tool's exit code 3). `reached` holds what was reached (the keys
    the tool adds to its JSON error object: method, iterations, load_factor, ...)."""

    def __init__(self, message, reached=None):
        super().__init__(message)
        self.reached = dict(reached or {})


class FlexureWarning(UserWarning):
    """What the tool prints as 'flexure: warning: ...' (a likely unit slip, a PRBM outside its
    validity limits, a yielding pivot, ...)."""


def flag_name(keyword):
    """The tool's flag for a keyword argument: b_over_l -> --b-over-l, theta_max_K -> --theta-max-K."""
    return "--" + keyword.replace("_", "-")


def flag_value(keyword, value):
    """The text the tool parses for `value` (floats in their shortest exact form)."""
    if isinstance(value, bool):
        raise InvalidInput(f"{keyword}={value!r}: expected a value, not True or False (only "
                           f"the tool's switches take those)")
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, (str, os.PathLike)):
        return os.fspath(value)
    if hasattr(value, "item") and getattr(value, "ndim", 1) == 0:  # a numpy scalar
        return flag_value(keyword, value.item())
    if isinstance(value, (list, tuple)):
        return ",".join(flag_value(keyword, v) for v in value)
    raise InvalidInput(f"{keyword}={value!r}: expected a number, a string or a path "
                       f"(got {type(value).__name__})")


def to_flags(options, switches=()):
    """[--flag, value, ...] for the keyword arguments that are set (None is left out). The
    keywords in `switches` are the tool's switches: True adds the flag, False leaves it out."""
    args = []
    for keyword, value in options.items():
        if value is None:
            continue
        if keyword in switches:
            if not isinstance(value, bool):
                raise InvalidInput(f"{keyword}={value!r}: a switch, True or False")
            if value:
                args.append(flag_name(keyword))
        else:
            args += [flag_name(keyword), flag_value(keyword, value)]
    return args


def raise_for(kind, payload):
    if kind == "invalid":
        raise InvalidInput(payload[0])
    if kind == "no_convergence":
        raise NoConvergence(payload[0], payload[1])
    raise RuntimeError(payload[0])


def emit(texts, stacklevel):
    for text in texts:
        warnings.warn(text, FlexureWarning, stacklevel=stacklevel + 1)


def run(command, options, positional=(), switches=(), json=True, progress=None):
    """Runs `flexure COMMAND [positional] --flags [--json]` in this process and returns its JSON
    object as a dict (arrays of numbers as numpy arrays). Raises InvalidInput / NoConvergence.
    progress(done, total), if given, is called at each step of the commands whose long work can
    be stopped (docs/python.md "Progress and Ctrl-C"); an exception it raises (or Ctrl-C) stops
    the command and propagates."""
    args = list(command) + [os.fspath(p) for p in positional] + to_flags(options, switches)
    if json:
        args.append("--json")
    kind, payload, texts, exit_code = _core.run(args, progress=progress)
    emit(texts, stacklevel=3)
    if kind != "ok":
        raise_for(kind, payload)
    if payload is None:
        raise RuntimeError(f"flexure {' '.join(command)} printed no JSON object")
    return payload
