#!/usr/bin/python3
"""Plot `flexure dynamics --out FILE.h5` files: a thin wrapper over the plot module `flexure_plot`
(python/flexure_plot), which `flexure plot FILE.h5` runs for one file (docs/cli.md "flexure
plot"). Mean and peak-to-peak input force and percent constant force against the drive frequency,
one line per file (all files must hold forces of the same thing, `force_of`), and for one file the
force over one period at its stored frequencies.

    /usr/bin/python3 scripts/plot_dynamics.py full.h5 noslider.h5 --labels full "no slider mass" \\
        --out dynamics.png

--out is the image file (.png, .pdf, .svg; default dynamics.png). Prints the path written. Exits
1 with a message when matplotlib or h5py is missing, a file is not a dynamics file or the image
cannot be written.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from flexure_plot import PlotError, plot_file  # noqa: E402


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="+", help="HDF5 files written by `flexure dynamics`")
    parser.add_argument("--labels", nargs="*", help="one label per file")
    parser.add_argument("--out", default="dynamics.png", help="output image (png, pdf, svg)")
    args = parser.parse_args(argv)
    labels = args.labels or args.files
    if len(labels) != len(args.files):
        parser.error("--labels needs one label per file")
    try:
        result = plot_file(args.files[0], args.out, expect_kind="dynamics", label=labels[0],
                           extra=list(zip(args.files[1:], labels[1:])))
    except PlotError as e:
        print(f"plot_dynamics.py: error: {e}", file=sys.stderr)
        return 1
    print(f"wrote {os.path.realpath(result['out'])}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
