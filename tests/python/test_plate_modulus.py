"""The plate modulus from Python (docs/plate-modulus.md): beam, mechanism.analyze and
design.mechanism take plate= and nu=; with plate='on' a pure end moment turns the tip by
M L (1 - nu^2)/(E I) (hand value), and the mechanism's stroke forces are 1/(1 - nu^2) times
plate='off' (nu = 0.3: 1.0989); plate without nu is an InvalidInput naming it."""
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
