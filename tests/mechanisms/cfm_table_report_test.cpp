// `flexure cfm --table` as library calls (cfm_comparison.h): compare_printed_tables() gives the
// verdict of every row that the tool printed before the comparisons moved into the library (the
// frozen output tests/golden/cfm_table.json and .txt: names, within, all_within and the worst
// deviation per quantity, to the two printed decimals), and compare_exact_table() selects the nine
// sub-classes "a" (one per configuration, no design-stroke suffix) or all 68, reports progress in
// stroke points up to rows x points, and calls on_row once per row in table order.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "flexure/mechanisms/cfm_comparison.h"

namespace flexure::test {
namespace {

using nlohmann::json;

std::string golden(const std::string& name) {
  std::ifstream in(std::string(FLEXURE_SOURCE_DIR) + "/tests/golden/" + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CfmTableReport, VerdictsEqualTheFrozenTable) {
  const cfm::PrintedTablesReport r = cfm::compare_printed_tables();
  const json g = json::parse(golden("cfm_table.json"));
  ASSERT_EQ(r.subclasses.size(), g["subclasses"].size());
  for (std::size_t i = 0; i < r.subclasses.size(); ++i) {
    EXPECT_EQ(r.subclasses[i].row->name, g["subclasses"][i]["name"].get<std::string>());
    EXPECT_EQ(r.subclasses[i].all_within(), g["subclasses"][i]["within"].get<bool>());
    EXPECT_EQ(r.subclasses[i].Phi.computed, g["subclasses"][i]["Phi"]["computed"].get<double>());
  }
  ASSERT_EQ(r.class_rows.size(), g["class_rows"].size());
  for (std::size_t i = 0; i < r.class_rows.size(); ++i) {
    const json& row = g["class_rows"][i];
    const cfm::ClassRowReport& c = r.class_rows[i];
    EXPECT_EQ(c.comparison.row->name, row["name"].get<std::string>());
    EXPECT_EQ(c.verdict == cfm::RowVerdict::kWithin, row["within"].get<bool>()) << i;
    EXPECT_EQ(c.verdict == cfm::RowVerdict::kOutsideIrreproducible,
              !row["within"].get<bool>() && !row["reproducible"].get<bool>())
        << i;
    EXPECT_EQ(c.comparison.Xi.tolerance, row["Xi"]["tolerance"].get<double>()) << i;
  }
  EXPECT_EQ(r.all_within, g["all_within"].get<bool>());
  EXPECT_EQ(r.converged(), r.all_within);
  EXPECT_EQ(r.ratios.size(), cfm::thesis_thickness_ratios().size());

  // "Largest |computed - printed| / tolerance over the 68 rows: Phi 0.77 (lps-b95IO); ..."
  const std::string text = golden("cfm_table.txt");
  for (const cfm::WorstDeviation& w : r.worst) {
    const std::regex pattern(" " + w.quantity + " ([0-9.]+) \\(([^)]*)\\)[;.]");
    std::smatch m;
    const std::size_t at = text.find("Largest |computed");
    ASSERT_NE(at, std::string::npos);
    const std::string line = text.substr(at, text.find('\n', at) - at);
    ASSERT_TRUE(std::regex_search(line, m, pattern)) << w.quantity << " in " << line;
    EXPECT_EQ(fmt::format("{:.2f}", w.ratio), m[1].str()) << w.quantity;
    EXPECT_EQ(w.row, m[2].str()) << w.quantity;
    EXPECT_LE(w.ratio, 1.0);
  }
}

TEST(CfmTableReport, ExactTableSelectsTheNineSubclassesA) {
  const std::vector<const cfm::CfmSubclass*> a =
      cfm::exact_table_rows(cfm::ExactTableRows::kSubclassA);
  ASSERT_EQ(a.size(), 9u);
  std::set<std::string> configs;
  for (const cfm::CfmSubclass* row : a) {
    EXPECT_TRUE(std::regex_match(std::string(row->name), std::regex("[a-z]{3}-a[IOo]*")))
        << row->name;
    configs.insert(row->config);
  }
  EXPECT_EQ(configs.size(), 9u);  // one per configuration
  EXPECT_EQ(cfm::exact_table_rows(cfm::ExactTableRows::kAll).size(), 68u);
}

TEST(CfmTableReport, ExactTableProgressAndRowsInOrder) {
  cfm::CfmExactOptions options;
  options.points = 8;
  std::vector<std::size_t> done;
  std::size_t total = 0;
  std::vector<std::string> names;
  const cfm::ExactTableReport r = cfm::compare_exact_table(
      cfm::ExactTableRows::kSubclassA,
      options,
      [&](std::size_t d, std::size_t t) {
        done.push_back(d);
        total = t;
      },
      [&](const cfm::ExactTableRow& row) { names.push_back(row.row->name); });
  ASSERT_EQ(r.rows.size(), 9u);
  ASSERT_EQ(names.size(), 9u);
  bool every = true;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    EXPECT_EQ(names[i], r.rows[i].row->name);
    EXPECT_EQ(r.rows[i].prbm.Phi, cfm::CfmModel().evaluate(cfm::parameters_of(*r.rows[i].row)).Phi);
    every = every && r.rows[i].exact.converged();
  }
  EXPECT_EQ(r.all_converged, every);
  EXPECT_EQ(r.converged(), every);
  EXPECT_EQ(total, 9u * 8u);
  ASSERT_FALSE(done.empty());
  EXPECT_EQ(done.back(), total);
  for (std::size_t i = 1; i < done.size(); ++i) EXPECT_GE(done[i], done[i - 1]);
}

}  // namespace
}  // namespace flexure::test
