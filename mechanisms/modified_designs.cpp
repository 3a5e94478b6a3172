#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cctype>
#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/data/data_files.h"
#include "flexure/solver/common/csv_table.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

// Paper eq. 1: gamma and K_theta of long segments, Howell's averages (§5.2).
double long_gamma() { return howell_average_fixed_pinned().constants().gamma; }
double long_K_theta() { return howell_average_fixed_pinned().constants().K_theta; }
constexpr double kL = 3.0 / 7.0;  // Table 3 factor of an l segment (times its rigid remainder)
constexpr double kS = 0.1;        // Table 3 factor of an s segment
constexpr double kTotalLength = 0.160;   // m: L_tot = Lambda r_tot = 160 mm (Tables 4-6)
constexpr double kWidth = 25.4e-3;       // m, Table 5 b
constexpr double kE = 207e9;             // Pa, Table 5 E
constexpr double kStrokeFraction = 0.4;  // Table 6: 40 % slider displacement of r2 + r3

// data/paper_tables_2_4.csv: Table 2's n for l segments (1 = EI/L for s, "-" for a pin, stored
// as 0), Table 4's R and Lambda, as printed.
std::vector<ModifiedConfiguration> make_configurations() {
  const CsvTable t = CsvTable::parse(data::paper_tables_2_4());
  std::vector<ModifiedConfiguration> list;
  for (std::size_t i = 0; i < t.row_count(); ++i) {
    // "2B-lplm" -> class 2B, name lplm.
    const std::string& full = t.text(i, "configuration");
    const std::size_t dash = full.find('-');
    const std::string name = dash == std::string::npos ? "" : full.substr(dash + 1);
    if (name.size() != 4 || name.back() != 'm' || name.find_first_not_of("pls") != 3) {
      throw t.cell_error(
          i, "configuration", fmt::format("'{}' is not <class>-<pivots p|l|s>m", full));
    }
    ModifiedConfiguration c;
    c.name = name;
    c.class_name = full.substr(0, dash);
    for (int p = 0; p < 3; ++p) {
      const std::string column = fmt::format("n{}", p + 1);
      c.letters[p] = name[p];
      c.length_factor[p] = name[p] == 'l' ? kL : name[p] == 's' ? kS : 0.0;
      c.table2_factor[p] = t.number_or(i, column, 0.0);
      if ((name[p] == 'p') != (c.table2_factor[p] == 0.0) ||
          (name[p] == 's' && c.table2_factor[p] != 1.0)) {
        throw t.cell_error(
            i, column, fmt::format("pivot {} of {} needs - (p), 1 (s) or n > 0 (l)", p + 1, full));
      }
    }
    c.R = t.number(i, "R");
    c.Lambda = t.number(i, "Lambda");
    list.push_back(c);
  }
  return list;
}

// Table 5's k = factor EI/L for pivot p of configuration c (twice Table 2, docs/dynamics.md §2).
double table5_factor(const ModifiedConfiguration& c, int p) {
  const char letter = c.letters[p - 1];
  return 2.0 * (letter == 'l' ? c.table2_factor[p - 1] * long_gamma() * long_K_theta() : 1.0);
}

// The rigid remainders of Table 3: link 2 loses half of each flexible segment at pivots 1 and 2,
// link 3 half of each at pivots 2 and 3.
bool centred(const JointDesign& j) { return j.type == PivotType::kSmall; }

MechanismDesign base_design(const ModifiedConfiguration& c, SpringRule rule) {
  MechanismDesign d;
  d.name = c.class_name + "-" + c.name;
  d.paper_config = c.name;
  d.config = c.thesis_pattern();
  d.material.E = kE;
  d.material.yield_strength = kModifiedYieldStrength;
  d.spring_rule = rule;
  for (int i = 0; i < 3; ++i) {
    JointDesign& j = d.joints[i];
    if (c.letters[i] == 'p') continue;
    j.type = PivotType::kSmall;
    j.segment = SegmentKind::kFixedFixed;
    j.paper_letter = c.letters[i];
    j.table2_factor = c.table2_factor[i];
    j.width = kWidth;
  }
  return d;
}

// 2A-slpm and 2B-lpsm have no Table 5 column. Built like the tabulated designs: R from Table 4,
// r_tot = 160 mm / Lambda with Lambda from Table 4's formula (the tabulated r2 agree with the
// formula's value, e.g. 1A-lppm 160/(1.85/1.7) = 147.027 mm = 2 x 73.5135), lengths by Table 3.
// Thicknesses: the springs of the sibling design of the same class (2A-llpm; 2B-lplm) scaled by
// r2/r2_sibling -- the same spring ratios and the same force scale k_ref/r2, so the same F_Nom for
// the same Phi -- with Table 5's rule (the sibling's k are Table 5 values); h from k = c EI/L.
MechanismDesign constructed_design(const ModifiedConfiguration& c, SpringRule rule) {
  MechanismDesign d = base_design(c, rule);
  const double R = c.R;
  double Lambda = 0.0;
  std::string sibling;
  if (c.name == "slpm") {
    Lambda = (R + 1.05) / (R + 1.0);  // Table 4
    sibling = "2A-llpm";
  } else {
    const double gamma = long_gamma();
    Lambda = (1.05 * R * gamma + 1.0) / (gamma * (R + 1.0));  // Table 4 (2B-lpsm)
    sibling = "2B-lplm";
  }
  const double r_tot = kTotalLength / Lambda;
  d.r2 = r_tot / (R + 1.0);  // paper eq. 3
  d.r3 = R * d.r2;
  const std::array<double, 3> L = table3_lengths(c, d.r2, d.r3);
  const dynamics::CfsmDesign& sib = dynamics::find_cfsm_design(sibling);
  const double scale = d.r2 / sib.r2;
  for (int p = 1; p <= 3; ++p) {
    JointDesign& j = d.joints[p - 1];
    if (j.type == PivotType::kPin) continue;
    j.length = L[p - 1];
    const double k = sib.k[p - 1] * scale;
    j.thickness = std::cbrt(12.0 * k * j.length / (table5_factor(c, p) * d.material.E * j.width));
  }
  d.stroke = kStrokeFraction * (d.r2 + d.r3);
  d.note = fmt::format(
      "paper 004 {}-{} (no Table 5 column): R = {} and L_tot = Lambda r_tot = 160 mm (Table 4), "
      "lengths by Table 3, springs of {} scaled by r2 (Table 5 rule), b = 25.4 mm, E = 207 GPa, "
      "S_y = 200 ksi (chosen), stroke 40 % of r2 + r3; spring rule {}",
      c.class_name,
      c.name,
      R,
      sibling,
      spring_rule_name(rule));
  d.finalise();
  return d;
}

}  // namespace

std::string ModifiedConfiguration::thesis_pattern() const {
  std::string s;
  for (char l : letters) s += (l == 'p' ? 'p' : 's');
  return s;
}

const std::vector<ModifiedConfiguration>& modified_configurations() {
  static const std::vector<ModifiedConfiguration> configs = make_configurations();
  return configs;
}

const ModifiedConfiguration& find_modified_configuration(const std::string& name) {
  const std::string key = to_lower(name);
  std::string names;
  for (const auto& c : modified_configurations()) {
    if (key == c.name || key == to_lower(c.class_name) + "-" + c.name) return c;
    names += (names.empty() ? "" : ", ") + c.class_name + "-" + c.name;
  }
  throw InvalidInput(fmt::format("unknown modified configuration '{}' (allowed: {})", name, names));
}

std::array<double, 3> table3_lengths(const ModifiedConfiguration& c, double r2, double r3) {
  // Unknowns L1, L2, L3: L_i - f_i r_i'(L) = 0, r2' = r2 - (s1 L1 + s2 L2)/2,
  // r3' = r3 - (s2 L2 + s3 L3)/2, r'_ave = (r2' + r3')/2, s_i = 1 for a flexible pivot.
  const double f1 = c.length_factor[0], f2 = c.length_factor[1], f3 = c.length_factor[2];
  const double s1 = f1 > 0 ? 1 : 0, s2 = f2 > 0 ? 1 : 0, s3 = f3 > 0 ? 1 : 0;
  Eigen::Matrix3d A;
  Eigen::Vector3d b;
  A << 1 + 0.5 * f1 * s1, 0.5 * f1 * s2, 0,                    //
      0.25 * f2 * s1, 1 + 0.25 * f2 * 2 * s2, 0.25 * f2 * s3,  //
      0, 0.5 * f3 * s2, 1 + 0.5 * f3 * s3;
  b << f1 * r2, f2 * 0.5 * (r2 + r3), f3 * r3;
  const Eigen::Vector3d L = A.fullPivLu().solve(b);
  return {L(0), L(1), L(2)};
}

double spring_rule_factor(SpringRule rule, const JointDesign& j) {
  if (j.segment != SegmentKind::kFixedFixed) {
    throw InvalidInput("a spring rule applies to fixed-fixed segments only");
  }
  const double table2 =
      j.paper_letter == 'l' ? j.table2_factor * long_gamma() * long_K_theta() : 1.0;
  switch (rule) {
    case SpringRule::kPureBending:
      return 1.0;  // end-moment strip between two rigid bodies: k = EI/L (Howell eq. 5.14)
    case SpringRule::kTable2:
      return table2;  // paper Table 2 as printed
    case SpringRule::kTable5:
      return 2.0 * table2;  // paper Table 5's values (docs/dynamics.md §2)
  }
  return 1.0;
}

SpringRule parse_spring_rule(const std::string& text) {
  const std::string t = to_lower(text);
  if (t == "pure-bending") return SpringRule::kPureBending;
  if (t == "table2") return SpringRule::kTable2;
  if (t == "table5") return SpringRule::kTable5;
  throw InvalidInput(
      fmt::format("spring rule '{}' is unknown (allowed: pure-bending, table2, table5)", text));
}

std::string spring_rule_name(SpringRule rule) {
  switch (rule) {
    case SpringRule::kPureBending:
      return "pure-bending";
    case SpringRule::kTable2:
      return "table2";
    case SpringRule::kTable5:
      return "table5";
  }
  return "pure-bending";
}

bool has_fixed_fixed(const MechanismDesign& d) {
  return std::any_of(d.joints.begin(), d.joints.end(), [](const JointDesign& j) {
    return j.segment == SegmentKind::kFixedFixed;
  });
}

void apply_spring_rule(MechanismDesign& d, SpringRule rule) {
  if (!has_fixed_fixed(d)) {
    throw InvalidInput(
        fmt::format("a spring rule applies to designs with fixed-fixed segments (the modified "
                    "configurations, e.g. 2B-lplm); '{}' has none",
                    d.name));
  }
  d.spring_rule = rule;
  const std::string tag = "; spring rule ";
  const auto at = d.note.rfind(tag);
  if (at != std::string::npos) d.note = d.note.substr(0, at);
  if (!d.paper_config.empty()) d.note += tag + spring_rule_name(rule);
}

void check_fixed_fixed_lengths(const MechanismDesign& d) {
  if (!has_fixed_fixed(d)) return;
  const auto& j = d.joints;
  for (const auto& jd : j) {
    if (jd.segment == SegmentKind::kFixedFixed &&
        (jd.type != PivotType::kSmall || (jd.paper_letter != 'l' && jd.paper_letter != 's'))) {
      throw InvalidInput(
          "a fixed-fixed segment is a centred flexure (type s) with paper letter 'l' or 's'");
    }
  }
  auto check = [&](int a, int b, double r, const char* link) {
    // A thesis l segment replaces the whole link: nothing rigid to check.
    if (j[a - 1].type == PivotType::kLong || j[b - 1].type == PivotType::kLong) return;
    if (j[a - 1].segment != SegmentKind::kFixedFixed &&
        j[b - 1].segment != SegmentKind::kFixedFixed) {
      return;
    }
    const double La = centred(j[a - 1]) ? j[a - 1].length : 0.0;
    const double Lb = centred(j[b - 1]) ? j[b - 1].length : 0.0;
    const double rest = r - 0.5 * (La + Lb);
    if (!(rest > 0.0)) {
      throw InvalidInput(fmt::format(
          "fixed-fixed segment lengths too long for {}: {} - (L{} + L{})/2 = {:.6g} m must be > 0 "
          "(each segment is centred on its PRB pivot; L{} = {:.6g} m, L{} = {:.6g} m)",
          link,
          link,
          a,
          b,
          rest,
          a,
          La,
          b,
          Lb));
    }
  };
  check(1, 2, d.r2, "r2");
  check(2, 3, d.r3, "r3");
}

MechanismDesign modified_design(const ModifiedConfiguration& c, SpringRule rule) {
  if (c.name == "slpm" || c.name == "lpsm") return constructed_design(c, rule);
  // Table 5 column (builtin_designs.h): r2, r3, b, h, L, E; stroke 40 % (Table 6).
  const dynamics::CfsmDesign& t = dynamics::find_cfsm_design(c.class_name + "-" + c.name);
  MechanismDesign d = base_design(c, rule);
  d.r2 = t.r2;
  d.r3 = t.r3;
  d.material.E = t.material.E;
  for (int i = 0; i < 3; ++i) {
    JointDesign& j = d.joints[i];
    if (j.type == PivotType::kPin) continue;
    j.length = t.l[i];
    j.thickness = t.h[i];
    j.width = t.width_b;
  }
  d.stroke = kStrokeFraction * (d.r2 + d.r3);
  d.note = fmt::format(
      "paper 004 Table 5 column {}-{}: r2, r3, b, h, L, E as printed, every segment fixed-fixed "
      "and centred on its PRB pivot, stroke 40 % of r2 + r3 (Table 6), S_y = 200 ksi (chosen); "
      "spring rule {}",
      c.class_name,
      c.name,
      spring_rule_name(rule));
  d.finalise();
  return d;
}

const std::vector<MechanismDesign>& modified_designs() {
  static const std::vector<MechanismDesign> designs = [] {
    std::vector<MechanismDesign> list;
    for (const auto& c : modified_configurations()) list.push_back(modified_design(c));
    return list;
  }();
  return designs;
}

}  // namespace flexure::mechanism
