"""flexure.beam with numpy arrays: broadcasting, agreement with the scalar call point by point,
failed points that do not raise, worker threads, and the interpreter's lock released."""
import threading
import time

import numpy as np
import pytest

import flexure
from conftest import assert_same


def test_broadcast_shape_and_scalar_agreement():
    n = np.array([[-1.0], [0.0], [2.5]])
    alpha2 = np.linspace(0.25, 12.0, 7)
    many = flexure.beam(n=n, alpha2=alpha2, mu=0.5)
    assert many["theta0"].shape == (3, 7)
    assert many["converged"].all() and (many["status"] == 0).all()
    for i in range(3):
        for j in range(7):
            one = flexure.beam(n=float(n[i, 0]), alpha2=float(alpha2[j]), mu=0.5)
            point = {k: (v[i, j] if not isinstance(v, dict) else {c: a[i, j] for c, a in v.items()})
                     for k, v in many.items() if k != "status"}
            assert_same(point, one, where=f"point ({i}, {j})")


@pytest.mark.filterwarnings("ignore::flexure.FlexureWarning")  # PRBM outside its limits
@pytest.mark.parametrize("method", ["elliptic", "shooting", "chain", "prbm", "auto"])
def test_every_method_agrees_with_the_scalar_call(method):
    rng = np.random.default_rng(15)
    n = rng.uniform(-1, 2, 12)
    alpha2 = rng.uniform(0.2, 4, 12)
    many = flexure.beam(n=n, alpha2=alpha2, method=method)
    assert many["converged"].all()
    for i in range(12):
        one = flexure.beam(n=float(n[i]), alpha2=float(alpha2[i]), method=method)
        point = {k: (v[i] if not isinstance(v, dict) else {c: a[i] for c, a in v.items()})
                 for k, v in many.items() if k != "status"}
        assert_same(point, one, where=f"{method} point {i}")


@pytest.mark.filterwarnings("ignore::flexure.FlexureWarning")  # the BCM beyond |y| = 0.1
@pytest.mark.parametrize("method,extra", [("linear", {}), ("prbm3r", {"constants": "flexure"}),
                                          ("bcm", {"slenderness": 30.0}),
                                          ("cbcm", {"elements": 4})])
def test_every_model_of_the_ladder_agrees_with_the_scalar_call(method, extra):
    rng = np.random.default_rng(30)
    n = rng.uniform(-0.5, 1, 8)
    alpha2 = rng.uniform(0.1, 1.5, 8)
    many = flexure.beam(n=n, alpha2=alpha2, mu=0.2, method=method, **extra)
    assert many["converged"].all()
    for i in range(8):
        one = flexure.beam(n=float(n[i]), alpha2=float(alpha2[i]), mu=0.2, method=method, **extra)
        point = {k: (v[i] if not isinstance(v, dict) else {c: a[i] for c, a in v.items()})
                 for k, v in many.items() if k != "status"}
        assert_same(point, one, where=f"{method} point {i}")


def test_inverse_problems_hit_their_targets():
    targets = np.linspace(0.05, 0.8, 9)
    r = flexure.beam(b_over_l=targets, n=np.array([[0.0], [1.0]]))
    assert r["converged"].all()
    np.testing.assert_allclose(r["b_over_l"], np.broadcast_to(targets, (2, 9)), atol=1e-9)
    theta = flexure.beam(theta0=np.linspace(0.1, 1.2, 5))
    np.testing.assert_allclose(theta["theta0"], np.linspace(0.1, 1.2, 5), atol=1e-9)


def test_failed_points_do_not_raise():
    alpha2 = np.array([1.0, np.nan, 2.0, np.inf])
    r = flexure.beam(alpha2=alpha2)
    assert r["status"].tolist() == [0, 2, 0, 2]
    assert r["converged"].tolist() == [True, False, True, False]
    assert np.isnan(r["theta0"][1]) and np.isfinite(r["theta0"][0])
    assert "--alpha2" in r["message"][1] and "finite" in r["message"][1]
    assert r["termination"][1] == "invalid_input"
    # b/l outside [-1, 1] at one point: the tool's message for it, the others solved.
    r = flexure.beam(b_over_l=np.array([0.2, 1.5]))
    assert r["status"].tolist() == [0, 2]
    assert "outside the allowed range" in r["message"][1]


def test_elliptic_domain_point_is_refused_not_raised():
    r = flexure.beam(alpha2=np.array([1.0, 1e7]), method="elliptic")
    assert r["status"].tolist() == [0, 2]
    assert "shooting" in r["message"][1]  # the message names the method that reaches further


def test_prbm_outside_its_limits_warns_once():
    with pytest.warns(flexure.FlexureWarning, match="2 of 3 loads solved by the PRBM"):
        r = flexure.beam(alpha2=np.array([0.5, 8.0, 12.0]), method="prbm")
    assert r["within_validity"].tolist() == [True, False, False]


def test_threads_give_identical_results():
    alpha2 = np.linspace(0.1, 20, 3000)
    one = flexure.beam(alpha2=alpha2, n=1.0, mu=0.3, threads=1)
    two = flexure.beam(alpha2=alpha2, n=1.0, mu=0.3, threads=2)
    for key in ("theta0", "a_over_l", "b_over_l", "iterations"):
        np.testing.assert_array_equal(one[key], two[key])


def test_options_are_validated_by_the_tool():
    with pytest.raises(flexure.InvalidInput, match="--method"):
        flexure.beam(alpha2=np.ones(3), method="magic")
    with pytest.raises(flexure.InvalidInput, match="exactly one|Exactly one|excludes|at most"):
        flexure.beam(alpha2=np.ones(3), theta0=np.ones(3))
    with pytest.raises(flexure.InvalidInput, match="one of --alpha2"):
        flexure.beam(n=np.ones(3))
    with pytest.raises(flexure.InvalidInput, match="do not broadcast"):
        flexure.beam(alpha2=np.ones(3), n=np.ones(4))
    with pytest.raises(flexure.InvalidInput, match="scalar loads"):
        flexure.beam(alpha2=np.ones(3), shape=5)
    with pytest.raises(flexure.InvalidInput, match="threads"):
        flexure.beam(alpha2=np.ones(3), threads=0)


def test_lock_is_released_during_a_long_call():
    # A shooting solve of many loads takes seconds; another Python thread must run meanwhile.
    alpha2 = np.linspace(0.5, 15, 4000)
    done = threading.Event()
    result = {}

    def long_call():
        result["r"] = flexure.beam(alpha2=alpha2, n=0.5, method="shooting", threads=1)
        done.set()

    worker = threading.Thread(target=long_call)
    ticks = 0
    worker.start()
    time.sleep(0.05)
    while not done.is_set():
        ticks += 1  # pure Python: runs only while the call does not hold the lock
        time.sleep(0)
    worker.join()
    assert result["r"]["converged"].all()
    assert ticks > 1000, f"only {ticks} ticks ran during the call"


def test_stability_columns_agree_with_the_scalar_call():
    # The clamped-clamped beam of issue 27 at two tip angles: the second mode (unstable) at 0,
    # the first (stable) at 0.01; one warning for the call.
    args = dict(alpha2=np.zeros(2), boundary="fixed", tip_x=0.9, tip_y=0.001, tip_angle=0.0,
                threads=1)
    with pytest.warns(flexure.FlexureWarning, match="2 of 2 loads have an UNSTABLE answer"):
        many = flexure.beam(**args)
    assert many["stability"].tolist() == ["unstable", "unstable"]
    assert many["stability_index"].tolist() == [1.0, 1.0]
    with pytest.warns(flexure.FlexureWarning):
        one = flexure.beam(alpha2=0.0, boundary="fixed", tip_x=0.9, tip_y=0.001, tip_angle=0.0)
    point = {k: (v[0] if not isinstance(v, dict) else {c: a[0] for c, a in v.items()})
             for k, v in many.items() if k != "status"}
    assert_same(point, one)
    stable = flexure.beam(**{**args, "stable": True})
    assert stable["stability"].tolist() == ["stable", "stable"]
    assert all(s.startswith("the shooting answer") for s in stable["stable_search"])
    off = flexure.beam(alpha2=np.array([1.0, 2.0]), stability="off")
    assert off["stability"].tolist() == ["not_checked"] * 2
    assert np.isnan(off["stability_index"]).all() and np.isnan(off["stability_margin"]).all()


def test_failed_loads_carry_no_verdict_and_no_warnings():
    # A failed load was judged by nothing: its text columns must not read another load's texts
    # (the interned columns share texts between loads).
    r = flexure.beam(n=np.array([0.0, np.nan, 0.0]), alpha2=np.array([1.0, 1.0, 1e9]),
                     threads=1)
    assert r["status"].tolist() == [0, 2, 1]
    assert r["stability"].tolist() == ["stable", "not_checked", "not_checked"]
    assert r["stability_index"][0] == 0.0 and np.isnan(r["stability_index"][1:]).all()
    assert [list(w) for w in r["warnings"]] == [[], [], []]
