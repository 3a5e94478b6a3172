#!/usr/bin/env python3
"""Regenerates the generated tables of docs/design.md by running `flexure design cfm`.

    python3 scripts/regen_design_tables.py --flexure build/flexure

Tables between `<!-- design-table: NAME -->` and `<!-- end design-table -->` are replaced;
no number in them is typed by hand. Standard library only.
"""
import argparse
import json
import os
import re
import statistics
import subprocess

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


# Chapter-7 sub-classes whose printed point breaks its own orientation rule: that one limit is
# loosened to the printed point's computed value, as in tests/mechanisms/
# cfm_subclass_synthesis_test.cpp (docs/errata.md).
RULE_LIMITS = {
    "ssp-b90o": "o:D_equal<=10.351",  # D_equal1 = 10.3504
    "lps-a99IO": "O:D_equal>=0.4668",  # D_equal1 = 0.46685
    "lps-b99IO": "O:C>=0.9939",  # C1 = 0.99396
    "lps-b95IO": "O:C>=0.9935",  # C1 = 0.99355
}


def run_json(flexure, args):
    out = subprocess.run([flexure, *args, "--json"], capture_output=True, text=True,
                         check=True).stdout
    return json.loads(out)


def design(flexure, args):
    """`flexure design cfm` and the synthesis's own time (the JSON key seconds)."""
    j = run_json(flexure, ["design", "cfm", *args])
    return j, j["seconds"]


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
                     f"{seconds * 1e3:.1f} ms |")
    return "\n".join(lines)


def strict_rules(flexure):
    """The sub-classes of RULE_LIMITS under the thesis's own (strict) rules."""
    lines = ["| sub-class | printed Ψ_raw | flexure Ψ_raw, strict rule | Δ |", "|---|---|---|---|"]
    for name in RULE_LIMITS:
        m = re.fullmatch(r"([a-z]+)-([ab])(\d*)([IOo]*)", name)
        printed = run_json(flexure, ["cfm", "--subclass", name])
        j, _ = design(flexure, ["--config", m.group(1), "--d", repr(printed["stroke_percent"]),
                                "--objective", "max-psi", "--pcf-min", m.group(3),
                                "--orientation", m.group(4)])
        delta = 100.0 * (j["Psi_raw"] / printed["Psi_raw"] - 1.0)
        lines.append(f"| {name} | {printed['Psi_raw']:.5g} | {j['Psi_raw']:.5g} | {delta:+.2f} % |")
    return "\n".join(lines)


def subclasses(flexure):
    """The 68 chapter-7 sub-classes re-derived from their own objective and constraints."""
    rows = run_json(flexure, ["cfm", "--list"])["subclasses"]
    lines = ["| sub-class | d (%) | objective | printed | flexure | Δ | printed R | K1 | K2 | "
             "flexure R | K1 | K2 | evaluations (full) | time |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    times = []
    for row in rows:
        name = row["name"]
        m = re.fullmatch(r"([a-z]+)-([ab])(\d*)([IOo]*)", name)
        digits, flags = m.group(3), m.group(4)
        printed = run_json(flexure, ["cfm", "--subclass", name])
        d = printed["stroke_percent"]  # the effective (toggle-clamped) stroke
        args = ["--config", row["config"], "--d", repr(d)]
        if digits:
            args += ["--objective", "max-psi", "--pcf-min", digits]
            if flags:
                args += ["--orientation", flags]
            if name in RULE_LIMITS:
                args += ["--rule-limits", RULE_LIMITS[name]]
            key, label, fmt = "Psi_raw", f"Ψ, Ξ′ ≥ {digits}" + (f" {flags}" if flags else ""), ".5g"
        else:
            args += ["--objective", "max-pcf"]
            key, label, fmt = "percent_constant_force", "Ξ′", ".3f"
        if name in RULE_LIMITS:
            label += f" ({RULE_LIMITS[name]})"
        j, seconds = design(flexure, args)
        times.append(seconds)
        ks = [(row["K1"], j["K1"]) if row["class"] not in ("1A", "1B") else ("–", "–"),
              (row["K2"], j["K2"]) if row["class"] in ("2B", "3A") else ("–", "–")]
        fk = [f"{a:.4f}" if a != "–" else a for a, _ in ks]
        jk = [f"{b:.4f}" if b != "–" else b for _, b in ks]
        delta = 100.0 * (j[key] / printed[key] - 1.0)
        lines.append(f"| {name} | {d:.2f} | {label} | {printed[key]:{fmt}} | {j[key]:{fmt}} | "
                     f"{delta:+.2f} % | {row['R']:.4f} | {fk[0]} | {fk[1]} | {j['R']:.4f} | "
                     f"{jk[0]} | {jk[1]} | {j['evaluations']} ({j['full_sampling_evaluations']}) | "
                     f"{seconds * 1e3:.1f} ms |")
    times.sort()
    lines += ["", f"Time per design (the synthesis alone, JSON `seconds`): median "
              f"{statistics.median(times) * 1e3:.1f} ms, slowest {times[-1] * 1e3:.1f} ms, all 68 "
              f"{sum(times):.2f} s."]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--flexure", default=os.path.join(ROOT, "build", "flexure"))
    args = parser.parse_args()
    tables = {"table_2_1": table_2_1, "subclasses": subclasses, "strict_rules": strict_rules}
    rewrite_blocks(DOC, "design-table", lambda name: tables[name](args.flexure))
    print(f"wrote {DOC}")


if __name__ == "__main__":
    main()
