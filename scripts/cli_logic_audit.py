#!/usr/bin/env python3
"""How much library logic is left in cli/ (issue 28: "a thin command line").

    python3 scripts/cli_logic_audit.py [--blocks FILE] [--source DIR] [--update]

reads the block list (scripts/cli_logic_blocks.txt: the rules of the classification, one line per
block of cli/ that does library work) and prints the code lines per category and in all, counting
each line once and leaving out blank lines and `//` comments. The list is the measurement: a block
that moves into the library is deleted from it, so the total falls.

A block's first line must still hold the block's anchor text: otherwise (an edit above it moved
it, or the block changed) the script fails and says where the anchor is now. With --update it
moves the ranges of blocks whose anchor it found (same length; re-check the end by eye) and
rewrites the list. Standard library only.

    python3 scripts/cli_logic_audit.py --hdf5

prints the HDF5 calls of cli/ (the issue's "no HDF5 call in cli/"): a line of code (not a
comment) that uses the HDF5 C API or hdf5.h, opens a file itself (AtomicHdf5File, Hdf5File) or
writes into one (Hdf5Group, write_dataset, set_attribute, ...). It then lists, for
information only, the other lines that name HDF5: flags and help texts (--hdf5, "the HDF5 file
of ..."), paths handed to a library writer (csv.hdf5_path()), calls of the library's writers
(write_*_hdf5) and the catch of io::Hdf5Error that maps a failed write to exit 2; these are not
calls and do not make it fail. And

    python3 scripts/cli_logic_audit.py --raw-stderr

the statements of cli/*_command.cpp that write a warning to stderr themselves instead of through
the tool's warn() (one warning channel: Python turns warn() texts into FlexureWarning; progress
lines are not warnings and are not listed); both exit 1 when they print anything.
"""

import argparse
import collections
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

HDF5_TOKENS = re.compile(
    r"Hdf5|hdf5|write_dataset|set_attribute|create_group|create_dataset|write_range|"
    r"write_scalar|write_provenance|H5[A-Z]")
# What counts as an HDF5 call: the C API (H5Fcreate, H5T_NATIVE_DOUBLE, hid_t), its headers, the
# library's file types (opening a file: AtomicHdf5File, Hdf5File; writing into one: Hdf5Group,
# Hdf5Dataset) and their write methods, and the header that exposes them (hdf5_file.h).
HDF5_CALLS = re.compile(
    r"\bH5[A-Z][A-Za-z]*_?\w*\(|\bH5[A-Z]_[A-Z]|\bhid_t\b|\bherr_t\b|[<\"/]hdf5\.h|H5Cpp|"
    r"AtomicHdf5|Hdf5File|Hdf5Group|Hdf5Dataset|hdf5_file\.h|"
    r"\b(write_dataset|set_attribute|create_group|create_dataset|write_range|write_scalar|"
    r"write_provenance)\(")
RAW_STDERR = re.compile(r"fmt::print\(\s*stderr|std::cerr|fprintf\(\s*stderr|fputs\([^)]*stderr")


class Block:
    def __init__(self, number, category, file, start, end, anchor):
        self.number = number  # line of the block list, for messages
        self.category = category
        self.file = file
        self.start = start
        self.end = end
        self.anchor = anchor


def read_blocks(path):
    categories = collections.OrderedDict()
    blocks = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            text = line.rstrip("\n")
            if not text.strip() or text.startswith("#"):
                continue
            if text.startswith("@"):
                name, _, description = text[1:].partition(" ")
                categories[name] = description.strip()
                continue
            fields = text.split(None, 4)
            if len(fields) < 5:
                sys.exit(f"{path}:{number}: expected CATEGORY FILE START END ANCHOR")
            category, file, start, end, anchor = fields
            if category not in categories:
                sys.exit(f"{path}:{number}: category {category} has no @{category} line")
            start, end = int(start), int(end)
            if start < 1 or end < start:
                sys.exit(f"{path}:{number}: bad range {start}..{end}")
            blocks.append(Block(number, category, file, start, end, anchor.strip()))
    return categories, blocks


def is_code(line):
    stripped = line.strip()
    return bool(stripped) and not stripped.startswith("//")


def locate(lines, block):
    """Line numbers (1-based) whose text is the anchor, nearest to the listed start first."""
    hits = [i + 1 for i, text in enumerate(lines) if text.strip() == block.anchor]
    return sorted(hits, key=lambda i: abs(i - block.start))


def audit(args):
    categories, blocks = read_blocks(args.blocks)
    sources = {}
    problems = []
    moved = {}
    for b in blocks:
        path = os.path.join(args.source, b.file)
        if b.file not in sources:
            if not os.path.exists(path):
                problems.append(f"line {b.number}: {b.file} does not exist")
                continue
            with open(path, encoding="utf-8") as f:
                sources[b.file] = f.read().split("\n")
        lines = sources[b.file]
        if b.start <= len(lines) and lines[b.start - 1].strip() == b.anchor:
            if b.end > len(lines):
                problems.append(f"line {b.number}: {b.file}:{b.end} is past the end of the file")
            continue
        hits = locate(lines, b)
        if hits:
            shift = hits[0] - b.start
            moved[b.number] = shift
            problems.append(
                f"line {b.number}: {b.file}:{b.start} no longer holds '{b.anchor}'; it is at "
                f"line {hits[0]} (range {b.start + shift}..{b.end + shift}?)")
        else:
            problems.append(
                f"line {b.number}: '{b.anchor}' is no longer in {b.file} (block changed or moved "
                "to the library: update or delete the line)")

    if args.update and moved:
        with open(args.blocks, encoding="utf-8") as f:
            text = f.read().split("\n")
        for b in blocks:
            if b.number in moved:
                s = moved[b.number]
                text[b.number - 1] = f"{b.category} {b.file} {b.start + s} {b.end + s} {b.anchor}"
        with open(args.blocks, "w", encoding="utf-8") as f:
            f.write("\n".join(text))
        print(f"moved {len(moved)} block(s) in {os.path.relpath(args.blocks)}; re-run to count")
        return 0 if len(moved) == len(problems) else 1

    if problems:
        print("the block list does not match cli/:", file=sys.stderr)
        for p in problems:
            print("  " + p, file=sys.stderr)
        return 1

    counted = set()
    per_category = collections.OrderedDict((name, 0) for name in categories)
    raw = 0
    for b in blocks:
        lines = sources[b.file]
        for i in range(b.start, b.end + 1):
            if (b.file, i) in counted:
                continue
            counted.add((b.file, i))
            raw += 1
            if is_code(lines[i - 1]):
                per_category[b.category] += 1
    width = max(len(n) for n in categories) if categories else 1
    for name, description in categories.items():
        print(f"{name:<{width}} {per_category[name]:>5}  {description}")
    total = sum(per_category.values())
    print(f"{'total':<{width}} {total:>5}  code lines of library logic in cli/ "
          f"({raw} lines with blanks and comments, {len(blocks)} blocks)")
    return 0


def grep(pattern, files):
    found = 0
    for path in files:
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                if pattern.search(line):
                    print(f"{os.path.relpath(path, ROOT)}:{number}: {line.rstrip()}")
                    found += 1
    print(f"{found} line(s)", file=sys.stderr)
    return 1 if found else 0


def hdf5_calls(files):
    """The HDF5 calls of `files` (HDF5_CALLS in code, comments left out); exit 1 when any. The
    other lines naming HDF5 are listed after them as mentions, which do not count."""
    calls, mentions = [], []
    for path in files:
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                code = line.split("//", 1)[0]
                where = f"{os.path.relpath(path, ROOT)}:{number}: {line.rstrip()}"
                if HDF5_CALLS.search(code):
                    calls.append(where)
                elif HDF5_TOKENS.search(line):
                    mentions.append(where)
    print(f"HDF5 calls in cli/: {len(calls)}")
    for where in calls:
        print(f"  {where}")
    print(f"other lines naming HDF5 (flags, help texts, comments, paths handed to the library's "
          f"writers, write_*_hdf5 calls, the io::Hdf5Error catch; not calls): {len(mentions)}")
    for where in mentions:
        print(f"  {where}")
    print(f"{len(calls)} HDF5 call(s), {len(mentions)} other mention(s)", file=sys.stderr)
    return 1 if calls else 0


def raw_warnings(files):
    """Statements (from a write to stderr to the next ';') whose text says "warning"."""
    found = 0
    for path in files:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for m in RAW_STDERR.finditer(text):
            end = text.find(";", m.end())
            statement = text[m.start():end if end >= 0 else len(text)]
            if "warning" in statement.lower():
                number = text.count("\n", 0, m.start()) + 1
                print(f"{os.path.relpath(path, ROOT)}:{number}: {' '.join(statement.split())}")
                found += 1
    print(f"{found} raw warning(s)", file=sys.stderr)
    return 1 if found else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--blocks", default=os.path.join(ROOT, "scripts", "cli_logic_blocks.txt"))
    parser.add_argument("--source", default=os.path.join(ROOT, "cli"), help="the cli/ folder")
    parser.add_argument("--update", action="store_true", help="move ranges whose anchor moved")
    parser.add_argument("--hdf5", action="store_true", help="list the HDF5 calls of cli/ (then the other lines naming HDF5)")
    parser.add_argument("--raw-stderr", action="store_true",
                        help="list warnings written to stderr by cli/*_command.cpp")
    args = parser.parse_args()
    if args.hdf5:
        files = sorted(glob.glob(os.path.join(args.source, "*.cpp")) +
                       glob.glob(os.path.join(args.source, "*.h")))
        return hdf5_calls(files)
    if args.raw_stderr:
        return raw_warnings(sorted(glob.glob(os.path.join(args.source, "*_command.cpp"))))
    return audit(args)


if __name__ == "__main__":
    sys.exit(main())
