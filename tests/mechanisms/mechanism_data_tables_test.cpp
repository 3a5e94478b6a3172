// What is checked against what: the printed tables of the mechanisms layer, now data files
// compiled into the library (data/*.csv, cmake/embed_data.cmake).
//  * Each embedded copy is the file in the repository, byte for byte.
//  * The structs read from them hold the printed values, written out here from the sources:
//    Weight (2001) Tables 7.2-7.13 (two sub-class rows, two thickness-ratio rows), Table 2.1,
//    Howell Table 10.1, and Tables 2, 4, 5 and 6 of Ugwuoke & Abolarin (JETIR 2023).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <optional>
#include <string>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/data/data_files.h"
#include "flexure/solver/common/csv_table.h"
#include "tests/support/data_file_support.h"

namespace flexure {
namespace {

using test::expect_embedded_equals_file;

TEST(MechanismDataTables, EmbeddedCopiesEqualTheFiles) {
  for (const EmbeddedFile& file : {data::weight_thesis_subclasses(),
                                   data::weight_thesis_thickness_ratios(),
                                   data::weight_table_2_1(),
                                   data::howell_table_10_1(),
                                   data::paper_table_5(),
                                   data::paper_table_6(),
                                   data::paper_tables_2_4()}) {
    expect_embedded_equals_file(file);
    // Every file cites its source in the comment block.
    const CsvTable t = CsvTable::parse(file);
    EXPECT_TRUE(std::any_of(t.comments().begin(), t.comments().end(), [](const std::string& c) {
      return c.rfind("Source: ", 0) == 0;
    })) << file.path;
  }
}

TEST(MechanismDataTables, RowCountsAreTheSources) {
  EXPECT_EQ(cfm::thesis_subclasses().size(), 68u);
  EXPECT_EQ(cfm::thesis_thickness_ratios().size(), 45u);
  EXPECT_EQ(cfm::thesis_table_2_1().size(), 10u);
  EXPECT_EQ(cfm::howell_table_10_1().size(), 10u);
  EXPECT_EQ(dynamics::cfsm_designs().size(), 9u);
  EXPECT_EQ(mechanism::modified_configurations().size(), 11u);
}

// Weight, Table 7.2: the first row (class 1A, long segment).
TEST(MechanismDataTables, SubclassLppA) {
  const cfm::CfmSubclass& r = cfm::thesis_subclasses().front();
  EXPECT_STREQ(r.name, "lpp-a");
  EXPECT_STREQ(r.config, "lpp");
  EXPECT_EQ(r.stroke_percent, 16.0);
  EXPECT_EQ(r.primary_pivot, 1);
  EXPECT_EQ(r.percent_constant_force, 99.7);
  EXPECT_EQ(r.R, 0.8274);
  EXPECT_EQ(r.K1, 0.0);
  EXPECT_EQ(r.K2, 0.0);
  EXPECT_EQ(r.kappa1, 3.50);
  EXPECT_FALSE(r.kappa2.has_value());
  EXPECT_FALSE(r.kappa3.has_value());
  EXPECT_EQ(r.Phi, 0.4537);
  EXPECT_EQ(r.beta, 2.901);
  EXPECT_EQ(r.Psi, 1.000);
  EXPECT_EQ(r.lambda, 1.097);
  EXPECT_EQ(r.M, 0.4501);
  EXPECT_EQ(r.n, 0.5004);
  EXPECT_EQ(r.d_N_max, 26.96);
  EXPECT_FALSE(r.toggle_clamped);
}

// Weight, Table 7.6 (class 2A): a row that reproduces only with the toggle clamp.
TEST(MechanismDataTables, SubclassSspB94I) {
  const cfm::CfmSubclass& r = cfm::find_thesis_subclass("ssp-b94I");
  EXPECT_STREQ(r.config, "ssp");
  EXPECT_EQ(r.stroke_percent, 40.0);
  EXPECT_EQ(r.primary_pivot, 2);
  EXPECT_EQ(r.percent_constant_force, 94.1);
  EXPECT_EQ(r.R, 0.3000);
  EXPECT_EQ(r.K1, 0.1000);
  EXPECT_EQ(r.K2, 0.0);
  EXPECT_EQ(r.kappa1, 13.00);
  EXPECT_EQ(r.kappa2, 20.00);
  EXPECT_FALSE(r.kappa3.has_value());
  EXPECT_EQ(r.Phi, 0.6423);
  EXPECT_EQ(r.beta, 10.854);
  EXPECT_EQ(r.Psi, 0.030);
  EXPECT_EQ(r.lambda, 1.038);
  EXPECT_EQ(r.M, 6.3534);
  EXPECT_EQ(r.n, 0.5372);
  EXPECT_EQ(r.d_N_max, 23.08);
  EXPECT_TRUE(r.toggle_clamped);
  // The last row of the master table (Table 7.12, class 3A).
  const cfm::CfmSubclass& last = cfm::thesis_subclasses().back();
  EXPECT_STREQ(last.name, "sss-b88IO");
  EXPECT_EQ(last.K2, 3.3349);
  EXPECT_EQ(last.beta, 264.926);
}

// Weight, Tables 7.7 (2A) and 7.13 (3A).
TEST(MechanismDataTables, ThicknessRatios) {
  const auto& rows = cfm::thesis_thickness_ratios();
  const cfm::CfmThicknessRatios& first = rows.front();
  EXPECT_STREQ(first.name, "slp-aIo");
  EXPECT_EQ(first.primary_pivot, 2);
  EXPECT_EQ(first.decimals, 2);
  EXPECT_EQ(first.C[0], 1.71);
  EXPECT_EQ(first.C[1], 1.00);
  EXPECT_FALSE(first.C[2].has_value());
  EXPECT_EQ(first.D_equal[0], 2.54);
  EXPECT_EQ(first.D_min[0], 0.51);
  const auto sss = std::find_if(rows.begin(), rows.end(), [](const cfm::CfmThicknessRatios& r) {
    return std::string(r.name) == "sss-a95I";
  });
  ASSERT_NE(sss, rows.end());
  EXPECT_EQ(sss->primary_pivot, 3);
  EXPECT_EQ(sss->decimals, 3);
  EXPECT_EQ(sss->C[0], 0.340);
  EXPECT_EQ(sss->C[1], 0.289);
  EXPECT_EQ(sss->D_equal[1], 0.022);
  EXPECT_EQ(sss->D_min[0], 0.997);
  EXPECT_EQ(sss->D_min[2], 1.000);
}

// Weight, Table 2.1 and Howell, Table 10.1.
TEST(MechanismDataTables, ClassLevelRows) {
  const cfm::CfmClassRow* t = cfm::find_class_row("table2.1-2B-a");
  ASSERT_NE(t, nullptr);
  EXPECT_STREQ(t->class_name, "2B");
  EXPECT_STREQ(t->config, "sps");
  EXPECT_EQ(t->stroke_percent, 16.0);
  EXPECT_EQ(t->R, 0.7591);
  EXPECT_FALSE(t->K1.has_value());
  EXPECT_EQ(t->K2, 0.1208);
  EXPECT_EQ(t->Xi, 1.0029);
  EXPECT_EQ(t->Phi, 0.5230);
  EXPECT_TRUE(t->reproducible);
  // Table 2.1 prints K1 = 1.0000 for class 1B, Howell prints "-".
  EXPECT_EQ(cfm::find_class_row("table2.1-1B-b")->K1, 1.0);
  EXPECT_FALSE(cfm::find_class_row("howell10.1-1B-b")->K1.has_value());
  const cfm::CfmClassRow* h = cfm::find_class_row("howell10.1-2B-b");
  ASSERT_NE(h, nullptr);
  EXPECT_STREQ(h->config, "sps");
  EXPECT_EQ(h->stroke_percent, 40.0);
  EXPECT_EQ(h->R, 0.8441);
  EXPECT_EQ(h->K2, 0.1208);
  EXPECT_EQ(h->Xi, 1.1914);
  EXPECT_EQ(h->Phi, 1.2154);
  EXPECT_FALSE(h->reproducible);
  const cfm::CfmClassRow* h3 = cfm::find_class_row("howell10.1-3A-a");
  ASSERT_NE(h3, nullptr);
  EXPECT_EQ(h3->R, 2.6633);
  EXPECT_EQ(h3->K1, 1.0);
  EXPECT_EQ(h3->K2, 12.6704);
  EXPECT_EQ(h3->Xi, 1.0002);
  EXPECT_EQ(h3->Phi, 3.4016);
}

// Ugwuoke & Abolarin, Tables 5 and 6 (SI units in the structs).
TEST(MechanismDataTables, PaperTable5And6) {
  const dynamics::CfsmDesign& d = dynamics::find_cfsm_design("2B-lplm");
  EXPECT_DOUBLE_EQ(d.r2, 68.0e-3);
  EXPECT_DOUBLE_EQ(d.r3, 68.0e-3);
  EXPECT_DOUBLE_EQ(d.r5, 12.0e-3);
  EXPECT_DOUBLE_EQ(d.r6, 12.0e-3);
  EXPECT_DOUBLE_EQ(d.m2, 74.1147e-3);
  EXPECT_DOUBLE_EQ(d.m_slider, 116.7138e-3);
  EXPECT_EQ(d.pivots, (std::array<char, 3>{'l', 'p', 'l'}));
  EXPECT_EQ(d.k, (std::array<double, 3>{3.4322, 0.0, 3.4322}));
  EXPECT_DOUBLE_EQ(d.h[0], 0.5181e-3);
  EXPECT_EQ(d.h[1], 0.0);
  EXPECT_DOUBLE_EQ(d.l[2], 24.0e-3);
  EXPECT_DOUBLE_EQ(d.width_b, 25.4e-3);
  EXPECT_DOUBLE_EQ(d.material.E, 207e9);
  EXPECT_EQ(d.F_nom_paper, 109.2944);
  EXPECT_EQ(d.Phi_paper, 1.0827);
  const dynamics::CfsmDesign& first = dynamics::cfsm_designs().front();
  EXPECT_EQ(first.name, "1A-lppm");
  EXPECT_EQ(first.r6, 0.0);  // "-": no extension at the slider
  const dynamics::CfsmDesign& last = dynamics::cfsm_designs().back();
  EXPECT_EQ(last.name, "3A-lllm");
  EXPECT_DOUBLE_EQ(last.l[1], 20.8696e-3);
  EXPECT_EQ(last.F_nom_paper, 25.2446);
  EXPECT_EQ(last.Phi_paper, 0.0);  // no Phi
}

// Ugwuoke & Abolarin, Tables 2 and 4.
TEST(MechanismDataTables, PaperTables2And4) {
  const mechanism::ModifiedConfiguration& c = mechanism::find_modified_configuration("3A-lslm");
  EXPECT_EQ(c.name, "lslm");
  EXPECT_EQ(c.class_name, "3A");
  EXPECT_EQ(c.letters, (std::array<char, 3>{'l', 's', 'l'}));
  EXPECT_EQ(c.table2_factor, (std::array<double, 3>{0.3, 1.0, 0.3}));
  EXPECT_EQ(c.length_factor, (std::array<double, 3>{3.0 / 7.0, 0.1, 3.0 / 7.0}));
  EXPECT_EQ(c.R, 1.0);
  EXPECT_EQ(c.Lambda, 1.1694);
  const mechanism::ModifiedConfiguration& p = mechanism::find_modified_configuration("1B-plpm");
  EXPECT_EQ(p.table2_factor, (std::array<double, 3>{0.0, 0.3, 0.0}));
  EXPECT_EQ(p.R, 0.9);
  EXPECT_EQ(p.Lambda, 1.0);
  EXPECT_EQ(mechanism::modified_configurations().front().name, "lppm");
  EXPECT_EQ(mechanism::modified_configurations().back().name, "lllm");
}

}  // namespace
}  // namespace flexure
