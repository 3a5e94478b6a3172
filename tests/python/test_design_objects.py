"""The dimensional design of constant-force slider mechanisms as objects
(python/design_objects.cpp): MechanismSpec built by keyword gives the designs of
`flexure design mechanism --json` for the same specification (the same library call),
design_mechanisms reports progress per sub-class, and a KeyboardInterrupt from the callable (or
Ctrl-C) stops it."""
import math

import pytest

import flexure

INCH = 0.0254
LBF = 4.4482216152605
PSI = LBF / INCH**2

# Weight's thesis, design example 1 (ch. 8): 25 lbf over a 4 in stroke in steel, by the tool's
# default (computed) stress rule; tests/cli/cli_design_mechanism_test.cpp runs it by the thesis's.
EXAMPLE_1 = dict(force=25 * LBF, stroke=4 * INCH, E=30e6 * PSI, safety_factor=1.2,
                 length=(12 * INCH, 15 * INCH), width=(3 * INCH, 5 * INCH),
                 thickness=(0.04 * INCH, 0.07 * INCH), configs=["lpp"])


def cli_args(spec):
    """The same specification as flags, every number in SI as Python's shortest exact text."""
    return ["--force", repr(spec["force"]), "--stroke", repr(spec["stroke"]),
            "--E", repr(spec["E"]), "--safety-factor", repr(spec["safety_factor"]),
            "--length-range", "{!r}:{!r}".format(*spec["length"]),
            "--width-range", "{!r}:{!r}".format(*spec["width"]),
            "--thickness-range", "{!r}:{!r}".format(*spec["thickness"]),
            "--config", ",".join(spec["configs"])]


def close(a, b, rel=1e-12):
    if a is None or b is None:
        return a is None and b is None
    return math.isclose(a, b, rel_tol=rel, abs_tol=1e-300)


def test_spec_is_built_by_keyword_and_validated():
    spec = flexure.MechanismSpec(**EXAMPLE_1)
    assert spec.length == pytest.approx((12 * INCH, 15 * INCH), rel=1e-15)
    assert spec.configs == ["lpp"] and spec.stress_rule == flexure.StressRule.computed
    free = flexure.MechanismSpec(force=10, stroke=0.01, E=2e11, length=0.1, yield_strength=1e9)
    assert free.width is None and free.length == (0.1, 0.1)
    with pytest.raises(flexure.InvalidInput, match="stroke"):
        flexure.MechanismSpec(**{**EXAMPLE_1, "stroke": -1.0})
    with pytest.raises(flexure.InvalidInput, match="nope"):
        flexure.MechanismSpec(**{**EXAMPLE_1, "configs": ["nope"]})
    with pytest.raises(TypeError):
        flexure.MechanismSpec(**EXAMPLE_1, strok=1.0)


def test_spec_takes_a_material_object_and_gives_the_same_designs():
    # The same specification with its material as a Material: the same designs, to the bit, and
    # the material's other fields carried onto every design; E beside a Material is refused.
    by_value = flexure.MechanismSpec(**EXAMPLE_1, yield_strength=170e3 * PSI)
    steel = flexure.Material(E=EXAMPLE_1["E"], yield_strength=170e3 * PSI, density=7850.0)
    spec = flexure.MechanismSpec(**{k: v for k, v in EXAMPLE_1.items() if k != "E"},
                                 material=steel)
    assert spec.E == by_value.E and spec.yield_strength == by_value.yield_strength
    assert spec.material.density == 7850.0 and spec.material_id == ""
    a, b = flexure.design_mechanisms(by_value), flexure.design_mechanisms(spec)
    assert [d.subclass for d in a.designs] == [d.subclass for d in b.designs]
    assert [d.thicknesses for d in a.designs] == [d.thicknesses for d in b.designs]
    assert all(d.design.material.density == 7850.0 for d in b.designs)
    with pytest.raises(flexure.InvalidInput, match="not both"):
        flexure.MechanismSpec(**EXAMPLE_1, material=steel)
    with pytest.raises(flexure.InvalidInput, match="give the material"):
        flexure.MechanismSpec(**{k: v for k, v in EXAMPLE_1.items() if k != "E"})


def test_designs_equal_the_command_lines(cli):
    report = flexure.design_mechanisms(flexure.MechanismSpec(**EXAMPLE_1))
    j = cli.json("design", "mechanism", *cli_args(EXAMPLE_1))
    assert [d.subclass for d in report.designs] == [d["subclass"] for d in j["designs"]]
    assert [d.subclass for d in report.rejected] == [d["subclass"] for d in j["rejected"]]
    assert report.designs[0].subclass == "lpp-b"  # the thesis's choice for example 1
    for got, want in zip(report.designs, j["designs"]):
        assert got.feasible
        for key in ("l_tot", "r2", "r3", "R", "K1", "K2", "stroke_percent", "primary_stress",
                    "required_yield_strength", "required_yield_strength_prbm",
                    "required_yield_strength_exact", "force_prbm", "force_exact",
                    "percent_constant_force_prbm", "percent_constant_force_exact",
                    "safety_factor_prbm", "safety_factor_exact", "footprint", "flexure_volume",
                    "subclass_percent_constant_force"):
            assert close(getattr(got, key), want[key]), (got.subclass, key)
        flexible = [i for i in range(3) if got.thicknesses[i] > 0]
        assert [i + 1 for i in flexible] == want["flexible_pivots"]
        for mine, theirs in (("thicknesses", "thicknesses"), ("widths", "widths"),
                             ("segment_lengths", "segment_lengths")):
            values = getattr(got, mine)
            assert all(close(values[i], w) for i, w in zip(flexible, want[theirs]))
        assert got.section_rule == want["section_rule"]
    for got, want in zip(report.rejected, j["rejected"]):
        assert not got.feasible and got.binding == want["binding"]
        assert close(got.shortfall, want["shortfall"])
    # The best design analyses as a mechanism (its force by the PRBM is the one it was sized by).
    best = report.designs[0]
    a = flexure.analyze_mechanism(best.design, flexure.AnalysisOptions(exact=False))
    assert a.mean_force_prbm == pytest.approx(best.force_prbm, rel=1e-9)


def test_progress_reaches_the_total_and_keyboard_interrupt_stops_it(interrupting_progress):
    spec = flexure.MechanismSpec(force=10.0, stroke=0.01, E=200e9, yield_strength=1.2e9,
                                 safety_factor=1.5, length=(0.06, 0.15), exact=False)
    calls = []
    report = flexure.design_mechanisms(spec, progress=lambda d, t: calls.append((d, t)))
    total = calls[-1][1]
    # One call per sub-class the specification admits, every one reported.
    assert total == len(report.designs) + len(report.rejected) >= 5
    assert [d for d, _ in calls[:total]] == list(range(1, total + 1))
    assert all(t == total for _, t in calls)

    stop = interrupting_progress(2)
    with pytest.raises(KeyboardInterrupt):
        flexure.design_mechanisms(spec, progress=stop)
    assert stop.seen == [1, 2]
    # The module keeps working after the interrupted call, with the same answer.
    again = flexure.design_mechanisms(spec)
    assert [d.subclass for d in again.designs] == [d.subclass for d in report.designs]


def test_ctrl_c_interrupts_a_long_synthesis_without_a_callable(interrupt_python):
    # About 25 s of work on an idle machine (38 sub-classes, the exact model at 1000 points; the
    # longest sub-class about 5 s); SIGINT 1 s after it starts must end it with KeyboardInterrupt
    # at the next sub-class, well before it would have finished.
    code = ("import flexure\n"
            "spec = flexure.MechanismSpec(force=10.0, stroke=0.01, E=200e9, yield_strength=1.2e9,"
            " safety_factor=1.5, length=(0.06, 0.15), points=1000)\n"
            "print('started', flush=True)\n"
            "flexure.design_mechanisms(spec)\n"
            "print('finished', flush=True)\n")
    assert interrupt_python(code, timeout=120) < 10.0


def test_report_is_a_solve_status_with_its_warnings_as_flexure_warning():
    """The report is a SolveStatus (mechanisms/design/design_status.h): by the thesis's stress
    rule (eq. 8.5) at S_y = 170 ksi, lpp-b is feasible but short of SF 1.2 by its own stresses
    (about 1.2 * 170/190 = 1.07 by the printed 190 ksi, to 1 %; tests/mechanisms/
    mechanism_design_test.cpp): converged, and the
    warning arrives as FlexureWarning; at 150 ksi nothing is feasible: infeasible, saying why."""
    thesis = dict(EXAMPLE_1, stress_rule=flexure.StressRule.thesis, max_width_to_thickness=1e6,
                  max_width_to_length=1e3, force_tolerance=1.0)
    with pytest.warns(flexure.FlexureWarning, match=r"designs miss safety factor 1.2 .*lpp-b 1\.0\d"):
        report = flexure.design_mechanisms(
            flexure.MechanismSpec(**thesis, yield_strength=170e3 * PSI))
    assert report.termination == flexure.Termination.converged and report.converged()
    assert [w.kind for w in report.warnings] == [flexure.WarningKind.safety_factor]
    assert all(d.termination == flexure.Termination.converged for d in report.designs)
    weak = flexure.design_mechanisms(flexure.MechanismSpec(**thesis, yield_strength=150e3 * PSI))
    assert not weak.designs and weak.termination == flexure.Termination.infeasible
    closest = weak.rejected[0]
    assert weak.message.startswith(
        f"no sub-class meets the specification; the closest, {closest.subclass}, fails on "
        f"{closest.binding}")
    assert closest.termination == flexure.Termination.infeasible
    assert closest.message == closest.binding
