#include <fmt/format.h>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/data/data_files.h"
#include "flexure/solver/common/csv_table.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure::dynamics {
namespace {

constexpr double mm = 1e-3;
constexpr double g = 1e-3;
constexpr double GPa = 1e9;

// data/paper_table_5.csv (lengths mm, masses g, k N m, E GPa; "-" where there is no flexure or
// extension) and data/paper_table_6.csv (F_Nom N, Phi; "-": no Phi, stored as 0).
std::vector<CfsmDesign> make_designs() {
  const CsvTable t5 = CsvTable::parse(data::paper_table_5());
  const CsvTable t6 = CsvTable::parse(data::paper_table_6());
  std::vector<CfsmDesign> d;
  for (std::size_t i = 0; i < t5.row_count(); ++i) {
    CfsmDesign x;
    x.name = t5.text(i, "design");
    // The pivot letters sit between the class and the trailing 'm': "2B-lplm" -> l, p, l.
    const std::size_t dash = x.name.find('-');
    if (dash == std::string::npos || x.name.size() != dash + 5 || x.name.back() != 'm' ||
        x.name.find_first_not_of("pls", dash + 1) != x.name.size() - 1) {
      throw t5.cell_error(i, "design", fmt::format("'{}' is not <class>-<pivots p|l|s>m", x.name));
    }
    if (i >= t6.row_count() || t6.text(i, "design") != x.name) {
      throw t6.cell_error(
          i, "design", fmt::format("expected {}, the design of Table 5's row {}", x.name, i + 1));
    }
    x.r2 = t5.number(i, "r2") * mm;
    x.r3 = t5.number(i, "r3") * mm;
    x.r5 = t5.number_or(i, "r5", 0.0) * mm;
    x.r6 = t5.number_or(i, "r6", 0.0) * mm;
    x.m2 = t5.number(i, "m2") * g;
    x.m3 = t5.number(i, "m3") * g;
    x.m_slider = t5.number(i, "m_slider") * g;
    for (int p = 0; p < 3; ++p) {
      x.pivots[p] = x.name[dash + 1 + p];
      x.k[p] = t5.number_or(i, fmt::format("k{}", p + 1), 0.0);
      x.h[p] = t5.number_or(i, fmt::format("h{}", p + 1), 0.0) * mm;
      x.l[p] = t5.number_or(i, fmt::format("L{}", p + 1), 0.0) * mm;
    }
    x.width_b = t5.number(i, "b") * mm;
    x.material.E = t5.number(i, "E") * GPa;
    x.F_nom_paper = t6.number(i, "F_nom");
    x.Phi_paper = t6.number_or(i, "Phi", 0.0);
    d.push_back(x);
  }
  if (t6.row_count() != t5.row_count()) {
    throw InvalidInput(fmt::format("{} has {} rows, {} has {}: one per design",
                                   t6.source(),
                                   t6.row_count(),
                                   t5.source(),
                                   t5.row_count()));
  }
  return d;
}

}  // namespace

const std::vector<CfsmDesign>& cfsm_designs() {
  static const std::vector<CfsmDesign> designs = make_designs();
  return designs;
}

const CfsmDesign& find_cfsm_design(const std::string& name) {
  std::string names;
  for (const CfsmDesign& d : cfsm_designs()) {
    if (same_name(d.name, name)) return d;
    names += (names.empty() ? "" : ", ") + d.name;
  }
  throw InvalidInput(fmt::format("mechanism '{}' is unknown; allowed: {}", name, names));
}

}  // namespace flexure::dynamics
