"""Materials by name (docs/materials.md) where the tool asks for a modulus: `dynamics --material`,
`mechanism tolerance --material` and `material = "NAME"` in a general mechanism TOML. Each is
checked against data/materials.csv, read here independently: every spring, PRBM force and
flexure load computed from the strips is linear in E, so two materials' results stand in the
ratio of their moduli in the table."""
import csv
import os
import subprocess

import pytest

from conftest import BINARY, ROOT

SWITCH = os.path.join(ROOT, "docs", "examples", "howell_bistable_switch.toml")


def table():
    with open(os.path.join(ROOT, "data", "materials.csv"), newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return {r["id"]: r for r in rows}


def modulus(material):
    return float(table()[material]["E"]) * 1e9  # the table's E is in GPa


def yield_strength(material):
    return float(table()[material]["S_y"]) * 1e6  # MPa


def test_dynamics_material_scales_the_springs_by_its_modulus(cli):
    args = ["dynamics", "--mechanism", "2B-lplm", "--omega", "1:60:2", "--samples", "64",
            "--spring-rule", "pure-bending"]
    steel = cli.json(*args, "--material", "steel-1095-hr")
    titanium = cli.json(*args, "--material", "ti-8al-1mo-1v-annealed")
    assert steel["material"] == "steel-1095-hr" and cli.json(*args)["material"] is None
    ratio = modulus("steel-1095-hr") / modulus("ti-8al-1mo-1v-annealed")
    for k_steel, k_titanium in zip(steel["spring_constants"], titanium["spring_constants"]):
        assert k_steel == pytest.approx(ratio * k_titanium, rel=1e-12)
    assert any(k > 0 for k in steel["spring_constants"])
    # The printed Table 5 springs are constants: a material there is refused, saying why.
    _, err = cli(*args[:-2], "--material", "steel-1095-hr", "--json", expect=2)
    assert "printed Table 5 springs" in err and "--spring-rule" in err
    _, err = cli(*args, "--material", "unobtainium", "--json", expect=2)
    assert "unobtainium" in err and "flexure materials" in err


def test_tolerance_material_sets_the_nominal_design(cli):
    args = ["mechanism", "tolerance", "1A-lpp", "--method", "prbm", "--samples", "8",
            "--thickness", "1%", "--points", "8"]
    a = cli.json(*args, "--material", "steel-1095-hr")
    b = cli.json(*args, "--material", "al-7075-t6")
    assert a["material"] == "steel-1095-hr" and b["material"] == "al-7075-t6"
    # The PRBM force is linear in E (k = EI/L): the nominal forces stand in the moduli's ratio.
    ratio = modulus("steel-1095-hr") / modulus("al-7075-t6")
    assert a["mean_force_prbm"]["nominal"] == pytest.approx(
        ratio * b["mean_force_prbm"]["nominal"], rel=1e-12)
    # The nominal safety factor is the one `mechanism analyze --material` reports.
    analyzed = cli.json("mechanism", "analyze", "1A-lpp", "--method", "prbm", "--points", "8",
                        "--material", "steel-1095-hr")
    assert a["safety_factor"]["nominal"] == pytest.approx(analyzed["safety_factor"], rel=1e-12)
    # The stresses are linear in E too, the strength the table's S_y: SF ratio = S_y ratio / E
    # ratio.
    expected = (yield_strength("steel-1095-hr") / yield_strength("al-7075-t6")) / ratio
    assert a["safety_factor"]["nominal"] == pytest.approx(
        expected * b["safety_factor"]["nominal"], rel=1e-9)


def write_switch(tmp_path, replace):
    text = open(SWITCH).read()
    old = 'E = "1.4 GPa"\n'
    assert old in text
    path = tmp_path / "switch.toml"
    path.write_text(replace(text, old))
    return path


def test_general_mechanism_toml_material(cli, tmp_path):
    base = cli.json("mechanism", "analyze", SWITCH, "--input", "0deg:30deg:7")
    # The flexure's own material, and the file's (top-level) material: both set its E.
    own = write_switch(tmp_path, lambda t, old: t.replace(old, 'material = "polypropylene"\n'))
    top = tmp_path / "top.toml"
    top.write_text('material = "polypropylene"\n' + open(own).read().replace(
        'material = "polypropylene"\n', ""))
    ratio = modulus("polypropylene") / 1.4e9
    for path in (own, top):
        j = cli.json("mechanism", "analyze", str(path), "--input", "0deg:30deg:7")
        # The switch's only spring is the flexure: the input moment is linear in its E.
        for m, m0 in zip(j["input_load"], base["input_load"]):
            assert m == pytest.approx(ratio * m0, rel=1e-9, abs=1e-15)
    # A flexure's own E replaces the file's material (the file's default).
    both = tmp_path / "both.toml"
    both.write_text('material = "steel-1095-hr"\n' + open(SWITCH).read())
    j = cli.json("mechanism", "analyze", str(both), "--input", "0deg:30deg:7")
    assert j["input_load"] == pytest.approx(base["input_load"], rel=1e-12, abs=1e-15)
    # Refusals with file:line: E and material in one flexure, an unknown name, not a string.
    for text, words in (
            (lambda t, old: t.replace(old, old + 'material = "polypropylene"\n'),
             "gives both E and material"),
            (lambda t, old: t.replace(old, 'material = "unobtainium"\n'), "unobtainium"),
            (lambda t, old: t.replace(old, "material = 3\n"), "must be a material name")):
        path = write_switch(tmp_path, text)
        p = subprocess.run([BINARY, "mechanism", "analyze", str(path)], capture_output=True,
                           text=True, timeout=120)
        assert p.returncode == 2 and words in p.stderr and "switch.toml:" in p.stderr, p.stderr
