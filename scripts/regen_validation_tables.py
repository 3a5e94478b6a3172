#!/usr/bin/env python3
"""Regenerates the generated tables of docs/validation.md in place.

Each table in that file follows the command that makes it (in a ``` block or in backticks in the
paragraph just above). This script runs every such command with ./build/flexure and replaces the
table that follows it, so that the document is never typed by hand. Usage (from the repository
root, after building): python3 scripts/regen_validation_tables.py [--binary build/flexure]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

COMMANDS = [
    "mechanism validate --markdown --points 50",
    "mechanism validate --spring-rules --markdown --points 50",
    "mechanism validate --markdown --toggle-fraction 0.9",
    "mechanism validate --designs howell --markdown --points 50",
    "cfm --table --exact --markdown",
    "cfm --table --exact --exact-rows all --markdown",
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default="build/flexure")
    parser.add_argument("--doc", default="docs/validation.md")
    args = parser.parse_args()
    lines = open(args.doc, encoding="utf-8").read().split("\n")
    for command in COMMANDS:
        # The command's last mention before a table; the table is the next block of '|' lines.
        mention = [i for i, l in enumerate(lines) if ("flexure " + command) in l]
        if not mention:
            sys.exit(f"error: '{command}' is not named in {args.doc}")
        # A table: a "| ..." header followed by its "|---" rule (prose may also start with '|').
        start = mention[-1]
        while start + 1 < len(lines) and not (
            lines[start].startswith("| ") and lines[start + 1].startswith("|---")
        ):
            start += 1
        end = start
        while end < len(lines) and lines[end].startswith("|"):
            end += 1
        if start + 1 >= len(lines):
            sys.exit(f"error: no table after '{command}' in {args.doc}")
        run = subprocess.run([args.binary] + command.split(), capture_output=True, text=True)
        if run.returncode not in (0, 1):  # 1: a check outside its tolerance, still a table
            sys.exit(f"error: '{command}' exited {run.returncode}: {run.stderr.strip()}")
        table = [l for l in run.stdout.split("\n") if l.startswith("|")]
        if not table:
            sys.exit(f"error: '{command}' printed no table")
        lines[start:end] = table
        print(f"{command}: {len(table)} table lines", file=sys.stderr)
    folder = os.path.dirname(os.path.abspath(args.doc))
    with tempfile.NamedTemporaryFile("w", dir=folder, delete=False, encoding="utf-8") as tmp:
        tmp.write("\n".join(lines))
    os.replace(tmp.name, args.doc)


if __name__ == "__main__":
    main()
