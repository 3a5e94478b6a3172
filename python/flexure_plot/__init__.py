"""flexure_plot: draws any HDF5 file the flexure tool writes (docs/cli.md "flexure plot";
docs/hdf5-schema.md). Run as `flexure plot FILE.h5 [--out FIG.png|.pdf|.svg] [--animate A.gif]`
or `/usr/bin/python3 -m flexure_plot FILE.h5 ...`; from Python, plot_file().

The kind of file is read from the file itself (_detect.py); every array drawn is recorded in the
file's units with the dataset it came from (--dump-json), so tests compare the figure with the
file. Needs matplotlib and h5py (Debian: python3-matplotlib, python3-h5py); without them the
command says so and exits 4. Exit 2: a file that is missing, not HDF5 or not written by flexure,
or an output path that cannot be written. Images are written whole or not at all.
"""
import argparse
import json
import os
import sys

from ._errors import PlotError

__all__ = ["plot_file", "main", "PlotError"]


def _libraries():
    try:
        import numpy  # noqa: F401
        import h5py  # noqa: F401
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        raise PlotError(
            f"plot: {e.name or e} is not importable by {sys.executable}; install the Debian "
            "packages python3-matplotlib and python3-h5py (apt-get install python3-matplotlib "
            "python3-h5py python3-numpy), or set FLEXURE_PYTHON to an interpreter that has them", 4) from e
    return h5py, plt


def default_out(path):
    stem, ext = os.path.splitext(path)
    return (stem if ext.lower() in (".h5", ".hdf5") else path) + ".png"


def plot_file(path, out=None, animate=None, dump_json=None, no_stress=False, n_value=None,
              extra=(), expect_kind=None, label=None):
    """Draws `path` into `out` (default: the file's name with .png); returns
    {file, kind, description, out, animate, written}. `no_stress`: a mechanism stroke without
    its stress panel (mechanism analyze files only); `n_value`: the load ratio n of a models map's
    plane (models map files with several n and several mu or tip angles only; None: the n nearest
    0). Either given for another kind of file is refused (exit 2). `extra`: [(path, label)] of further
    dynamics files drawn on the same axes, `label` the legend entry of `path` there
    (scripts/plot_dynamics.py); `expect_kind`: refuse a file of another kind (the scripts)."""
    h5py, plt = _libraries()
    from . import beam, design, mechanism, studies
    from ._common import FORMATS, Recorder, check_output, save_figure, style
    from ._detect import DESCRIPTIONS, detect

    kinds = tuple(DESCRIPTIONS)

    out = out or default_out(path)
    check_output(out, FORMATS, "--out")
    if animate:
        check_output(animate, ("gif",), "--animate")
    if dump_json:
        check_output(dump_json, ("json",), "--dump-json")
    if not os.path.exists(path):
        raise PlotError(f"plot: {path}: no such file")
    if os.path.abspath(out) == os.path.abspath(path):
        raise PlotError(f"plot: --out {out} would overwrite the input file")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise PlotError(f"plot: {path} is not an HDF5 file ({e})") from e
    opened = [f]
    style(plt)
    rec = Recorder()
    written = []
    try:
        kind = detect(f)
        if kind is None:
            raise PlotError(
                f"plot: {path} was not written by flexure (no `schema` or `command_line` of a "
                "known command and none of the datasets of docs/hdf5-schema.md); `flexure plot` "
                "draws the files of: " + ", ".join(kinds))
        if expect_kind and kind != expect_kind:
            raise PlotError(f"plot: {path} is a `{kind}` file, not a `{expect_kind}` file "
                            f"({DESCRIPTIONS[expect_kind]})")
        if no_stress and kind != "mechanism-analyze":
            raise PlotError(f"plot: --no-stress leaves out the stress panel of a mechanism stroke "
                            f"(`flexure mechanism analyze --out`); {path} is a `{kind}` file")
        if n_value is not None and kind != "models-map":
            raise PlotError(f"plot: --n picks the load ratio of a `flexure models map` file's "
                            f"plane; {path} is a `{kind}` file")
        if animate and kind == "mechanism-analyze":
            if "shapes/x" not in f:
                mechanism.animate_analyze(f, plt, animate)  # raises, naming what is missing
        elif animate and kind != "path":
            raise PlotError(f"plot: --animate needs deformed shapes; {path} ({kind}) holds none "
                            "(write a path with `flexure path ... --shapes K`, or a stroke with "
                            "`flexure mechanism analyze --out`)")
        for other, _ in extra:
            g = h5py.File(other, "r")
            opened.append(g)
            if detect(g) != "dynamics":
                raise PlotError(f"plot: {other} is not a `flexure dynamics` file")
        try:
            if kind == "sweep":
                fig = beam.draw_sweep(f, plt, rec)
            elif kind == "path":
                fig = beam.draw_path(f, plt, rec)
            elif kind == "validate":
                fig = beam.draw_validate(f, plt, rec)
            elif kind == "mechanism-analyze":
                fig = mechanism.draw_analyze(f, plt, rec, stress=not no_stress)
            elif kind == "mechanism-general":
                fig = mechanism.draw_general(f, plt, rec)
            elif kind == "mechanism-validate":
                fig = mechanism.draw_validate(f, plt, rec)
            elif kind == "mechanism-tolerance":
                fig = mechanism.draw_tolerance(f, plt, rec)
            elif kind == "dynamics":
                labels = [label or os.path.basename(path)] + [lab for _, lab in extra]
                fig = studies.draw_dynamics(list(zip(opened, labels)), plt, rec)
            elif kind == "design-history":
                fig = design.draw_history(f, plt, rec)
            elif kind == "design-table":
                fig = design.draw_table(f, plt, rec)
            elif kind == "cfm-map":
                fig = design.draw_cfm_map(f, plt, rec)
            elif kind == "models-map":
                fig = studies.draw_models(f, plt, rec, n_value)
            else:
                fig = studies.draw_bench(f, plt, rec)
        except KeyError as e:
            raise PlotError(f"plot: {path} looks like a `{kind}` file but lacks {e} "
                            "(docs/hdf5-schema.md)") from e
        try:
            save_figure(fig, out)
            written.append(os.path.abspath(out))
            rec.figure(fig)
            plt.close(fig)
            if animate and kind == "mechanism-analyze":
                mechanism.animate_analyze(f, plt, animate)
                written.append(os.path.abspath(animate))
            elif animate:
                beam.animate_path(f, plt, animate)
                written.append(os.path.abspath(animate))
            if dump_json:
                rec.dump(dump_json, kind, os.path.abspath(path))
                written.append(os.path.abspath(dump_json))
        except OSError as e:
            raise PlotError(f"plot: cannot write {out}: {e.strerror or e}", 4) from e
    finally:
        for g in opened:
            g.close()
    return {"file": os.path.abspath(path), "kind": kind, "description": DESCRIPTIONS[kind],
            "out": os.path.abspath(out), "animate": os.path.abspath(animate) if animate else None,
            "written": written}


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="flexure plot", description="Plot any HDF5 file flexure writes (docs/cli.md).")
    parser.add_argument("file", help="HDF5 file written by flexure")
    parser.add_argument("--out", help="figure (.png, .pdf, .svg; default FILE with .png)")
    parser.add_argument("--animate", help="animation of the deformed shapes (.gif)")
    parser.add_argument("--dump-json", help="write the plotted arrays (file units) as JSON")
    parser.add_argument("--no-stress", action="store_true",
                        help="mechanism analyze files: leave out the stress panel")
    parser.add_argument("--n", type=float, default=None,
                        help="models map files: the load ratio n of the plane drawn (one of the "
                             "file's n; default the n nearest 0)")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    # Used by the tool's `flexure plot` (cli/plot_command.cpp): the answer or the error as one
    # JSON object on stdout, which the tool prints or turns into its own error and exit code.
    parser.add_argument("--front-end-json", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    try:
        result = plot_file(args.file, args.out, args.animate, args.dump_json, args.no_stress,
                           args.n)
    except PlotError as e:
        if args.front_end_json or args.json:
            print(json.dumps({"error": str(e), "exit_code": e.exit_code}))
        if not args.front_end_json:
            print(f"flexure: {e}", file=sys.stderr)
        return e.exit_code
    if args.front_end_json or args.json:
        print(json.dumps(result))
    else:
        print(f"{result['kind']}: {result['description']}")
        for w in result["written"]:
            print(f"wrote {w}")
    return 0
