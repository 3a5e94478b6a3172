"""Bad input through Python raises the module's exceptions with the tool's own messages, and
never crashes the interpreter (issue 15)."""
import math

import numpy as np
import pytest

import flexure


def tool_message(cli, *args):
    """The one-line message the tool prints on stderr for these arguments, without 'flexure: '."""
    _, err = cli(*args, expect=2)
    line = err.strip().splitlines()[-1]
    assert line.startswith("flexure: ")
    return line[len("flexure: "):]


@pytest.mark.parametrize("kwargs,flags", [
    (dict(alpha2=math.nan), ["beam", "--alpha2", "nan"]),
    (dict(alpha2=1.0, method="magic"), ["beam", "--alpha2", "1", "--method", "magic"]),
    (dict(alpha2=1.0, n=math.inf), ["beam", "--alpha2", "1", "--n", "inf"]),
    (dict(b_over_l=1.5), ["beam", "--b-over-l", "1.5"]),
    (dict(length=-1.0, E="200GPa", I=1e-12, Fy=1.0),
     ["beam", "--length", "-1", "--E", "200GPa", "--I", "1e-12", "--Fy", "1"]),
    (dict(length="50mm", E="200Gpa", I=1e-12, Fy=1.0),
     ["beam", "--length", "50mm", "--E", "200Gpa", "--I", "1e-12", "--Fy", "1"]),
    (dict(alpha2=1.0, boundary="clamped"), ["beam", "--alpha2", "1", "--boundary", "clamped"]),
    (dict(), ["beam"]),
    (dict(alpha2=""), ["beam", "--alpha2", ""]),
])
def test_beam_errors_carry_the_tools_message(cli, kwargs, flags):
    with pytest.raises(flexure.InvalidInput) as e:
        flexure.beam(**kwargs)
    assert str(e.value) == tool_message(cli, *flags)
    assert isinstance(e.value, ValueError)


def test_unknown_names(cli):
    with pytest.raises(flexure.InvalidInput) as e:
        flexure.mechanism.analyze("no-such-design")
    assert str(e.value) == tool_message(cli, "mechanism", "analyze", "no-such-design")
    with pytest.raises(flexure.InvalidInput) as e:
        flexure.prbm.derive(segment="pinned-pinned")
    assert str(e.value) == tool_message(cli, "prbm", "derive", "--segment", "pinned-pinned")
    with pytest.raises(TypeError):
        flexure.beam(alpha2=1.0, alpah2=2.0)  # a misspelt keyword is Python's own error


def test_wrong_types_and_shapes():
    with pytest.raises(flexure.InvalidInput, match="expected a number"):
        flexure.beam(alpha2=object())
    with pytest.raises(flexure.InvalidInput, match="float64"):
        flexure.beam(alpha2=np.array(["a", "b"]))
    with pytest.raises(flexure.InvalidInput, match="do not broadcast"):
        flexure.beam(alpha2=np.ones((2, 3)), mu=np.ones(2))
    with pytest.raises(flexure.InvalidInput, match="switches"):
        flexure.beam(alpha2=1.0, shape=True)
    with pytest.raises(flexure.InvalidInput, match="None has no TOML form"):
        flexure.mechanism.analyze({"name": "x", "config": None})


def test_no_convergence_carries_what_was_reached(cli):
    # A large end moment with a reversed load: the path passes eight limit points, which the chain
    # algorithm's load increments cannot follow (tests/cli/cli_beam_test.cpp, exit code 3).
    flags = ["beam", "--method", "chain", "--n", "1", "--alpha2", "-50", "--mu", "30"]
    out, err = cli(*flags, "--json", expect=3)
    with pytest.raises(flexure.NoConvergence) as e:
        flexure.beam(method="chain", n=1.0, alpha2=-50.0, mu=30.0)
    assert isinstance(e.value, RuntimeError)
    assert str(e.value) == out["error"]
    assert e.value.reached == {k: v for k, v in out.items() if k not in ("error", "exit_code")}
    assert e.value.reached["method"] == "chain"


def test_interpreter_survives_a_thousand_bad_calls():
    for value in [math.nan, -math.inf, "x", "1e999", "--alpha2", ""] * 150:
        with pytest.raises((flexure.InvalidInput, TypeError)):
            flexure.beam(alpha2=value)
    assert flexure.beam(alpha2=1.0)["converged"]


def test_cfm_clamped_stroke_warns(capfd):
    """A stroke past the toggle position (lpp, R = 0.5: toggle at 42.26 %) is clamped with the
    model's warning, which Python raises as FlexureWarning; nothing is printed raw on stderr."""
    with pytest.warns(flexure.FlexureWarning, match="past the toggle position") as caught:
        result = flexure.cfm(config="lpp", R=0.5, d=95)
    assert result["stroke_clamped"]
    assert result["stroke_percent"] < 95
    assert any(f"clamped to {result['stroke_percent']:.4f} %" in str(w.message) for w in caught)
    assert capfd.readouterr().err == ""
