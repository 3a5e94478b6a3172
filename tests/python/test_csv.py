"""CSV output (docs/cli.md "CSV output"): `--csv FILE`, or `--out FILE.csv`, writes the table of
a command's result with a header of names and [units]. Read back, every column equals the same
command's JSON (exactly: both print the computed doubles to round-trip precision) or, where the
JSON holds only a summary, the command's HDF5 file read with h5py."""
import csv
import json
import os
import re
import subprocess

import numpy as np
import pytest

from conftest import BINARY

h5py = pytest.importorskip("h5py")


def run(args, cwd):
    p = subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=600, cwd=cwd)
    return p


def read_csv(path):
    """{name: (unit, values, of)}: numbers as floats (an empty field is NaN), text as strings;
    `of` is a force's "half" or "whole" (the unit `N (half)`), else None."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    table = {}
    for k, field in enumerate(header):
        m = re.fullmatch(r"(.+) \[(.+?)(?: \((half|whole)\))?\]", field)
        assert m, f"header field without a unit: {field!r}"
        name, unit, of = m.groups()
        column = [r[k] for r in body]
        if unit != "text":
            column = np.array([float(v) if v != "" else np.nan for v in column])
        table[name] = (unit, column, of)
    return table


def exact_equal(a, b, what):
    a = np.asarray(a, dtype=float)
    b = np.asarray([np.nan if v is None else v for v in np.ravel(b)], dtype=float)
    np.testing.assert_allclose(a, b, rtol=1e-12, atol=0, equal_nan=True, err_msg=what)


def test_mechanism_stroke_csv_equals_the_json(tmp_path):
    p = run(["mechanism", "analyze", "1A-lpp", "--points", "8", "--csv", "stroke.csv", "--json"],
            tmp_path)
    assert p.returncode == 0, p.stderr
    j = json.loads(p.stdout)
    t = read_csv(tmp_path / "stroke.csv")
    assert t["displacement"][0] == "m" and t["force_prbm"][0] == "N"
    assert t["stress_exact_pivot1"][0] == "Pa"
    # Whose force: the header's unit says "N (half)", as the JSON's force_of says one half.
    assert j["force_of"] == "one half"
    assert t["force_prbm"][2] == "half" and t["force_exact"][2] == "half"
    assert t["displacement"][2] is None and t["stress_exact_pivot1"][2] is None
    # The stored shapes (/shapes, one row per converged exact point) are not the stroke's table.
    assert not any(k.startswith("shapes/") for k in t)
    for key in ("displacement", "force_prbm", "force_exact", "prbm_within_validity"):
        exact_equal(t[key][1], j[key], key)
    assert len(t["displacement"][1]) == 8
    # --csv alone leaves no HDF5 file (nor a temporary) behind.
    assert sorted(os.listdir(tmp_path)) == ["stroke.csv"]


def test_design_table_csv_equals_the_json(tmp_path):
    p = run(["design", "cfm", "--all-subclasses", "--config", "lpp", "--out", "t.h5", "--csv",
             "t.csv", "--json"], tmp_path)
    assert p.returncode == 0, p.stderr
    rows = json.loads(p.stdout)["subclasses"]
    t = read_csv(tmp_path / "t.csv")
    assert t["name"][1] == [r["name"] for r in rows]
    assert t["objective"][1] == [r["objective"] for r in rows]
    for key in ("stroke_percent", "R", "K1", "K2", "percent_constant_force", "objective_value",
                "printed_objective", "evaluations"):
        exact_equal(t[key][1], [r[key] for r in rows], key)
    assert t["percent_constant_force"][0] == "%"


def test_sweep_grid_csv_is_the_file_row_major(tmp_path):
    p = run(["sweep", "beam", "--alpha2", "0:5:4", "--n", "-1:1:3", "--out", "s.h5", "--csv",
             "s.csv"], tmp_path)
    assert p.returncode == 0, p.stderr
    t = read_csv(tmp_path / "s.csv")
    with h5py.File(tmp_path / "s.h5", "r") as f:
        a, n = f["axes/alpha2"][()], f["axes/load_ratio_n"][()]
        # The axes expanded over the grid, the last fastest.
        exact_equal(t["axes/alpha2"][1], np.repeat(a, len(n)), "alpha2 axis")
        exact_equal(t["axes/load_ratio_n"][1], np.tile(n, len(a)), "n axis")
        for key in ("a_over_l", "b_over_l", "theta0", "stability_margin", "status"):
            exact_equal(t[key][1], f[key][()].ravel(), key)
            assert t[key][0] == f[key].attrs["units"]
    assert t["theta0"][0] == "rad"


def test_path_csv_equals_the_file_and_out_csv_equals_csv(tmp_path):
    args = ["path", "--alpha2", "10", "--mu", "-6.2832"]
    assert run([*args, "--out", "p.h5", "--csv", "p.csv"], tmp_path).returncode == 0
    assert run([*args, "--out", "only.csv"], tmp_path).returncode == 0
    t = read_csv(tmp_path / "p.csv")
    with h5py.File(tmp_path / "p.h5", "r") as f:
        for key in ("load_factor", "tip_x", "tip_y", "tip_theta", "stability", "status"):
            exact_equal(t[key][1], f[key][()], key)
        # The limit points are rows of their own (status 2), so they are in the table too.
        assert np.count_nonzero(t["status"][1] == 2) == len(f["special_points/kind"])
    assert "shapes/x" not in t and not any(k.startswith("special_points") for k in t)
    assert (tmp_path / "only.csv").read_text() == (tmp_path / "p.csv").read_text()
    assert not [f for f in os.listdir(tmp_path) if f.startswith(".")]


def test_map_and_models_map_csv(tmp_path):
    assert run(["map", "cfm", "--config", "lpp", "--R", "0.5:2:3", "--d", "10:40:2", "--out",
                "m.h5", "--csv", "m.csv"], tmp_path).returncode == 0
    t = read_csv(tmp_path / "m.csv")
    with h5py.File(tmp_path / "m.h5", "r") as f:
        grid = np.meshgrid(f["R"][()], f["d"][()], f["K1"][()], f["K2"][()], indexing="ij")
        exact_equal(t["R"][1], grid[0].ravel(), "R")
        exact_equal(t["d"][1], grid[1].ravel(), "d")
        exact_equal(t["percent_constant_force"][1], f["percent_constant_force"][()].ravel(), "pcf")
    assert t["d"][0] == "%"
    assert run(["models", "map", "--n", "0", "--alpha2", "0.5:5:3", "--mu", "-1:1:2",
                "--min-seconds", "0", "--models", "prbm,cbcm", "--out", "mm.csv"],
               tmp_path).returncode == 0
    t = read_csv(tmp_path / "mm.csv")
    assert len(t["alpha2"][1]) == 6 and t["prbm/angle_error"][0] == "rad"
    assert "cbcm/position_error" in t and "reference/b_over_l" in t


def test_bad_csv_paths_are_refused_before_any_work(tmp_path):
    p = run(["sweep", "beam", "--alpha2", "0:5:4", "--out", "s.h5", "--csv", "nodir/s.csv"],
            tmp_path)
    assert p.returncode == 2 and "--csv 'nodir/s.csv'" in p.stderr
    assert not (tmp_path / "s.h5").exists()
    p = run(["path", "--alpha2", "3", "--out", "p.csv", "--csv", "q.csv"], tmp_path)
    assert p.returncode == 2 and "CSV file already" in p.stderr
    assert os.listdir(tmp_path) == []


def test_design_mechanism_csv_equals_the_json_designs(tmp_path):
    p = run(["design", "mechanism", "--force", "20N", "--force-of", "whole", "--stroke", "10mm",
             "--E", "200GPa", "--yield-strength", "1200MPa", "--safety-factor", "1.5",
             "--length-range", "30mm:150mm", "--csv", "designs.csv", "--json"], tmp_path)
    assert p.returncode == 0, p.stderr
    designs = json.loads(p.stdout)["designs"]
    t = read_csv(tmp_path / "designs.csv")
    assert t["subclass"][1] == [d["subclass"] for d in designs]
    for key, unit in (("R", "1"), ("l_tot", "m"), ("r2", "m"), ("force_prbm", "N"),
                      ("force_exact", "N"), ("yield_strength", "Pa"), ("footprint", "m^2"),
                      ("safety_factor_exact", "1"), ("percent_constant_force_exact", "%")):
        assert t[key][0] == unit, key
        exact_equal(t[key][1], [d[key] for d in designs], key)
    # --force-of whole: the forces' unit says so, as the JSON's force_of does.
    assert json.loads(p.stdout)["force_of"] == "whole symmetric mechanism"
    assert t["force_prbm"][2] == "whole" and t["force_exact"][2] == "whole"
    assert t["yield_strength"][2] is None
    # Per-flexure arrays: one column per entry, NaN where a design has fewer flexures.
    width = max(len(d["thicknesses"]) for d in designs)
    for i in range(width):
        exact_equal(t[f"thicknesses_{i + 1}"][1],
                    [d["thicknesses"][i] if i < len(d["thicknesses"]) else None for d in designs],
                    f"thicknesses_{i + 1}")
    assert "geometry" not in t
    # --fatigue adds the critical pivot's Goodman check; its stresses are in Pa like the JSON's.
    p = run(["design", "mechanism", "--force", "20N", "--stroke", "10mm", "--material",
             "ss-301-cr", "--safety-factor", "1.5", "--length-range", "60mm:100mm", "--no-exact",
             "--fatigue", "--Kf", "1.2", "--csv", "fatigue.csv", "--json"], tmp_path)
    assert p.returncode == 0, p.stderr
    designs = json.loads(p.stdout)["designs"]
    assert designs
    t = read_csv(tmp_path / "fatigue.csv")
    for key, unit in (("alternating_stress", "Pa"), ("mean_stress", "Pa"),
                      ("endurance_limit", "Pa"), ("fatigue_safety_factor", "1"),
                      ("fatigue_critical_pivot", "1")):
        assert t[key][0] == unit, key
        exact_equal(t[key][1], [d[key] for d in designs], key)
    # S_e of 301 cold-rolled (S_e' 689.5 MPa, Howell Table C.6) after its Marin factors: a few
    # hundred MPa, so a value in MPa or a unitless ratio would fail here.
    assert np.all((t["endurance_limit"][1] > 1e8) & (t["endurance_limit"][1] < 689.5e6))


def test_dynamics_csv_equals_the_json(tmp_path):
    # The frequency table, one row per omega; --csv alone writes no HDF5 file.
    p = run(["dynamics", "--mechanism", "2B-lplm", "--omega", "1:60:5", "--samples", "64",
             "--csv", "d.csv", "--json"], tmp_path)
    assert p.returncode == 0, p.stderr
    j = json.loads(p.stdout)
    t = read_csv(tmp_path / "d.csv")
    assert t["omega"][0] == "rad/s" and t["mean_force"][0] == "N"
    assert t["percent_constant_force"][0] == "%"
    # dynamics reports the whole mechanism's forces by default, and the header says so.
    assert j["force_of"] == "whole symmetric mechanism"
    assert t["mean_force"][2] == "whole" and t["peak_to_peak_force"][2] == "whole"
    for key in ("omega", "mean_force", "median_force", "min_force", "max_force",
                "peak_to_peak_force", "percent_constant_force"):
        exact_equal(t[key][1], j[key], key)
    assert j["csv"] == "d.csv"
    assert sorted(os.listdir(tmp_path)) == ["d.csv"]
    # --out FILE.csv: the same table.
    p = run(["dynamics", "--mechanism", "2B-lplm", "--omega", "1:60:5", "--samples", "64",
             "--out", "o.csv"], tmp_path)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "o.csv").read_text() == (tmp_path / "d.csv").read_text()


def test_mechanism_validate_csv_equals_the_json(tmp_path):
    p = run(["mechanism", "validate", "--points", "6", "--designs", "howell", "--out", "v.h5",
             "--csv", "v.csv", "--json"], tmp_path)
    assert p.returncode == 0, p.stderr
    rows = json.loads(p.stdout)["mechanisms"]
    t = read_csv(tmp_path / "v.csv")
    assert t["name"][1] == [r["design"]["name"] for r in rows]
    assert t["safety_factor"][0] == "1" and t["stroke"][0] == "m"
    exact_equal(t["percent_constant_force"][1], [r["percent_constant_force_prbm"] for r in rows],
                "percent_constant_force")
    exact_equal(t["safety_factor"][1], [r["safety_factor"] for r in rows], "safety_factor")
    exact_equal(t["percent_constant_force_exact"][1],
                [r["percent_constant_force_exact"] for r in rows], "percent_constant_force_exact")
    # The table's tip error is relative to r2 (docs/hdf5-schema.md); the JSON's in m.
    np.testing.assert_allclose(
        t["chain_check_tip_error"][1],
        [r["chain_check_tip_error"] / r["design"]["r2"] for r in rows], rtol=1e-14)
    with h5py.File(tmp_path / "v.h5", "r") as f:
        for key in ("percent_constant_force", "max_force_error", "stroke", "status"):
            exact_equal(t[key][1], f[key][()], key)
    # --spring-rules has no table file: --csv with it is refused.
    p = run(["mechanism", "validate", "--spring-rules", "--csv", "x.csv"], tmp_path)
    assert p.returncode == 2 and not (tmp_path / "x.csv").exists()


def test_mechanism_tolerance_csv_is_the_samples_of_the_file(tmp_path):
    # One row per sample: its relative draws and its quantities, equal to the HDF5 file's.
    args = ["mechanism", "tolerance", "1A-lpp", "--thickness", "3%", "--samples", "7",
            "--method", "prbm", "--points", "12", "--seed", "5"]
    p = run([*args, "--out", "t.h5", "--csv", "t.csv", "--json"], tmp_path)
    assert p.returncode == 0, p.stderr
    j = json.loads(p.stdout)
    assert j["out"] == "t.h5" and j["csv"] == "t.csv"
    t = read_csv(tmp_path / "t.csv")
    with h5py.File(tmp_path / "t.h5", "r") as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["parameters"][()]]
        draws = f["draws"][()]
        assert draws.shape == (7, len(names))
        exact_equal(t["sample"][1], np.arange(7), "sample")
        for k, name in enumerate(names):
            column = "draws/" + name.replace(" ", "_")
            assert t[column][0] == "1"
            exact_equal(t[column][1], draws[:, k], column)
        for q in ("mean_force_prbm", "percent_constant_force_prbm", "safety_factor"):
            assert t[q][0] == f[q]["values"].attrs["units"], q
            exact_equal(t[q][1], f[q]["values"][()], q)
    assert t["mean_force_prbm"][0] == "N" and t["percent_constant_force_prbm"][0] == "%"
    # Only the thicknesses were spread: their draws are within the normal cut (3.5 sigma), the
    # widths' and lengths' are exactly 0.
    for name, (unit, values, _) in t.items():
        if name.startswith("draws/thickness"):
            assert np.all(np.abs(values) <= 3.5 * 0.03) and np.any(values != 0)
        elif name.startswith("draws/"):
            assert np.all(values == 0), name
    # The statistics of the JSON are those of the CSV's column.
    np.testing.assert_allclose(np.mean(t["mean_force_prbm"][1]), j["mean_force_prbm"]["mean"],
                               rtol=1e-12)
    # --out FILE.csv: the same table and no HDF5 file (nor a temporary).
    p = run([*args, "--out", "only.csv"], tmp_path)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "only.csv").read_text() == (tmp_path / "t.csv").read_text()
    assert sorted(os.listdir(tmp_path)) == ["only.csv", "t.csv", "t.h5"]
    p = run([*args, "--out", "x.csv", "--csv", "y.csv"], tmp_path)
    assert p.returncode == 2 and "CSV file already" in p.stderr


def test_validate_and_bench_refuse_a_csv_out(tmp_path):
    # Their files have no one table: an --out FILE.csv would be HDF5 under a CSV name.
    p = run(["validate", "--out", "v.csv"], tmp_path)
    assert p.returncode == 2, p.stderr
    assert "--out 'v.csv' names a CSV file, but this command writes HDF5 only" in p.stderr
    p = run(["bench", "--quick", "--out", "b.CSV", "--json"], tmp_path)
    assert p.returncode == 2, p.stderr
    error = json.loads(p.stdout)
    assert error["exit_code"] == 2 and "--out 'b.CSV' names a CSV file" in error["error"]
    assert os.listdir(tmp_path) == []


def test_csv_alone_is_enough_and_no_output_is_refused(tmp_path):
    # --csv without --out: only the CSV is written, the same table as with --out.
    commands = {
        "sweep": ["sweep", "beam", "--alpha2", "0:5:4", "--n", "-1:1:3"],
        "path": ["path", "--alpha2", "10", "--mu", "-6.2832"],
        "map": ["map", "cfm", "--config", "lpp", "--R", "0.5:2:3", "--d", "10:40:2"],
        "models": ["models", "map", "--n", "0", "--alpha2", "0.5:5:3", "--mu", "-1:1:2",
                   "--min-seconds", "0", "--models", "prbm"],
    }
    for name, args in commands.items():
        d = tmp_path / name
        d.mkdir()
        p = run([*args, "--csv", "alone.csv", "--json"], d)
        assert p.returncode == 0, (name, p.stderr)
        j = json.loads(p.stdout)
        assert j["out"] is None and j["csv"] == "alone.csv", name
        assert sorted(os.listdir(d)) == ["alone.csv"], name
        p = run([*args, "--out", "both.h5", "--csv", "both.csv"], d)
        assert p.returncode == 0, (name, p.stderr)
        both, alone = read_csv(d / "both.csv"), read_csv(d / "alone.csv")
        assert both.keys() == alone.keys(), name
        for key in both:
            if key == "prbm/seconds" or key.endswith("/seconds"):
                continue  # a timing
            assert both[key][0] == alone[key][0], (name, key)
            if both[key][0] == "text":
                assert both[key][1] == alone[key][1], (name, key)
            else:
                exact_equal(alone[key][1], both[key][1], f"{name} {key}")
        # Neither --out nor --csv: exit 2 before any work, naming both.
        p = run(args, d)
        assert p.returncode == 2, (name, p.stderr)
        assert "no output file: give --out FILE.h5" in p.stderr and "--csv" in p.stderr, name
        assert sorted(os.listdir(d)) == ["alone.csv", "both.csv", "both.h5"], name


def test_a_chain_file_in_si_labels_the_path_in_newtons_and_metres(tmp_path):
    # The same numbers with and without units = "SI": equal values; the SI file's are labelled
    # m, N, N m, the other's in the chain file's own units.
    chain = """
[[segment]]
type = "flexible"
length = 0.05
EI = 0.02
[tip_load]
Fy = 20.0
"""
    (tmp_path / "si.toml").write_text('units = "SI"\n' + chain)
    (tmp_path / "own.toml").write_text(chain)
    for name in ("si", "own"):
        p = run(["path", "--chain", f"{name}.toml", "--out", f"{name}.h5", "--csv", f"{name}.csv",
                 "--json"], tmp_path)
        assert p.returncode == 0, p.stderr
        assert json.loads(p.stdout)["units"] == ("SI" if name == "si" else "chain file")
    si, own = read_csv(tmp_path / "si.csv"), read_csv(tmp_path / "own.csv")
    assert si["tip_x"][0] == "m" and si["reaction_Fy"][0] == "N" and si["reaction_M"][0] == "N m"
    assert own["tip_x"][0] == "length unit of the chain file"
    for key in ("load_factor", "tip_x", "tip_y", "tip_theta"):
        exact_equal(si[key][1], own[key][1], key)
    with h5py.File(tmp_path / "si.h5", "r") as f:
        assert f.attrs["units"] == "SI"
        assert f["tip_y"].attrs["units"] == "m" and f["reaction_Fy"].attrs["units"] == "N"


SWITCH = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "examples",
                      "howell_bistable_switch.toml")


def test_general_mechanism_out_and_csv_equal_the_json(tmp_path):
    # A general mechanism file, both models: the HDF5 file and the CSV hold the JSON's numbers.
    p = run(["mechanism", "analyze", SWITCH, "--model", "both", "--input", "-5deg:33deg:20",
             "--out", "g.h5", "--csv", "g.csv", "--json"], tmp_path)
    assert p.returncode == 0, p.stderr
    j = json.loads(p.stdout)
    assert j["out"] == "g.h5" and j["csv"] == "g.csv"
    t = read_csv(tmp_path / "g.csv")
    assert t["input"][0] == "rad" and t["input_load"][0] == "N m" and t["energy"][0] == "J"
    for key in ("input", "input_load", "energy"):
        exact_equal(t[key][1], j[key], key)
    exact_equal(t["stability_displacement_control_margin"][1],
                j["stability"]["displacement_control_margin"], "margin")
    assert t["stability_force_control"][1] == j["stability"]["force_control"]
    exact_equal(t["exact/input_load"][1], j["models"]["exact"]["input_load"], "exact load")
    with h5py.File(tmp_path / "g.h5", "r") as f:
        assert f.attrs["model"] in ("both", b"both") and f.attrs["input_unit"] in ("rad", b"rad")
        for name in ("prbm", "exact"):
            m, g = j["models"][name], f["models"][name]
            for key in ("input", "input_load", "energy"):
                exact_equal(g[key][()], m[key], f"{name}/{key}")
            exact_equal(g["equilibria/input"][()], [e["input"] for e in m["equilibria"]],
                        f"{name} equilibria")
            kinds = ["stable", "unstable", "critical", "not_conservative", "not_checked"]
            assert [kinds[c] for c in g["equilibria/stability_force_control"][()]] == \
                [e["stability"] for e in m["equilibria"]]
            exact_equal(g["limit_points/input"][()], [e["input"] for e in m["limit_points"]],
                        f"{name} limit points")
        exact_equal(f["input_load"][()], j["input_load"], "root = first model")
    # --out FILE.csv alone: the same table, no HDF5 file.
    p = run(["mechanism", "analyze", SWITCH, "--model", "both", "--input", "-5deg:33deg:20",
             "--out", "only.csv"], tmp_path)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "only.csv").read_text() == (tmp_path / "g.csv").read_text()


def test_mixed_model_of_a_design_csv_has_the_stroke_and_says_half(tmp_path):
    p = run(["mechanism", "analyze", "3A-sss", "--model", "mixed", "--flexure-model", "exact",
             "--points", "6", "--out", "d.csv", "--json"], tmp_path)
    assert p.returncode == 0, p.stderr
    j = json.loads(p.stdout)
    t = read_csv(tmp_path / "d.csv")
    assert t["displacement"][0] == "m" and t["force"][0] == "N"
    assert t["force"][2] == "half" and j["force_of"] == "half"
    exact_equal(t["displacement"][1], j["displacement"], "displacement")
    exact_equal(t["force"][1], j["force"], "force")
    exact_equal(t["input_load"][1], [-v for v in j["force"]], "input load = -force")
    assert sorted(os.listdir(tmp_path)) == ["d.csv"]


def test_general_mechanism_bad_outputs_are_refused_before_solving(tmp_path):
    p = run(["mechanism", "analyze", SWITCH, "--out", "nodir/g.h5"], tmp_path)
    assert p.returncode == 2 and "nodir/g.h5" in p.stderr
    p = run(["mechanism", "analyze", SWITCH, "--out", "g.csv", "--csv", "h.csv"], tmp_path)
    assert p.returncode == 2 and "CSV file already" in p.stderr
    assert os.listdir(tmp_path) == []
