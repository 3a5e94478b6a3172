"""The plate modulus from Python (docs/plate-modulus.md): beam, mechanism.analyze and
design.mechanism take plate= and nu=; with plate='on' a pure end moment turns the tip by
M L (1 - nu^2)/(E I) (hand value), and the mechanism's stroke forces are 1/(1 - nu^2) times
plate='off' (nu = 0.3: 1.0989); plate without nu is an InvalidInput naming it. A chain file's
plate = "on" bends `path` with E I/(1 - nu^2) (tip angle by hand); "auto" is refused there."""
import h5py
import pytest

import flexure


def test_beam_plate_on_pure_moment():
    E, b, h, L, M = 200e9, 0.127, 1.31e-3, 0.1, 10.0
    I = b * h**3 / 12
    for plate, E_eff in (("off", E), ("on", E / 0.91)):
        r = flexure.beam(length=L, E=E, width=b, thickness=h, M=M, plate=plate, nu=0.3,
                         method="shooting")
        assert r["effective_E"] == pytest.approx(E_eff, rel=1e-15)
        assert r["theta0"] == pytest.approx(M * L / (E_eff * I), rel=1e-9)
    r = flexure.beam(length=L, E=E, width=b, thickness=h, M=M, plate="auto", nu=0.3)
    assert r["modulus_rule"] == "plate (auto)"
    assert r["modulus"][0]["searle_beta"] == pytest.approx(b * b * M / (E * I) / h, rel=1e-6)


def test_plate_without_nu_is_invalid_input():
    with pytest.raises(flexure.InvalidInput, match="needs Poisson's ratio"):
        flexure.beam(length=0.1, E=200e9, width=0.127, thickness=1.31e-3, M=1.0, plate="on")


def test_mechanism_forces_scale():
    off = flexure.mechanism.analyze("1A-lpp", points=8, method="prbm", plate="off", nu=0.3)
    on = flexure.mechanism.analyze("1A-lpp", points=8, method="prbm", plate="on", nu=0.3)
    assert on["modulus_rule"] == "plate (on)"
    ratio = on["force_prbm"] / off["force_prbm"]
    assert ratio == pytest.approx(1 / 0.91, rel=1e-12)


STRIP_SEGMENT = """[[segment]]
type = "flexible"
length = "50 mm"
E = "200 GPa"
nu = 0.3
width = "127 mm"
thickness = "1.31 mm"
plate = "{plate}"
"""


def test_path_chain_file_plate(cli, tmp_path):
    # plate = "on" bends the path's chain with E I/(1 - nu^2): a pure end moment of 10 N m turns
    # the tip by M L (1 - nu^2)/(E I) (hand value); "auto" is refused (one curvature decides it,
    # a path passes through many), exit 2 naming the segment, and nothing is written.
    E, b, h, L, M = 200e9, 0.127, 1.31e-3, 0.05, 10.0
    I = b * h**3 / 12
    for plate, expect in (("on", 0), ("auto", 2)):
        chain = tmp_path / f"{plate}.toml"
        chain.write_text('units = "SI"\n' + STRIP_SEGMENT.format(plate=plate)
                         + '[tip_load]\nM = "10 N m"\n')
        out = tmp_path / f"{plate}.h5"
        j, err = cli("path", "--chain", chain, "--out", out, "--json", expect=expect)
        if expect == 0:
            with h5py.File(out, "r") as f:
                theta = f["tip_theta"][-1]
            assert theta == pytest.approx(M * L * 0.91 / (E * I), rel=1e-8)
        else:
            assert 'segment 1 has plate = "auto"' in j["error"]
            assert not out.exists()
