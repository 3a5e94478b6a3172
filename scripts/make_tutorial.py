#!/usr/bin/env python3
"""Writes docs/tutorial.md by running every command it shows, so the tutorial stays true.

    python3 scripts/make_tutorial.py --flexure build/flexure            # rewrite docs/tutorial.md
    python3 scripts/make_tutorial.py --flexure build/flexure --check    # exit 1 if it is stale

Standard library only. Commands run from the repository root; files they write go to a temporary
directory. ctest runs the --check form (Tutorial.IsUpToDate).
"""
import argparse
import difflib
import json
import os
import shlex
import subprocess
import sys
import tempfile

from doc_blocks import write_atomically

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STRIP = ("--length 50mm --E 200GPa --width 10mm --thickness 0.5mm "
         "--Fx -2.5N --Fy 4.330127N --yield-strength 1.2GPa")

# The tutorial: prose, and commands whose output is inserted. ("run", ARGS[, options]) runs
# `flexure ARGS`; {tmp} in ARGS is the scratch directory, shown as the file name alone. ("values",
# ARGS, {name: (key, scale)}) runs `flexure ARGS --json` without showing it and keeps key * scale
# as `name` for the prose that follows ({name:.3g} in "text"), so no number in the prose is typed
# by hand.
TUTORIAL = [
    ("text", """# Tutorial: a steel strip, then a constant-force mechanism of your own

Every command below was run by `scripts/make_tutorial.py`, which wrote this page with the output
shown; the test suite reruns it and fails if any output changed. Units follow docs/units.md: plain
numbers are SI, values may carry a unit (`50mm`, `200GPa`, `25lbf`, `30deg`).

## 1. A steel strip

A spring-steel strip 50 mm long, 10 mm wide and 0.5 mm thick (E = 200 GPa, yield strength taken as
1.2 GPa) is clamped at one end. Its tip carries 5 N at 30° from the perpendicular, leaning back
toward the clamp: across the strip Fy = 5 cos 30° = 4.330127 N, along it Fx = −5 sin 30° = −2.5 N
(+x runs along the undeformed strip from the clamp, +y across it). How far does the tip move, and
how close is the strip to yielding?
"""),
    ("run", "beam " + STRIP),
    ("values", "beam " + STRIP, {
        "alpha2": ("alpha2", 1), "n": ("n", 1), "tip_x": ("tip_x", 1e3), "tip_y": ("tip_y", 1e3),
        "theta0": ("theta0", 180 / 3.141592653589793), "moment": ("max_moment_Nm", 1),
        "stress": ("max_stress", 1e-6), "safety": ("safety_factor", 1),
        "b_exact": ("b_over_l", 1)}),
    ("text", """flexure worked out Howell's nondimensional load (α² = Fy L²/EI = {alpha2:.4g}, n = −Fx/Fy =
{n:.4g}), chose the exact elliptic-integral solution (`auto`: the PRBM is not accurate to the
default tolerance 1e-6 here) and converted back: the tip moves to ({tip_x:.2f}, {tip_y:.2f}) mm and
turns {theta0:.1f}°; the bending moment is largest at the clamp, {moment:.4g} N·m, a stress of
{stress:.0f} MPa, so the safety factor against yield is {safety:.2f}.

The shape, with the bending moment and stress along the strip (here 6 points; any number):
"""),
    ("run", "beam " + STRIP + " --shape 6"),
    ("text", """The pseudo-rigid-body model answers at once, and says whether it may be trusted here:
"""),
    ("run", "beam " + STRIP + " --method prbm"),
    ("values", "beam " + STRIP + " --method prbm", {
        "b_prbm": ("b_over_l", 1), "stress_prbm": ("max_stress", 1e-6)}),
    ("text", """Inside its validity limit, the PRBM's tip deflection b/l = {b_prbm:.4f} is {b_error:.1f} % below
the exact {b_exact:.4f}, and its stress {stress_prbm:.0f} MPa {stress_error:.1f} % below: a quick
estimate, not the answer to six digits.

For a script, `--json` prints one JSON object with every key of docs/cli.md (shown here
pretty-printed, shortened to the SI keys):
"""),
    ("run", "beam " + STRIP + " --json", {"keys": [
        "alpha2", "n", "mu", "tip_x", "tip_y", "theta0", "root_moment_Nm", "max_moment_Nm",
        "max_stress", "safety_factor", "method", "method_reason"]}),
    ("text", """The same strip as a file (`docs/examples/steel_strip.toml`, docs/chain-toml.md) gives the same
answer, by the shooting method, which solves any chain of flexible and rigid segments:
"""),
    ("file", "docs/examples/steel_strip.toml"),
    ("run", "beam --chain docs/examples/steel_strip.toml"),
    ("text", """Unit slips are caught. A modulus typed with the wrong case is an error that names the fix, and a
plain angle above a full turn is a warning (plain angles are radians):
"""),
    ("run", "beam --length 50mm --E 200Gpa --width 10mm --thickness 0.5mm --Fy 1N"),
    ("run", "beam --theta0 30"),
    ("text", """## 2. A constant-force mechanism of your own

A designer's slider mechanism in the lpp configuration of Weight's thesis (a long flexible crank
clamped at the ground, a rigid coupler, a pin at the slider), polypropylene, written as a TOML file
(format: docs/mechanisms.md "TOML"; values may carry units there too):
"""),
    ("file", "docs/examples/mechanism_lpp.toml"),
    ("text", """`mechanism analyze` solves it with the PRBM and, where the PRBM's measured error is above the
tolerance, with the exact model of the same mechanism, and reports the force over the stroke,
the percent constant force of both models, the stresses and the safety factor:
"""),
    ("run", "mechanism analyze docs/examples/mechanism_lpp.toml --points 11"),
    ("values", "mechanism analyze docs/examples/mechanism_lpp.toml --points 11", {
        "pcf_prbm": ("percent_constant_force_prbm", 1),
        "pcf_exact": ("percent_constant_force_exact", 1)}),
    ("text", """The PRBM predicts {pcf_prbm:.1f} % constant force; the exact model of the same mechanism,
{pcf_exact:.1f} %: the PRBM's optimum is not the real mechanism's.

The stroke curves, stresses and the design go to an HDF5 file for plotting
(`/usr/bin/python3 scripts/plot_mechanism.py lpp.h5 --out lpp.png`, docs/hdf5-schema.md):
"""),
    ("run", "mechanism analyze docs/examples/mechanism_lpp.toml --points 11 --out {tmp}/lpp.h5"),
    ("text", """Next: docs/cli.md lists every command and key; docs/mechanisms.md explains the models and their
validation; `flexure help COMMAND` prints examples for each command.

## Tutorial programs: the library from C++ and Python

The same strip, with a rigid link on its tip, built from the library's objects instead of flags
([examples/tutorial/step-1](../examples/tutorial/step-1/README.md)): `step-1.cc`, a C++ program
built against the installed package that links `flexure::beam` alone, and `step-1.py`, the same in
Python. Each makes a `Section`, a `Material`, a `FlexibleSegment`, a `RigidSegment` and a
`TipLoad` into a `SegmentChain`, solves it by the shooting method and by Howell's chain algorithm,
prints both tips and their difference, and plots both deflected shapes (SVG from C++, PNG with
matplotlib from Python). The test suite builds and runs both (ctest `Install.TutorialStep1*`,
pytest `tests/python/test_tutorial.py`).
"""),
]


def run(flexure, args, scratch, options):
    argv = [flexure] + shlex.split(args.replace("{tmp}", scratch))
    done = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True, timeout=300)
    shown = "$ flexure " + args.replace("{tmp}/", "")
    out = done.stdout
    if "keys" in options:
        full = json.loads(out)
        out = json.dumps({k: full[k] for k in options["keys"]}, indent=2) + "\n"
    out = out.replace(scratch + "/", "")
    err = done.stderr.replace(scratch + "/", "")
    text = shown + "\n" + out + err
    if done.returncode != 0:
        text += f"(exit code {done.returncode})\n"
    return "```console\n" + text + "```\n"


def values(flexure, args, wanted):
    argv = [flexure] + shlex.split(args) + ["--json"]
    done = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True, timeout=300, check=True)
    full = json.loads(done.stdout)
    return {name: full[key] * scale for name, (key, scale) in wanted.items()}


def derived(v):
    """Numbers the prose computes from the runs' values."""
    out = dict(v)
    if "b_prbm" in v and "b_exact" in v:
        out["b_error"] = 100 * (v["b_exact"] - v["b_prbm"]) / v["b_exact"]
    if "stress_prbm" in v and "stress" in v:
        out["stress_error"] = 100 * (v["stress"] - v["stress_prbm"]) / v["stress"]
    return out


def render(flexure):
    parts = []
    known = {}
    with tempfile.TemporaryDirectory(prefix="flexure-tutorial-") as scratch:
        for item in TUTORIAL:
            kind = item[0]
            if kind == "values":
                known.update(values(flexure, item[1], item[2]))
                continue
            if kind == "text":
                parts.append(item[1].format(**derived(known)))
            elif kind == "file":
                with open(os.path.join(ROOT, item[1]), encoding="utf-8") as f:
                    parts.append(f"`{item[1]}`:\n\n```toml\n{f.read()}```\n")
            else:
                parts.append(run(flexure, item[1], scratch, item[2] if len(item) > 2 else {}))
            parts.append("\n")
    return "".join(parts).rstrip("\n") + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--flexure", default=os.path.join(ROOT, "build", "flexure"),
                        help="the flexure binary (default: build/flexure)")
    parser.add_argument("--check", action="store_true",
                        help="compare with docs/tutorial.md instead of writing it; exit 1 if stale")
    args = parser.parse_args()
    flexure = os.path.abspath(args.flexure)
    if not os.access(flexure, os.X_OK):
        sys.exit(f"make_tutorial.py: {flexure} is not an executable; build flexure first")
    text = render(flexure)
    target = os.path.join(ROOT, "docs", "tutorial.md")
    if args.check:
        with open(target, encoding="utf-8") as f:
            current = f.read()
        if current != text:
            sys.stdout.writelines(difflib.unified_diff(
                current.splitlines(True), text.splitlines(True), "docs/tutorial.md", "regenerated"))
            sys.exit("docs/tutorial.md is stale: run python3 scripts/make_tutorial.py")
        print("docs/tutorial.md is up to date")
        return
    write_atomically(target, text)
    print(f"wrote {target}")


if __name__ == "__main__":
    main()
