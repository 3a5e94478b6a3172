"""The module's classes over the library's types (python/objects.cpp; docs/python.md "Objects").

Checked against independent values: Howell's worked example of sec. 2.9.2 (alpha2 = 3.087003 gives
theta0 = 1 rad, a/l = 0.7383564, b/l = 0.6103718; his Table of the n = 0 cantilever), the shooting
method against the elliptic solution (two independent solvers), a chain built from objects against
the same chain read from TOML by the tool (bitwise), and the tool's own answer for the same load.
"""
import math
import os

import numpy
import pytest

import flexure

HOWELL_ALPHA2 = 3.087003
HOWELL_A = 0.7383564
HOWELL_B = 0.6103718


def test_elliptic_solver_gives_howell_2_9_2():
    r = flexure.EllipticSolver().solve(flexure.EndLoad.howell(0, HOWELL_ALPHA2, 0))
    assert r.termination == flexure.Termination.converged
    assert r.converged()
    assert abs(r.tip.a_over_l - HOWELL_A) < 1e-7
    assert abs(r.tip.b_over_l - HOWELL_B) < 1e-7
    assert abs(r.tip.theta0 - 1.0) < 1e-6
    assert isinstance(r, flexure.SolveStatus)
    # The inverse problem: theta0 = 1 rad needs alpha2 = 3.087003 (the same table entry).
    inv = flexure.EllipticSolver().solve_for_tip_angle(n=0, theta0=1.0)
    assert abs(inv.load.Fy - HOWELL_ALPHA2) < 1e-6


def test_shooting_agrees_with_elliptic_and_takes_options():
    load = flexure.EndLoad.howell(0.5, 4.0, 0.2)
    exact = flexure.EllipticSolver().solve(load)
    solver = flexure.ShootingSolver(flexure.ShootingSolver.Options(rtol=1e-10))
    assert solver.options.rtol == 1e-10
    r = solver.solve(load)
    assert r.termination == flexure.Termination.converged
    pose = r.tip_pose()
    assert abs(pose.a_over_l - exact.tip.a_over_l) < 1e-8
    assert abs(pose.b_over_l - exact.tip.b_over_l) < 1e-8
    assert abs(pose.theta0 - exact.tip.theta0) < 1e-8


def test_bad_options_raise_invalid_input_naming_the_field():
    with pytest.raises(flexure.InvalidInput, match="rtol"):
        flexure.ShootingSolver.Options(rtol=-1)
    assert issubclass(flexure.InvalidInput, ValueError)
    with pytest.raises(flexure.InvalidInput, match="E"):
        flexure.Material(E=-1.0)
    with pytest.raises(flexure.InvalidInput, match="exactly one"):
        flexure.BeamProblem(alpha2=1.0, theta0=0.5)


def test_keyword_typo_is_a_type_error_naming_the_keyword():
    with pytest.raises(TypeError, match="rtl"):
        flexure.ShootingSolver.Options(rtl=1e-10)
    with pytest.raises(TypeError, match="lenght"):
        flexure.FlexibleSegment(lenght=1.0)


def test_shape_columns_are_float64_arrays():
    solver = flexure.ShootingSolver(flexure.ShootingSolver.Options(shape_points=51))
    r = solver.solve(flexure.EndLoad.howell(0, 2.0))
    shape = r.shape
    for column in (shape.s, shape.x, shape.y, shape.theta):
        assert isinstance(column, numpy.ndarray)
        assert column.dtype == numpy.float64 and column.shape == (51,)
    matrix = numpy.asarray(shape)
    assert matrix.shape == (51, 4)
    assert matrix[-1, 1] == pytest.approx(r.tip.x, abs=1e-12)
    assert matrix[-1, 2] == pytest.approx(r.tip.y, abs=1e-12)
    # Statics of a tip force: the angle at the tip is the tip's theta.
    assert shape.theta[-1] == pytest.approx(r.tip.theta, abs=1e-12)


def test_chain_of_objects_equals_the_chain_read_from_toml():
    # docs/examples/two_flexures_rigid_link.toml, written as objects.
    chain = flexure.SegmentChain(
        segments=[flexure.FlexibleSegment(length=0.3, EI=1.0),
                  flexure.RigidSegment(length=0.4),
                  flexure.FlexibleSegment(length=0.3, EI=1.0)],
        tip_load=flexure.TipLoad(Fy=2.0))
    r = flexure.ShootingSolver().solve(chain)
    assert r.termination == flexure.Termination.converged
    path = os.path.join(os.environ.get("FLEXURE_SOURCE_DIR", os.path.join(
        os.path.dirname(__file__), "..", "..")), "docs", "examples", "two_flexures_rigid_link.toml")
    tool = flexure.beam(chain=path, method="shooting")
    # Bitwise: the same chain, the same solver and options.
    assert r.tip.x == tool["a_over_l"]
    assert r.tip.y == tool["b_over_l"]
    assert r.tip.theta == tool["theta0"]
    # And the object path of solve_beam gives the same.
    s = flexure.solve_beam(flexure.BeamProblem(chain=chain), flexure.BeamMethod.shooting)
    assert s.tip.a_over_l == tool["a_over_l"]


def test_physical_chain_of_objects_gives_howell_pivot():
    # Howell sec. 5.1 (eqs. 5.26-5.34): polypropylene E = 2e5 psi, flexible 0.5 in of 0.75 x
    # 0.03 in, rigid 5 in, 0.096 lbf: b = 3 in, sigma_max = 3900 psi (the PRBM's; 2 %).
    inch, lbf = 0.0254, 4.4482216152605
    psi = lbf / inch**2
    section = flexure.Section.rectangle(width=0.75 * inch, thickness=0.03 * inch)
    material = flexure.Material(E=2e5 * psi, yield_strength=4000 * psi)
    EI = material.E * section.second_moment()
    chain = flexure.SegmentChain(
        segments=[flexure.FlexibleSegment(length=0.5 * inch, EI=EI),
                  flexure.RigidSegment(length=5 * inch)],
        tip_load=flexure.TipLoad(Fy=0.096 * lbf))
    physical = flexure.PhysicalChain(
        chain=chain,
        segments=[flexure.SegmentProperties(section=section, material=material), None])
    got = flexure.solve_physical_chain(physical, method=flexure.BeamMethod.shooting)
    assert got.solution.converged()
    assert got.physical.tip_y / inch == pytest.approx(3.0, rel=0.02)
    assert got.physical.max_stress / psi == pytest.approx(3900.0, rel=0.02)
    assert got.physical.safety_factor == pytest.approx(4000 * psi / got.physical.max_stress,
                                                       rel=1e-12)
    with pytest.raises(flexure.InvalidInput, match="is not E I"):
        flexure.PhysicalChain(
            chain=chain,
            segments=[flexure.SegmentProperties(
                section=section, material=flexure.Material(E=1e9)), None])


def test_physical_chain_plate_on_bends_with_the_plate_modulus():
    # Pure bending by an end moment: theta0 = M L (1 - nu^2)/(E I) with plate "on" (by hand); the
    # segment's EI must be E I/(1 - nu^2) (chain_modulus), E I is refused naming the rule.
    section = flexure.Section.rectangle(width=0.127, thickness=0.00131)
    material = flexure.Material(E=200e9, nu=0.3)
    props = flexure.SegmentProperties(section=section, material=material, plate="on")
    assert props.plate == "on"
    assert props.chain_modulus() == pytest.approx(200e9 / 0.91, rel=1e-15)
    I = section.second_moment()
    chain = flexure.SegmentChain(
        segments=[flexure.FlexibleSegment(length=0.1, EI=props.chain_modulus() * I)],
        tip_load=flexure.TipLoad(M=10.0))
    got = flexure.solve_physical_chain(flexure.PhysicalChain(chain=chain, segments=[props]),
                                       method=flexure.BeamMethod.shooting)
    assert got.solution.converged()
    assert got.solution.tip.theta0 == pytest.approx(10.0 * 0.1 * 0.91 / (200e9 * I), rel=1e-9)
    beam_chain = flexure.SegmentChain(
        segments=[flexure.FlexibleSegment(length=0.1, EI=200e9 * I)],
        tip_load=flexure.TipLoad(M=10.0))
    with pytest.raises(flexure.InvalidInput, match="plate on"):
        flexure.PhysicalChain(chain=beam_chain, segments=[props])


def test_solve_beam_object_path_matches_the_tool():
    tool = flexure.beam(alpha2=2.0)
    s = flexure.solve_beam(flexure.BeamProblem(alpha2=2.0))
    assert s.method == flexure.BeamMethod.elliptic
    assert s.tip.a_over_l == tool["a_over_l"]
    assert s.tip.b_over_l == tool["b_over_l"]
    assert s.tip.theta0 == tool["theta0"]
    assert s.termination == flexure.Termination.converged


def test_warnings_of_a_result_are_flexure_warnings():
    # The PRBM chosen outside its validity limits says so in its result's warnings (solve_beam
    # adds none itself; the BCM beyond its deflection range does).
    problem = flexure.BeamProblem(alpha2=40.0)
    with pytest.warns(flexure.FlexureWarning):
        s = flexure.solve_beam(problem, flexure.BeamMethod.bcm)
    assert s.warnings and all(isinstance(w.text, str) for w in s.warnings)
    assert not math.isnan(s.tip.a_over_l)


def _outcome(call):
    import warnings as w
    with w.catch_warnings(record=True) as caught:
        w.simplefilter("always")
        try:
            result = ("ok", call())
        except (flexure.InvalidInput, flexure.NoConvergence) as e:
            result = (type(e).__name__, str(e), getattr(e, "reached", None))
    return result, [str(c.message) for c in caught]


def _same(a, b):
    if isinstance(a, dict):
        return isinstance(b, dict) and list(a) == list(b) and all(_same(a[k], b[k]) for k in a)
    if isinstance(a, numpy.ndarray):
        return numpy.array_equal(a, b, equal_nan=True)
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if isinstance(a, float) and math.isnan(a):
        return isinstance(b, float) and math.isnan(b)
    return a == b


@pytest.mark.parametrize("keywords", [
    dict(alpha2=2.0),
    dict(alpha2=2, n=1, mu=0.5, stability="off"),
    dict(theta0="30deg"),
    dict(theta0=0.5, method="Shooting", shape=5),
    dict(b_over_l=0.4, n=-1.0),
    dict(alpha2=25.0, method="prbm"),                    # outside the PRBM's validity: a warning
    dict(alpha2=1.0, boundary="guided", method="shooting"),
    dict(alpha2=1.0, boundary="pinned", tip_x=0.9, method="chain", elements=40, increments=2),
    dict(alpha2=float("nan")),                           # refused, the command's message
    dict(alpha2=1.0, tip_x=0.5),                         # tip-x on a free end: refused
    dict(theta0=400.0),                                  # a plain angle above a turn: a warning
    dict(alpha2=2.0, stable=True, stability="on"),
    dict(alpha2=1.0, boundary="Free", follower=0.5, method="shooting", integrator="cvodes"),
])
def test_scalar_beam_without_a_command_line_equals_the_command(keywords):
    # flexure.beam takes the path without a command line for these keywords; the command run
    # in-process (the path before) must give the same dict, message and warnings.
    from flexure import _beam, _command
    assert _beam._fast_values(keywords.items()) is not None
    fast = _outcome(lambda: flexure.beam(**keywords))
    slow = _outcome(lambda: _command.run(["beam"], keywords, switches={"stable"}))
    assert _same(fast, slow), (fast, slow)


# --- The ladder's models (python/ladder_objects.cpp) -----------------------------------------------
# Each object gives the tool's own answer for the same load (flexure.beam(method=...) runs the same
# library through the command; an independent path through the bindings), and refuses a bad option
# naming it.

LADDER_LOAD = dict(n=0.4, alpha2=1.5, mu=0.3)


def _ladder_objects():
    return {
        "linear": flexure.LinearBeamSolver(),
        "prbm3r": flexure.Prbm3rSolver(flexure.Prbm3rSolver.Options(constants="su")),
        "bcm": flexure.BcmSolver(flexure.BcmSolver.Options(slenderness=0.0)),
        "cbcm": flexure.ChainedBcmSolver(flexure.ChainedBcmSolver.Options(elements=6)),
    }


@pytest.mark.filterwarnings("ignore::flexure.FlexureWarning")  # the BCM beyond |y| = 0.1
@pytest.mark.parametrize("method", ["linear", "prbm3r", "bcm", "cbcm"])
def test_ladder_objects_give_the_tools_answer(method):
    load = flexure.EndLoad.howell(LADDER_LOAD["n"], LADDER_LOAD["alpha2"], LADDER_LOAD["mu"])
    r = _ladder_objects()[method].solve(flexure.CantileverCase(load=load))
    assert r.converged(), r.message
    assert isinstance(r, flexure.SolveStatus)
    tip = r.tip_pose() if method == "cbcm" else r.tip
    tool = flexure.beam(method=method, **LADDER_LOAD)
    assert abs(tip.a_over_l - tool["a_over_l"]) < 1e-12
    assert abs(tip.b_over_l - tool["b_over_l"]) < 1e-12
    assert abs(tip.theta0 - tool["theta0"]) < 1e-12
    # The same solve from the EndLoad alone (the free cantilever).
    again = _ladder_objects()[method].solve(load)
    again_tip = again.tip_pose() if method == "cbcm" else again.tip
    assert again_tip.b_over_l == tip.b_over_l


@pytest.mark.filterwarnings("ignore::flexure.FlexureWarning")  # the BCM beyond |y| = 0.1
def test_ladder_objects_on_a_guided_end_and_a_chain():
    load = flexure.EndLoad.howell(0.5, 8.0)
    guided = flexure.CantileverCase(load=load, end=flexure.EndCondition.guided)
    tool = flexure.beam(method="bcm", n=0.5, alpha2=8.0, boundary="guided")
    r = flexure.BcmSolver().solve(guided)
    assert abs(r.tip.b_over_l - tool["b_over_l"]) < 1e-12
    # The chained BCM of the chain equals that of the cantilever it is made from.
    cbcm = flexure.ChainedBcmSolver(flexure.ChainedBcmSolver.Options(elements=8))
    a = cbcm.solve(guided)
    b = cbcm.solve(guided.to_chain())
    assert a.tip.y == b.tip.y
    assert math.isinf(a.axial_stiffness)
    assert cbcm.model_name() == "cbcm"
    assert len(numpy.asarray(a.nodes)) == 9


@pytest.mark.parametrize("make, field", [
    (lambda: flexure.ChainedBcmSolver.Options(elements=0), "elements"),
    (lambda: flexure.ChainedBcmSolver.Options(slenderness=-1.0), "slenderness"),
    (lambda: flexure.ChainedBcmSolver.Options(tolerance=float("nan")), "tolerance"),
    (lambda: flexure.BcmSolver.Options(slenderness=float("inf")), "slenderness"),
    (lambda: flexure.Prbm3rSolver.Options(tolerance=0.0), "tolerance"),
    (lambda: flexure.Prbm3rSolver.Options(max_load_steps=0), "max_load_steps"),
    (lambda: flexure.Prbm3rSolver.Options(constants="howell"), "su-moment"),
])
def test_ladder_options_raise_invalid_input_naming_the_field(make, field):
    with pytest.raises(flexure.InvalidInput, match=field):
        make()


def test_ladder_keyword_typo_is_a_type_error():
    with pytest.raises(TypeError, match="element"):
        flexure.ChainedBcmSolver.Options(element=4)


def test_chained_bcm_object_takes_the_segments_ea():
    # The inclined bistable beam (docs/examples/inclined_bistable_path.toml) moved to y = 2 mm:
    # the object's d is the segment's EA L^2/EI = 12 (L/t)^2.
    E, b, h, L = 1.379e9, 12.55e-3, 1.5e-3, 70e-3
    beam = flexure.FlexibleSegment(length=L, EI=E * b * h**3 / 12, EA=E * b * h)
    chain = flexure.SegmentChain(
        segments=[flexure.RigidSegment(length=0.0, angle_offset=math.radians(5.5)), beam],
        end=flexure.EndCondition.fixed, prescribed=flexure.TipPrescription(y=2e-3))
    r = flexure.ChainedBcmSolver().solve(chain)
    assert r.converged(), r.message
    assert abs(r.axial_stiffness / (12 * (L / h) ** 2) - 1) < 1e-9
    with pytest.raises(flexure.InvalidInput, match="EA"):
        flexure.ChainedBcmSolver(flexure.ChainedBcmSolver.Options(slenderness=46.667)).solve(chain)


def test_command_functions_live_under_flexure_cli_and_keep_their_names():
    # Issue 28 item 7: the command functions are flexure.cli's; the first names are the same
    # function objects, so existing scripts are unchanged.
    import flexure.cli
    for name in ("beam", "path", "sweep", "cfm", "dynamics", "bench", "validate", "materials",
                 "read"):
        assert getattr(flexure.cli, name) is getattr(flexure, name), name
    for name in ("design", "mechanism", "prbm", "map"):
        assert getattr(flexure.cli, name) is getattr(flexure, name), name
    assert flexure.cli.design.cfm is flexure.design.cfm
    assert all(hasattr(flexure.cli, n) for n in flexure.cli.__all__)
    # The command function and the solver object answer Howell's example 2.9.2 alike.
    by_command = flexure.cli.beam(alpha2=HOWELL_ALPHA2, method="elliptic")
    assert abs(by_command["theta0"] - 1.0) < 1e-6
    assert abs(by_command["a_over_l"] - HOWELL_A) < 1e-7
