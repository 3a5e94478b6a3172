"""The XDMF sidecar of `flexure path --shapes K --out FILE.h5` (io/shapes_xdmf.h): well-formed
XML of XDMF 3, one polyline grid per path point whose declared dimensions match the HDF5
datasets it references, every referenced dataset present in FILE.h5, and a time per grid equal
to the path's load factor; the stored internal forces N . t and N . n equal the tip load on the
local frame, and dm/ds = -V by central differences."""
import os
import xml.etree.ElementTree as ET

import h5py
import numpy as np


def test_path_shapes_xdmf(cli, tmp_path):
    out = tmp_path / "run.h5"
    result = cli.json("path", "--alpha2", "2", "--shapes", "9", "--out", str(out))
    xdmf = tmp_path / "run.xdmf"
    assert result["xdmf"] == str(xdmf)
    assert os.path.exists(xdmf)
    root = ET.parse(xdmf).getroot()  # well-formed XML
    assert root.tag == "Xdmf" and root.get("Version") == "3.0"
    with h5py.File(out, "r") as f:
        P, K = f["/shapes/x"].shape
        load = f["/load_factor"][()]
        grids = root.findall("./Domain/Grid/Grid")
        assert len(grids) == P and K == 9
        for i, g in enumerate(grids):
            assert float(g.find("Time").get("Value")) == load[i]
            top = g.find("Topology")
            assert top.get("TopologyType") == "Polyline" and int(top.get("NodesPerElement")) == K
            conn = np.array(top.find("DataItem").text.split(), dtype=int)
            assert list(conn) == list(range(K))
            for item in g.iter("DataItem"):
                if item.get("Format") != "HDF":
                    continue
                name, path = item.text.strip().split(":")
                assert name == "run.h5"
                assert path in f, path  # the referenced dataset exists
                dims = tuple(int(d) for d in item.get("Dimensions").split())
                assert dims == f[path].shape, (path, dims, f[path].shape)
            for slab in g.iter("DataItem"):
                if slab.get("ItemType") == "HyperSlab":
                    start, stride, count = (np.array(slab[0].text.split(), dtype=int)
                                            .reshape(3, 2))
                    assert list(start) == [i, 0] and list(count) == [1, K]
                    assert slab.get("Dimensions") == f"1 {K}"
            names = {a.get("Name") for a in g.findall("Attribute")}
            assert names == {"s", "theta", "moment", "axial_force", "shear_force"}
        # The internal forces: the tip load on the local frame (1e-12), and dm/ds = -V by
        # central differences (second order in the station spacing).
        th, fx, fy = f["/shapes/theta"][()], f["/tip_Fx"][()][:, None], f["/tip_Fy"][()][:, None]
        scale = max(1.0, float(np.abs(f["/tip_Fy"][()]).max()))
        assert np.allclose(f["/shapes/axial_force"][()], fx * np.cos(th) + fy * np.sin(th),
                           rtol=0, atol=1e-12 * scale)
        V = f["/shapes/shear_force"][()]
        assert np.allclose(V, -fx * np.sin(th) + fy * np.cos(th), rtol=0, atol=1e-12 * scale)
        m, s = f["/shapes/moment"][()], f["/shapes/s"][()]
        dm = (m[:, 2:] - m[:, :-2]) / (s[2:] - s[:-2])
        assert np.abs(dm + V[:, 1:-1]).max() < 0.05 * scale  # h = 1/8: O(h^2 |V''|)
