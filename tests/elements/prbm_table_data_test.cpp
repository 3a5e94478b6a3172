// What is checked against what: Howell's Tables 5.1-5.3, now data files compiled into the library
// (data/howell_table_5_*.csv). The embedded copies are the files, byte for byte, and the rows read
// from them hold the values printed in Howell, Compliant Mechanisms (2001), written out here.
#include <gtest/gtest.h>

#include "flexure/elements/data_files.h"
#include "flexure/elements/prbm_element.h"
#include "tests/support/data_file_support.h"

namespace flexure {
namespace {

TEST(PrbmTableData, EmbeddedCopiesEqualTheFiles) {
  test::expect_embedded_equals_file(data::howell_table_5_1());
  test::expect_embedded_equals_file(data::howell_table_5_2());
  test::expect_embedded_equals_file(data::howell_table_5_3());
}

TEST(PrbmTableData, Table51) {
  const auto& rows = table_5_1();
  ASSERT_EQ(rows.size(), 17u);
  // The book's order: n = 0 ... 10, then -0.5 ... -5.
  const FixedPinnedTableRow& n0 = rows.front();
  EXPECT_EQ(n0.load_ratio_n, 0.0);
  EXPECT_EQ(n0.phi_deg, 90.0);
  EXPECT_EQ(n0.gamma, 0.8517);
  EXPECT_EQ(n0.theta_max_gamma_deg, 64.3);
  EXPECT_EQ(n0.c_theta, 1.2385);
  EXPECT_EQ(n0.K_theta, 2.67617);
  EXPECT_EQ(n0.theta_max_K_deg, 58.5);
  EXPECT_EQ(rows[9].load_ratio_n, 10.0);
  EXPECT_EQ(rows[10].load_ratio_n, -0.5);
  const FixedPinnedTableRow& n5 = rows.back();
  EXPECT_EQ(n5.load_ratio_n, -5.0);
  EXPECT_EQ(n5.phi_deg, 11.3);
  EXPECT_EQ(n5.gamma, 0.8391);
  EXPECT_EQ(n5.theta_max_gamma_deg, 9.7);
  EXPECT_EQ(n5.c_theta, 1.1788);
  EXPECT_EQ(n5.K_theta, 2.49874);
  EXPECT_EQ(n5.theta_max_K_deg, 7.9);
}

TEST(PrbmTableData, Tables52And53) {
  const auto& curved = table_5_2();
  ASSERT_EQ(curved.size(), 7u);
  EXPECT_EQ(curved[4].kappa0, 1.00);
  EXPECT_EQ(curved[4].gamma, 0.81);
  EXPECT_EQ(curved[4].rho, 0.797);
  EXPECT_EQ(curved[4].K_theta, 2.60);
  const auto& pinned = table_5_3();
  ASSERT_EQ(pinned.size(), 5u);
  EXPECT_EQ(pinned[3].kappa0, 1.25);
  EXPECT_EQ(pinned[3].gamma, 0.779);
  EXPECT_EQ(pinned[3].rho, 0.768);
  EXPECT_EQ(pinned[3].delta_theta_max_gamma, 1.203);
  EXPECT_EQ(pinned[3].K_theta, 2.75);
  EXPECT_EQ(pinned[3].delta_theta_max_K, 0.71);
}

}  // namespace
}  // namespace flexure
