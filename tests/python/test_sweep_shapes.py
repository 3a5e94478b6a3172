"""`flexure sweep beam --shapes K --out FILE.h5`: the deformed shape of every sweep point in
/shapes (benchmarks/studies/shapes_group.h, the writer `path --shapes` uses) and its XDMF sidecar.
Checked against values the sweep stores independently of the shapes: the shape's last point is the
sweep's tip (a/l, b/l, theta0 of the solver, 1e-9); the moment at the clamp is the reaction moment
from the statics of the whole beam, M + x_tip Fy - y_tip Fx (1e-9), and at the free tip the applied
moment; a physical beam's fibre stresses are N/A -+ 6 m/(b h^2) with N = Fx at the clamp. Bad
requests fail with exit 2 and leave no file."""
import os
import xml.etree.ElementTree as ET

import h5py
import numpy as np
import pytest


def check_xdmf(xdmf, h5, rows, K, fields):
    root = ET.parse(xdmf).getroot()
    assert root.tag == "Xdmf"
    with h5py.File(h5, "r") as f:
        grids = root.findall("./Domain/Grid/Grid")
        assert len(grids) == rows
        for g in grids:
            for item in g.iter("DataItem"):
                if item.get("Format") != "HDF":
                    continue
                name, path = item.text.strip().split(":")
                assert name == os.path.basename(h5)
                assert path in f, path
                dims = tuple(int(d) for d in item.get("Dimensions").split())
                assert dims == f[path].shape, (path, dims, f[path].shape)
            assert {a.get("Name") for a in g.findall("Attribute")} == {"s", *fields}
            assert int(g.find("Topology").get("NodesPerElement")) == K


@pytest.mark.parametrize("method,extra", [("elliptic", []), ("shooting", []),
                                          ("chain", ["--n", "0.4"])])
def test_sweep_shapes_end_at_the_tip_and_carry_the_clamp_moment(cli, tmp_path, method, extra):
    out = tmp_path / "sweep.h5"
    mu, n, K = 0.3, 0.4 if extra else 0.0, 11
    r = cli.json("sweep", "beam", "--alpha2", "0.5:6:5", "--mu", mu, "--method", method,
                 *extra, "--shapes", K, "--out", out)
    assert r["converged_count"] == 5 and r["shape_points"] == K
    assert r["xdmf"] == str(tmp_path / "sweep.xdmf")
    with h5py.File(out, "r") as f:
        sh = f["shapes"]
        assert sh["x"].shape == (5, K) and sh["s"].shape == (K,)
        assert np.allclose(sh["s"][()], np.linspace(0, 1, K), rtol=0, atol=1e-15)
        a, b, t, al = (f[k][()] for k in ("a_over_l", "b_over_l", "theta0", "alpha2"))
        assert np.abs(sh["x"][:, -1] - a).max() <= 1e-9
        assert np.abs(sh["y"][:, -1] - b).max() <= 1e-9
        assert np.abs(sh["theta"][:, -1] - t).max() <= 1e-9
        assert np.abs(sh["x"][:, 0]).max() <= 1e-12 and np.abs(sh["theta"][:, 0]).max() <= 1e-12
        # Howell's loads Fx = -n alpha2, Fy = alpha2, M = mu: the clamp's reaction moment.
        m = sh["moment"][()]
        m_clamp = mu + a * al - b * (-n * al)
        assert np.abs(m[:, 0] - m_clamp).max() <= 1e-9 * np.abs(m_clamp).max()
        assert np.abs(m[:, -1] - mu).max() <= 1e-9
        # N . t at the tip is the tip force on the tip tangent.
        N_tip = -n * al * np.cos(t) + al * np.sin(t)
        assert np.abs(sh["axial_force"][:, -1] - N_tip).max() <= 1e-9 * al.max()
    check_xdmf(tmp_path / "sweep.xdmf", out, 5, K, {"theta", "moment", "axial_force",
                                                     "shear_force"})


def test_physical_sweep_shapes_in_si_with_fibre_stresses(cli, tmp_path):
    out = tmp_path / "strip.h5"
    L, E, w, h, Fx, K = 0.1, 200e9, 0.01, 0.001, -2.0, 9
    r = cli.json("sweep", "beam", "--length", "100mm", "--E", "200GPa", "--width", "10mm",
                 "--thickness", "1mm", "--Fy", "0N:5N:6", "--Fx", "-2N", "--shapes", K,
                 "--out", out)
    assert r["converged_count"] == 6
    with h5py.File(out, "r") as f:
        sh = f["shapes"]
        assert sh["x"].attrs["units"] in (b"m", "m") and sh["moment"].attrs["units"] in (
            b"N m", "N m")
        a, b, t = f["a_over_l"][()], f["b_over_l"][()], f["theta0"][()]
        Fy = np.linspace(0, 5, 6)
        assert np.abs(sh["x"][:, -1] - a * L).max() <= 1e-9 * L
        assert np.abs(sh["y"][:, -1] - b * L).max() <= 1e-9 * L
        assert np.abs(sh["theta"][:, -1] - t).max() <= 1e-9
        m0 = sh["moment"][:, 0]
        m_clamp = a * L * Fy - b * L * Fx
        assert np.abs(m0 - m_clamp).max() <= 1e-9 * np.abs(m_clamp).max()
        # At the clamp (theta = 0) N . t = Fx; stresses N/A -+ m c/I of the rectangle.
        A, Z = w * h, w * h * h / 6
        assert np.allclose(sh["axial_force"][:, 0], Fx, rtol=1e-12, atol=0)
        assert np.allclose(sh["stress_pos_fibre"][:, 0], Fx / A - m_clamp / Z, rtol=1e-9, atol=1)
        assert np.allclose(sh["stress_neg_fibre"][:, 0], Fx / A + m_clamp / Z, rtol=1e-9, atol=1)
    check_xdmf(tmp_path / "strip.xdmf", out, 6, K, {"theta", "moment", "axial_force",
                                                    "shear_force", "stress_pos_fibre",
                                                    "stress_neg_fibre"})


def test_sweep_shapes_refusals(cli, tmp_path):
    # Too many values (points x shape points > 5e6), without --out, with a CSV only: exit 2.
    _, err = cli("sweep", "beam", "--alpha2", "0.5:8:100000", "--shapes", 100, "--out",
                 tmp_path / "big.h5", expect=2)
    assert "exceeds" in err and "5000000" in err
    _, err = cli("sweep", "beam", "--alpha2", "0.5:8:4", "--shapes", 5, "--csv",
                 tmp_path / "t.csv", expect=2)
    assert "--shapes needs --out" in err
    _, err = cli("sweep", "beam", "--alpha2", "0.5:8:4", "--shapes", 1, "--out",
                 tmp_path / "one.h5", expect=2)
    assert "[2, 100000]" in err
    assert os.listdir(tmp_path) == []


def test_chain_file_sweep_shapes_in_the_files_units(cli, tmp_path):
    # docs/examples/steel_strip.toml: 50 mm, SI, Fx = -2.5 N fixed; Fy swept. The shape is in m
    # (the tip: a/l times the root attribute length); the clamp moment is x_tip Fy - y_tip Fx.
    here = os.path.dirname(os.path.abspath(__file__))
    strip = os.path.join(here, "..", "..", "docs", "examples", "steel_strip.toml")
    out = tmp_path / "strip.h5"
    cli.json("sweep", "beam", "--chain", strip, "--Fy", "0N:2N:5", "--shapes", 9, "--out", out)
    with h5py.File(out, "r") as f:
        L, sh = f.attrs["length"], f["shapes"]
        assert abs(L - 0.05) < 1e-15 and abs(sh["s"][-1] - L) < 1e-15
        a, b, Fy = f["a_over_l"][()], f["b_over_l"][()], f["axes/Fy"][()]
        xt, yt = sh["x"][:, -1], sh["y"][:, -1]
        assert np.abs(xt - a * L).max() <= 1e-9 * L and np.abs(yt - b * L).max() <= 1e-9 * L
        m_clamp = xt * Fy - yt * -2.5
        assert np.abs(sh["moment"][:, 0] - m_clamp).max() <= 1e-9 * np.abs(m_clamp).max()
        assert np.abs(sh["moment"][:, -1]).max() <= 1e-9 * np.abs(m_clamp).max()
    # A distributed load (self-weight, q L^3/EI = 2.31: large deflection): the internal forces
    # integrated from the clamp's reaction (midpoint rule over the shape's intervals) must close at
    # the free tip: m = 0 there and V = the tip force on the tip normal (1e-3 of the largest m, V
    # on 41 points: the rule's O(h^2)).
    out = tmp_path / "weight.h5"
    weight = os.path.join(here, "..", "..", "docs", "examples", "self_weight_cantilever.toml")
    cli.json("sweep", "beam", "--chain", weight, "--Fy", "0N:0.2N:3", "--shapes", 41, "--out", out)
    with h5py.File(out, "r") as f:
        sh = f["shapes"]
        m, V, t = sh["moment"][()], sh["shear_force"][()], sh["theta"][()]
        assert np.isfinite(m).all() and np.isfinite(V).all()
        assert np.abs(m[:, -1]).max() <= 1e-3 * np.abs(m).max()
        Fy = f["axes/Fy"][()]
        assert np.abs(V[:, -1] - Fy * np.cos(t[:, -1])).max() <= 1e-3 * np.abs(V).max()
        assert np.abs(f["shapes/x"][:, -1] - f["a_over_l"][()] * f.attrs["length"]).max() <= 1e-9


def test_sweep_shapes_of_a_uniformly_loaded_cantilever(cli, tmp_path):
    # L = 1, EI = 1, q = 1e-3 along y, a tip force Fy from 0 to 1e-3: linear theory's
    # V(s) = Fy + q (L - s), m(s) = Fy (L - s) + q (L - s)^2 / 2 (1e-5 of the largest values: the
    # nonlinear remainder is O(theta^2) ~ 1e-7 and the rule's error smaller).
    toml = tmp_path / "q.toml"
    toml.write_text('[[segment]]\ntype = "flexible"\nlength = 1.0\nEI = 1.0\n'
                    'q = [0.0, 1e-3]\n')
    out = tmp_path / "q.h5"
    q, K = 1e-3, 41
    cli.json("sweep", "beam", "--chain", toml, "--Fy", "0:1e-3:3", "--shapes", K, "--out", out)
    with h5py.File(out, "r") as f:
        sh = f["shapes"]
        s = sh["s"][()]
        Fy = f["axes/Fy"][()][:, None]
        m_lin = Fy * (1 - s) + q * (1 - s) ** 2 / 2
        V_lin = Fy + q * (1 - s)
        scale = np.abs(m_lin).max()
        assert np.abs(sh["moment"][()] - m_lin).max() <= 1e-5 * scale
        assert np.abs(sh["shear_force"][()] - V_lin).max() <= 1e-5 * np.abs(V_lin).max()
        # N = (0, Fy + q (L - s)) exactly (a dead load per undeformed length), so N . t is
        # (Fy + q (L - s)) sin(theta), about 7e-7 here.
        N_t = V_lin * np.sin(sh["theta"][()])
        assert np.abs(sh["axial_force"][()] - N_t).max() <= 1e-12 * np.abs(V_lin).max()


def test_python_sweep_takes_shapes(tmp_path):
    import flexure
    out = tmp_path / "py.h5"
    r = flexure.sweep(alpha2="1:4:4", shapes=6, out=str(out))
    assert r["shape_points"] == 6 and r["xdmf"] == str(tmp_path / "py.xdmf")
    d = flexure.read(str(out))
    with h5py.File(out, "r") as f:
        assert f["shapes/x"].shape == (4, 6)
        assert np.abs(f["shapes/theta"][:, -1] - d["theta0"]).max() <= 1e-9
