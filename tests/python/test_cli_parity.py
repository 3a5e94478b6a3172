"""Every function of the module agrees with the tool's --json output on the same input: equal
keys, numbers to 1e-12 (issue 15). The tool runs as a subprocess; the module in-process."""
import math
import os

import pytest

import flexure
from conftest import ROOT, assert_same

BEAMS = [
    (dict(alpha2=2.0), ["--alpha2", "2"]),
    (dict(n=1.0, theta0=0.6), ["--n", "1", "--theta0", "0.6"]),
    (dict(theta0="30deg"), ["--theta0", "30deg"]),
    (dict(b_over_l=0.3, n=-0.5), ["--b-over-l", "0.3", "--n", "-0.5"]),
    (dict(alpha2=5.0, mu=-2.0, shape=11), ["--alpha2", "5", "--mu", "-2", "--shape", "11"]),
    (dict(alpha2=8.0, method="shooting", boundary="guided"),
     ["--alpha2", "8", "--method", "shooting", "--boundary", "guided"]),
    (dict(alpha2=10.0, method="chain", elements=50),
     ["--alpha2", "10", "--method", "chain", "--elements", "50"]),
    (dict(alpha2=1.5, method="prbm"), ["--alpha2", "1.5", "--method", "prbm"]),
    (dict(alpha2=1.5, mu=0.3, method="linear"),
     ["--alpha2", "1.5", "--mu", "0.3", "--method", "linear"]),
    (dict(alpha2=1.5, mu=0.3, method="prbm3r", constants="flexure"),
     ["--alpha2", "1.5", "--mu", "0.3", "--method", "prbm3r", "--constants", "flexure"]),
    (dict(alpha2=0.2, n=0.5, method="bcm", slenderness=40.0),
     ["--alpha2", "0.2", "--n", "0.5", "--method", "bcm", "--slenderness", "40"]),
    (dict(theta0=0.4, method="cbcm", elements=12, shape=5),
     ["--theta0", "0.4", "--method", "cbcm", "--elements", "12", "--shape", "5"]),
    (dict(alpha2=0.1 + 0.2, n=1 / 3), ["--alpha2", repr(0.1 + 0.2), "--n", repr(1 / 3)]),
    # Stability (issue 27): an unstable answer, labelled; --stable; the verdict switched off.
    (dict(length=1, E="1MPa", I=1e-6, Fx=-3), ["--length", "1", "--E", "1MPa", "--I", "1e-6",
                                               "--Fx", "-3"]),
    (dict(length=1, E="1MPa", I=1e-6, Fx=-3, stable=True),
     ["--length", "1", "--E", "1MPa", "--I", "1e-6", "--Fx", "-3", "--stable"]),
    (dict(alpha2=0.0, boundary="fixed", tip_x=0.9, tip_y=0.001, tip_angle=0.0, stable=True),
     ["--alpha2", "0", "--boundary", "fixed", "--tip-x", "0.9", "--tip-y", "0.001",
      "--tip-angle", "0", "--stable"]),
    (dict(alpha2=2.0, stability="off"), ["--alpha2", "2", "--stability", "off"]),
    (dict(length="20in", E="30Msi", width="1in", thickness="0.1in", Fy="0.49lbf",
          yield_strength="167ksi", shape=5),
     ["--length", "20in", "--E", "30Msi", "--width", "1in", "--thickness", "0.1in",
      "--Fy", "0.49lbf", "--yield-strength", "167ksi", "--shape", "5"]),
]


@pytest.mark.filterwarnings("ignore::flexure.FlexureWarning")  # the unstable column warns
@pytest.mark.parametrize("kwargs,flags", BEAMS, ids=[str(k) for k, _ in BEAMS])
def test_beam(cli, kwargs, flags):
    assert_same(flexure.beam(**kwargs), cli.json("beam", *flags))


def test_beam_stability_keys():
    with pytest.warns(flexure.FlexureWarning, match="UNSTABLE"):
        r = flexure.beam(length=1, E="1MPa", I=1e-6, Fx=-30)
    assert (r["stability"], r["stability_index"]) == ("unstable", 2)
    # 1 - 4 P L^2 / (pi^2 EI): P L^2/EI = 30.
    assert abs(r["stability_margin"] - (1 - 120 / 3.141592653589793 ** 2)) < 1e-8
    assert r["stable_search"] is None and len(r["warnings"]) == 1
    stable = flexure.beam(length=1, E="1MPa", I=1e-6, Fx=-30, stable=True)
    assert stable["stability"] == "stable" and stable["warnings"] == []
    assert stable["stable_search"].startswith("the shooting answer")
    with pytest.raises(flexure.InvalidInput, match="stable equilibrium"):
        flexure.beam(theta0=0.5, stable=True)
    with pytest.raises(flexure.NoConvergence, match="no stable equilibrium"):
        flexure.beam(length=1, E="1MPa", I=1e-6, Fx=-2.4674011002723395, stable=True)


EXAMPLES = os.path.join(ROOT, "docs", "examples")


@pytest.mark.parametrize("name", ["two_flexures_rigid_link.toml", "steel_strip.toml"])
def test_beam_chain_file(cli, name):
    path = os.path.join(EXAMPLES, name)
    assert_same(flexure.beam(chain=path, method="shooting"),
                cli.json("beam", "--chain", path, "--method", "shooting"))


def test_path(cli, tmp_path):
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    assert_same(flexure.path(alpha2=3.0, mu=-1.0, out=a),
                cli.json("path", "--alpha2", "3", "--mu", "-1", "--out", b),
                skip=("seconds", "out"))


def test_path_bifurcations_branch_and_control(cli, tmp_path):
    """The keys of issue 27 (bifurcations, limit_point_list, control, shapes) come through."""
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    column = flexure.path(length="1m", E="1GPa", I=1e-9, Fx="-30N", out=a)
    assert_same(column, cli.json("path", "--length", "1m", "--E", "1GPa", "--I", "1e-9",
                                 "--Fx", "-30N", "--out", b), skip=("seconds", "out"))
    # pi^2/4 and 9 pi^2/4 of the load 30 N on a beam with EI = 1 N m^2, L = 1 m.
    loads = [30.0 * p["load_factor"] for p in column["bifurcations"]]
    assert loads == pytest.approx([math.pi ** 2 / 4, 9 * math.pi ** 2 / 4], rel=1e-8)
    assert column["bifurcations"][0]["index_after"] == column["bifurcations"][0]["index"] + 1
    buckled = flexure.path(length="1m", E="1GPa", I=1e-9, Fx="-3N", branch=1, out=a)
    assert_same(buckled, cli.json("path", "--length", "1m", "--E", "1GPa", "--I", "1e-9",
                                  "--Fx", "-3N", "--branch", "1", "--out", b),
                skip=("seconds", "out"))
    assert buckled["switched_branch"] is True
    guided = flexure.path(boundary="guided", control="tip-y", tip_y=0.3, shapes=5, out=a)
    assert_same(guided, cli.json("path", "--boundary", "guided", "--control", "tip-y",
                                 "--tip-y", "0.3", "--shapes", "5", "--out", b),
                skip=("seconds", "out", "xdmf"))  # the sidecar is named after --out
    assert guided["control"] == "tip-y" and guided["shape_points"] == 5
    assert flexure.read(a)["shapes"]["x"].shape == (guided["points"], 5)


def test_sweep_and_read(cli, tmp_path):
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    assert_same(flexure.sweep(alpha2="0:5:11", n="0:1:3", out=a),
                cli.json("sweep", "beam", "--alpha2", "0:5:11", "--n", "0:1:3", "--out", b),
                skip=("seconds", "out"))
    data_a, data_b = flexure.read(a), flexure.read(b)
    assert data_a["theta0"].shape == (11, 3)
    assert data_a["units"]["theta0"] == "rad"
    assert (data_a["theta0"] == data_b["theta0"]).all()
    assert "flexure" in data_a["attributes"]["command_line"]


@pytest.mark.parametrize("kwargs,flags", [
    (dict(), []),
    (dict(segment="end-moment"), ["--segment", "end-moment"]),
    (dict(n=1.0, step=0.5), ["--n", "1", "--step", "0.5"]),
])
def test_prbm_derive(cli, kwargs, flags):
    assert_same(flexure.prbm.derive(**kwargs), cli.json("prbm", "derive", *flags))


def test_prbm_table(cli):
    assert_same(flexure.prbm.table(step=0.5, n_steps=2),
                cli.json("prbm", "table", "--step", "0.5", "--n-steps", "2"))


def test_prbm_compare(cli):
    assert_same(flexure.prbm.compare(n=0.5, range="0.5:5:4"),
                cli.json("prbm", "compare", "--n", "0.5", "--range", "0.5:5:4"))


@pytest.mark.parametrize("kwargs,flags", [
    (dict(config="lpp", R=0.6, d=0.5), ["--config", "lpp", "--R", "0.6", "--d", "0.5"]),
    (dict(subclass="lpp-b", curve=True), ["--subclass", "lpp-b", "--curve"]),
    (dict(list=True), ["--list"]),
])
def test_cfm(cli, kwargs, flags):
    assert_same(flexure.cfm(**kwargs), cli.json("cfm", *flags))


def test_mechanism_list_and_analyze(cli):
    assert_same(flexure.mechanism.list(), cli.json("mechanism", "list"))
    assert_same(flexure.mechanism.analyze("1A-lpp", points=8, method="exact"),
                cli.json("mechanism", "analyze", "1A-lpp", "--points", "8", "--method", "exact"))


def test_materials_fatigue_and_tolerance(cli):
    # docs/materials.md, docs/fatigue.md, docs/tolerance.md: the same JSON in-process.
    assert_same(flexure.materials(), cli.json("materials"))
    assert_same(flexure.materials("1095 HR"), cli.json("materials", "1095 HR"))
    assert_same(flexure.mechanism.analyze("1A-lpp", points=8, method="prbm",
                                          material="polypropylene", Kf=1.2, reliability=0.9),
                cli.json("mechanism", "analyze", "1A-lpp", "--points", "8", "--method", "prbm",
                         "--material", "polypropylene", "--Kf", "1.2", "--reliability", "0.9"))
    assert_same(flexure.beam(length="20in", width="3in", thickness="0.2in", Fy="8lbf",
                             material="steel-1095-hr", cycle="reversed", Kf=1.4),
                cli.json("beam", "--length", "20in", "--width", "3in", "--thickness", "0.2in",
                         "--Fy", "8lbf", "--material", "steel-1095-hr", "--cycle", "reversed",
                         "--Kf", "1.4"))
    assert_same(flexure.mechanism.tolerance("1A-lpp", thickness="3%", samples=5, method="prbm"),
                cli.json("mechanism", "tolerance", "1A-lpp", "--thickness", "3%", "--samples",
                         "5", "--method", "prbm"))
    with pytest.raises(flexure.InvalidInput, match="closest: polypropylene"):
        flexure.materials("polyproplene")


def test_mechanism_stability_keys(cli):
    # docs/stability.md "Mechanisms": one verdict per stroke point, per model and control.
    got = flexure.mechanism.analyze("2A-ssp", points=8, method="exact")
    assert_same(got, cli.json("mechanism", "analyze", "2A-ssp", "--points", "8", "--method",
                              "exact"))
    for control in ("stability_displacement_control", "stability_force_control"):
        for model in ("prbm", "exact"):
            v = got[control][model]
            assert len(v["stability"]) == 8
            assert len(v["stability_margin"]) == 8
            assert v["not_checked_points"] == 0
    assert list(got["stability_displacement_control"]["prbm"]["stability_margin"]) == [1.0] * 8


def test_mechanism_stable(cli):
    # --stable (docs/stability.md "Mechanisms"): the same JSON as the command line; 3A-lslm's exact
    # stroke, unstable with the slider held at every point by default, is stable at every point.
    got = flexure.mechanism.analyze("3A-lslm", points=6, method="exact", stable=True)
    assert_same(got, cli.json("mechanism", "analyze", "3A-lslm", "--points", "6", "--method",
                              "exact", "--stable"))
    assert got["stable"] is True and "lowest buckling mode" in got["stable_search"]
    assert list(got["stability_displacement_control"]["exact"]["stability"]) == ["stable"] * 6
    default = flexure.mechanism.analyze("3A-lslm", points=6, method="exact")
    assert default["stable"] is False and default["stable_search"] is None
    assert default["stability_displacement_control"]["exact"]["unstable_points"] == 6


def test_mechanism_from_file_and_dict(cli):
    toml = os.path.join(EXAMPLES, "mechanism_lpp.toml")
    expected = cli.json("mechanism", "analyze", toml, "--points", "6", "--method", "prbm")
    assert_same(flexure.mechanism.analyze(toml, points=6, method="prbm"), expected)
    import tomllib
    with open(toml, "rb") as f:
        design = tomllib.load(f)
    assert_same(flexure.mechanism.analyze(design, points=6, method="prbm"), expected)


def test_mechanism_validate(cli):
    assert_same(flexure.mechanism.validate(designs="thesis", points=6),
                cli.json("mechanism", "validate", "--designs", "thesis", "--points", "6"))


def test_dynamics(cli):
    assert_same(flexure.dynamics(mechanism="2B-lplm", omega="5:50:4", samples=64),
                cli.json("dynamics", "--mechanism", "2B-lplm", "--omega", "5:50:4",
                         "--samples", "64"))


def test_bench(cli, tmp_path):
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    got = flexure.bench(out=a, quick=True, problems="tip_moment", methods=["elliptic", "prbm"])
    assert_same(got, cli.json("bench", "--out", b, "--quick", "--problems", "tip_moment",
                              "--methods", "elliptic,prbm"),
                skip=("seconds", "median_seconds", "file"))  # timings differ between runs
    assert flexure.read(a)["tip_moment"]["elliptic"]["units"]


def test_concurrent_calls_from_threads_are_independent():
    # Each thread has its own captured output, warnings and exit code (cli/command_runner.h).
    import threading
    loads = [0.5 + 0.25 * i for i in range(40)]
    expected = [flexure.beam(alpha2=a, method="shooting")["theta0"] for a in loads]
    results = {}

    def work(k):
        results[k] = [flexure.beam(alpha2=a, method="shooting")["theta0"] for a in loads]

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(results[k] == expected for k in range(4))


# The largest tolerance `validate` may give a check, by method: the solvers' own accuracy
# (elliptic 1e-10, shooting 1e-8, chain N = 100 1e-5) or the rounding of a printed reference
# (7 significant digits of a value up to 10: 2e-6); docs/validation.md.
VALIDATE_TOLERANCE_CAP = {"elliptic": 2e-6, "shooting": 2e-6, "chain": 1e-5}


def test_validate(cli, tmp_path):
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    got = flexure.validate(out=a)
    # Every verdict recomputed here from the computed and reference values, not read from the
    # tool's "passed" and "all_passed": the error relative to the reference, absolute where the
    # reference is zero (a/l of the half and full circle). The tool divides by max(|reference|,
    # a floor <= 1), so its rel_error lies between |diff| / max(1, |reference|) and ours.
    assert len(got["checks"]) >= 200
    for c in got["checks"]:
        diff = abs(c["computed"] - c["reference"])
        error = diff / abs(c["reference"]) if abs(c["reference"]) > 1e-6 else diff
        assert c["tolerance"] <= VALIDATE_TOLERANCE_CAP[c["method"]], c
        assert error <= c["tolerance"], c
        assert c["passed"] is True, c
        assert diff / max(1.0, abs(c["reference"])) * (1 - 1e-12) <= c["rel_error"], c
        assert c["rel_error"] <= error * (1 + 1e-12) + 1e-300, c
        # The end-moment references are the circular arc a/l = sin(mu)/mu, b/l = (1 - cos mu)/mu
        # (Howell eqs. 2.59, 2.64), recomputed here.
        if c["problem"].startswith("end-moment mu="):
            mu = {"1": 1.0, "pi": math.pi, "2pi": 2.0 * math.pi}[c["problem"].split()[1][3:]]
            arc = {"a_over_l": math.sin(mu) / mu, "b_over_l": (1.0 - math.cos(mu)) / mu,
                   "theta0": mu}
            if c["quantity"] in arc:
                assert abs(c["reference"] - arc[c["quantity"]]) <= 1e-15, c
    assert got["all_passed"] is True
    assert_same(got, cli.json("validate", "--out", b), skip=("seconds_per_solve", "out"))


def test_design_cfm(cli):
    assert_same(flexure.design.cfm(config="lps", d=16, objective="max-psi", pcf_min=95.0,
                                   orientation="I"),
                cli.json("design", "cfm", "--config", "lps", "--d", "16", "--objective", "max-psi",
                         "--pcf-min", "95", "--orientation", "I"))


def test_design_mechanism(cli):
    args = ["--force", "25lbf", "--stroke", "4in", "--E", "30Msi", "--safety-factor", "1.2",
            "--length-range", "12in:15in", "--width-range", "3in:5in",
            "--thickness-range", "0.04in:0.07in", "--config", "lpp"]
    got = flexure.design.mechanism(force="25lbf", stroke="4in", E="30Msi", safety_factor=1.2,
                                   length_range=("12in", "15in"), width_range=("3in", "5in"),
                                   thickness_range=("0.04in", "0.07in"), config=["lpp"])
    assert got["designs"][0]["subclass"] == "lpp-b"
    assert_same(got, cli.json("design", "mechanism", *args))
    # SI numbers give the same design as the units.
    si = flexure.design.mechanism(force=25 * 4.4482216152605, stroke=4 * 0.0254,
                                  E=30e6 * 6894.757293168361, safety_factor=1.2,
                                  length_range=(12 * 0.0254, 15 * 0.0254),
                                  width_range=(3 * 0.0254, 5 * 0.0254),
                                  thickness_range=(0.04 * 0.0254, 0.07 * 0.0254), config="lpp",
                                  exact=False)
    assert abs(si["designs"][0]["thicknesses"][0] - got["designs"][0]["thicknesses"][0]) < 1e-12
    assert si["designs"][0]["force_exact"] is None


def test_design_mechanism_rules(cli, tmp_path):
    """The keywords of issue 27's flags give the tool's JSON for the same flags."""
    args = ["--force", "20N", "--stroke", "10mm", "--E", "200GPa", "--yield-strength", "1200MPa",
            "--safety-factor", "1.5", "--length-range", "60mm:150mm", "--config", "lpp",
            "--stress-rule", "computed", "--minimize", "length", "--max-width-to-thickness", "150",
            "--max-width-to-length", "0.8", "--force-tolerance", "8", "--force-of", "whole"]
    got = flexure.design.mechanism(force="20N", stroke="10mm", E="200GPa",
                                   yield_strength="1200MPa", safety_factor=1.5,
                                   length_range=("60mm", "150mm"), config="lpp",
                                   stress_rule="computed", minimize="length",
                                   max_width_to_thickness=150, max_width_to_length=0.8,
                                   force_tolerance=8, force_of="whole")
    assert got["minimize"] == "length" and got["stress_rule"] == "computed"
    assert got["section_bounds"] == {"max_width_to_thickness": 150.0, "max_width_to_length": 0.8}
    for d in got["designs"]:
        assert min(d["safety_factor_prbm"], d["safety_factor_exact"]) >= 1.5
    assert_same(got, cli.json("design", "mechanism", *args))
    # A refinement that misses the specification raises, and with allow_infeasible writes it.
    out = tmp_path / "x.toml"
    with pytest.raises(flexure.NoConvergence) as e:
        flexure.design.mechanism(force="25lbf", stroke="4in", E="30Msi", yield_strength="167ksi",
                                 safety_factor=1.5, length_range=("10in", "20in"), config="lpp",
                                 stress_rule="thesis", model="exact", allow_infeasible=True,
                                 out=out)
    assert "not feasible" in str(e.value)
    assert out.read_text().startswith("# NOT FEASIBLE")


def test_design_cfm_exact(cli):
    got = flexure.design.cfm(subclass="lpp-b", model="exact")
    assert got["percent_constant_force_exact"] > 96.0
    assert_same(got, cli.json("design", "cfm", "--subclass", "lpp-b", "--model", "exact"),
                skip=("seconds",))


def test_map_cfm(cli, tmp_path):
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    got = flexure.map.cfm(config="lps", R="0.5:2:4", d=16, K2=1.0, out=a)
    assert got["dims"].tolist() == [4, 1, 1, 1]
    assert_same(got, cli.json("map", "cfm", "--config", "lps", "--R", "0.5:2:4", "--d", "16",
                              "--K2", "1.0", "--out", b), skip=("out",))


def test_path_stability_per_point(cli, tmp_path):
    """Every path point's verdict: the straight column against 1 - P/(pi^2/4), as the tool."""
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    column = flexure.path(length="1m", E="1GPa", I=1e-9, Fx="-3N", out=a)
    assert_same(column, cli.json("path", "--length", "1m", "--E", "1GPa", "--I", "1e-9",
                                 "--Fx", "-3N", "--out", b), skip=("seconds", "out"))
    data = flexure.read(a)
    P = 3.0 * data["load_factor"]
    assert column["stability_margin"] == pytest.approx(1 - P / (math.pi ** 2 / 4), abs=1e-8)
    assert (data["stability_margin"] == column["stability_margin"]).all()
    kinds = [("stable" if p < math.pi ** 2 / 4 else "unstable") for p in P]
    critical = data["status"] == 4
    assert [k for k, c in zip(column["stability"], critical) if not c] == \
        [k for k, c in zip(kinds, critical) if not c]
    off = flexure.path(alpha2=3.0, stability="off", out=a)
    assert set(off["stability"]) == {"not_checked"}


def test_mechanism_mixed_model(cli):
    # --model mixed with per-flexure models (docs/models.md "A model per flexure"): the keywords
    # model=, flexure_models= (a dict or the CLI's text), flexure_tol=, check_flexures= give the
    # command line's JSON.
    expected = cli.json("mechanism", "analyze", "3A-sss", "--model", "mixed", "--flexure-model",
                        "f1=cbcm,f2=exact,f3=bcm", "--points", "6")
    got = flexure.mechanism.analyze("3A-sss", model="mixed", points=6,
                                    flexure_models={"f1": "cbcm", "f2": "exact", "f3": "bcm"})
    assert_same(got, expected)
    assert [f["model"] for f in got["flexure_models"]] == ["cbcm", "exact", "bcm"]
    assert_same(flexure.mechanism.analyze("3A-sss", model="mixed", points=6,
                                          flexure_models="f1=cbcm,f2=exact,f3=bcm"), expected)
    automatic = flexure.mechanism.analyze("3A-sss", model="mixed", points=6,
                                          flexure_models="auto", flexure_tol=1e-3,
                                          check_flexures=True)
    assert_same(automatic, cli.json("mechanism", "analyze", "3A-sss", "--model", "mixed",
                                    "--flexure-model", "auto", "--flexure-tol", "1e-3",
                                    "--check-flexures", "--points", "6"))
    for f in automatic["flexure_models"]:
        assert f["requested"] == "auto" and f["expected_error_per_length"] <= 1e-3
    with pytest.raises(flexure.InvalidInput, match="flexure_models"):
        flexure.mechanism.analyze("3A-sss", model="mixed", flexure_models={})
    with pytest.raises(flexure.InvalidInput, match="f7"):
        flexure.mechanism.analyze("3A-sss", model="mixed", flexure_models={"f7": "bcm"})


def test_path_cbcm(cli, tmp_path):
    """path(method='cbcm', elements=N) (docs/models.md "Paths under displacement control"): the
    CLI's JSON, and at the end of the travel the support's force within 1e-4 of shooting's."""
    a, b, c = tmp_path / "a.h5", tmp_path / "b.h5", tmp_path / "c.h5"
    got = flexure.path(boundary="guided", control="tip-y", tip_y=0.3, method="cbcm", elements=12,
                       out=a)
    assert_same(got, cli.json("path", "--boundary", "guided", "--control", "tip-y", "--tip-y",
                              "0.3", "--method", "cbcm", "--elements", "12", "--out", b),
                skip=("seconds", "out"))
    assert got["method"] == "cbcm" and got["elements"] == 12 and got["completed"] is True
    flexure.path(boundary="guided", control="tip-y", tip_y=0.3, out=c)
    cbcm, shooting = flexure.read(a), flexure.read(c)
    assert cbcm["tip_y"][-1] == pytest.approx(0.3, abs=1e-12)
    assert cbcm["tip_Fy"][-1] == pytest.approx(shooting["tip_Fy"][-1], rel=1e-4)
    with pytest.raises(flexure.InvalidInput, match="--control"):
        flexure.path(alpha2=1.0, method="cbcm", out=a)
