#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <deque>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/data/data_files.h"
#include "flexure/solver/common/csv_table.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure::cfm {
namespace {

// "slp-bIO" -> "slp-b": drops the orientation flags I, O, o at the end.
std::string without_orientation(const std::string& name) {
  std::string s = name;
  while (!s.empty() && (s.back() == 'I' || s.back() == 'O' || s.back() == 'o')) s.pop_back();
  return s;
}

// Owner of the strings that the rows' `const char*` fields point to; lives as long as its table.
class StringPool {
 public:
  const char* keep(std::string s) {
    strings_.push_back(std::move(s));
    return strings_.back().c_str();
  }

 private:
  std::deque<std::string> strings_;  // push_back keeps the earlier elements in place
};

bool is_configuration(const std::string& name) {
  const auto& all = cfm_configurations();
  return std::any_of(
      all.begin(), all.end(), [&](const CfmConfiguration& c) { return c.name == name; });
}

// data/weight_thesis_subclasses.csv: Weight, Tables 7.2, 7.4, 7.6, 7.9, 7.12.
std::vector<CfmSubclass> read_subclasses(StringPool& pool) {
  const CsvTable t = CsvTable::parse(data::weight_thesis_subclasses());
  std::vector<CfmSubclass> rows;
  for (std::size_t i = 0; i < t.row_count(); ++i) {
    const std::string& name = t.text(i, "name");
    const std::string& config = t.text(i, "config");
    if (!is_configuration(config)) {
      throw t.cell_error(
          i, "config", fmt::format("'{}' is not one of the nine configurations", config));
    }
    const double d = t.number(i, "d");
    // The name is config-<a|b>...: a for the 16 % stroke, b for 40 %.
    const char letter = name.size() > config.size() + 1 ? name[config.size() + 1] : '\0';
    if (name.rfind(config + "-", 0) != 0 ||
        !((letter == 'a' && d == 16.0) || (letter == 'b' && d == 40.0))) {
      throw t.cell_error(
          i,
          "name",
          fmt::format(
              "'{}' does not match config {} and stroke d = {} (a: 16, b: 40)", name, config, d));
    }
    CfmSubclass r{};
    r.name = pool.keep(name);
    r.config = pool.keep(config);
    r.stroke_percent = d;
    r.primary_pivot = t.integer(i, "p");
    r.percent_constant_force = t.number(i, "Xi_prime");
    r.R = t.number(i, "R");
    r.K1 = t.number(i, "K1");
    r.K2 = t.number(i, "K2");
    r.kappa1 = t.optional_number(i, "kappa1");
    r.kappa2 = t.optional_number(i, "kappa2");
    r.kappa3 = t.optional_number(i, "kappa3");
    r.Phi = t.number(i, "Phi");
    r.beta = t.number(i, "beta");
    r.Psi = t.number(i, "Psi");
    r.lambda = t.number(i, "lambda");
    r.M = t.number(i, "M");
    r.n = t.number(i, "n");
    r.d_N_max = t.number(i, "d_N_max");
    r.toggle_clamped = t.yes_no(i, "toggle_clamped");
    rows.push_back(r);
  }
  return rows;
}

// data/weight_thesis_thickness_ratios.csv: Weight, Tables 7.7, 7.10, 7.13.
std::vector<CfmThicknessRatios> read_thickness_ratios() {
  const CsvTable t = CsvTable::parse(data::weight_thesis_thickness_ratios());
  std::vector<CfmThicknessRatios> rows;
  for (std::size_t i = 0; i < t.row_count(); ++i) {
    const std::string& name = t.text(i, "name");
    const auto& subclasses = thesis_subclasses();
    const auto sub = std::find_if(
        subclasses.begin(), subclasses.end(), [&](const CfmSubclass& s) { return name == s.name; });
    if (sub == subclasses.end()) {
      throw t.cell_error(i, "name", fmt::format("'{}' is not one of the thesis sub-classes", name));
    }
    CfmThicknessRatios r{};
    r.name = sub->name;
    r.primary_pivot = t.integer(i, "p");
    r.decimals = t.integer(i, "decimals");
    for (int k = 0; k < 3; ++k) {
      r.C[k] = t.optional_number(i, fmt::format("C{}", k + 1));
      r.D_equal[k] = t.optional_number(i, fmt::format("D{}_equal", k + 1));
      r.D_min[k] = t.optional_number(i, fmt::format("D{}_min", k + 1));
    }
    rows.push_back(r);
  }
  return rows;
}

// A class-level table (data/weight_table_2_1.csv, data/howell_table_10_1.csv). Row names are
// <prefix>-<class>-<a|b> (a: d = 16, b: d = 40); the configuration evaluated is the class's first
// in the thesis's order, its all-s-pivot member.
std::vector<CfmClassRow> read_class_rows(const EmbeddedFile& file,
                                         const std::string& prefix,
                                         StringPool& pool) {
  const CsvTable t = CsvTable::parse(file);
  std::vector<CfmClassRow> rows;
  for (std::size_t i = 0; i < t.row_count(); ++i) {
    const std::string& class_name = t.text(i, "class");
    const auto& all = cfm_configurations();
    const auto config = std::find_if(all.begin(), all.end(), [&](const CfmConfiguration& c) {
      return c.class_name == class_name;
    });
    if (config == all.end()) {
      throw t.cell_error(
          i, "class", fmt::format("'{}' is not a class (1A, 1B, 2A, 2B, 3A)", class_name));
    }
    const double d = t.number(i, "d");
    if (d != 16.0 && d != 40.0) {
      throw t.cell_error(i, "d", fmt::format("{} is neither 16 nor 40", d));
    }
    CfmClassRow r{};
    r.name = pool.keep(fmt::format("{}-{}-{}", prefix, class_name, d == 16.0 ? 'a' : 'b'));
    r.class_name = config->class_name.c_str();
    r.config = config->name.c_str();
    r.stroke_percent = d;
    r.R = t.number(i, "R");
    r.K1 = t.optional_number(i, "K1");
    r.K2 = t.optional_number(i, "K2");
    r.Xi = t.number(i, "Xi");
    r.Phi = t.number(i, "Phi");
    r.reproducible = t.yes_no(i, "reproducible");
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

const std::vector<CfmSubclass>& thesis_subclasses() {
  static StringPool pool;
  static const std::vector<CfmSubclass> kRows = read_subclasses(pool);
  return kRows;
}

const CfmSubclass& find_thesis_subclass(const std::string& name) {
  std::string key = name;
  // Optional class prefix, e.g. "2A-slp-bIO".
  if (key.size() > 3 && key[2] == '-' && std::isdigit(static_cast<unsigned char>(key[0]))) {
    const std::string class_name = key.substr(0, 2);
    key = key.substr(3);
    const std::string config = to_lower(key.substr(0, key.find('-')));
    const CfmConfiguration& c = find_cfm_configuration(config);
    if (to_lower(c.class_name) != to_lower(class_name)) {
      throw InvalidInput(fmt::format("sub-class '{}': configuration {} is class {}, not {}",
                                     name,
                                     c.name,
                                     c.class_name,
                                     class_name));
    }
  }
  const std::vector<CfmSubclass>& rows = thesis_subclasses();
  for (const CfmSubclass& row : rows) {
    if (key == row.name) return row;
  }
  std::vector<const CfmSubclass*> matches;
  for (const CfmSubclass& row : rows) {
    if (to_lower(key) == to_lower(row.name) ||
        to_lower(without_orientation(key)) == to_lower(without_orientation(row.name))) {
      matches.push_back(&row);
    }
  }
  if (matches.size() == 1) return *matches.front();
  if (matches.empty()) {
    throw InvalidInput(fmt::format(
        "sub-class '{}' is not one of the 68 thesis sub-classes (see `flexure cfm --list`)", name));
  }
  std::string candidates;
  for (const CfmSubclass* row : matches)
    candidates += std::string(candidates.empty() ? "" : ", ") + row->name;
  throw InvalidInput(fmt::format("sub-class '{}' is ambiguous: {}", name, candidates));
}

const std::vector<CfmThicknessRatios>& thesis_thickness_ratios() {
  static const std::vector<CfmThicknessRatios> kRows = read_thickness_ratios();
  return kRows;
}

const std::vector<CfmClassRow>& thesis_table_2_1() {
  static StringPool pool;
  static const std::vector<CfmClassRow> kRows =
      read_class_rows(data::weight_table_2_1(), "table2.1", pool);
  return kRows;
}

const std::vector<CfmClassRow>& howell_table_10_1() {
  static StringPool pool;
  static const std::vector<CfmClassRow> kRows =
      read_class_rows(data::howell_table_10_1(), "howell10.1", pool);
  return kRows;
}

const CfmClassRow* find_class_row(const std::string& name) {
  for (const auto* table : {&thesis_table_2_1(), &howell_table_10_1()}) {
    for (const CfmClassRow& row : *table) {
      if (name == row.name) return &row;
    }
  }
  return nullptr;
}

}  // namespace flexure::cfm
