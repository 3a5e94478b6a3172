#!/usr/bin/python3
"""Plot one stroke of `flexure mechanism analyze NAME --out FILE.h5`: a thin wrapper over the plot
module `flexure_plot` (python/flexure_plot), which `flexure plot FILE.h5` runs too (docs/cli.md
"flexure plot"). Three panels: the slider force of the PRBM and of the exact model (the force of
one half or of the whole mechanism, from the file's `force_of`), the PRBM's force error, and the
stress of every flexure against the yield strength (--no-stress leaves it out); the points outside
the PRBM's validity shaded.

    flexure mechanism analyze 1A-lpp --method exact --out lpp.h5
    /usr/bin/python3 scripts/plot_mechanism.py lpp.h5 --out lpp.png     # = flexure plot lpp.h5 --out lpp.png

--out is the image file (.png, .pdf, .svg; default mechanism.png). Prints the path written. Exits
1 with a message (no traceback) when matplotlib or h5py is missing, the file is not a mechanism
stroke or the image cannot be written; the image is written whole or not at all.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from flexure_plot import PlotError, plot_file  # noqa: E402


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file", help="HDF5 file written by `flexure mechanism analyze --out`")
    parser.add_argument("--out", default="mechanism.png", help="output image (png, pdf, svg)")
    parser.add_argument("--stress", action="store_true",
                        help="draw the stress panel (the default; kept for older command lines)")
    parser.add_argument("--no-stress", action="store_true", help="leave the stress panel out")
    args = parser.parse_args(argv)
    try:
        result = plot_file(args.file, args.out, no_stress=args.no_stress,
                           expect_kind="mechanism-analyze")
    except PlotError as e:
        print(f"plot_mechanism.py: error: {e}", file=sys.stderr)
        return 1
    print(f"wrote {os.path.realpath(result['out'])}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
