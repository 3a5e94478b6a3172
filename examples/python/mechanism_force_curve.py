"""Force curve of a constant-force mechanism: the exact model against its PRBM.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/mechanism_force_curve.py \
        [--mechanism 1A-lpp] [--points 50] [--out DIR]

flexure.mechanism.analyze solves the stroke with both models (the exact, elastica-based model and
the pseudo-rigid-body model of Weight's thesis); the figure shows both slider forces and the
PRBM's error. Writes mechanism_force_curve.png to DIR and prints each model's percent constant
force.
"""
import argparse
import os

import matplotlib
import matplotlib.pyplot as plt
import numpy as np

import flexure


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mechanism", default="1A-lpp", help="built-in name or FILE.toml")
    parser.add_argument("--points", type=int, default=50, help="stroke points")
    parser.add_argument("--out", default=".", help="folder for mechanism_force_curve.png")
    args = parser.parse_args()
    r = flexure.mechanism.analyze(args.mechanism, points=args.points, method="exact")
    x = np.asarray(r["displacement"]) * 1e3  # mm
    prbm, exact = np.asarray(r["force_prbm"]), np.asarray(r["force_exact"])
    print(f"{r['design']['name']}: percent constant force {r['percent_constant_force_prbm']:.2f} "
          f"(PRBM), {r['percent_constant_force_exact']:.2f} (exact); forces of: "
          f"{r['force_of']}")

    matplotlib.rcParams["font.size"] = 8
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6, 5), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 1]})
    top.plot(x, exact, "k-", label="exact (elastica)")
    top.plot(x, prbm, "C1--", label="PRBM")
    top.set_ylabel("slider input force [N]")
    top.legend()
    top.set_title(f"{r['design']['name']}: {r['force_of']}")
    bottom.plot(x, 100.0 * (prbm - exact) / np.abs(exact).max(), "C1-")
    bottom.set_xlabel("slider displacement [mm]")
    bottom.set_ylabel("PRBM error [% of max]")
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "mechanism_force_curve.png")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
