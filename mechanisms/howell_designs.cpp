#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

// Howell §10.1.4 (the SI values as printed; the inch values are 0.20, 0.50, 0.030 in).
constexpr double kE = 1655e6;               // polypropylene, Pa (240,000 psi)
constexpr double kFlexureLength = 5.08e-3;  // l of every small-length flexural pivot, m
constexpr double kWidth = 12.70e-3;         // w, m
constexpr double kThickness = 0.76e-3;      // h1 (reference flexure), m
// Howell Table C.2: tensile yield strength of polypropylene 4500-5400 psi; the lower end.
constexpr double kYield = 4500.0 * 6894.757293;  // Pa
// Example 2: L = 203.2 mm (8 in), h = 0.125 in (the printed 3.18 mm; I = 33.86 mm^4).
constexpr double kLongLength = 203.2e-3;
constexpr double kLongThickness = 0.125 * 0.0254;
// Example 1: r2 = 78.74 mm and R = 0.8853, so r2 + r3 = 148.45 mm: the size of the other rows.
constexpr double kExample1R2 = 78.74e-3;

// Stroke: the row's Delta x/(r2 + r3), held just inside the toggle position where the row's
// stroke passes it (2A 0.40: R = 0.4323 toggles at 37.04 %; the thesis clamps the same way).
double row_stroke(const cfm::CfmClassRow& row, double r_tot) {
  const double percent = std::min(row.stroke_percent, 0.999 * cfm::toggle_stroke_percent(row.R));
  return percent / 100.0 * r_tot;
}

// A Table 10.1 row as s-pivot design: r2 given, r3 = R r2 (Howell: "r3 = r2 R"), every flexure
// 5.08 mm long and 12.70 mm wide, the reference flexure (k1; k2 for class 1B) 0.76 mm thick and
// the others sized so that k2/k1 = K1 and k3/k1 = K2 (Howell §10.1.4: h_i = h1 K^(1/3)).
MechanismDesign table_design(const std::string& name,
                             const char* config,
                             const char* row_name,
                             double r2,
                             const std::string& note) {
  const cfm::CfmClassRow* row = cfm::find_class_row(row_name);
  MechanismDesign d;
  d.name = name;
  d.config = config;
  d.note = note;
  d.r2 = r2;
  d.r3 = row->R * r2;
  d.material.E = kE;
  d.material.yield_strength = kYield;
  d.stroke = row_stroke(*row, d.r2 + d.r3);
  for (auto& j : d.joints) j.length = kFlexureLength;  // kept by the sizing (only pins reset)
  size_flexures_for_spring_ratios(
      d, kWidth, kThickness, row->K1.value_or(0.0), row->K2.value_or(0.0));
  if (100.0 * d.stroke / (d.r2 + d.r3) < row->stroke_percent) {
    d.note += fmt::format("; stroke held at 0.999 x the toggle position ({:.2f} % of r2 + r3)",
                          100.0 * d.stroke / (d.r2 + d.r3));
  }
  return d;
}

MechanismDesign example_2_lpp() {
  const cfm::CfmClassRow* row = cfm::find_class_row("howell10.1-1A-b");
  // The library's l segment: Howell's average gamma (§5.2), not the book's 0.83 of this example.
  const double gamma = howell_average_fixed_pinned().constants().gamma;
  MechanismDesign d;
  d.name = "howell-1A-lpp-b";
  d.config = "lpp";
  d.note = fmt::format(
      "Howell §10.1.4 example 2 (class 1A, fixed-pinned segment, Delta x/(r2+r3) = 0.40): L = "
      "203.2 mm, w = 12.7 mm, h = 3.175 mm (0.125 in, I = 33.86 mm^4), polypropylene E = 1655 "
      "MPa; r2 = {:g} L (the book: 0.83 L = 168.7 mm), target F = 1.68 N",
      gamma);
  d.r2 = gamma * kLongLength;  // finalise() sets the segment length r2/gamma = L
  d.r3 = row->R * d.r2;
  d.material.E = kE;
  d.material.yield_strength = kYield;
  d.stroke = row_stroke(*row, d.r2 + d.r3);
  d.joints[0] = JointDesign{PivotType::kLong, 0.0, kLongThickness, kWidth};
  d.finalise();
  return d;
}

std::vector<MechanismDesign> make_designs() {
  const double r_tot = kExample1R2 * (1.0 + cfm::find_class_row("howell10.1-1A-b")->R);
  const auto r2_of = [r_tot](const char* row) {
    return r_tot / (1.0 + cfm::find_class_row(row)->R);
  };
  const std::string rows_note =
      "Howell Table 10.1 row {}, r2 + r3 = 148.45 mm (example 1), polypropylene E = 1655 MPa, "
      "flexures l = 5.08 mm, w = 12.70 mm, reference h = 0.76 mm";
  std::vector<MechanismDesign> list;
  list.push_back(table_design("howell-1A-spp-a",
                              "spp",
                              "howell10.1-1A-a",
                              r2_of("howell10.1-1A-a"),
                              fmt::format(fmt::runtime(rows_note), "1A 0.16 (R = 0.8274)")));
  list.push_back(table_design(
      "howell-1A-spp-b",
      "spp",
      "howell10.1-1A-b",
      kExample1R2,
      "Howell §10.1.4 example 1 (class 1A, small-length flexural pivot, Delta x/(r2+r3) = 0.40, "
      "R = 0.8853): r2 = 78.74 mm, r3 = R r2, polypropylene E = 1655 MPa, l = 5.08 mm, w = 12.70 "
      "mm, h = 0.76 mm; book k1 = 151 N mm/rad, F = 0.92 N"));
  list.push_back(example_2_lpp());
  list.push_back(table_design("howell-1B-psp-a",
                              "psp",
                              "howell10.1-1B-a",
                              r2_of("howell10.1-1B-a"),
                              fmt::format(fmt::runtime(rows_note), "1B 0.16 (R = 1)")));
  list.push_back(table_design("howell-1B-psp-b",
                              "psp",
                              "howell10.1-1B-b",
                              r2_of("howell10.1-1B-b"),
                              fmt::format(fmt::runtime(rows_note), "1B 0.40 (R = 1)")));
  list.push_back(
      table_design("howell-2A-ssp-a",
                   "ssp",
                   "howell10.1-2A-a",
                   r2_of("howell10.1-2A-a"),
                   fmt::format(fmt::runtime(rows_note), "2A 0.16 (R = 0.3945, K1 = 0.1906)")));
  list.push_back(
      table_design("howell-2A-ssp-b",
                   "ssp",
                   "howell10.1-2A-b",
                   r2_of("howell10.1-2A-b"),
                   fmt::format(fmt::runtime(rows_note), "2A 0.40 (R = 0.4323, K1 = 0.2237)")));
  list.push_back(table_design(
      "howell-3A-sss-a",
      "sss",
      "howell10.1-3A-a",
      40.2e-3,
      "Howell §10.1.4 example 3 (class 3A, three flexural pivots, Delta x/(r2+r3) = 0.16, R = "
      "2.6633, K1 = 1, K2 = 12.6704): r2 = 40.2 mm, r3 = R r2, polypropylene E = 1655 MPa, l = "
      "5.08 mm, w = 12.7 mm, h1 = h2 = 0.76 mm, h3 = h1 K2^(1/3); book h3 = 1.78 mm, F = 13 N"));
  list.push_back(table_design(
      "howell-3A-sss-b",
      "sss",
      "howell10.1-3A-b",
      r2_of("howell10.1-3A-b"),
      fmt::format(fmt::runtime(rows_note), "3A 0.40 (R = 2.0821, K1 = 1, K2 = 9.3816)")));
  return list;
}

}  // namespace

const std::vector<MechanismDesign>& howell_mechanisms() {
  static const std::vector<MechanismDesign> designs = make_designs();
  return designs;
}

std::optional<MechanismDesign> find_howell_mechanism(const std::string& name) {
  const std::string key = to_lower(name);
  static const char* const kExamples[3][2] = {{"howell-ex1", "howell-1a-spp-b"},
                                              {"howell-ex2", "howell-1a-lpp-b"},
                                              {"howell-ex3", "howell-3a-sss-a"}};
  for (const MechanismDesign& d : howell_mechanisms()) {
    const std::string full = to_lower(d.name);                   // howell-1a-spp-b
    const std::string short_name = "howell-" + full.substr(10);  // howell-spp-b
    bool match = key == full || key == short_name;
    for (const auto& e : kExamples) match = match || (key == e[0] && full == e[1]);
    if (match) return d;
  }
  return std::nullopt;
}

std::string howell_table_row_name(const std::string& design_name) {
  // howell-<class>-<config>-<a|b>  ->  howell10.1-<class>-<a|b>
  if (design_name.rfind("howell-", 0) != 0 || design_name.size() != 15) return "";
  return "howell10.1-" + design_name.substr(7, 2) + "-" + design_name.substr(14, 1);
}

}  // namespace flexure::mechanism
