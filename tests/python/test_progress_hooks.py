"""Progress callables and Ctrl-C on the long calls that had none (docs/python.md "Progress and
Ctrl-C"): solve_general_prbm and select_stable_points (per recorded point, per grid value),
refine_design_exact (per exact stroke, against its budget), and the command functions whose work
stops between steps (flexure.dynamics per frequency, flexure.design.cfm per scan point and local
run of its PRBM synthesis and, with model="exact", per exact stroke, flexure.mechanism.analyze
per point of the exact stroke, flexure.map.cfm per block of points). For each: the steps reach
a total counted independently, the answer is the one without a callable, and a
KeyboardInterrupt from the callable (conftest's interrupting_progress) stops the call after the
step it raises at."""
import math
import pathlib
import warnings

import numpy as np
import pytest

import flexure

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples"


def switch_under_torque():
    """Howell's bistable switch loaded by a dead torque from 0 to 1.2 N m at 13 values: the path
    crosses 0, 0.1 and 0.2 N m three times (two stable branches and the unstable one between,
    below the limit torque 0.2676 N m) and the ten others once: 19 recorded points."""
    m = flexure.GeneralMechanism.from_toml(str(EXAMPLES / "howell_bistable_switch.toml"))
    m.input(flexure.InputCoordinate.angle, "crank.O2", "crank.A",
            control=flexure.InputControl.force, start=0.0, stop=1.2, count=13)
    return m


def quiet(solve, *args, **kwargs):
    # The switch's pivot is thick for its length (h/l = 0.55): a FlexureWarning says so.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", flexure.FlexureWarning)
        return solve(*args, **kwargs)


def test_prbm_path_reports_each_recorded_point(interrupting_progress):
    m = switch_under_torque()
    plain = quiet(flexure.solve_general_prbm, m)
    calls = []
    r = quiet(flexure.solve_general_prbm, m, progress=lambda d, t: calls.append((d, t)))
    assert r.converged() and len(r.points) == 19
    # One call per recorded point; done counts them, capped at the 13 grid values.
    assert calls == [(min(k, 13), 13) for k in range(1, 20)]
    assert r.input == plain.input and r.input_load == plain.input_load
    assert r.limit_loads == plain.limit_loads

    stop = interrupting_progress(2)
    with pytest.raises(KeyboardInterrupt):
        quiet(flexure.solve_general_prbm, m, progress=stop)
    assert stop.seen == [1, 2]
    assert quiet(flexure.solve_general_prbm, m).input_load == plain.input_load


def test_stable_selection_reports_each_grid_value(interrupting_progress):
    m = switch_under_torque()
    path = quiet(flexure.solve_general_prbm, m)
    plain = flexure.select_stable_points(m, path)
    calls = []
    s = flexure.select_stable_points(m, path, progress=lambda d, t: calls.append((d, t)))
    assert calls == [(k, 13) for k in range(1, 14)]
    assert s.result.input == plain.result.input and s.search == plain.search
    assert s.snaps == plain.snaps == 1

    stop = interrupting_progress(2)
    with pytest.raises(KeyboardInterrupt):
        flexure.select_stable_points(m, path, progress=stop)
    assert stop.seen == [1, 2]


# A specification whose best design is lpp: R alone is free in its exact refinement (pivots 2
# and 3 are pins), so the search makes 1 + 2 x 1 local runs of at most 300 strokes each.
SPEC = dict(force=10.0, stroke=0.01, E=200e9, yield_strength=1.2e9, safety_factor=1.5,
            length=(0.06, 0.15), exact=False, configs=["lpp"])


def test_exact_refinement_reports_each_stroke_against_its_budget(interrupting_progress):
    spec = flexure.MechanismSpec(**SPEC)
    best = flexure.design_mechanisms(spec).designs[0]
    free = 1 + sum(1 for h in best.thicknesses[1:] if h > 0)  # R, and K1, K2 where sprung
    runs = 1 + 2 * free
    plain = flexure.refine_design_exact(spec, best)
    calls = []
    refined = flexure.refine_design_exact(spec, best, progress=lambda d, t: calls.append((d, t)))
    total = 1 + runs * (300 + 1)
    assert all(t == total for _, t in calls)
    dones = [d for d, _ in calls]
    assert dones == sorted(dones) and dones[0] == 1 and dones[-1] == total
    # The start's confirmation, each stroke of the search, each run's confirmation.
    assert len(calls) == 1 + refined.exact_evaluations + runs
    for key in ("l_tot", "r2", "r3", "R", "K1", "K2", "percent_constant_force_exact",
                "force_exact", "exact_evaluations", "feasible", "binding"):
        assert getattr(refined, key) == getattr(plain, key), key
    assert refined.thicknesses == plain.thicknesses

    stop = interrupting_progress(2)
    with pytest.raises(KeyboardInterrupt):
        flexure.refine_design_exact(spec, best, progress=stop)
    assert stop.seen == [1, 2]


def test_dynamics_reports_each_frequency_and_writes_nothing_when_stopped(interrupting_progress,
                                                                         tmp_path):
    plain = flexure.dynamics(mechanism="2B-lplm", omega="5:50:10", samples=64)
    calls = []
    r = flexure.dynamics(mechanism="2B-lplm", omega="5:50:10", samples=64,
                         progress=lambda d, t: calls.append((d, t)))
    assert calls == [(k, 10) for k in range(1, 11)]
    for key in ("omega", "mean_force", "median_force", "min_force", "max_force",
                "peak_to_peak_force", "percent_constant_force"):
        assert len(r[key]) == 10 and np.array_equal(r[key], plain[key]), key

    out = tmp_path / "dynamics.h5"
    stop = interrupting_progress(2)
    with pytest.raises(KeyboardInterrupt):
        flexure.dynamics(mechanism="2B-lplm", omega="5:50:10", samples=64, out=str(out),
                         progress=stop)
    assert stop.seen == [1, 2]
    # The HDF5 file is written whole at the end or not at all (no temporary left either).
    assert list(tmp_path.iterdir()) == []


def test_exact_cfm_design_reports_each_stroke(interrupting_progress):
    args = dict(config="lpp", d=40, objective="max-pcf", model="exact", exact_starts=1)
    plain = flexure.design.cfm(**args)
    calls = []
    r = flexure.design.cfm(**args, progress=lambda d, t: calls.append((d, t)))
    # Local runs: the PRBM optimum, the printed sub-classes of lpp at 40 % inside the toggle
    # interval, one Halton start; the JSON's exact_starts counts them.
    runs = r["exact_starts"]
    assert runs >= 2
    total = 1 + runs * (300 + 1)
    # First the PRBM synthesis (its own total, ending at it), then the exact strokes.
    first_exact = next(i for i, (_, t) in enumerate(calls) if t == total)
    synthesis, calls = calls[:first_exact], calls[first_exact:]
    assert synthesis and synthesis[-1][0] == synthesis[-1][1] != total
    assert all(t == total for _, t in calls)
    dones = [d for d, _ in calls]
    assert dones == sorted(dones) and dones[0] == 1 and dones[-1] == total
    assert len(calls) == 1 + r["exact_evaluations"] + runs
    for key in ("R", "percent_constant_force_exact", "exact_evaluations"):
        assert r[key] == plain[key], key

    stop = interrupting_progress(2)
    with pytest.raises(KeyboardInterrupt):
        flexure.design.cfm(**args, progress=stop)
    assert stop.seen == [1, 2]


def test_prbm_cfm_design_reports_its_scan_and_local_runs(interrupting_progress):
    # One phase (coarse_stride 1: no polish), one region (lpp: R alone): 40 scan points and at
    # most 2 local runs, so 42 steps; the scan's points come first, in order.
    args = dict(config="lpp", d=40, objective="max-pcf", scan_points=40, starts=2,
                coarse_stride=1)
    plain = flexure.design.cfm(**args)
    calls = []
    r = flexure.design.cfm(**args, progress=lambda d, t: calls.append((d, t)))
    assert calls[:40] == [(k, 42) for k in range(1, 41)]
    dones = [d for d, _ in calls]
    assert dones == sorted(dones) and calls[-1] == (42, 42) and len(calls) <= 43
    for key in ("R", "percent_constant_force", "evaluations"):
        assert r[key] == plain[key], key

    stop = interrupting_progress(3)
    with pytest.raises(KeyboardInterrupt):
        flexure.design.cfm(**args, progress=stop)
    assert stop.seen == [1, 2, 3]


def test_mechanism_analyze_reports_the_exact_stroke(interrupting_progress):
    plain = flexure.mechanism.analyze("1A-lpp", points=20, method="exact")
    calls = []
    r = flexure.mechanism.analyze("1A-lpp", points=20, method="exact",
                                  progress=lambda d, t: calls.append((d, t)))
    # As analyze_mechanism's: stroke points, stresses and stability verdicts.
    assert calls[-1] == (3 * 20, 3 * 20)
    dones = [d for d, _ in calls]
    assert dones == sorted(dones)
    assert np.array_equal(r["force_exact"], plain["force_exact"])

    stop = interrupting_progress(2)
    with pytest.raises(KeyboardInterrupt):
        flexure.mechanism.analyze("1A-lpp", points=20, method="exact", progress=stop)
    assert stop.seen == [1, 2]
    assert math.isfinite(flexure.mechanism.analyze("1A-lpp", points=5)["mean_force_exact"])


def test_cfm_map_reports_its_blocks_and_writes_nothing_when_stopped(tmp_path, interrupting_progress):
    # 40 points of the exact model in blocks of 16 (cfm_map_file.cpp): 16, 32, 40 of 40.
    args = dict(config="lpp", R="0.5:1.5:40", d=40, model="exact", exact_points=10)
    plain = flexure.map.cfm(**args, out=str(tmp_path / "plain.h5"))
    calls = []
    r = flexure.map.cfm(**args, out=str(tmp_path / "progress.h5"),
                        progress=lambda d, t: calls.append((d, t)))
    assert calls == [(16, 40), (32, 40), (40, 40)]
    assert r["ok"] == plain["ok"] == 40
    key = "percent_constant_force_exact"
    np.testing.assert_array_equal(flexure.read(str(tmp_path / "progress.h5"))[key],
                                  flexure.read(str(tmp_path / "plain.h5"))[key])

    stopped = tmp_path / "stopped"
    stopped.mkdir()
    stop = interrupting_progress(16)
    with pytest.raises(KeyboardInterrupt):
        flexure.map.cfm(**args, out=str(stopped / "map.h5"), progress=stop)
    assert stop.seen == [16]
    assert list(stopped.iterdir()) == []  # written whole at the end or not at all


def test_sweep_reports_its_points_and_writes_nothing_when_stopped(tmp_path):
    plain = tmp_path / "plain.h5"
    flexure.sweep(alpha2="0:20:501", n="0:2:3", out=str(plain), threads=2)
    calls = []
    with_progress = tmp_path / "progress.h5"
    flexure.sweep(alpha2="0:20:501", n="0:2:3", out=str(with_progress), threads=2,
                  progress=lambda d, t: calls.append((d, t)))
    # Polled every 0.1 s while the threads solve, and the total at the end.
    assert calls[-1] == (501 * 3, 501 * 3)
    assert all(t == 501 * 3 for _, t in calls)
    dones = [d for d, _ in calls]
    assert dones == sorted(dones)
    a, b = flexure.read(str(plain)), flexure.read(str(with_progress))
    for key in ("theta0", "a_over_l", "b_over_l"):
        assert np.array_equal(a[key], b[key], equal_nan=True), key

    stopped = tmp_path / "stopped"
    stopped.mkdir()

    def stop(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        flexure.sweep(alpha2="0:20:501", n="0:2:3", out=str(stopped / "s.h5"), threads=2,
                      progress=stop)
    assert list(stopped.iterdir()) == []
    # The module keeps working after it.
    assert flexure.beam(alpha2=1.0)["theta0"] > 0.0


def test_ctrl_c_interrupts_an_array_of_beams(interrupt_python):
    # Arrays of loads are solved on worker threads without a progress callable; the calling
    # thread's worker looks for Ctrl-C after each chunk of 256 loads. Without the signal this is
    # well over a minute of shooting solves.
    code = ("import numpy, flexure\n"
            "loads = numpy.linspace(0.1, 10.0, 400000)\n"
            "print('started', flush=True)\n"
            "flexure.beam(alpha2=loads, method='shooting', threads=2)\n"
            "print('finished', flush=True)\n")
    assert interrupt_python(code, timeout=60) < 5.0


def test_design_mechanism_command_reports_each_subclass(interrupting_progress):
    args = dict(force=10.0, stroke=0.01, E=200e9, yield_strength=1.2e9, safety_factor=1.5,
                length_range=(0.06, 0.15), exact=False)
    plain = flexure.design.mechanism(**args)
    calls = []
    r = flexure.design.mechanism(**args, progress=lambda d, t: calls.append((d, t)))
    total = len(r["designs"]) + len(r["rejected"])
    assert total >= 5
    assert calls == [(k, total) for k in range(1, total + 1)]
    assert [d["subclass"] for d in r["designs"]] == [d["subclass"] for d in plain["designs"]]
    assert [d["l_tot"] for d in r["designs"]] == [d["l_tot"] for d in plain["designs"]]

    stop = interrupting_progress(2)
    with pytest.raises(KeyboardInterrupt):
        flexure.design.mechanism(**args, progress=stop)
    assert stop.seen == [1, 2]


def test_mechanism_analyze_reports_a_general_mechanisms_path(interrupting_progress):
    # The switch file's crank path: 77 input values, each recorded once (no limit point of the
    # angle), by the PRBM and then the exact model, each counted from 1.
    path = str(EXAMPLES / "howell_bistable_switch.toml")
    calls = []
    r = quiet(flexure.mechanism.analyze, path, model="both",
              progress=lambda d, t: calls.append((d, t)))
    assert calls == [(k, 77) for k in range(1, 78)] * 2
    plain = quiet(flexure.mechanism.analyze, path, model="both")
    for model in ("prbm", "exact"):
        got, want = r["models"][model], plain["models"][model]
        assert len(got["input"]) == 77
        assert np.array_equal(got["input"], want["input"]), model
        assert np.array_equal(got["input_load"], want["input_load"]), model

    stop = interrupting_progress(2)
    with pytest.raises(KeyboardInterrupt):
        quiet(flexure.mechanism.analyze, path, model="prbm", progress=stop)
    assert stop.seen == [1, 2]
