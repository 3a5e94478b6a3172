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

# The start-up: mpirun, MPI's initialisation and a file written by every rank, for two loads.
STARTUP_ARGS = "sweep beam --alpha2 0:1:2 --n 1 --method elliptic"
STARTUP = ("start-up", STARTUP_ARGS, 2, "loads")
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
    """Wall seconds of one mpirun, and the items per rank it reported (empty for 1 rank)."""
    out = os.path.join(directory, f"r{ranks}.h5")
    command = ["mpirun", "-np", str(ranks), binary] + args.split() + ["--out", out]
    start = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"scaling: {' '.join(command)} failed ({done.returncode}):\n{done.stderr}")
    os.remove(out)
    balance = ""
    for line in done.stderr.splitlines():
        if "items per rank: " in line:
            balance = line.split("items per rank: ")[1].strip()
    return seconds, balance


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
    startup = (0.0, 0.0)
    with tempfile.TemporaryDirectory() as directory:
        for name, args, items, unit in [STARTUP] + STUDIES:
            one, two, ratios, balances = [], [], [], []
            for _ in range(a.pairs):
                t1, _ = run(binary, 1, args, directory)
                t2, balance = run(binary, 2, args, directory)
                one.append(t1)
                two.append(t2)
                ratios.append(t1 / t2)
                balances.append(balance)
            m1, m2 = statistics.median(one), statistics.median(two)
            if args == STARTUP_ARGS:
                startup = (m1, m2)
                print(f"start-up: 1 rank {m1:.2f} s, 2 ranks {m2:.2f} s", flush=True)
                continue
            # The work alone: each median less the start-up of as many ranks.
            work = (m1 - startup[0]) / (m2 - startup[1]) if m2 > startup[1] else float("nan")
            row = (name, items, unit, m1, m2, statistics.median(ratios), min(ratios), max(ratios),
                   work, balances[len(balances) // 2])
            rows.append(row)
            print(f"{name}: 1 rank {m1:.2f} s, 2 ranks {m2:.2f} s, speed-up {row[5]:.2f} "
                  f"({row[6]:.2f}-{row[7]:.2f}), without start-up {work:.2f}; items per rank "
                  f"{row[9]}", flush=True)
    lines = [f"Measured by `scripts/scaling.py --pairs {a.pairs}` on {platform.node()} "
             f"({os.cpu_count()} cores), wall time of the whole `mpirun` (start-up and the file "
             "included), medians of the pairs. The start-up alone (mpirun, MPI's initialisation and "
             f"the file: `{STARTUP_ARGS}`) "
             f"took {startup[0]:.2f} s with 1 rank and {startup[1]:.2f} s with 2; the last but one "
             "column is the speed-up of what remains. The last column is what the 2-rank run "
             "reported (the pair in the middle).", "",
             "| study | items | 1 rank (s) | 2 ranks (s) | speed-up (median; range) | without "
             "start-up | items per rank (2 ranks) |",
             "|---|---|---|---|---|---|---|"]
    for name, items, unit, t1, t2, ratio, lo, hi, work, balance in rows:
        lines.append(f"| {name} | {items} {unit} | {t1:.2f} | {t2:.2f} | "
                     f"{ratio:.2f} ({lo:.2f}-{hi:.2f}) | {work:.2f} | {balance} |")
    table = "\n".join(lines)
    if a.write:
        rewrite_blocks(a.write, "scaling", lambda name: table if name == "strong" else None)
    else:
        print(table)


if __name__ == "__main__":
    main()
