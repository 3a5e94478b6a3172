"""flexure.beam and flexure.path with physical values (issue 29 item 5): arrays of SI numbers
solved at every entry, checked against Howell's nondimensional beam scaled (alpha2 = Fy L^2/EI,
b/l = y/L) and against linear theory (a uniform load: q L^4/(8 EI)); a list is the same as an
array and never read as text; curvature, taper and boundary keywords give the command line's
answer; a displacement-controlled path of an SI chain file with a target in mm."""
import os

import numpy as np
import pytest

import flexure

L, E, B, H = 0.05, 200e9, 0.01, 0.5e-3
EI = E * B * H ** 3 / 12
STRIP = dict(length=L, E=E, width=B, thickness=H)
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_array_of_forces_is_the_nondimensional_sweep_scaled():
    Fy = np.linspace(0.0, 5.0, 11)
    many = flexure.beam(**STRIP, Fy=Fy, Fx=-0.5)
    assert many["tip_y"].shape == (11,) and many["converged"].all()
    # Howell's beam: alpha2 = Fy L^2/EI, n = -Fx/Fy (Fy = 0 is the column below its Euler load).
    howell = flexure.beam(alpha2=Fy[1:] * L * L / EI, n=0.5 / Fy[1:], method="elliptic")
    np.testing.assert_allclose(many["tip_y"][1:] / L, howell["b_over_l"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(many["tip_x"][1:] / L, howell["a_over_l"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(many["theta0"][1:], howell["theta0"], rtol=0, atol=1e-9)
    assert many["tip_y"][0] == 0.0
    # A list is many values (never one text), and each entry is the scalar call's.
    listed = flexure.beam(**STRIP, Fy=list(Fy[:3]), Fx=-0.5)
    np.testing.assert_array_equal(listed["tip_y"], many["tip_y"][:3])
    one = flexure.beam(**STRIP, Fy=float(Fy[2]), Fx=-0.5)
    assert one["tip_y"] == many["tip_y"][2]


def test_arrays_broadcast_and_a_bad_entry_does_not_raise():
    r = flexure.beam(**STRIP, Fy=np.array([[0.1], [0.2]]), M=np.array([0.0, 1e-3, np.nan]))
    assert r["tip_y"].shape == (2, 3)
    assert list(r["status"][:, 2]) == [2, 2] and r["converged"][:, :2].all()
    assert "--M" in r["message"][0, 2]
    with pytest.raises(flexure.InvalidInput, match="do not broadcast"):
        flexure.beam(**STRIP, Fy=[1.0, 2.0], M=[0.0, 1.0, 2.0])
    with pytest.raises(flexure.InvalidInput, match="cannot be mixed"):
        flexure.beam(alpha2=[1.0, 2.0], length=[1.0, 2.0], E=1.0, I=1.0)


def test_uniform_load_array_against_linear_theory():
    # Small uniform loads: tip deflection q L^4/(8 EI) (nonlinearity ~ (y/L)^2 ~ 1e-8).
    q = np.array([1e-3, 2e-3, -3e-3])
    r = flexure.beam(**STRIP, qy=q)
    np.testing.assert_allclose(r["tip_y"], q * L ** 4 / (8 * EI), rtol=1e-6)
    np.testing.assert_array_equal(r["qy_N_per_m"], q)


def test_curvature_taper_and_boundary_keywords_equal_the_tool(cli):
    for keywords, flags in [
        (dict(curvature=8.0, Fy=0.3), ["--curvature", "8", "--Fy", "0.3"]),
        (dict(width_tip="5mm", thickness_tip=0.4e-3, Fy=0.5),
         ["--width-tip", "5mm", "--thickness-tip", "0.0004", "--Fy", "0.5"]),
        (dict(boundary="pinned", tip_x="45mm", tip_y=0.005),
         ["--boundary", "pinned", "--tip-x", "45mm", "--tip-y", "0.005"]),
    ]:
        r = flexure.beam(**STRIP, **keywords)
        expected = cli.json("beam", "--length", L, "--E", E, "--width", B, "--thickness", H,
                            *flags)
        for key in ("tip_x", "tip_y", "theta0", "root_moment_Nm", "max_stress"):
            assert r[key] == expected[key], (keywords, key)
    # The identity kappa0 <-> end moment EI kappa0 (another method: the elliptic integrals).
    curved = flexure.beam(**STRIP, curvature=np.array([4.0, 8.0]), Fy=0.3)
    for k, kappa in enumerate((4.0, 8.0)):
        straight = flexure.beam(**STRIP, Fy=0.3, M=EI * kappa, method="elliptic")
        assert abs(curved["tip_y"][k] - straight["tip_y"]) < 1e-9 * L


def test_displacement_controlled_path_of_an_si_chain_file(tmp_path):
    toml = os.path.join(ROOT, "docs", "examples", "inclined_bistable_path.toml")
    out = tmp_path / "inclined.h5"
    r = flexure.path(chain=toml, control="tip-y", tip_y="-5.2907973mm", branch=1, one_way=True,
                     min_points=61, out=str(out))
    assert r["completed"] and r["force_zero_crossings"] == 2
    data = flexure.read(str(out))
    assert abs(data["tip_y"][-1] + 0.0052907973) < 1e-12
    zeros = [p["coordinate"] for p in r["force_points"] if p["kind"] == "force_zero"]
    assert abs(zeros[0]) < 1e-12  # the level position (point symmetry)


def test_path_shapes_carry_internal_forces_and_fibre_stresses(tmp_path):
    """A tapered strip under a tip force and a uniform dead load: at every stored point N . t and
    N . n against the statics of the part beyond s (lambda (F + q (L - s)) in the root frame, an
    independent sum), the moment zero at the free tip, the fibre stresses against N/A -+ m c/I
    with the section at s, and the XDMF sidecar naming every dataset with its shape."""
    import xml.etree.ElementTree as ET
    out = tmp_path / "loaded.h5"
    Fx, Fy, q, h_tip, K = -0.3, 1.0, 10.0, 0.3e-3, 21
    r = flexure.path(**STRIP, Fx=Fx, Fy=Fy, qy=q, thickness_tip=h_tip, shapes=K, out=str(out))
    assert r["completed"]
    d = flexure.read(str(out))
    sh = d["shapes"]
    lam, s, theta = d["load_factor"], sh["s"], sh["theta"]
    assert sh["axial_force"].shape == (len(lam), K)
    Nx = lam[:, None] * Fx + 0 * s
    Ny = lam[:, None] * (Fy + q * (L - s))
    c, n = np.cos(theta), np.sin(theta)
    np.testing.assert_allclose(sh["axial_force"], Nx * c + Ny * n, rtol=0, atol=1e-9)
    np.testing.assert_allclose(sh["shear_force"], -Nx * n + Ny * c, rtol=0, atol=1e-9)
    np.testing.assert_allclose(sh["moment"][:, -1], 0.0, atol=1e-8 * np.abs(sh["moment"]).max())
    h = H + (s / L) * (h_tip - H)
    A, Z = B * h, B * h * h / 6
    np.testing.assert_allclose(sh["stress_pos_fibre"], sh["axial_force"] / A - sh["moment"] / Z,
                               rtol=1e-12, atol=1e-3)
    np.testing.assert_allclose(sh["stress_neg_fibre"], sh["axial_force"] / A + sh["moment"] / Z,
                               rtol=1e-12, atol=1e-3)
    assert sh["units"]["stress_pos_fibre"] == "Pa"
    root = ET.parse(tmp_path / "loaded.xdmf").getroot()
    names = set()
    import h5py
    with h5py.File(out, "r") as f:
        for item in root.iter("DataItem"):
            if item.get("Format") != "HDF":
                continue
            path = item.text.strip().split(":")[1]
            dims = tuple(int(x) for x in item.get("Dimensions").split())
            assert path in f and f[path].shape == dims, (path, dims)
            names.add(path)
    assert {"/shapes/stress_pos_fibre", "/shapes/stress_neg_fibre", "/shapes/axial_force",
            "/shapes/shear_force"} <= names


def test_physical_sweep_from_python_equals_the_array_call(tmp_path):
    """flexure.sweep over Fy with units: its tips (a_over_l length_m) equal flexure.beam with the
    same forces as an array, and its axis is stored in newtons."""
    out = tmp_path / "strip.h5"
    r = flexure.sweep(**STRIP, Fy="0N:2N:5", Fx="-0.5 N", out=str(out))
    assert r["axes"] == "Fy" and r["converged_count"] == 5
    d = flexure.read(str(out))
    assert d["axes"]["units"]["Fy"] == "N"
    np.testing.assert_array_equal(d["axes"]["Fy"], np.linspace(0.0, 2.0, 5))
    attributes = d["attributes"]
    assert attributes["units"] == "SI" and attributes["length_m"] == L
    many = flexure.beam(**STRIP, Fy=np.linspace(0.0, 2.0, 5), Fx=-0.5, method="shooting")
    np.testing.assert_allclose(d["b_over_l"] * attributes["length_m"], many["tip_y"], rtol=0,
                               atol=1e-9 * L)


def test_path_and_sweep_refuse_lists(tmp_path):
    with pytest.raises(flexure.InvalidInput, match="one value per keyword"):
        flexure.path(**STRIP, Fy=[1.0, 2.0], out=str(tmp_path / "p.h5"))
    with pytest.raises(flexure.InvalidInput, match="one value per keyword"):
        flexure.sweep(**STRIP, Fy=np.array([1.0, 2.0]), out=str(tmp_path / "s.h5"))
