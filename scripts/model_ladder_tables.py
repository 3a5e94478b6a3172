#!/usr/bin/python3
"""The convergence and limit tables of docs/models.md, measured with the flexure module.

Usage (from a build tree; Debian's numpy):
  PYTHONPATH=build/python /usr/bin/python3 scripts/model_ladder_tables.py [--write | --check]

Without an option, prints the tables as Markdown. --write replaces the blocks
`<!-- ladder-table: NAME -->` ... `<!-- end ladder-table -->` of docs/models.md with them (whole or
not at all, scripts/doc_blocks.py); --check recomputes them and exits 1, printing the difference,
if a block of the document is not what the library gives now (ctest ModelLadder.TablesAreUpToDate).
The tables:
  cbcm_convergence: the chained BCM's tip position error per length against N on seeded random
     free-end loads (n in [-0.5, 1], alpha2 in [0.5, 5], mu in [-1, 1]; seed 30), the largest over
     the loads, and the order log2(e(N/2)/e(N)) measured between successive N;
  bcm_deflection: the BCM's error (one element) against its transverse deflection |y|/l, free and
     guided ends (n = 0), with linear theory's;
  prbm_force, prbm_moment: the PR-3R model (Su's constants and flexure's), Howell's 1R model and
     linear theory against the load alpha2 (n = 0, mu = 0), and against mu alone.
Every error is |(a, b) - (a, b)_exact| / l against the elliptic solution (the shooting method for
the guided end). Numbers are printed to two significant digits (scientific below 0.1), orders to
two decimals. tests/elements/ladder_convergence_test.cpp checks the same tables' claims in C++.

--check also reruns the three `flexure models map` commands of docs/models.md "The map" (with
--flexure, default build/flexure; about 5 s) and compares the document's map tables with
scripts/plot_models.py's table of each file: every column but the median time (a timing of one
machine), the shares and counts exactly, the errors to their two printed digits; and the median
errors quoted in the page's first table (one row per rung) against the default free-end map.
"""
import argparse
import difflib
import math
import os
import re
import subprocess
import sys
import tempfile
import warnings

import numpy as np

import flexure

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from doc_blocks import rewrite_blocks  # noqa: E402

DOC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "models.md")
KIND = "ladder-table"


def number(x):
    """Two significant digits: plain from 0.1 up (25, 0.70), scientific below (3.7e-03)."""
    if x >= 0.1:
        return f"{x:.{max(0, 1 - math.floor(math.log10(x)))}f}"
    return f"{x:.1e}"


def exact(**loads):
    return flexure.beam(method="elliptic", **loads)


def quiet_beam(**kwargs):
    # The BCM warns where a load is near its buckling limit; the table reports its answer anyway.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return flexure.beam(**kwargs)


def error(model, reference):
    return np.hypot(model["a_over_l"] - reference["a_over_l"],
                    model["b_over_l"] - reference["b_over_l"])


def cbcm_convergence():
    rng = np.random.default_rng(30)
    count = 40
    loads = dict(n=rng.uniform(-0.5, 1.0, count), alpha2=rng.uniform(0.5, 5.0, count),
                 mu=rng.uniform(-1.0, 1.0, count))
    ref = exact(**loads)
    lines = ["| N | largest error/l | median error/l | order (largest) | order (median) |",
             "|---|---|---|---|---|"]
    previous, refused_at_1, last_order = None, 0, None
    for n in (1, 2, 4, 8, 16, 32, 64):
        extra = {"method": "bcm"} if n == 1 else {"method": "cbcm", "elements": n}
        r = quiet_beam(**extra, **loads)
        ok = r["converged"] & ref["converged"]
        e = error(r, ref)[ok]
        worst, median = e.max(), np.median(e)
        orders = ("", "")
        if previous is not None:
            last_order = math.log2(previous[0] / worst)
            orders = (f"{last_order:.2f}", f"{math.log2(previous[1] / median):.2f}")
        if n == 1:
            refused_at_1 = int((~ok).sum())
        elif not ok.all():
            sys.exit(f"error: the CBCM with N = {n} did not converge at {(~ok).sum()} loads")
        lines.append(f"| {n} | {number(worst)} | {number(median)} | {orders[0]} | {orders[1]} |")
        previous = (worst, median)
    lines.append("")
    lines.append(f"(N = 1, the BCM, was refused past its buckling load at {refused_at_1} of the "
                 f"{count} loads.) Order {last_order:.2f}, measured.")
    return "\n".join(lines)


def bcm_deflection():
    alpha2 = np.array([0.03, 0.1, 0.2, 0.3, 0.45, 0.6, 0.9, 1.2, 1.8, 2.4])
    lines = ["| end | α² | BCM \\|y\\|/l | BCM error/l | linear error/l |", "|---|---|---|---|---|"]
    rows = {}
    for boundary in ("free", "guided"):
        # A fixed-guided beam is two antisymmetric cantilevers of half its length: 4 alpha2.
        a = alpha2 if boundary == "free" else 4 * alpha2
        ref = flexure.beam(alpha2=a, boundary=boundary,
                           method="elliptic" if boundary == "free" else "shooting")
        b = quiet_beam(alpha2=a, boundary=boundary, method="bcm")
        lin = flexure.beam(alpha2=a, boundary=boundary, method="linear")
        rows[boundary] = [(f"{a[i]:g}", f"{b['max_element_deflection'][i]:.3f}",
                           number(error(b, ref)[i]), number(error(lin, ref)[i]))
                          for i in range(len(a))]
    for row in rows["free"]:
        lines.append("| free | " + " | ".join(row) + " |")
    if [r[1:] for r in rows["guided"]] == [r[1:] for r in rows["free"]]:
        g = rows["guided"]
        lines.append(f"| guided | {g[0][0]} … {g[-1][0]} | {g[0][1]} … {g[-1][1]} | "
                     "the same as free, row by row | the same |")
    else:
        for row in rows["guided"]:
            lines.append("| guided | " + " | ".join(row) + " |")
    return "\n".join(lines)


def prbm_rows(label, values, loads):
    ref = exact(**loads)
    models = [quiet_beam(method=m, **extra, **loads)
              for m, extra in (("linear", {}), ("prbm", {}), ("prbm3r", {}),
                               ("prbm3r", {"constants": "flexure"}))]
    errors = [error(r, ref) for r in models]
    lines = [f"| {label} | θ0 exact | linear | 1R (prbm) | PR-3R su | PR-3R flexure |",
             "|---|---|---|---|---|---|"]
    for i in range(len(values)):
        lines.append(f"| {values[i]:g} | {ref['theta0'][i]:.3f} | "
                     + " | ".join(number(e[i]) for e in errors) + " |")
    return "\n".join(lines)


def prbm_force():
    alpha2 = np.array([0.01, 0.1, 0.5, 1.0, 2.0, 3.0, 5.0, 8.0, 10.0, 15.0])
    return prbm_rows("α² (μ = 0)", alpha2, dict(alpha2=alpha2))


def prbm_moment():
    mu = np.array([0.1, 0.5, 1.0, 2.0, 3.0, 4.0])
    return prbm_rows("μ (α² = 0)", mu, dict(alpha2=0.0 * mu, mu=mu))


TABLES = {"cbcm_convergence": cbcm_convergence, "bcm_deflection": bcm_deflection,
          "prbm_force": prbm_force, "prbm_moment": prbm_moment}


def blocks_of(path):
    with open(path, encoding="utf-8") as f:
        doc = f.read()
    pattern = rf"<!-- {KIND}: (\S+) -->\n(.*?)\n<!-- end {KIND} -->"
    return {m.group(1): m.group(2) for m in re.finditer(pattern, doc, re.S)}


# The maps of docs/models.md "The map": the heading of each table and its command's arguments.
MAPS = [
    ("### Large loads, free end", ["models", "map"]),
    ("### Small loads, free end",
     ["models", "map", "--n", "0", "--alpha2", "0.02:1:50", "--mu=-0.5:0.5:11"]),
    ("### Guided end", ["models", "map", "--boundary", "guided", "--n=-0.5:1:4",
                        "--alpha2", "0.5:20:20", "--tip-angle=-0.3:0.3:3"]),
]


def table_rows(lines):
    """The body rows of the first Markdown table in `lines`, by model name (first cell)."""
    rows, inside = {}, False
    for line in lines:
        if line.startswith("|---"):
            inside = True
        elif inside and line.startswith("|"):
            cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.strip().strip("|"))]
            rows[cells[0]] = cells
        elif inside:
            break
    return rows


def same_number(documented, measured):
    """`documented` is `measured` printed to two significant digits (any format)."""
    try:
        d, m = float(documented), float(measured)
    except ValueError:
        return documented == measured
    if m == 0.0:
        return d == 0.0
    return abs(d - m) <= 0.51 * 10.0 ** (math.floor(math.log10(abs(m))) - 1)


def check_rung_table(doc, free_map):
    """The page's first table (one row per rung) quotes each model's median error on the default
    free-end map: its column "median error/l" against the map's (the number leading the cell)."""
    start = [i for i, line in enumerate(doc) if line.startswith("| rung |")]
    if not start:
        return ["no table '| rung |'"]
    problems = []
    for cells in table_rows(doc[start[0]:]).values():
        name, quoted = cells[1].strip("`"), cells[4].split(" ")[0]
        if name not in free_map:
            continue  # the elliptic solution: the map's reference
        if not same_number(quoted, free_map[name][7]):
            problems.append(f"rung table, {name}: median error {quoted} in the document, "
                            f"{free_map[name][7]} in the map")
    return problems


def check_maps(doc_path, flexure_binary):
    """Differences between the document's map tables and the maps computed now (list of text)."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import contextlib
    import io

    import h5py
    import plot_models
    with open(doc_path, encoding="utf-8") as f:
        doc = f.read().split("\n")
    problems = []
    with tempfile.TemporaryDirectory() as folder:
        for heading, args in MAPS:
            start = [i for i, line in enumerate(doc) if line.startswith(heading)]
            if not start:
                problems.append(f"no heading '{heading}'")
                continue
            documented = table_rows(doc[start[0]:])
            out = os.path.join(folder, "map.h5")
            subprocess.run([flexure_binary] + args + ["--out", out], check=True,
                           stdout=subprocess.DEVNULL)
            text = io.StringIO()
            with h5py.File(out, "r") as f, contextlib.redirect_stdout(text):
                plot_models.print_table(f)
            measured = table_rows(text.getvalue().split("\n"))
            if set(documented) != set(measured):
                problems.append(f"{heading}: models {sorted(documented)} in the document, "
                                f"{sorted(measured)} in the map")
            if heading == MAPS[0][0]:
                problems += check_rung_table(doc, measured)
            for name in sorted(set(documented) & set(measured)):
                d, m = documented[name], measured[name]
                # settings, answered, the three shares exactly; largest and median error.
                same = d[1:6] == m[1:6] and all(same_number(a, b) for a, b in zip(d[6:8], m[6:8]))
                if not same:
                    problems.append(f"{heading}, {name}: document {d[1:8]}, now {m[1:8]}")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--write", action="store_true", help="rewrite the blocks of --doc")
    group.add_argument("--check", action="store_true",
                       help="exit 1 if a block of --doc differs from what the library gives")
    parser.add_argument("--doc", default=DOC)
    parser.add_argument("--flexure", default=os.path.join(os.path.dirname(DOC), "..", "build",
                                                          "flexure"),
                        help="the tool that --check runs for the map tables")
    args = parser.parse_args()
    tables = {name: make() for name, make in TABLES.items()}
    if args.write:
        rewrite_blocks(args.doc, KIND, lambda name: tables.get(name))
    if args.write or args.check:
        found = blocks_of(args.doc)
        stale = False
        for name, text in tables.items():
            if name not in found:
                print(f"{args.doc}: no block <!-- {KIND}: {name} -->", file=sys.stderr)
                stale = True
            elif found[name] != text:
                print(f"{args.doc}: block {name} is stale (- document, + library now):",
                      file=sys.stderr)
                sys.stderr.writelines(difflib.unified_diff(
                    found[name].splitlines(True), text.splitlines(True), lineterm="\n"))
                print(file=sys.stderr)
                stale = True
        if args.check:
            for problem in check_maps(args.doc, args.flexure):
                print(f"{args.doc}: map table stale: {problem}", file=sys.stderr)
                stale = True
        return 1 if stale else 0
    for name, text in tables.items():
        print(f"<!-- {KIND}: {name} -->\n{text}\n<!-- end {KIND} -->\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
