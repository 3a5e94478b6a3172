"""pytest set-up for the Python module: the module from the build tree, the tool beside it.

Run by scripts/test.sh as
    PYTHONPATH=build/python FLEXURE_BINARY=build/flexure /usr/bin/python3 -m pytest tests/python
(both variables default to those paths below the repository root)."""
import json
import math
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("FLEXURE_BUILD_DIR", os.path.join(ROOT, "build"))
if not any(os.path.isdir(os.path.join(p, "flexure")) for p in sys.path if p):
    sys.path.insert(0, os.path.join(BUILD, "python"))
BINARY = os.environ.get("FLEXURE_BINARY", os.path.join(BUILD, "flexure"))


class Cli:
    """The `flexure` tool as a subprocess: JSON object, exit code, stderr."""

    def __call__(self, *args, expect=0):
        p = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True,
                           timeout=600)
        assert p.returncode == expect, (args, p.returncode, p.stderr)
        out = json.loads(p.stdout) if p.stdout.strip() else None
        return out, p.stderr

    def json(self, *args, expect=0):
        return self(*args, "--json", expect=expect)[0]


@pytest.fixture(scope="session")
def cli():
    if not os.access(BINARY, os.X_OK):
        pytest.fail(f"the tool is not built: {BINARY} (cmake --build build)")
    return Cli()


def is_record_array(value):
    return (isinstance(value, list) and value and all(isinstance(v, dict) for v in value)
            and all(set(v) == set(value[0]) for v in value)
            and all(x is None or isinstance(x, (int, float)) for v in value for x in v.values()))


def columns(value):
    """The CLI's JSON in the module's layout: arrays of records as dicts of columns."""
    if isinstance(value, dict):
        return {k: columns(v) for k, v in value.items()}
    if is_record_array(value):
        return {k: [v[k] for v in value] for k in value[0]}
    if isinstance(value, list):
        return [columns(v) for v in value]
    return value


def plain(value):
    """The module's result as JSON values: numpy arrays as lists, NaN as None."""
    import numpy
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, numpy.ndarray):
        return plain(value.tolist())
    if isinstance(value, list):
        return [plain(v) for v in value]
    if isinstance(value, float) and math.isnan(value):
        return None
    if isinstance(value, numpy.generic):
        return plain(value.item())
    return value


def assert_same(module_result, cli_result, rtol=1e-12, skip=("seconds",), where=""):
    """Equal keys everywhere; numbers to rtol (relative, absolute below 1); the rest equal."""
    a, b = plain(module_result), columns(cli_result)
    _same(a, b, rtol, set(skip), where or "result")


def _same(a, b, rtol, skip, where):
    if isinstance(b, dict):
        assert isinstance(a, dict), f"{where}: {type(a).__name__} instead of an object"
        assert list(a) == list(b), f"{where}: keys {list(a)} != {list(b)}"
        for k in b:
            if k not in skip:
                _same(a[k], b[k], rtol, skip, f"{where}.{k}")
    elif isinstance(b, list):
        assert isinstance(a, list) and len(a) == len(b), f"{where}: {a!r:.80} != {b!r:.80}"
        for i, (x, y) in enumerate(zip(a, b)):
            _same(x, y, rtol, skip, f"{where}[{i}]")
    elif isinstance(b, bool) or b is None or isinstance(b, str):
        assert a == b, f"{where}: {a!r} != {b!r}"
    else:
        assert isinstance(a, (int, float)) and not isinstance(a, bool), f"{where}: {a!r}"
        assert abs(a - b) <= rtol * max(1.0, abs(b)), f"{where}: {a!r} != {b!r}"


def _interrupt_python(code, timeout):
    """Runs `code` in a fresh interpreter, which prints 'started' before its long call and
    'finished' after it; sends SIGINT 1 s after 'started' and checks that the call ended with
    KeyboardInterrupt (not finished, a non-zero exit). Returns the seconds from the signal to the
    end of the process."""
    import signal
    import time
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=dict(os.environ))
    try:
        assert proc.stdout.readline().strip() == "started"
        time.sleep(1.0)
        sent = time.monotonic()
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=timeout)
        elapsed = time.monotonic() - sent
    finally:
        if proc.poll() is None:
            proc.kill()
    assert "finished" not in out
    assert proc.returncode != 0
    assert "KeyboardInterrupt" in err, err
    return elapsed


@pytest.fixture(scope="session")
def interrupt_python():
    """A function (code, timeout) -> seconds from SIGINT to the end (_interrupt_python)."""
    return _interrupt_python


class InterruptingProgress:
    """A progress callable that records each `done` it is given and raises KeyboardInterrupt
    when `done` reaches `at` (the Python side of Ctrl-C inside a long library call)."""

    def __init__(self, at):
        self.at = at
        self.seen = []

    def __call__(self, done, total):
        self.seen.append(done)
        if done == self.at:
            raise KeyboardInterrupt


@pytest.fixture
def interrupting_progress():
    """InterruptingProgress(at): a fresh progress callable that stops a call at step `at`."""
    return InterruptingProgress

