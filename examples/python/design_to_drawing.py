"""From a specification to a drawing, a force curve and its CSV: the designer's path of issue 32.

    /usr/bin/python3 examples/python/design_to_drawing.py [--out DIR]

1. `flexure design mechanism` sizes a constant-force mechanism for a 20 N whole-mechanism force
   over a 10 mm stroke (E 200 GPa, S_y 1200 MPa, safety factor 1.5, flexures 30-150 mm, the
   shortest design) and writes it as TOML with its drawing (SVG, to scale in mm; docs/drawings.md);
2. `flexure mechanism analyze` runs the design's stroke through the PRBM and the exact model and
   writes it as HDF5 and as CSV (a spreadsheet's force curve; docs/cli.md "CSV output");
3. `flexure plot` draws the stroke (force, PRBM error, stresses against the yield strength).

Writes design.toml, design.svg, stroke.h5, stroke.csv and design_force_curve.png to DIR (default:
the current folder) and prints the mean force of the whole mechanism by the PRBM (the model the
design is sized with: 20 N) and by the exact model. The tool is $FLEXURE_BINARY, else build/flexure of this checkout, else `flexure` on the PATH.
"""
import argparse
import csv
import os

from _tool import flexure


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="folder for the files")
    args = parser.parse_args()
    out = lambda name: os.path.join(args.out, name)  # noqa: E731
    flexure("design", "mechanism", "--force", "20N", "--force-of", "whole", "--stroke", "10mm",
            "--E", "200GPa", "--yield-strength", "1200MPa", "--safety-factor", "1.5",
            "--length-range", "30mm:150mm", "--minimize", "length", "--out", out("design.toml"),
            "--drawing", out("design.svg"))
    flexure("mechanism", "analyze", out("design.toml"), "--points", "40", "--out",
            out("stroke.h5"), "--csv", out("stroke.csv"))
    flexure("plot", out("stroke.h5"), "--out", out("design_force_curve.png"))
    with open(out("stroke.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    # The header says whose force: [N (whole)], the whole mechanism (--force-of whole).
    mean = {m: sum(float(r[f"force_{m} [N (whole)]"]) for r in rows) / len(rows)
            for m in ("prbm", "exact")}
    print(f"design.svg, design_force_curve.png written; mean force of the whole mechanism over "
          f"{len(rows)} stroke points: {mean['prbm']:.3f} N (PRBM, the model the design is sized "
          f"with; asked: 20 N), {mean['exact']:.3f} N (exact)")


if __name__ == "__main__":
    main()
