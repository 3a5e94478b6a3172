"""`flexure plot` (docs/cli.md "flexure plot"): for every kind of HDF5 file the tool writes, a small
file made by the tool is plotted through the tool; the image must be a valid image and every array
the figure draws (recorded by --dump-json in the file's units, with the dataset and the indices
it came from) must equal the file's data, read here independently with h5py. Bad input: exit 2
naming the file; matplotlib missing: exit 4 with the packages to install."""
import json
import math
import os
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from conftest import BINARY, BUILD, ROOT

h5py = pytest.importorskip("h5py")
pytest.importorskip("matplotlib")

# (file, kind, the command that makes it (after `flexure`), datasets the figure must draw)
CASES = [
    ("sweep.h5", "sweep", "sweep beam --alpha2 0:5:11", ["a_over_l", "b_over_l", "theta0"]),
    ("grid.h5", "sweep", "sweep beam --alpha2 0:5:6 --n -1:1:3", ["b_over_l", "axes/alpha2"]),
    ("path.h5", "path", "path --alpha2 10 --mu -6.2832 --shapes 11",
     ["load_factor", "tip_x", "tip_y", "tip_theta", "special_points/load_factor", "shapes/x"]),
    ("validate.h5", "validate", "validate", ["rel_error", "tolerance"]),
    ("stroke.h5", "mechanism-analyze", "mechanism analyze 1A-lpp --method exact --points 6",
     ["displacement", "force_prbm", "force_exact", "stress_prbm_pivot1", "shapes/x",
      "shapes/rest_x"]),
    ("general.h5", "mechanism-general",
     f"mechanism analyze {ROOT}/docs/examples/howell_bistable_switch.toml --model both "
     "--input -5deg:33deg:20",
     ["models/prbm/input", "models/prbm/input_load", "models/exact/input_load",
      "models/prbm/equilibria/input", "models/exact/energy"]),
    ("mixed.h5", "mechanism-general",
     "mechanism analyze 3A-sss --model mixed --flexure-model exact --points 6",
     ["displacement", "force", "models/mixed/input_load"]),
    ("designs.h5", "mechanism-validate", "mechanism validate --points 6 --designs howell",
     ["percent_constant_force", "safety_factor"]),
    ("tolerance.h5", "mechanism-tolerance",
     "mechanism tolerance 1A-lpp --method prbm --samples 12 --thickness 3%",
     ["mean_force_prbm/values", "safety_factor/parameter_sensitivity"]),
    ("dynamics.h5", "dynamics", "dynamics --mechanism 2B-lplm --omega 1:60:5 --samples 64",
     ["omega", "mean_force", "history/0/force"]),
    ("history.h5", "design-history", "design cfm --config lpp --d 40 --objective min-xi",
     ["history/objective", "history/R"]),
    ("subclasses.h5", "design-table", "design cfm --all-subclasses --config lpp",
     ["percent_constant_force", "R"]),
    ("map.h5", "cfm-map", "map cfm --config lpp --R 0.5:2:5 --d 10:40:4",
     ["percent_constant_force", "Phi", "R", "d"]),
    ("models.h5", "models-map",
     "models map --n 0 --alpha2 0.5:5:4 --mu -1:1:3 --min-seconds 0 --models prbm,bcm",
     ["prbm/position_error", "bcm/position_error", "alpha2", "mu"]),
    ("bench.h5", "bench", "bench --quick --problems tip_moment,cfm_stroke --methods prbm,exact",
     ["cfm_stroke/prbm/force", "cfm_stroke/prbm/displacement"]),
]


def run(args, env=None, cwd=None):
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=600, env=env,
                          cwd=cwd)


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("plot_files")
    for name, _, command, _ in CASES:
        p = run([*command.split(), "--out", str(d / name)], cwd=d)
        assert p.returncode == 0, (command, p.stderr)
    return d


def as_array(values):
    return np.array([np.nan if v is None else v for v in values], dtype=float)


def source_values(f, source):
    data = np.asarray(f[source["dataset"]][()], dtype=float).ravel()
    return data[source["indices"]] if "indices" in source else data


def check_series_against_file(dump, path):
    """Every recorded array equals the file's values at the recorded indices (exactly: the
    figure draws the file's numbers, scaled for display and scaled back to 1e-12)."""
    compared = set()
    with h5py.File(path, "r") as f:
        for s in dump["series"]:
            for axis in ("x", "y", "z"):
                source = s.get(axis + "_source")
                if not source:
                    continue
                drawn = as_array(s[axis])
                expected = source_values(f, source)
                assert drawn.shape == expected.shape, (s["panel"], axis, source["dataset"])
                np.testing.assert_allclose(drawn, expected, rtol=1e-12, atol=0, equal_nan=True,
                                           err_msg=f"{path}: {s['panel']} {axis}")
                compared.add(source["dataset"])
    return compared


def assert_valid_png(path):
    import matplotlib.image

    with open(path, "rb") as fh:
        assert fh.read(8) == b"\x89PNG\r\n\x1a\n", path
    image = matplotlib.image.imread(path)
    assert image.ndim == 3 and image.shape[0] > 200 and image.shape[1] > 300, image.shape
    assert np.ptp(image[..., :3]) > 0.5  # not blank


@pytest.mark.parametrize("name,kind,command,drawn", CASES, ids=[c[0] for c in CASES])
def test_every_file_kind_is_plotted_from_its_own_data(files, tmp_path, name, kind, command,
                                                      drawn):
    out, dump = tmp_path / "fig.png", tmp_path / "plotted.json"
    p = run(["plot", str(files / name), "--out", str(out), "--dump-json", str(dump), "--json"])
    assert p.returncode == 0, p.stderr
    answer = json.loads(p.stdout)
    assert answer["kind"] == kind and answer["out"] == str(out)
    assert_valid_png(out)
    recorded = json.loads(dump.read_text())
    assert recorded["kind"] == kind
    compared = check_series_against_file(recorded, files / name)
    missing = [d for d in drawn if d not in compared]
    assert not missing, f"not drawn from the file: {missing}; drawn: {sorted(compared)}"


def test_path_marks_the_limit_points_and_the_unstable_stretch(files, tmp_path):
    dump = tmp_path / "p.json"
    p = run(["plot", str(files / "path.h5"), "--out", str(tmp_path / "p.svg"), "--dump-json",
             str(dump)])
    assert p.returncode == 0, p.stderr
    ET.parse(tmp_path / "p.svg")  # a well-formed SVG
    series = json.loads(dump.read_text())["series"]
    with h5py.File(files / "path.h5", "r") as f:
        kinds = [k.decode() for k in f["special_points/kind"][()]]
        stability = f["stability"][()]
        lam_limits = f["special_points/load_factor"][()][[i for i, k in enumerate(kinds)
                                                          if k == "limit_point"]]
    assert len(lam_limits) == 2  # the bistable path folds twice (docs/stability.md)
    marked = [s for s in series if s["panel"] == "tip_y:limit_point"]
    assert len(marked) == 1
    np.testing.assert_allclose(as_array(marked[0]["y"]), lam_limits, rtol=1e-12)
    # The dashed (unstable) stretch covers exactly the rows the file calls unstable.
    unstable_rows = set()
    for s in series:
        if s["panel"] == "tip_y" and s["label"] == "unstable":
            unstable_rows |= set(s["y_source"]["indices"])
    assert set(np.flatnonzero(stability == 1)) <= unstable_rows
    assert not (set(np.flatnonzero(stability == 0)) & unstable_rows - {min(unstable_rows)})


def test_displacement_controlled_path_is_force_against_displacement(tmp_path):
    # The inclined bistable beam of docs/paths.md: tip y moved 12 mm down. The figure is the
    # support's force against the prescribed coordinate, in the file's SI units shown as mm and
    # N, with every force point of /force_points marked at its stored value, zeros split by the
    # sign of the stored slope; nothing is drawn against the load factor.
    h5 = tmp_path / "inclined.h5"
    p = run(["path", "--chain", os.path.join(ROOT, "docs/examples/inclined_bistable_path.toml"),
             "--control", "tip-y", "--tip-y", "-0.0052907973", "--branch", "1", "--one-way",
             "--min-points", "121", "--out", str(h5)])
    assert p.returncode == 0, p.stderr
    dump = tmp_path / "inclined.json"
    p = run(["plot", str(h5), "--out", str(tmp_path / "inclined.png"), "--dump-json", str(dump)])
    assert p.returncode == 0, p.stderr
    assert_valid_png(tmp_path / "inclined.png")
    recorded = json.loads(dump.read_text())
    compared = check_series_against_file(recorded, h5)
    assert {"tip_y", "tip_Fy", "force_points/coordinate", "force_points/force"} <= compared
    assert "load_factor" not in compared
    main = recorded["axes"][0]
    assert main["xlabel"].startswith("tip y") and main["xlabel"].endswith("[mm]"), main
    assert "Fy" in main["ylabel"] and main["ylabel"].endswith("[N]"), main
    # No offset text ("1e-11+6.96e-2") on any axes: it overlapped the labels.
    assert all(a["x_offset"] == "" and a["y_offset"] == "" for a in recorded["axes"])
    with h5py.File(h5, "r") as f:
        assert f["tip_y"].attrs["units"] in ("m", b"m")
        kinds = [k.decode() for k in f["force_points/kind"][()]]
        slope = f["force_points/slope"][()]
        y, fy = f["tip_y"][()], f["tip_Fy"][()]
        zeros_c = f["force_points/coordinate"][()][[k == "force_zero" for k in kinds]]
    assert kinds.count("force_zero") == 2  # bistable: the force changes sign twice
    marks = [s for s in recorded["series"] if s["panel"].startswith("force_points:")]
    marked = sorted(i for s in marks for i in s["y_source"]["indices"])
    assert marked == list(range(len(kinds)))  # every force point once
    for s in marks:
        for i in s["y_source"]["indices"]:
            assert s["panel"] == "force_points:" + kinds[i]
            if kinds[i] == "force_zero":
                assert s["label"].endswith(": stable when released") == (slope[i] > 0)
                assert s["label"].endswith(": unstable when released") == (slope[i] < 0)
    # Independently of /force_points: the drawn curve changes sign between rows k and k + 1
    # exactly where a marked zero lies (on the chord's coordinate span, to 1e-9 m).
    curve = [s for s in recorded["series"] if s["panel"] == "force"]
    rows = sorted({i for s in curve for i in s["y_source"]["indices"]})
    assert rows == list(range(len(y)))
    crossings = [k for k in range(len(y) - 1) if fy[k] * fy[k + 1] < 0]
    assert len(crossings) == len(zeros_c)
    for k, c in zip(crossings, sorted(zeros_c, key=lambda c: -c)):
        assert min(y[k], y[k + 1]) - 1e-9 <= c <= max(y[k], y[k + 1]) + 1e-9, (k, c)


def test_animation_has_one_frame_per_path_point(files, tmp_path):
    from PIL import Image

    gif = tmp_path / "a.gif"
    p = run(["plot", str(files / "path.h5"), "--out", str(tmp_path / "a.pdf"), "--animate",
             str(gif)])
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "a.pdf").read_bytes()[:5] == b"%PDF-"
    with h5py.File(files / "path.h5", "r") as f:
        points = len(f["load_factor"])
    with Image.open(gif) as im:
        assert im.format == "GIF" and im.n_frames == points


def test_mechanism_stroke_shapes_are_drawn_and_animated(files, tmp_path):
    # /shapes of `mechanism analyze`: one exact shape per solved stroke point. Independent checks
    # of the stored geometry: the ground end stays where it is at rest, the slider end moves by
    # -Delta x along the axis (y = 0), and every flexure keeps its length (the polyline through 41
    # stations is shorter than the arc by O(h^2): 1e-3 relative).
    from PIL import Image

    with h5py.File(files / "stroke.h5", "r") as f:
        x, y = f["shapes/x"][()], f["shapes/y"][()]
        rx, ry = f["shapes/rest_x"][()], f["shapes/rest_y"][()]
        part = f["shapes/part"][()]
        dx = f["shapes/displacement"][()]
        rows = f["shapes/point_index"][()]
        np.testing.assert_array_equal(dx, f["displacement"][()][rows])
        assert len(dx) == len(f["displacement"])  # the exact model solved every point
        pivots = f["design/joints/length"][()]
    span = np.ptp(rx)
    np.testing.assert_allclose(x[:, 0], rx[0], atol=1e-9 * span)
    np.testing.assert_allclose(y[:, 0], ry[0], atol=1e-9 * span)
    np.testing.assert_allclose(x[:, -1], rx[-1] - dx, atol=1e-9 * span)
    np.testing.assert_allclose(y[:, -1], 0.0, atol=1e-9 * span)
    flexures = sorted(set(part) - {0})
    assert flexures
    for p in flexures:
        on = np.flatnonzero(part == p)
        rest_length = np.hypot(np.diff(rx[on]), np.diff(ry[on])).sum()
        assert rest_length == pytest.approx(pivots[p - 1], rel=1e-9)
        bent = np.hypot(np.diff(x[:, on], axis=1), np.diff(y[:, on], axis=1)).sum(axis=1)
        np.testing.assert_allclose(bent, rest_length, rtol=1e-3)
        assert np.all(bent <= rest_length * (1 + 1e-9))
    gif = tmp_path / "stroke.gif"
    p = run(["plot", str(files / "stroke.h5"), "--out", str(tmp_path / "s.png"), "--animate",
             str(gif)])
    assert p.returncode == 0, p.stderr
    with Image.open(gif) as im:
        assert im.format == "GIF" and im.n_frames == len(dx) + 1  # at rest, then every point


def test_mechanism_without_shapes_refuses_to_animate(tmp_path):
    # A PRBM-only analysis (no exact model): no /shapes, and --animate says what is missing.
    h5 = tmp_path / "prbm.h5"
    p = run(["mechanism", "analyze", "1A-lpp", "--method", "prbm", "--points", "6", "--out",
             str(h5)])
    assert p.returncode == 0, p.stderr
    with h5py.File(h5, "r") as f:
        assert "shapes" not in f
    p = run(["plot", str(h5), "--out", str(tmp_path / "m.png"), "--animate",
             str(tmp_path / "m.gif")])
    assert p.returncode == 2 and "/shapes" in p.stderr, p.stderr
    assert not (tmp_path / "m.png").exists() and not (tmp_path / "m.gif").exists()


def test_mechanism_force_error_panel_is_the_relative_difference(files, tmp_path):
    dump = tmp_path / "m.json"
    assert run(["plot", str(files / "stroke.h5"), "--out", str(tmp_path / "m.png"),
                "--dump-json", str(dump)]).returncode == 0
    series = {s["panel"]: s for s in json.loads(dump.read_text())["series"]}
    with h5py.File(files / "stroke.h5", "r") as f:
        expected = 100 * (f["force_prbm"][()] - f["force_exact"][()]) / f["force_exact"][()]
        assert f.attrs["force_of"] in ("one half", b"one half")
    np.testing.assert_allclose(as_array(series["force_error"]["y"]), expected, rtol=1e-12)


def test_default_out_is_the_file_name_with_png(files, tmp_path):
    src = tmp_path / "s.h5"
    src.write_bytes((files / "sweep.h5").read_bytes())
    p = run(["plot", str(src)])
    assert p.returncode == 0, p.stderr
    assert f"wrote {tmp_path / 's.png'}" in p.stdout
    assert_valid_png(tmp_path / "s.png")


def test_unknown_and_bad_files_are_refused_naming_the_file(files, tmp_path):
    foreign = tmp_path / "foreign.h5"
    with h5py.File(foreign, "w") as f:
        f["x"] = np.arange(3.0)
    p = run(["plot", str(foreign), "--out", str(tmp_path / "x.png")])
    assert p.returncode == 2 and str(foreign) in p.stderr and "not written by flexure" in p.stderr
    assert not (tmp_path / "x.png").exists()
    text = tmp_path / "notes.h5"
    text.write_text("not hdf5")
    p = run(["plot", str(text), "--json"])
    assert p.returncode == 2 and str(text) in p.stderr
    error = json.loads(p.stdout)
    assert error["exit_code"] == 2 and "not an HDF5 file" in error["error"]
    p = run(["plot", str(tmp_path / "missing.h5")])
    assert p.returncode == 2 and "missing.h5: no such file" in p.stderr
    p = run(["plot", str(files / "sweep.h5"), "--out", str(tmp_path / "x.jpg")])
    assert p.returncode == 2 and ".png, .pdf, .svg" in p.stderr
    p = run(["plot", str(files / "sweep.h5"), "--out", str(tmp_path / "x.png"), "--animate",
             str(tmp_path / "x.gif")])
    assert p.returncode == 2 and "--animate" in p.stderr
    assert not (tmp_path / "x.png").exists() and not (tmp_path / "x.gif").exists()


def test_missing_matplotlib_is_reported_with_exit_4(files, tmp_path):
    # An interpreter without site-packages: no numpy, h5py or matplotlib.
    bare = tmp_path / "bare-python"
    bare.write_text("#!/bin/sh\nexec /usr/bin/python3 -S \"$@\"\n")
    bare.chmod(0o755)
    env = dict(os.environ, FLEXURE_PYTHON=str(bare))
    p = run(["plot", str(files / "sweep.h5"), "--out", str(tmp_path / "x.png")], env=env)
    assert p.returncode == 4, p.stderr
    assert "python3-matplotlib" in p.stderr and "not importable" in p.stderr


def test_module_missing_is_reported_with_exit_4(files, tmp_path):
    # A copy of the tool with no share/ beside it and no install: it says where it looked.
    lonely = tmp_path / "bin" / "flexure"
    lonely.parent.mkdir()
    lonely.write_bytes(open(BINARY, "rb").read())
    lonely.chmod(0o755)
    env = {k: v for k, v in os.environ.items() if k != "FLEXURE_PLOT_PATH"}
    p = subprocess.run([str(lonely), "plot", str(files / "sweep.h5")], capture_output=True,
                       text=True, env=env, timeout=60)
    if os.path.isdir(os.path.join("/usr/local/share/flexure/python/flexure_plot")):
        pytest.skip("a flexure install in /usr/local provides the module")
    assert p.returncode == 4 and "flexure_plot is not installed" in p.stderr
    assert BUILD  # the module is found beside the build tree's tool (the other tests)


def test_the_installed_tool_finds_the_installed_module(files, tmp_path):
    # `cmake --install` puts the module in <prefix>/share/flexure/python beside <prefix>/bin.
    prefix = tmp_path / "prefix"
    p = subprocess.run(["cmake", "--install", BUILD, "--prefix", str(prefix)], capture_output=True,
                       text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    assert (prefix / "share/flexure/python/flexure_plot/__main__.py").is_file()
    out = tmp_path / "installed.png"
    p = subprocess.run([str(prefix / "bin/flexure"), "plot", str(files / "sweep.h5"), "--out",
                        str(out)], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert_valid_png(out)


def test_tolerance_plot_states_which_force(files, tmp_path):
    # The file says which force its mean forces are (force_of), and the figure's label says it.
    p = run(["mechanism", "tolerance", "1A-lpp", "--method", "prbm", "--samples", "12",
             "--thickness", "3%", "--force-of", "whole", "--out", str(tmp_path / "w.h5")])
    assert p.returncode == 0, p.stderr
    dump = tmp_path / "w.json"
    assert run(["plot", str(tmp_path / "w.h5"), "--out", str(tmp_path / "w.png"),
                "--dump-json", str(dump)]).returncode == 0
    series = {s["panel"]: s for s in json.loads(dump.read_text())["series"]}
    assert "whole symmetric mechanism" in series["mean_force_prbm"]["label"]
    assert "mechanism" not in series["safety_factor"]["label"]
    with h5py.File(tmp_path / "w.h5", "r") as w, h5py.File(files / "tolerance.h5", "r") as h:
        assert w.attrs["force_of"] in ("whole symmetric mechanism", b"whole symmetric mechanism")
        assert h.attrs["force_of"] in ("one half", b"one half")
        # The same seeded samples: the whole mechanism's forces are twice the half's, exactly.
        np.testing.assert_array_equal(w["mean_force_prbm/values"][()],
                                      2 * h["mean_force_prbm/values"][()])
    dump = tmp_path / "h.json"
    assert run(["plot", str(files / "tolerance.h5"), "--out", str(tmp_path / "h.png"),
                "--dump-json", str(dump)]).returncode == 0
    series = {s["panel"]: s for s in json.loads(dump.read_text())["series"]}
    assert "one half" in series["mean_force_prbm"]["label"]


def test_no_stress_and_n_are_forwarded_and_refused_for_other_files(files, tmp_path):
    # --no-stress: the stroke's figure without its stress panel (with it by default).
    for extra, has_stress in (([], True), (["--no-stress"], False)):
        dump = tmp_path / "s.json"
        p = run(["plot", str(files / "stroke.h5"), "--out", str(tmp_path / "s.png"),
                 "--dump-json", str(dump), *extra])
        assert p.returncode == 0, p.stderr
        panels = {s["panel"] for s in json.loads(dump.read_text())["series"]}
        assert ("stress" in panels) == has_stress and "force" in panels
    # --n picks the plane of a map with two load ratios: the drawn errors are the file's at n = 1.
    maps = tmp_path / "two_n.h5"
    assert run(["models", "map", "--n", "0:1:2", "--alpha2", "0.5:5:3", "--mu", "-1:1:3",
                "--min-seconds", "0", "--models", "prbm", "--out", str(maps)]).returncode == 0
    for n, index in ((None, 0), (1.0, 1)):
        dump = tmp_path / "m.json"
        p = run(["plot", str(maps), "--out", str(tmp_path / "m.png"), "--dump-json", str(dump),
                 *([] if n is None else ["--n", str(n)])])
        assert p.returncode == 0, p.stderr
        [series] = [s for s in json.loads(dump.read_text())["series"] if s["panel"] == "prbm"]
        with h5py.File(maps, "r") as f:
            expected = f["prbm/position_error"][()][index]  # [alpha2, mu] at this n
        np.testing.assert_array_equal(as_array(series["z"]), expected.T.ravel())
    # Refusals (exit 2, nothing written): an n not in the file, --n or --no-stress on another kind.
    for args, words in ((["--n", "0.5"], "not a load ratio of the map; its n: 0, 1"),):
        p = run(["plot", str(maps), "--out", str(tmp_path / "x.png"), *args])
        assert p.returncode == 2 and words in p.stderr, p.stderr
    p = run(["plot", str(files / "models.h5"), "--out", str(tmp_path / "x.png"), "--n", "0"])
    assert p.returncode == 0, p.stderr  # its one n
    for args, words in ((["--no-stress"], "--no-stress"), (["--n", "0"], "--n picks")):
        p = run(["plot", str(files / "sweep.h5"), "--out", str(tmp_path / "y.png"), *args])
        assert p.returncode == 2 and words in p.stderr and "`sweep` file" in p.stderr, p.stderr
        assert not (tmp_path / "y.png").exists()
    single = tmp_path / "single_mu.h5"
    assert run(["models", "map", "--n", "0:1:2", "--alpha2", "0.5:5:3", "--mu", "0",
                "--min-seconds", "0", "--models", "prbm", "--out", str(single)]).returncode == 0
    p = run(["plot", str(single), "--out", str(tmp_path / "z.png"), "--n", "1"])
    assert p.returncode == 2 and "every n at once" in p.stderr, p.stderr


def test_benchmark_charts_are_drawn_from_the_file(files, tmp_path):
    # scripts/plot_benchmarks.py draws through the package (flexure_plot/bench.py): each method's
    # point of the accuracy chart is its worst converged error and median time in the file.
    import sys
    sys.path.insert(0, os.path.join(ROOT, "python"))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from flexure_plot import bench
    from flexure_plot._common import Recorder
    rec = Recorder()
    with h5py.File(files / "bench.h5", "r") as f:
        fig = bench.draw_pareto(f, plt, rec)
        assert bench.draw_stability(f, plt, Recorder()) is None  # no cantilever_force in it
        points = {s["panel"]: s["y"] for s in rec.series}
        checked = 0
        for problem in f:
            for method in f[problem]:
                g = f[problem][method]
                ok = g["status"][()] == 0
                if method == "reference" or not ok.any():
                    continue
                worst = max(float(np.max(g["error_relative"][()][ok])), 1e-16)
                assert points[f"pareto:{problem}:{method}"] == pytest.approx(
                    [float(np.median(g["seconds"][()])), worst], rel=1e-12)
                checked += 1
        assert checked >= 2
    texts = [t for ax in fig.axes for t in ax.texts]
    assert all(t.get_fontsize() >= 9 for t in texts)
    plt.close(fig)


def _bilinear(x, y, z, px, py):
    # z[j, i] on the grid x[i], y[j]: bilinear interpolation at (px, py) (on a cell edge, where
    # matplotlib's contour vertices lie, it is the linear interpolation along that edge).
    i = int(np.clip(np.searchsorted(x, px) - 1, 0, len(x) - 2))
    j = int(np.clip(np.searchsorted(y, py) - 1, 0, len(y) - 2))
    u = (px - x[i]) / (x[i + 1] - x[i])
    v = (py - y[j]) / (y[j + 1] - y[j])
    return ((1 - u) * (1 - v) * z[j, i] + u * (1 - v) * z[j, i + 1] + (1 - u) * v * z[j + 1, i]
            + u * v * z[j + 1, i + 1])


def test_models_map_contours_lie_on_the_errors_they_name(tmp_path):
    # docs/models.md: each model's map carries the 1 %, 0.1 % and 0.01 % contours. Every level
    # inside a model's error range must be drawn, and every vertex of a level's lines must lie
    # where the file's error (read here with h5py, interpolated on the grid) equals that level.
    import sys
    sys.path.insert(0, os.path.join(ROOT, "python"))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.axes import Axes
    from flexure_plot import studies
    from flexure_plot._common import Recorder
    out = tmp_path / "m.h5"
    assert run(["models", "map", "--n", "0", "--alpha2", "0.2:8:14", "--mu", "-2:2:9",
                "--min-seconds", "0", "--models", "linear,bcm,prbm3r", "--out",
                str(out)]).returncode == 0
    # The contour sets as drawn (matplotlib before 3.8 does not keep them among the axes'
    # children): Axes.contour wrapped to note what it returns, per axes.
    drawn_sets = {}
    contour = Axes.contour

    def noting_contour(ax, *args, **kwargs):
        c = contour(ax, *args, **kwargs)
        drawn_sets.setdefault(id(ax), []).append(c)
        return c

    Axes.contour = noting_contour
    try:
        with h5py.File(out, "r") as f:
            fig = studies.draw_models(f, plt, Recorder())
    finally:
        Axes.contour = contour
    with h5py.File(out, "r") as f:
        x, y = f["alpha2"][()], f["mu"][()]
        levels_seen = 0
        for ax in fig.axes:
            name = ax.get_title().split(" ")[0]
            if name not in ("linear", "bcm", "prbm3r"):
                continue  # colour bars
            error = f[name + "/position_error"][()][0].T  # [mu, alpha2]
            ok = f[name + "/status"][()][0].T == 0
            logged = np.where(ok, np.log10(np.maximum(error, 1e-16)), 1.0)
            expected = [math.log10(v) for v in (1e-4, 1e-3, 1e-2)
                        if np.log10(error[ok]).min() < math.log10(v) < np.log10(error[ok]).max()]
            sets = drawn_sets.get(id(ax), [])
            drawn = sorted(float(v) for c in sets for v in c.levels)
            assert drawn == pytest.approx(sorted(expected), abs=1e-12), name
            for c in sets:
                for level, segments in zip(c.levels, c.allsegs):
                    assert sum(len(seg) for seg in segments) > 0, (name, level)
                    for seg in segments:
                        for px, py in seg:
                            assert _bilinear(x, y, logged, px, py) == pytest.approx(level,
                                                                                    abs=1e-9)
                    levels_seen += 1
        # linear theory crosses 1 % and 0.1 % on this grid, the BCM all three, PR-3R 1 % and 0.1 %
        print("level lines checked:", levels_seen)
        assert levels_seen >= 5
    plt.close("all")


def test_general_mechanism_draws_its_bodies_and_flexures_at_their_poses(tmp_path):
    # The double-parallelogram stage (docs/examples), both models: at five inputs of each model
    # the figure draws every moving body through its named points and every flexure between its
    # ends. Checked against the file read here with h5py: each body's drawn vertices are its
    # described points (/geometry/points) moved by the model's pose at that point (about the
    # reference /geometry/bodies), the stage's point C at x = the input (the prescribed
    # coordinate: an independent value), each flexure's curve ends on its bodies' posed ends and
    # leaves a clamp along the body's rotated rest direction.
    h5 = tmp_path / "stage.h5"
    example = os.path.join(ROOT, "docs/examples/double_parallelogram_stage.toml")
    p = run(["mechanism", "analyze", example, "--model", "both", "--out", str(h5)])
    assert p.returncode == 0, p.stderr
    dump = tmp_path / "stage.json"
    p = run(["plot", str(h5), "--out", str(tmp_path / "stage.png"), "--dump-json", str(dump)])
    assert p.returncode == 0, p.stderr
    assert_valid_png(tmp_path / "stage.png")
    series = {s["panel"]: s for s in json.loads(dump.read_text())["series"]}
    text = lambda d: [v.decode() for v in d[()]]
    with h5py.File(h5, "r") as f:
        g = f["geometry"]
        body_of = text(g["points/body"])
        name_of = text(g["points/name"])
        pts = np.column_stack([g["points/x"][()], g["points/y"][()]])
        ref = dict(zip(text(g["bodies/name"]), np.column_stack([g["bodies/reference_x"][()],
                                                                g["bodies/reference_y"][()]])))
        fl = g["flexures"]
        flex = list(zip(text(fl["name"]), text(fl["body_a"]), text(fl["body_b"]),
                        np.column_stack([fl["a_x"][()], fl["a_y"][()]]),
                        np.column_stack([fl["b_x"][()], fl["b_y"][()]]), text(fl["end_b"])))
        checked = 0
        for m in ("prbm", "exact"):
            gm = f["models"][m]
            names = text(gm["bodies/name"])
            n = len(gm["input"])
            picks = sorted(set(int(round(v)) for v in np.linspace(0, n - 1, 5)))
            assert len(picks) == 5

            def moved(body, q, i):
                if body == "ground":
                    return np.asarray(q, dtype=float)
                c = names.index(body)
                x, y, phi = gm["bodies/x"][i, c], gm["bodies/y"][i, c], gm["bodies/phi"][i, c]
                d = np.asarray(q) - ref[body]
                return ref[body] + [x, y] + [math.cos(phi) * d[0] - math.sin(phi) * d[1],
                                             math.sin(phi) * d[0] + math.cos(phi) * d[1]]

            for i in picks:
                for body in ("intermediate", "stage"):
                    s = series[f"shape:{m}:{i}:body:{body}"]
                    drawn = np.unique(np.column_stack([as_array(s["x"]), as_array(s["y"])]),
                                      axis=0)
                    mine = [k for k, b in enumerate(body_of) if b == body]
                    expected = np.unique(np.array([moved(body, pts[k], i) for k in mine]), axis=0)
                    np.testing.assert_allclose(drawn, expected, rtol=0, atol=1e-15)
                    if body == "stage":
                        k_c = [k for k in mine if name_of[k] == "C"][0]
                        assert abs(moved(body, pts[k_c], i)[0] - gm["input"][i]) < 1e-12
                    checked += 1
                for name, a, b, pa, pb, end in flex:
                    s = series[f"shape:{m}:{i}:flexure:{name}"]
                    xy = np.column_stack([as_array(s["x"]), as_array(s["y"])])
                    np.testing.assert_allclose(xy[0], moved(a, pa, i), rtol=0, atol=1e-15)
                    np.testing.assert_allclose(xy[-1], moved(b, pb, i), rtol=0, atol=1e-15)
                    # End tangents (second-order one-sided differences of the drawn samples)
                    # along the rest direction turned with the body (clamped ends).
                    u = (pb - pa) / np.linalg.norm(pb - pa)
                    for body, t in ((a, -3 * xy[0] + 4 * xy[1] - xy[2]),
                                    (b, 3 * xy[-1] - 4 * xy[-2] + xy[-3])):
                        phi = 0.0 if body == "ground" else gm["bodies/phi"][i, names.index(body)]
                        want = math.atan2(u[1], u[0]) + phi
                        assert abs(math.remainder(math.atan2(t[1], t[0]) - want, 2 * math.pi)) \
                            < 1e-3, (m, i, name, body)
                    assert end == "clamped"
                    checked += 1
        assert checked == 2 * 5 * (2 + 4)
