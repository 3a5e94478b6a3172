"""How far each cheap model is from the exact elastica over a load plane: the PRB 1R model
(Howell Table 5.1), the PR-3R model and the chained beam constraint model against the elliptic solution
(docs/models.md).

    /usr/bin/python3 examples/python/prbm_error_study.py [--out DIR]

`flexure models map` solves Howell's cantilever over alpha2 x mu (n = 0) with each model and
the exact solution; `flexure plot` draws each model's error map with the 1 %, 0.1 % and 0.01 %
contours; `--out x.csv` of the same command is the table for a spreadsheet. Writes models.h5,
models.csv and prbm_error_study.png to DIR (default: the current folder) and prints each model's
median and largest tip position error per length.
"""
import argparse
import json
import os

from _tool import flexure


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="folder for the files")
    args = parser.parse_args()
    h5 = os.path.join(args.out, "models.h5")
    axes = ["--n", "0", "--alpha2", "0.25:8:24", "--mu", "-2:2:17", "--models", "prbm,prbm3r,cbcm",
            "--min-seconds", "0"]
    summary = json.loads(flexure("models", "map", *axes, "--out", h5, "--csv",
                                 os.path.join(args.out, "models.csv"), "--json"))
    flexure("plot", h5, "--out", os.path.join(args.out, "prbm_error_study.png"))
    for m in summary["models"]:
        print(f"{m['method']}: median error {m['median_position_error']:.3g}, largest "
              f"{m['max_position_error']:.3g} of the length ({m['converged_points']} points)")


if __name__ == "__main__":
    main()
