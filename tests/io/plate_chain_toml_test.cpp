// The chain file's plate key (docs/chain-toml.md segment.plate, docs/plate-modulus.md), read into
// the library's PhysicalChain (io/toml_files.h), checked against:
//  * what the reader must fill: each segment's SegmentProperties::plate and material nu, the
//    segment's EI as E I/(1 - nu^2) for "on" and E I for "auto" (by hand);
//  * the same chain solved from the file and built from objects with the same properties: the tip
//    angle M L/(E_eff I) of pure bending by hand (1e-8), and both answers equal;
//  * errors: plate on without nu, plate without a section, nu out of range with plate "off".
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "flexure/beam/physical_beam.h"
#include "flexure/io/toml_files.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InvalidInput thrown";
  return {};
}

constexpr const char* kTwoSegments = R"(units = "SI"
[[segment]]
type = "flexible"
length = "50 mm"
E = "200 GPa"
nu = 0.3
width = "127 mm"
thickness = "1.31 mm"
plate = "on"
[[segment]]
type = "flexible"
length = "50 mm"
E = "200 GPa"
nu = 0.3
width = "127 mm"
thickness = "1.31 mm"
plate = "auto"
[tip_load]
M = "10 N m"
)";

TEST(PlateChainToml, ReaderFillsThePhysicalChain) {
  const io::ChainFile file = io::parse_chain_file(kTwoSegments, "plate.toml");
  const double I = 0.127 * std::pow(0.00131, 3) / 12.0;
  ASSERT_EQ(file.segments.size(), 2u);
  ASSERT_TRUE(file.segments[0] && file.segments[1]);
  EXPECT_EQ(file.segments[0]->plate, PlateRule::kOn);
  EXPECT_EQ(file.segments[1]->plate, PlateRule::kAuto);
  EXPECT_EQ(file.segments[1]->material.nu, 0.3);
  EXPECT_NEAR(std::get<FlexibleSegment>(file.chain.segments[0]).EI, 200e9 / 0.91 * I, 1e-12);
  EXPECT_NEAR(std::get<FlexibleSegment>(file.chain.segments[1]).EI, 200e9 * I, 1e-12);
  EXPECT_NO_THROW(file.validate());
}

TEST(PlateChainToml, FileAndObjectsSolveAlike) {
  const io::ChainFile file = io::parse_chain_file(kTwoSegments, "plate.toml");
  const double I = 0.127 * std::pow(0.00131, 3) / 12.0;
  const PhysicalBeamSolution s = solve_physical_chain(BeamMethod::kShooting, {}, file);
  ASSERT_TRUE(s.solution.converged());
  ASSERT_EQ(s.physical.modulus.size(), 2u);
  EXPECT_TRUE(s.physical.modulus[0].plate);
  EXPECT_TRUE(s.physical.modulus[1].plate);  // beta = 26 at R = E I/M
  EXPECT_NEAR(s.solution.tip.theta0, 10.0 * 0.1 / (200e9 / 0.91 * I), 1e-8);
  PhysicalChain objects;
  objects.chain = file.chain;
  objects.segments = file.segments;
  const PhysicalBeamSolution o = solve_physical_chain(BeamMethod::kShooting, {}, objects);
  ASSERT_TRUE(o.solution.converged());
  EXPECT_EQ(o.solution.tip.theta0, s.solution.tip.theta0);
  EXPECT_EQ(o.physical.max_moment, s.physical.max_moment);
}

TEST(PlateChainToml, ClearErrors) {
  const std::string head = "units = \"SI\"\n[[segment]]\ntype = \"flexible\"\nlength = \"50 mm\"\n";
  EXPECT_NE(message_of([&] {
              io::parse_chain_file(
                  head +
                      "E = \"200 GPa\"\nwidth = \"127 mm\"\nthickness = \"1.31 mm\"\nplate = "
                      "\"on\"\n",
                  "t.toml");
            }).find("segment 1: plate = on needs Poisson's ratio nu"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              io::parse_chain_file(head + "EI = 1.0\nplate = \"on\"\nnu = 0.3\n", "t.toml");
            }).find("plate need the section"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              io::parse_chain_file(
                  head +
                      "E = \"200 GPa\"\nwidth = \"127 mm\"\nthickness = \"1.31 mm\"\nplate = "
                      "\"off\"\nnu = 0.7\n",
                  "t.toml");
            }).find("segment 1.nu must be in (-1, 0.5)"),
            std::string::npos);
}

}  // namespace
}  // namespace flexure
