#!/usr/bin/env python3
"""Strong scaling of the MPI studies on this machine (docs/scaling.md): each study run with 1 and
with 2 ranks, alternately, in one run, so that both see the same machine; the ratio per pair and
its median. Writes the table into the block `<!-- scaling: strong -->` of docs/scaling.md with
--write (whole or not at all, scripts/doc_blocks.py).

Needs the MPI build (cmake -S . -B build-mpi -DFLEXURE_MPI=ON) and mpirun; standard library only.
As root, Open MPI wants OMPI_ALLOW_RUN_AS_ROOT=1 and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 (set here).

    python3 scripts/scaling.py --binary build-mpi/flexure --pairs 3 --write docs/scaling.md
"""
import argparse
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from doc_blocks import rewrite_blocks  # noqa: E402

# name, arguments (without --out), items, what an item is
STUDIES = [
    ("map cfm, exact model",
     "map cfm --config lps --R 0.6:2.4:40 --d 15:45:40 --K2 1.5 --model exact",
     1600, "exact strokes (50 points)"),
    ("sweep beam, elliptic",
     "sweep beam --alpha2 0:6:1000001 --n 1 --method elliptic",
     1000001, "loads"),
    ("design cfm --all-subclasses, exact",
     "design cfm --all-subclasses --config lpp --model exact",
     7, "sub-classes optimised"),
    ("mechanism validate --designs all",
     "mechanism validate --designs all",
     40, "designs"),
]


def run(binary, ranks, args, directory):
    out = os.path.join(directory, f"r{ranks}.h5")
    command = ["mpirun", "-np", str(ranks), binary] + args.split() + ["--out", out]
    start = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"scaling: {' '.join(command)} failed ({done.returncode}):\n{done.stderr}")
    os.remove(out)
    return seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--binary", default="build-mpi/flexure", help="the MPI build's flexure")
    parser.add_argument("--pairs", type=int, default=3, help="1-rank/2-rank pairs per study")
    parser.add_argument("--write", metavar="DOC", help="write the table into DOC's block")
    a = parser.parse_args()
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    binary = os.path.abspath(a.binary)
    rows = []
    with tempfile.TemporaryDirectory() as directory:
        for name, args, items, unit in STUDIES:
            one, two, ratios = [], [], []
            for _ in range(a.pairs):
                t1 = run(binary, 1, args, directory)
                t2 = run(binary, 2, args, directory)
                one.append(t1)
                two.append(t2)
                ratios.append(t1 / t2)
            row = (name, items, unit, statistics.median(one), statistics.median(two),
                   statistics.median(ratios), min(ratios), max(ratios))
            rows.append(row)
            print(f"{name}: 1 rank {row[3]:.2f} s, 2 ranks {row[4]:.2f} s, "
                  f"speed-up {row[5]:.2f} ({row[6]:.2f}-{row[7]:.2f})", flush=True)
    lines = [f"Measured by `scripts/scaling.py --pairs {a.pairs}` on {platform.node()} "
             f"({os.cpu_count()} cores), wall time of the whole `mpirun` (start-up and the file "
             "included), medians of the pairs:", "",
             "| study | items | 1 rank (s) | 2 ranks (s) | speed-up (median; range) |",
             "|---|---|---|---|---|"]
    for name, items, unit, t1, t2, ratio, lo, hi in rows:
        lines.append(f"| {name} | {items} {unit} | {t1:.2f} | {t2:.2f} | "
                     f"{ratio:.2f} ({lo:.2f}-{hi:.2f}) |")
    table = "\n".join(lines)
    if a.write:
        rewrite_blocks(a.write, "scaling", lambda name: table if name == "strong" else None)
    else:
        print(table)


if __name__ == "__main__":
    main()
