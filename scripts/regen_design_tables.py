#!/usr/bin/env python3
"""Regenerates the generated tables of docs/design.md by running `flexure design cfm`.

    python3 scripts/regen_design_tables.py --flexure build/flexure

Tables between `<!-- design-table: NAME -->` and `<!-- end design-table -->` are replaced;
no number in them is typed by hand. Standard library only.
"""
import argparse
import json
import os
import subprocess
import time

from doc_blocks import rewrite_blocks

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "docs", "design.md")

# Table 2.1 of Weight's thesis (data/weight_table_2_1.csv): class, all-s member, d, printed R,
# K1, K2, Xi, and how the row is re-optimised (docs/design.md).
TABLE_2_1 = [
    ("1A", "spp", 16, "0.8274", "-", "-", "1.0030", []),
    ("1A", "spp", 40, "0.8853", "-", "-", "1.0241", []),
    ("1B", "psp", 16, "1.0000", "1.0000", "-", "1.0564", []),
    ("1B", "psp", 40, "1.0000", "1.0000", "-", "1.1576", []),
    ("2A", "ssp", 16, "0.3945", "0.1906", "-", "1.0015", []),
    ("2A", "ssp", 37.04, "0.4323", "0.2237", "-", "1.0058", []),
    ("2B", "sps", 16, "0.7591", "-", "0.1208", "1.0029", []),
    ("2B", "sps", 40, "0.8441", "-", "0.1208", "1.0235", []),
    ("3A", "sss", 16, "2.6633", "1.0000", "12.6704", "1.0002", ["--K1", "1"]),
    ("3A", "sss", 40, "2.0821", "1.0000", "9.3816", "1.0049", ["--K1", "1"]),
]


def design(flexure, args):
    start = time.perf_counter()
    out = subprocess.run([flexure, "design", "cfm", *args, "--json"], capture_output=True,
                         text=True, check=True).stdout
    return json.loads(out), time.perf_counter() - start


def table_2_1(flexure):
    lines = ["| class | d (%) | printed R | K1 | K2 | printed Ξ | flexure R | K1 | K2 | Ξ | "
             "evaluations | time |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for cls, config, d, R, K1, K2, Xi, extra in TABLE_2_1:
        j, seconds = design(flexure, ["--config", config, "--d", f"{d:g}", "--objective",
                                      "min-xi", *extra])
        k1 = f"{j['K1']:.4f}" if K1 != "-" else "–"
        k2 = f"{j['K2']:.4f}" if K2 != "-" else "–"
        lines.append(f"| {cls} | {d:g} | {R} | {K1.replace('-', '–')} | {K2.replace('-', '–')} | "
                     f"{Xi} | {j['R']:.4f} | {k1} | {k2} | {j['Xi']:.5f} | {j['evaluations']} | "
                     f"{seconds * 1e3:.0f} ms |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--flexure", default=os.path.join(ROOT, "build", "flexure"))
    args = parser.parse_args()
    tables = {"table_2_1": table_2_1}
    rewrite_blocks(DOC, "design-table", lambda name: tables[name](args.flexure))
    print(f"wrote {DOC}")


if __name__ == "__main__":
    main()
