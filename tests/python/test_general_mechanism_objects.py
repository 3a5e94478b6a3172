"""General planar mechanisms as Python objects (python/mechanism_objects.cpp): the description
built with the builder's calls gives the numbers of the same description read from TOML and of
the command line, and the solves meet independent values (Howell Table 11.2; the parallel
guide's small-displacement stiffness 24 EI/L^3)."""
import math
import pathlib
import warnings

import pytest

import flexure

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples"
MM = 1e-3


def howell_switch():
    """docs/examples/howell_bistable_switch.toml, built with the builder's calls."""
    deg = math.pi / 180
    return (flexure.GeneralMechanism("howell-bistable-switch")
            .body("ground", {"O2": (0.0, 0.0), "F": (37.754823 * MM, -1.292889 * MM)})
            .body("crank", {"O2": (0.0, 0.0), "A": (19.999726 * MM, -0.104658 * MM)})
            .body("coupler", {"A": (19.999726 * MM, -0.104658 * MM),
                              "B": (26.407468 * MM, 7.572636 * MM)})
            .body("rocker", {"B": (26.407468 * MM, 7.572636 * MM),
                             "F": (34.445177 * MM, 1.292889 * MM)})
            .pin("O2", "ground.O2", "crank.O2")
            .pin("A", "crank.A", "coupler.A")
            .pin("B", "coupler.B", "rocker.B")
            .flexure("pivot4", "ground.F", "rocker.F", width=6.3 * MM, thickness=2.3 * MM,
                     E=1.4e9, prbm=flexure.PrbmKind.small_length)
            .input(flexure.InputCoordinate.angle, "crank.O2", "crank.A", start=-5 * deg,
                   stop=33 * deg, count=77))


def quiet(solve, *args):
    # The switch's pivot is thick for its length (h/l = 0.55): a FlexureWarning says so.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", flexure.FlexureWarning)
        return solve(*args)


def test_builder_and_toml_give_the_same_switch():
    built = quiet(flexure.solve_general_prbm, howell_switch())
    read = quiet(flexure.solve_general_prbm,
                 flexure.GeneralMechanism.from_toml(str(EXAMPLES / "howell_bistable_switch.toml")))
    assert built.converged() and read.converged()
    assert len(built.points) == len(read.points) == 77
    for a, b in zip(built.input_load, read.input_load):
        assert a == pytest.approx(b, rel=1e-12, abs=1e-15)


def test_switch_equilibria_match_howell_table_11_2():
    # Howell Table 11.2: stable at theta2 = 0 and 32 deg, unstable at 18.7 deg (printed to 0.1
    # deg for the unstable one, to the degree for the stable ones).
    r = quiet(flexure.solve_general_prbm, howell_switch())
    found = [(math.degrees(e.input), e.stability.kind) for e in r.equilibria]
    assert len(found) == 3
    stable = flexure.StabilityKind.stable
    unstable = flexure.StabilityKind.unstable
    assert found[0][0] == pytest.approx(0.0, abs=0.5) and found[0][1] == stable
    assert found[1][0] == pytest.approx(18.7, abs=0.05) and found[1][1] == unstable
    assert found[2][0] == pytest.approx(32.0, abs=0.5) and found[2][1] == stable
    # The input load vanishes at each equilibrium and changes sign between them.
    loads = r.input_load
    assert min(loads) < 0 < max(loads)


def test_switch_objects_agree_with_the_command_line():
    r = quiet(flexure.solve_general_prbm, howell_switch())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", flexure.FlexureWarning)
        cli = flexure.mechanism.analyze(str(EXAMPLES / "howell_bistable_switch.toml"),
                                        model="prbm")
    prbm = cli["prbm"] if "prbm" in cli else cli
    assert len(prbm["input_load"]) == len(r.points)
    for a, b in zip(r.input_load, prbm["input_load"]):
        assert a == pytest.approx(b, rel=1e-9, abs=1e-12)


def parallel_guide(length, gap, width, thickness, E, stop):
    return (flexure.GeneralMechanism("parallel-guide")
            .body("ground", {"L": (0.0, 0.0), "R": (gap, 0.0)})
            .body("shuttle", {"L": (0.0, length), "R": (gap, length)})
            .flexure("left", "ground.L", "shuttle.L", width=width, thickness=thickness, E=E,
                     prbm=flexure.PrbmKind.fixed_guided)
            .flexure("right", "ground.R", "shuttle.R", width=width, thickness=thickness, E=E,
                     prbm=flexure.PrbmKind.fixed_guided)
            .input(flexure.InputCoordinate.x, "shuttle.L", start=0.0, stop=stop, count=5))


def test_parallel_guide_exact_stiffness_is_24_EI_over_L_cubed():
    # Two fixed-guided flexures in parallel, each 12 EI/L^3 for a small sideways motion (Howell
    # ch. 5); at 1e-3 L the large-deflection correction is of order 1e-6.
    L, b, h, E = 50 * MM, 10 * MM, 0.5 * MM, 200e9
    EI = E * b * h**3 / 12
    r = flexure.solve_general_exact(parallel_guide(L, 20 * MM, b, h, E, 1e-3 * L))
    assert r.converged()
    x, F = r.input[-1], r.input_load[-1]
    assert x == pytest.approx(1e-3 * L, rel=1e-12)
    assert F / x == pytest.approx(24 * EI / L**3, rel=1e-4)


def test_flexure_takes_a_material_object():
    # material=Material(...) instead of E=: the same stiffness 24 EI/L^3 (the E is the Material's);
    # E and material together, or neither, are refused naming the flexure.
    L, b, h = 50 * MM, 10 * MM, 0.5 * MM
    steel = flexure.Material(E=200e9, nu=0.29, yield_strength=1.2e9, density=7850.0)
    g = (flexure.GeneralMechanism("guide")
         .body("ground", {"L": (0.0, 0.0), "R": (20 * MM, 0.0)})
         .body("shuttle", {"L": (0.0, L), "R": (20 * MM, L)})
         .flexure("left", "ground.L", "shuttle.L", width=b, thickness=h, material=steel,
                  prbm=flexure.PrbmKind.fixed_guided)
         .flexure("right", "ground.R", "shuttle.R", width=b, thickness=h, material=steel,
                  prbm=flexure.PrbmKind.fixed_guided)
         .input(flexure.InputCoordinate.x, "shuttle.L", start=0.0, stop=1e-3 * L, count=5))
    by_E = flexure.solve_general_exact(parallel_guide(L, 20 * MM, b, h, 200e9, 1e-3 * L))
    by_material = flexure.solve_general_exact(g)
    assert list(by_material.input_load) == list(by_E.input_load)
    base = flexure.GeneralMechanism("x").body("a", {"P": (0.0, 0.0)}).body("b", {"P": (0.0, L)})
    with pytest.raises(flexure.InvalidInput, match="'f'.*one of them"):
        base.flexure("f", "a.P", "b.P", width=b, thickness=h, E=200e9, material=steel)
    with pytest.raises(flexure.InvalidInput, match="'f'.*one of them"):
        base.flexure("f", "a.P", "b.P", width=b, thickness=h)


def test_parallel_guide_chain_flexures_meet_the_exact_model():
    # Howell's chain algorithm per flexure (FlexureModel.chain) on the shipped parallel guide's
    # Delrin strips (docs/examples/parallel_guide.toml: l = 22 mm, b = 7 mm, h = 0.8 mm,
    # E = 2.9 GPa, x to 4 mm): the exact model's input loads within the chain's discretisation
    # error (measured 7e-7 of the largest load at N = 25, third order or better in 1/N:
    # tests/mechanisms/general_chain_flexure_test.cpp).
    guide = parallel_guide(22 * MM, 20 * MM, 7 * MM, 0.8 * MM, 2.9e9, 4 * MM)
    exact = flexure.solve_general_mixed(guide.set_flexure_model("", flexure.FlexureModel.exact))
    chain = flexure.solve_general_mixed(guide.set_flexure_model("", flexure.FlexureModel.chain,
                                                                elements=25))
    assert exact.converged() and chain.converged()
    assert [f.model for f in chain.flexure_models] == [flexure.FlexureModel.chain] * 2
    assert [f.elements for f in chain.flexure_models] == [25, 25]
    scale = max(abs(F) for F in exact.input_load)
    worst = max(abs(a - e) for a, e in zip(chain.input_load, exact.input_load))
    assert 0 < worst < 2e-6 * scale


def test_parallel_guide_points_report_reactions_stresses_and_shapes():
    # At a small sideways motion each flexure is the linear clamped-guided beam: end moment
    # 6 EI x/L^2, bending stress M c/I at its ends; the ground's reaction balances the input
    # force.
    L, b, h, E = 50 * MM, 10 * MM, 0.5 * MM, 200e9
    EI, c = E * b * h**3 / 12, h / 2
    r = flexure.solve_general_exact(parallel_guide(L, 20 * MM, b, h, E, 1e-3 * L))
    p = r.points[-1]
    x = p.input
    # The input force F acts at the tips' height: the stage's moment balance puts axial forces
    # +-N = F L/(2 gap) in the flexures (gap 20 mm), which add N/A to the bending stress.
    # Both are linear theory's: the axial forces' moment N x changes them by order x/L = 1e-3.
    N = abs(p.input_load) * L / (2 * 20 * MM)
    for f in p.flexures:
        assert abs(f.moment) * c / (EI / E) == pytest.approx(6 * E * x * c / L**2, rel=2e-3)
        assert abs(f.axial_force) == pytest.approx(N, rel=2e-3)
        assert f.max_stress == pytest.approx(6 * E * x * c / L**2 + N / (b * h), rel=2e-3)
        assert f.max_stress_from == "shape"
        assert len(f.shape_x) == len(f.shape_y) == 33
        assert f.shape_x[-1] - f.shape_x[0] == pytest.approx(x, rel=1e-9)
        assert f.on_a.fx == pytest.approx(-f.on_b.fx, rel=1e-9)
    assert p.ground_reaction.fx == pytest.approx(-p.input_load, rel=1e-8)
    assert p.joints == []


def test_bad_descriptions_raise_invalid_input_naming_the_item():
    g = (flexure.GeneralMechanism("bad")
         .body("ground", {"O": (0.0, 0.0)})
         .body("link", {"O": (0.0, 0.0), "P": (0.0, 0.0), "Q": (0.01, 0.0)})
         .pin("O", "ground.O", "link.O")
         .flexure("f", "link.P", "link.Q", width=1e-3, thickness=1e-4, E=2e11)
         .input(flexure.InputCoordinate.x, "link.Q", start=0.0, stop=1e-3, count=3))
    with pytest.raises(flexure.InvalidInput, match="'f'"):
        g.validate()
    with pytest.raises(flexure.InvalidInput, match="'nobody'"):
        flexure.GeneralMechanism().body("a", {"P": (0.0, 0.0)}).point("nobody.P")
    with pytest.raises(flexure.InvalidInput, match="tolerance"):
        flexure.GeneralPrbmOptions(tolerance=-1.0)


def test_stable_points_of_the_switch_under_torque_control():
    # select_stable_points (`mechanism analyze --stable`): loading the switch by a dead torque
    # from 0 to 1.2 N m it keeps its first branch up to 0.2 N m and snaps to the second before
    # 0.3 N m (the limit torque 0.2676 N m of the path lies between them).
    m = flexure.GeneralMechanism.from_toml(str(EXAMPLES / "howell_bistable_switch.toml"))
    m.input(flexure.InputCoordinate.angle, "crank.O2", "crank.A",
            control=flexure.InputControl.force, start=0.0, stop=1.2, count=13)
    path = quiet(flexure.solve_general_prbm, m)
    assert path.converged()
    assert len(path.points) == 19
    s = flexure.select_stable_points(m, path)
    assert s.stable and s.snaps == 1 and s.grid_values == 13 and s.without_stable == 0
    assert "between 0.2 N m and 0.3 N m" in s.search
    assert 0.2 < path.limit_loads[0] < 0.3
    loads = s.result.input_load
    assert loads == pytest.approx([0.1 * k for k in range(13)], abs=1e-9)
    angles = s.result.input
    assert all(a < path.limit_inputs[0] for a in angles[:3])
    assert all(a > path.limit_inputs[1] for a in angles[3:])
    assert all(p.force_control.kind == flexure.StabilityKind.stable for p in s.result.points)


def test_exact_progress_and_keyboard_interrupt(interrupting_progress):
    # The exact stroke reports each recorded point, (done, count) with done increasing to count,
    # and stops with the exception its callable raises; the module keeps working.
    L, b, h, E = 50 * MM, 10 * MM, 0.5 * MM, 200e9
    guide = parallel_guide(L, 20 * MM, b, h, E, 0.2 * L)
    calls = []
    r = flexure.solve_general_exact(guide, progress=lambda d, t: calls.append((d, t)))
    assert r.converged() and len(r.points) == 5
    assert calls == [(k, 5) for k in range(1, 6)]
    mixed = []
    auto = (parallel_guide(L, 20 * MM, b, h, E, 0.2 * L)
            .set_flexure_model("left", flexure.FlexureModel.auto, tolerance=1e-3)
            .set_flexure_model("right", flexure.FlexureModel.auto, tolerance=1e-3))
    assert flexure.solve_general_mixed(auto, progress=lambda d, t: mixed.append(d)).converged()
    assert mixed and mixed == sorted(mixed) and mixed[-1] == 5

    stop = interrupting_progress(2)
    with pytest.raises(KeyboardInterrupt):
        flexure.solve_general_exact(guide, progress=stop)
    assert stop.seen == [1, 2]
    again = flexure.solve_general_exact(guide)
    assert again.input_load == pytest.approx(r.input_load, rel=1e-12)
