"""A snap-through path: the cantilever under a tip force alpha2 = 10 and an opposing end moment
mu = -2 pi, loaded proportionally (docs/stability.md; docs/theory-shooting.md §5).

    /usr/bin/python3 examples/python/bistable_path.py [--out DIR]

`flexure path --shapes 21` follows the equilibrium path by pseudo-arclength continuation past its
two limit points (folds) and stores the deflected shape at every point; `flexure plot` draws the
load factor against the tip (stable solid, unstable dashed, the limit points marked) and the
shapes at six load levels, and `--animate` the shapes as a GIF. Writes bistable.h5,
bistable_path.png and bistable_path.gif to DIR (default: the current folder) and prints the load
factors of the limit points: under load control the beam snaps at the first.
"""
import argparse
import json
import os

from _tool import flexure


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="folder for the files")
    args = parser.parse_args()
    h5 = os.path.join(args.out, "bistable.h5")
    summary = json.loads(flexure("path", "--alpha2", "10", "--mu", "-6.2832", "--shapes", "21",
                                 "--out", h5, "--json"))
    flexure("plot", h5, "--out", os.path.join(args.out, "bistable_path.png"), "--animate",
            os.path.join(args.out, "bistable_path.gif"))
    print(f"{summary['points']} path points, {summary['limit_points']} limit points; first at "
          f"load factor {summary['first_limit_load_factor']:.6f}")


if __name__ == "__main__":
    main()
