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


INCH, KSI, LBF = 0.0254, 6894.757293168361e3, 4.4482216152605
EXAMPLE_1 = ["--force", "25lbf", "--stroke", "4in", "--E", "30Msi", "--safety-factor", "1.2",
             "--length-range", "12in:15in", "--width-range", "3in:5in",
             "--thickness-range", "0.04in:0.07in", "--config", "lpp"]
EXAMPLE_2 = ["--force", "3mN", "--stroke", "7.5mm", "--E", "110GPa", "--yield-strength", "552MPa",
             "--safety-factor", "1.1", "--length-range", "150mm",
             "--thickness-range", "1.5mm:2mm", "--pcf-min", "90", "--in-plane", "--config", "sss"]
EXAMPLE_3 = ["--force", "100lbf", "--stroke", "6in", "--E", "30Msi", "--yield-strength", "200ksi",
             "--safety-factor", "1", "--length-range", "24in", "--width-range", "5in"]
# The thesis's examples by its own rules: eq. 8.5, no section bounds, no check of the exact force
# (docs/design.md "The stress rule"); the tool's defaults are in the table after them.
THESIS = ["--stress-rule", "thesis", "--max-width-to-thickness", "1e6",
          "--max-width-to-length", "1000", "--force-tolerance", "100"]


def design_mechanism(flexure, args):
    start = time.perf_counter()
    r = subprocess.run([flexure, "design", "mechanism", *args, "--json"], capture_output=True,
                       text=True)
    if r.returncode not in (0, 3):
        raise SystemExit(f"flexure design mechanism failed ({r.returncode}): {r.stderr}")
    return json.loads(r.stdout), r.returncode, time.perf_counter() - start


def examples(flexure):
    lines = ["| thesis example | printed (after docs/errata.md) | flexure design mechanism | "
             "exact model of the design | time |", "|---|---|---|---|---|"]
    j, _, t = design_mechanism(flexure, EXAMPLE_1 + THESIS)
    d = j["designs"][0]
    lines.append(
        f"| 1: lpp, 25 lbf over 4 in, E 30 Msi, SF 1.2 | lpp-b, b = 5 in, h = 0.049 in, "
        f"S_y = 167 ksi, Ξ′ 97.6 | {d['subclass']}, b = {d['width'] / INCH:.3g} in, "
        f"h = {d['thicknesses'][0] / INCH:.4g} in, S_y = {d['required_yield_strength'] / KSI:.4g} "
        f"ksi, Ξ′ {d['subclass_percent_constant_force']:.1f}; F {d['force_prbm'] / LBF:.4g} lbf | "
        f"F {d['force_exact'] / LBF:.4g} lbf, Ξ′ {d['percent_constant_force_exact']:.1f}, SF "
        f"{d['safety_factor_exact']:.3g} (S_y for SF 1.2: "
        f"{d['required_yield_strength_exact'] / KSI:.4g} ksi) | {t * 1e3:.0f} ms |")
    j, code, t = design_mechanism(flexure, EXAMPLE_2 + THESIS)
    r = j["rejected"][0]
    lines.append(
        f"| 2: sss in-plane, 3 mN over 7.5 mm, l_tot 150 mm, h 1.5–2 mm | no sss: M_max = 0.3792 < "
        f"1.7796 (sss-a95I); 418.4 mm needed | exit {code}: M_max (screen) = "
        f"{j['screens']['M_max']:.4f}; closest {r['subclass']}: {r['binding']} | – | "
        f"{t * 1e3:.0f} ms |")
    j, code, t = design_mechanism(flexure,
                                  EXAMPLE_3 + THESIS + ["--thickness-range", "0.01in:0.035in"])
    sc = j["screens"]
    lines.append(
        f"| 3: 100 lbf over 6 in, l_tot 24 in, b 5 in, h 0.01–0.035 in (Table 8.6) | Method 2: "
        f"h_max 0.116 in, F_max 130.3 lbf, Ψ_min 0.767; M_min 1.83; five mechanisms | exit {code}: "
        f"h_max {sc['lpp_thickness_max'] / INCH:.4g} in, F_max {sc['lpp_force_max'] / LBF:.4g} "
        f"lbf, Ψ_min {sc['Psi_min']:.3f}, M_min {sc['M_min']:.3f}; no design (the five need "
        f"h ≈ 0.11 in) | – | {t * 1e3:.0f} ms |")
    j, code, t = design_mechanism(flexure,
                                  EXAMPLE_3 + THESIS + ["--thickness-range", "0.01in:0.12in"])
    names = ", ".join(f"{d['subclass']} (h {d['thicknesses'][0] / INCH:.3g} in)"
                      for d in j["designs"])
    exact = ", ".join(f"{d['percent_constant_force_exact']:.1f}" for d in j["designs"])
    lines.append(f"| 3 with h up to 0.12 in | lps-b90I, lpp-b90, lps-b95I, lpp-b95, lpp-b | "
                 f"{names} | Ξ′ {exact} | {t * 1e3:.0f} ms |")
    return "\n".join(lines)


STEEL_20N = ["--force", "20N", "--stroke", "10mm", "--E", "200GPa", "--yield-strength",
             "1200MPa", "--safety-factor", "1.5"]
SPRING_25LBF = ["--force", "25lbf", "--stroke", "4in", "--E", "30Msi", "--yield-strength", "167ksi",
                "--safety-factor", "1.5", "--length-range", "10in:20in"]


def rules(flexure):
    """Issue 27's reproducers before (the thesis's rule, no bounds) and after (the defaults)."""
    lines = ["| specification | options | designs | below SF 1.5 by exact, PRBM stresses | "
             "least SF exact, PRBM | largest b/h, b/l_tot | largest exact force error | best | "
             "time |", "|---|---|---|---|---|---|---|---|---|"]
    cases = [("20 N, 10 mm, 200 GPa, 1200 MPa, l_tot 30-150 mm", STEEL_20N +
              ["--length-range", "30mm:150mm"]),
             ("25 lbf, 4 in, 30 Msi, 167 ksi, l_tot 10-20 in", SPRING_25LBF)]
    for spec, args in cases:
        for options, extra in (("`--stress-rule thesis`, no bounds (as before issue 27)", THESIS),
                               ("defaults", []),
                               ("`--minimize length`", ["--minimize", "length"]),
                               ("`--minimize footprint`", ["--minimize", "footprint"]),
                               ("`--minimize mass`", ["--minimize", "mass"])):
            j, code, t = design_mechanism(flexure, args + extra)
            ds = j.get("designs", [])
            if not ds:
                lines.append(f"| {spec} | {options} | 0 (exit {code}) | | | | | | {t:.2f} s |")
                continue
            sfe = [d["safety_factor_exact"] for d in ds]
            sfp = [d["safety_factor_prbm"] for d in ds]
            best = ds[0]
            size = {"length": f"l_tot {best['l_tot'] * 1e3:.4g} mm",
                    "footprint": f"{best['footprint'] * 1e6:.4g} mm²",
                    "mass": f"flexures {best['flexure_volume'] * 1e9:.4g} mm³"}.get(
                        j.get("minimize"), f"l_tot {best['l_tot'] * 1e3:.4g} mm")
            lines.append(
                f"| {spec} | {options} | {len(ds)} | {sum(x < 1.5 for x in sfe)}, "
                f"{sum(x < 1.5 for x in sfp)} | {min(sfe):.3g}, {min(sfp):.3g} | "
                f"{max(d['width_to_thickness'] for d in ds):.3g}, "
                f"{max(d['width_to_length'] for d in ds):.3g} | "
                f"{max(abs(d['force_error_exact']) for d in ds) * 100:.1f} % | "
                f"{best['subclass']}, {size} | {t:.2f} s |")
    # --model exact on the second specification, and the length hint of an infeasible one.
    for options, extra in (("`--model exact --stress-rule thesis`, no bounds", THESIS),
                           ("`--model exact`", [])):
        j, code, t = design_mechanism(flexure, SPRING_25LBF + ["--model", "exact"] + extra)
        x = j.get("refined") or {}
        verdict = ("refined: exact F {:.4g} lbf, SF exact {:.3g}, PRBM {:.3g}".format(
            x["force_exact"] / LBF, x["safety_factor_exact"], x["safety_factor_prbm"])
            if x.get("feasible") else f"refinement not feasible: exit {code}")
        lines.append(f"| 25 lbf ... (as above) | {options} | {verdict} | | | | | | {t:.2f} s |")
    j, code, t = design_mechanism(flexure, STEEL_20N + ["--thickness-range", "0.2mm:1mm",
                                                        "--length-range", "40mm"])
    lines.append(f"| 20 N ..., h 0.2-1 mm, l_tot 40 mm | defaults | 0 (exit {code}): the shortest "
                 f"feasible mechanism l_tot = {j['length_needed'] * 1e3:.4g} mm "
                 f"({j['length_needed_subclass']}) | | | | | | {t:.2f} s |")
    return "\n".join(lines)


def exact_optimum(flexure):
    """Every sub-class in the exact model: the thesis's point and flexure's exact optimum."""
    rows = run_json(flexure, ["cfm", "--list"])["subclasses"]
    lines = ["| sub-class | PRBM Ξ′ | thesis point, exact Ξ′ | exact optimum Ξ′ | gain | "
             "R | K1 | K2 | exact strokes | time |", "|---|---|---|---|---|---|---|---|---|---|"]
    gains, times = [], []
    for row in rows:
        name = row["name"]
        thesis = run_json(flexure, ["cfm", "--subclass", name, "--exact"])
        start = time.perf_counter()
        r = subprocess.run([flexure, "design", "cfm", "--subclass", name, "--model", "exact",
                            "--json"], capture_output=True, text=True)
        seconds = time.perf_counter() - start
        times.append(seconds)
        base = thesis["percent_constant_force_exact"]
        if r.returncode != 0:
            # No point meets Xi'_exact >= the sub-class's floor (or its rules): the best reached.
            err = json.loads(r.stdout) if r.stdout.strip() else {}
            best = err.get("percent_constant_force_exact")
            what = (f"none meets its floor; best {best:.2f}" if best is not None
                    else f"exit {r.returncode}")
            lines.append(f"| {name} | {thesis['percent_constant_force']:.1f} | {base:.2f} | "
                         f"{what} | | | | | {err.get('exact_evaluations', '')} | "
                         f"{seconds:.1f} s |")
            continue
        j = json.loads(r.stdout)
        opt = j["percent_constant_force_exact"]
        gains.append(opt - base)
        k1 = f"{j['K1']:.4f}" if row["class"] not in ("1A", "1B") else "–"
        k2 = f"{j['K2']:.4f}" if row["class"] in ("2B", "3A") else "–"
        lines.append(f"| {name} | {thesis['percent_constant_force']:.1f} | {base:.2f} | {opt:.2f} | "
                     f"{opt - base:+.2f} | {j['R']:.4f} | {k1} | {k2} | "
                     f"{j['exact_evaluations']} | {seconds:.1f} s |")
    lines.append("")
    lines.append(f"{len(gains)} of {len(rows)} rows optimised; gain in points of Ξ′: median "
                 f"{statistics.median(gains):+.2f}, smallest {min(gains):+.2f}, largest "
                 f"{max(gains):+.2f}; time per design (whole process, PRBM synthesis and exact "
                 f"optimisation): median {statistics.median(times):.1f} s, slowest "
                 f"{max(times):.1f} s, {sum(times) / 60:.1f} min for all.")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--flexure", default=os.path.join(ROOT, "build", "flexure"))
    parser.add_argument("--only", nargs="+", metavar="TABLE",
                        help="regenerate only these tables (table_2_1 subclasses strict_rules "
                             "examples rules exact_optimum); the others stay as they are")
    args = parser.parse_args()
    tables = {"table_2_1": table_2_1, "subclasses": subclasses, "strict_rules": strict_rules,
              "examples": examples, "rules": rules, "exact_optimum": exact_optimum}
    rewrite_blocks(DOC, "design-table",
                   lambda name: tables[name](args.flexure)
                   if args.only is None or name in args.only else None)
    print(f"wrote {DOC}")


if __name__ == "__main__":
    main()
