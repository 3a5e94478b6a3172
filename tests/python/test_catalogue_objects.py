"""The constant-force slider mechanisms as Python objects (python/catalogue_objects.cpp):
analyze_mechanism on a MechanismDesign gives the command line's numbers and Weight's example 1
force, reports progress, and stops on KeyboardInterrupt (a raising callable, and Ctrl-C)."""
import pathlib

import pytest

import flexure

LBF = 4.4482216152605  # N


def test_example_one_matches_the_command_line_and_weights_target():
    d = flexure.MechanismDesign.builtin("1A-lpp")
    a = flexure.analyze_mechanism(d, flexure.AnalysisOptions(points=20))
    assert a.converged() and a.termination == flexure.Termination.converged
    assert a.has_exact
    assert len(a.displacement) == len(a.force_prbm) == len(a.force_exact) == 20
    # Weight 2001 §8.5.1, Table 8.4: the design is sized for F = 25 lbf (PRBM, one half).
    assert a.mean_force_prbm == pytest.approx(25 * LBF, rel=0.01)
    cli = flexure.mechanism.analyze("1A-lpp", points=20)
    for ours, theirs in ((a.force_prbm, cli["force_prbm"]), (a.force_exact, cli["force_exact"])):
        assert ours == pytest.approx(theirs, rel=1e-12)
    assert a.safety_factor == pytest.approx(cli["safety_factor"], rel=1e-12)
    assert a.percent_constant_force_exact == pytest.approx(cli["percent_constant_force_exact"],
                                                           rel=1e-12)


def test_a_design_from_toml_text_needs_no_file():
    text = (pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples"
            / "mechanism_lpp.toml").read_text()
    from_text = flexure.MechanismDesign.from_toml_text(text, "lpp.toml")
    options = flexure.AnalysisOptions(points=10, exact=False)
    a = flexure.analyze_mechanism(from_text, options)
    b = flexure.analyze_mechanism(
        flexure.MechanismDesign.from_toml(
            str(pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples"
                / "mechanism_lpp.toml")), options)
    assert a.force_prbm == b.force_prbm
    with pytest.raises(flexure.InvalidInput, match="bad.toml"):
        flexure.MechanismDesign.from_toml_text("config = 'nope'\n", "bad.toml")


def test_a_design_holds_its_material_and_keeps_e_and_yield_strength():
    # Howell's example 1 (Compliant Mechanisms §10.1.4): polypropylene E = 1655 MPa, and the
    # lower end of Table C.2's tensile yield strength, 4500 psi.
    d = flexure.MechanismDesign.builtin("howell-ex1")
    assert d.material.E == 1655e6
    assert d.material.yield_strength == pytest.approx(4500 * 6894.757293, rel=1e-15)
    assert d.E == d.material.E and d.yield_strength == d.material.yield_strength
    assert d.material_id is None  # given by value, not a data/materials.csv row


def test_progress_is_monotone_and_reaches_the_total():
    calls = []
    flexure.analyze_mechanism(flexure.MechanismDesign.builtin("1A-lpp"),
                              flexure.AnalysisOptions(points=30),
                              progress=lambda done, total: calls.append((done, total)))
    assert calls
    dones = [d for d, _ in calls]
    assert dones == sorted(dones)
    assert calls[-1][0] == calls[-1][1] == 3 * 30  # stroke, stresses, stability


def test_a_callable_that_raises_stops_the_analysis():
    calls = []

    def progress(done, total):
        calls.append(done)
        if len(calls) == 3:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        flexure.analyze_mechanism(flexure.MechanismDesign.builtin("1A-lpp"),
                                  flexure.AnalysisOptions(points=200), progress=progress)
    assert len(calls) == 3
    # The module keeps working after the interrupted call.
    assert flexure.analyze_mechanism(flexure.MechanismDesign.builtin("1A-lpp"),
                                     flexure.AnalysisOptions(points=5)).converged()


def test_ctrl_c_interrupts_a_long_analysis_without_a_callable(interrupt_python):
    # About a minute of work without the interrupt; SIGINT 1 s after it starts must end it with
    # KeyboardInterrupt within a few seconds (the bindings look for signals every 50 ms).
    code = ("import flexure, sys\n"
            "d = flexure.MechanismDesign.builtin('1A-lpp')\n"
            "print('started', flush=True)\n"
            "flexure.analyze_mechanism(d, flexure.AnalysisOptions(points=100000))\n"
            "print('finished', flush=True)\n")
    assert interrupt_python(code, timeout=30) < 5.0


def test_analysis_warnings_are_flexure_warnings_with_the_command_lines_text():
    # The example's strip in a material with a yield strength of 1 MPa yields: the analysis's
    # warning (MechanismAnalysis.warnings, the one channel) is a FlexureWarning, worded as the
    # command line prints it.
    text = (pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples"
            / "mechanism_lpp.toml").read_text().replace("yield_strength = 34.5e6",
                                                         "yield_strength = 1e6")
    design = flexure.MechanismDesign.from_toml_text(text, "weak.toml")
    with pytest.warns(flexure.FlexureWarning,
                      match=r"pivot 1 of lpp-example yields: max stress .* >= yield strength "
                            r"1e\+06 Pa"):
        flexure.analyze_mechanism(design, flexure.AnalysisOptions(points=10, exact=False))
