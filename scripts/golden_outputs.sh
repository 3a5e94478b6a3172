#!/usr/bin/env bash
# The outputs that a restructuring of the library must leave byte for byte unchanged (issue 28,
# "Done when"): `flexure validate` (text and JSON), `flexure mechanism validate --markdown`,
# `flexure cfm --table` (text, Markdown, JSON) and `flexure --help`.
#
#   scripts/golden_outputs.sh FLEXURE_BINARY OUTDIR
#
# writes one file per output into OUTDIR. The frozen copies live in tests/golden/ (regenerate
# them only for an intended change of output, and say so in the commit); the ctest
# `Outputs.Unchanged` (tests/golden/check_outputs.cmake) runs this script and compares.
#
# Timings are the only run-to-run differences and are masked: the last column of validate's table
# (us/solve) and every "seconds_per_solve" of its JSON. Everything else is deterministic (checked:
# two runs, and one run pinned to a single core, give identical files). Every command must exit 0:
# a failed check (exit 1) is a changed output too.
set -euo pipefail
if [[ $# -ne 2 ]]; then
  echo "usage: $0 FLEXURE_BINARY OUTDIR" >&2
  exit 2
fi
flexure="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
outdir="$2"
mkdir -p "$outdir"
cd "$outdir"

# validate writes an HDF5 file and names it in its output: a fixed relative name, removed after.
# Table rows start in column 0 and end in the us/solve number; the header, the summary line and
# the indented message lines keep their text.
"$flexure" validate --out validation.h5 | sed -E '/^[^ ]/ s/ +[0-9]+\.[0-9]+$//' >validate.txt
"$flexure" validate --out validation.h5 --json |
  sed -E 's/,"seconds_per_solve":[^,}]*//g' >validate.json
rm -f validation.h5

"$flexure" mechanism validate --markdown >mechanism_validate.md
"$flexure" cfm --table >cfm_table.txt
"$flexure" cfm --table --markdown >cfm_table.md
"$flexure" cfm --table --json >cfm_table.json
"$flexure" --help >help.txt
