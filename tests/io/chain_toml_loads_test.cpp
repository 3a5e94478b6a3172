// The TOML keys of distributed loads and extensible segments (docs/chain-toml.md,
// docs/distributed-loads.md, docs/extensible.md): each key lands in the segment with the value
// computed by hand (self-weight rho A g, EA = E A, GAs = k E A / (2 (1 + nu))), units convert, and
// every inconsistent combination is an InvalidInput naming the segment.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexure/io/toml_files.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

const FlexibleSegment& first(const io::ChainFile& f) {
  return std::get<FlexibleSegment>(f.chain.segments.at(0));
}

TEST(ChainTomlLoads, DeadFollowerAndRigidities) {
  const io::ChainFile f = io::parse_chain_file(R"(
[[segment]]
type = "flexible"
length = 1.0
q = [0.5, -2]
q_follower = 1.5
EA = 1e4
GAs = 3e3

[[segment]]
type = "flexible"
length = 1.0
q_profile = [[0, 1], [0, 0.5], [0, 0]]
)",
                                               "t.toml");
  EXPECT_EQ(first(f).qx, 0.5);
  EXPECT_EQ(first(f).qy, -2.0);
  EXPECT_EQ(first(f).q_follower, 1.5);
  EXPECT_EQ(first(f).EA, 1e4);
  EXPECT_EQ(first(f).GAs, 3e3);
  const auto& second = std::get<FlexibleSegment>(f.chain.segments.at(1));
  ASSERT_EQ(second.q_profile.size(), 3u);
  EXPECT_EQ(second.q_profile[1][1], 0.5);
  EXPECT_FALSE(second.extensible());
  // The resultant of the triangular profile: 1/2 (trapezoids exact for the linear profile).
  EXPECT_NEAR(second.q_resultant(1.0)[1], 0.5, 1e-15);
  EXPECT_NEAR(second.q_resultant(0.25)[1], 0.25 * (1.0 + 0.75) / 2.0, 1e-15);
}

TEST(ChainTomlLoads, SelfWeightAndExtensibleFromTheSection) {
  const io::ChainFile f = io::parse_chain_file(R"(
units = "SI"
[[segment]]
type = "flexible"
length = "500 mm"
E = "200 GPa"
width = "20 mm"
thickness = "0.5 mm"
density = 7850
q = ["1 N/mm", 0]
extensible = true
nu = 0.3
)",
                                               "t.toml");
  const double A = 0.02 * 0.0005;
  EXPECT_NEAR(first(f).qy, -7850.0 * A * 9.80665, 1e-15);
  EXPECT_NEAR(first(f).qx, 1000.0, 1e-12);
  EXPECT_NEAR(first(f).EA, 200e9 * A, 1e-3);
  EXPECT_NEAR(first(f).GAs, 5.0 / 6.0 * 200e9 / 2.6 * A, 1e-3);
  ASSERT_TRUE(f.segments.at(0).has_value());
  ASSERT_TRUE(f.segments[0]->cross_section_area().has_value());
  EXPECT_NEAR(*f.segments[0]->cross_section_area(), A, 1e-18);
  // g given, and a section by I and A with its own shear coefficient.
  const io::ChainFile g = io::parse_chain_file(R"(
units = "SI"
[[segment]]
type = "flexible"
length = 1
E = 70e9
I = 1e-10
A = 2e-5
density = 2700
g = 1.62
extensible = true
nu = 0.33
shear_coefficient = 0.9
)",
                                               "t.toml");
  EXPECT_NEAR(first(g).qy, -2700.0 * 2e-5 * 1.62, 1e-15);
  EXPECT_NEAR(first(g).GAs, 0.9 * 70e9 / 2.66 * 2e-5, 1e-3);
}

TEST(ChainTomlLoads, InconsistentInputIsRefused) {
  const char* bad[] = {
      // q of the wrong size
      "[[segment]]\ntype = \"flexible\"\nlength = 1\nq = [1, 2, 3]\n",
      // q and q_profile
      "[[segment]]\ntype = \"flexible\"\nlength = 1\nq = [1, 2]\nq_profile = [[0, 1], [0, 1]]\n",
      // one station
      "[[segment]]\ntype = \"flexible\"\nlength = 1\nq_profile = [[0, 1]]\n",
      // density without a section
      "[[segment]]\ntype = \"flexible\"\nlength = 1\ndensity = 7850\n",
      // extensible without nu
      "units = \"SI\"\n[[segment]]\ntype = \"flexible\"\nlength = 1\nE = 1e9\nwidth = 0.01\n"
      "thickness = 0.001\nextensible = true\n",
      // extensible and EA
      "units = \"SI\"\n[[segment]]\ntype = \"flexible\"\nlength = 1\nE = 1e9\nwidth = 0.01\n"
      "thickness = 0.001\nextensible = true\nnu = 0.3\nEA = 5\n",
      // I and A without a shear coefficient
      "units = \"SI\"\n[[segment]]\ntype = \"flexible\"\nlength = 1\nE = 1e9\nI = 1e-12\n"
      "A = 1e-5\nextensible = true\nnu = 0.3\n",
      // negative EA
      "[[segment]]\ntype = \"flexible\"\nlength = 1\nEA = -1\n",
      // nu without extensible
      "units = \"SI\"\n[[segment]]\ntype = \"flexible\"\nlength = 1\nE = 1e9\nwidth = 0.01\n"
      "thickness = 0.001\nnu = 0.3\n",
  };
  for (const char* text : bad) {
    EXPECT_THROW(io::parse_chain_file(text, "bad.toml"), InvalidInput) << text;
  }
}

}  // namespace
}  // namespace flexure
