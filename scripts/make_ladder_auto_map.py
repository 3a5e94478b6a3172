#!/usr/bin/env python3
"""Regenerates data/ladder_auto_error_map.csv: the model ladder's measured error and time over a
grid of free-cantilever loads, the data with which `flexure beam --method auto` chooses the
cheapest model whose error at a load is within --tol (beam/ladder_selector.h;
docs/models.md "auto across the ladder").

    /usr/bin/python3 scripts/make_ladder_auto_map.py --flexure build/flexure \
        --out data/ladder_auto_error_map.csv

With --grid axial it writes data/ladder_auto_error_map_axial.csv instead: the same measurements
over loads where the axial force dominates (|n| from 2 to 100 at small alpha2), the loads a
flexure inside a mechanism carries (a pin force nearly along it); the mechanisms' model per
flexure reads both (mechanisms/general/general_mechanism.h; docs/mechanisms.md "A model per flexure").

    /usr/bin/python3 scripts/make_ladder_auto_map.py --flexure build/flexure --grid axial \
        --out data/ladder_auto_error_map_axial.csv

With --grid guided it writes data/ladder_auto_error_map_guided.csv: the guided end (the tip angle
held at tip_angle, the guide's moment a reaction) over (n, alpha2, tip_angle), against the shooting
method (`models map --boundary guided`), for `beam --boundary guided --method auto`.

It runs `flexure models map` twice: on the grid's nodes (the file's rows) and at the centres of
the grid's cells, and prints, per model, the largest ratio of the error at a cell's centre to the
largest error at the cell's 8 corners: the measured part of the margin the selector multiplies
the corners' largest error by (ladder_selector.cpp, kBetweenNodesMargin). Errors are rounded UP
to two significant digits; times (each the median over the node's 3 x 3 x 3 neighbourhood, against
the noise of a shared machine) to two significant digits.
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

MODELS = ["linear", "prbm", "prbm3r", "bcm", "cbcm"]
# The grid: finer at small loads, where linear theory and the BCM are accurate and their errors
# change fastest (as the load squared and cubed).
N = [-2, -1.5, -1, -0.5, 0, 0.5, 1, 1.5, 2]
ALPHA2 = [0, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1, 1.5, 2, 2.5, 3, 4, 5, 6, 7, 8, 10]
MU = [-2, -1.5, -1, -0.75, -0.5, -0.3, -0.2, -0.1, -0.05, 0,
      0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1, 1.5, 2]
# --grid axial: the axial force |n| alpha2 up to 200 in tension and past the buckling load in
# compression (those loads have no answer), the transverse load small.
N_AXIAL = [-100, -50, -30, -20, -14, -10, -7, -5, -3.5, -2.5, -2,
           2, 2.5, 3.5, 5, 7, 10, 14, 20, 30, 50, 100]
# --grid guided: a guided beam is four times stiffer than a free one, so alpha2 reaches 40.
ALPHA2_GUIDED = [0, 0.05, 0.1, 0.2, 0.5, 1, 2, 3, 5, 7.5, 10, 15, 20, 30, 40]
TIP_ANGLE = [-1, -0.75, -0.5, -0.3, -0.2, -0.1, -0.05, 0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1]
BOUNDARY = "free"
ALPHA2_AXIAL = [0, 0.001, 0.002, 0.005, 0.01, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3, 0.5,
                0.75, 1, 1.5, 2]


def axis(values):
    return ",".join(f"{v:g}" for v in values)


def centres(values):
    return [(a + b) / 2 for a, b in zip(values[:-1], values[1:])]


def run_map(flexure, n, alpha2, mu, out, min_seconds):
    third = f"--mu={axis(mu)}" if BOUNDARY == "free" else f"--tip-angle={axis(mu)}"
    cmd = [flexure, "models", "map", f"--boundary={BOUNDARY}", f"--n={axis(n)}",
           f"--alpha2={axis(alpha2)}", third, "--models", ",".join(MODELS),
           f"--min-seconds={min_seconds}", "--out", out]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return cmd


def answered(f, model):
    g = f[model]
    ok = (g["status"][()] == 0) & (f["reference/limit_points"][()] == 0)
    return np.where(ok, g["position_error"][()], np.nan)


def smoothed(seconds):
    """The median over each node's 3 x 3 x 3 neighbourhood (its answered nodes): a machine shared
    with other work times one solve now and then several times too slow, and the selector ranks
    the models by these times."""
    out = np.full(seconds.shape, np.nan)
    for idx in np.ndindex(seconds.shape):
        if not math.isfinite(seconds[idx]):
            continue
        block = seconds[tuple(slice(max(i - 1, 0), i + 2) for i in idx)]
        out[idx] = np.nanmedian(block)
    return out


def round_up(x):
    if not math.isfinite(x):
        return "-"
    if x == 0:
        return "0"
    e = math.floor(math.log10(x)) - 1
    return f"{math.ceil(x / 10**e - 1e-9) * 10**e:.2g}"


def round_time(seconds):
    return "-" if not math.isfinite(seconds) else f"{seconds * 1e6:.2g}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--flexure", default="build/flexure")
    parser.add_argument("--out", default="data/ladder_auto_error_map.csv")
    parser.add_argument("--min-seconds", default="2e-3")
    parser.add_argument("--grid", choices=["main", "axial", "guided"], default="main")
    args = parser.parse_args()
    global N, ALPHA2, MU, BOUNDARY
    if args.grid == "axial":
        N, ALPHA2 = N_AXIAL, ALPHA2_AXIAL
    if args.grid == "guided":
        ALPHA2, MU, BOUNDARY = ALPHA2_GUIDED, TIP_ANGLE, "guided"
    exact = "elliptic" if BOUNDARY == "free" else "shooting"
    third = "mu" if BOUNDARY == "free" else "tip_angle"
    with tempfile.TemporaryDirectory() as tmp:
        nodes_h5 = os.path.join(tmp, "nodes.h5")
        centres_h5 = os.path.join(tmp, "centres.h5")
        run_map(args.flexure, N, ALPHA2, MU, nodes_h5, args.min_seconds)
        run_map(args.flexure, centres(N), centres(ALPHA2), centres(MU), centres_h5, 0)
        # The 1R model carries a force or a moment, not both: its cells lie in the plane mu = 0.
        plane_h5 = os.path.join(tmp, "plane.h5")
        run_map(args.flexure, centres(N), centres(ALPHA2), [0], plane_h5, 0)
        nodes = h5py.File(nodes_h5, "r")
        plane = h5py.File(plane_h5, "r")
        cells = h5py.File(centres_h5, "r")
        commit = nodes.attrs["git_commit"]
        commit = commit.decode() if isinstance(commit, bytes) else str(commit)
        errors = {m: answered(nodes, m) for m in MODELS}
        times = {m: smoothed(nodes[m]["seconds"][()]) for m in MODELS}
        times[exact] = smoothed(nodes["reference/seconds"][()])
        print("largest ratio of a cell centre's error to its 8 corners' largest error:")
        for m in MODELS:
            e = errors[m]
            corner = np.full(cells[m]["status"].shape, np.nan)
            ni, ai, mi = corner.shape
            for i in range(ni):
                for j in range(ai):
                    for k in range(mi):
                        block = e[i:i + 2, j:j + 2, k:k + 2]
                        if not np.isnan(block).any():
                            corner[i, j, k] = block.max()
            centre = answered(cells, m)
            if m == "prbm":  # the plane mu = 0: cells of (n, alpha2)
                zero = MU.index(0)
                corner = np.full(plane[m]["status"].shape, np.nan)
                for i in range(corner.shape[0]):
                    for j in range(corner.shape[1]):
                        block = e[i:i + 2, j:j + 2, zero]
                        if not np.isnan(block).any():
                            corner[i, j, 0] = block.max()
                centre = answered(plane, m)
            ok = ~np.isnan(corner) & ~np.isnan(centre) & (centre > 1e-12)
            ratio = np.where(ok, centre / np.maximum(corner, 1e-300), np.nan)
            worst = np.nanmax(ratio) if ok.any() else float("nan")
            where = np.unravel_index(np.nanargmax(ratio), ratio.shape) if ok.any() else None
            print(f"  {m}: {worst:.3f} over {int(ok.sum())} cells"
                  + (f" (worst at n={centres(N)[where[0]]:g}, alpha2={centres(ALPHA2)[where[1]]:g},"
                     f" mu={(centres(MU) if m != 'prbm' else [0])[where[2]]:g})" if where else ""))
    columns = ["n", "alpha2", third]
    for m in MODELS:
        columns += [f"{m}_error", f"{m}_us"]
    columns.append(f"{exact}_us")
    lines = [
        "# The model ladder's measured tip error and time over free-cantilever loads: the data with",
        "# which `flexure beam --method auto --tol T` chooses the cheapest model whose error at a load is",
        "# within T (beam/ladder_selector.h; docs/models.md \"auto across the ladder\").",
    ] + ([
        "# This file: loads where the axial force dominates (|n| >= 2, small alpha2), those of a",
        "# flexure inside a mechanism (docs/mechanisms.md \"A model per flexure\"); the selector reads",
        "# it where n lies outside data/ladder_auto_error_map.csv.",
    ] if args.grid == "axial" else []) + ([
        "# This file: the guided end, its tip angle held at tip_angle (the guide's moment a",
        "# reaction), against the shooting method: `beam --boundary guided --method auto`.",
    ] if args.grid == "guided" else []) + [
        f"# Source: measured by `flexure models map` (git commit {commit}) against the exact {exact}",
        "# solution; regenerated by",
        "#   /usr/bin/python3 scripts/make_ladder_auto_map.py --flexure build/flexure \\",
        "#       " + ("--grid axial " if args.grid == "axial" else "") + f"--out {args.out}",
        "# which runs",
        f"#   flexure models map --n={axis(N)}",
        f"#     --alpha2={axis(ALPHA2)}",
        f"#     --{third.replace('_', '-')}={axis(MU)}" + ("" if BOUNDARY == "free" else " --boundary guided"),
        f"#     --models {','.join(MODELS)} --min-seconds={args.min_seconds} --out FILE.h5",
        "# (the PR-3R model with Su's general constants, the chained BCM with 6 elements: the defaults).",
        "# Errors rounded UP to two significant digits; `-` where the model gives no answer on the",
        "# path of proportional loading (it cannot represent the load, it does not converge, or the",
        "# exact path passes a fold before this load).",
        "#",
        f"# One row per load; the loads form a full grid, n, alpha2 and {third} ascending, {third} fastest.",
        "# Columns:",
        "#   n             load ratio (horizontal force -n P for a vertical force P; n > 0 compressive), 1",
        "#   alpha2        vertical tip load P l^2/(E I), 1",
        ("#   mu            end moment M l/(E I), counter-clockwise positive, 1" if BOUNDARY == "free"
         else "#   tip_angle     the guided tip's prescribed angle, counter-clockwise positive, rad"),
        "#   MODEL_error   tip position error per length |(a, b) - (a, b)_exact|/l of MODEL, 1",
        "#   MODEL_us      time per solve of MODEL through solve_beam on one core, microseconds (the",
        "#                 median over the node's 3 x 3 x 3 neighbourhood: one shared machine's noise)",
        f"#   {exact}_us   time per solve of the exact {exact} solution, microseconds",
        "# MODEL: linear, prbm (Howell's 1R), prbm3r (Su's PR-3R), bcm (one element), cbcm (6 elements).",
        ",".join(columns),
    ]
    for i, n in enumerate(N):
        for j, a in enumerate(ALPHA2):
            for k, mu in enumerate(MU):
                row = [f"{n:g}", f"{a:g}", f"{mu:g}"]
                for m in MODELS:
                    e = errors[m][i, j, k]
                    row += [round_up(e), round_time(times[m][i, j, k]) if math.isfinite(e) else "-"]
                row.append(round_time(times[exact][i, j, k]))
                lines.append(",".join(row))
    tmp_out = args.out + ".tmp"
    with open(tmp_out, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp_out, args.out)
    print(f"wrote {args.out}: {len(N) * len(ALPHA2) * len(MU)} loads", file=sys.stderr)


if __name__ == "__main__":
    main()
