// What is checked against what: the segment-chain description (solver/chain_model) -- validation
// messages name the segment (counted from 1, as in the TOML files) and field; a zero total length
// and a prescribed tip on a chain of rigid links are refused, a zero-length kink is not; the
// stress-free geometry of kappa0 arcs and rigid links against circle geometry by hand; proportional
// loading (at_load_factor) against its definition; end-condition names and masks against the
// issue's table.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

// Geometry is evaluated by closed form; only rounding separates the two sides.
constexpr double kGeometryTolerance = 1e-14;

std::string validation_message(const SegmentChain& chain) {
  try {
    chain.validate();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(SegmentChain, ValidationNamesSegmentAndField) {
  SegmentChain chain;
  EXPECT_NE(validation_message(chain).find("at least one segment"), std::string::npos);

  chain.segments = {FlexibleSegment{1.0, 1.0, {}, 0.0}, FlexibleSegment{-0.5, 1.0, {}, 0.0}};
  EXPECT_NE(validation_message(chain).find("segment 2 (flexible): length"), std::string::npos);

  chain.segments = {FlexibleSegment{1.0, 0.0, {}, 0.0}};
  EXPECT_NE(validation_message(chain).find("segment 1 (flexible): EI"), std::string::npos);

  chain.segments = {RigidSegment{1.0, 0.0},
                    FlexibleSegment{1.0, std::numeric_limits<double>::quiet_NaN(), {}, 0.0}};
  EXPECT_NE(validation_message(chain).find("segment 2: EI"), std::string::npos);

  chain.segments = {FlexibleSegment{1.0, 1.0, {1.0, -2.0}, 0.0}};
  EXPECT_NE(validation_message(chain).find("EI_profile[1]"), std::string::npos);

  chain.segments = {RigidSegment{-1.0, 0.0}};
  EXPECT_NE(validation_message(chain).find("segment 1 (rigid): length"), std::string::npos);

  chain.segments = {FlexibleSegment{}, FlexibleSegment{}};
  chain.node_loads = {NodeLoad{2, 1.0, 0.0, 0.0}};
  EXPECT_NE(validation_message(chain).find("node must be an intermediate joint in [1, 1]"),
            std::string::npos);
  chain.node_loads = {NodeLoad{1, 1.0, 0.0, 0.0}};
  EXPECT_EQ(validation_message(chain), "");

  chain.end = EndCondition::kPinned;
  chain.tip_load.Fx = 2.0;
  EXPECT_NE(validation_message(chain).find("tip load Fx must be 0 for a pinned end"),
            std::string::npos);
}

TEST(SegmentChain, ZeroLengthKinksAreValidButAChainOfKinksOnlyIsNot) {
  SegmentChain chain;
  // Kinks only: nothing has length, a/l = x/0 would be NaN.
  chain.segments = {RigidSegment{0.0, 0.3}};
  EXPECT_NE(validation_message(chain).find("total length is 0"), std::string::npos)
      << validation_message(chain);
  chain.segments = {RigidSegment{0.0, 0.3}, RigidSegment{0.0, -0.1}};
  EXPECT_NE(validation_message(chain).find("total length is 0"), std::string::npos);
  // Kinks at the root, in the middle and at the tip of a flexible chain: valid with every end.
  chain.segments = {RigidSegment{0.0, 0.3},
                    FlexibleSegment{0.5, 1.0, {}, 0.0},
                    RigidSegment{0.0, -0.2},
                    FlexibleSegment{0.5, 1.0, {}, 0.0},
                    RigidSegment{0.0, 0.1}};
  for (EndCondition end : {EndCondition::kFree,
                           EndCondition::kGuided,
                           EndCondition::kPinned,
                           EndCondition::kSlider,
                           EndCondition::kFixed}) {
    chain.end = end;
    EXPECT_EQ(validation_message(chain), "") << to_string(end);
  }
  // A rigid body alone: free is a rigid cantilever; a prescribed tip cannot move or is
  // statically indeterminate.
  chain.segments = {RigidSegment{1.0, 0.0}, RigidSegment{0.0, 0.5}};
  chain.end = EndCondition::kFree;
  EXPECT_EQ(validation_message(chain), "");
  for (EndCondition end : {EndCondition::kGuided,
                           EndCondition::kPinned,
                           EndCondition::kSlider,
                           EndCondition::kFixed}) {
    chain.end = end;
    EXPECT_NE(validation_message(chain).find(std::string("a ") + to_string(end) +
                                             " end needs a flexible segment"),
              std::string::npos)
        << validation_message(chain);
  }
  // Node loads are counted from 1 as well.
  chain.segments = {FlexibleSegment{}, FlexibleSegment{}};
  chain.end = EndCondition::kFree;
  chain.node_loads = {NodeLoad{1, 1.0, 0.0, 0.0}, NodeLoad{3, 1.0, 0.0, 0.0}};
  EXPECT_NE(validation_message(chain).find("node load 2: node must be"), std::string::npos)
      << validation_message(chain);
}

TEST(SegmentChain, UnloadedGeometryOfArcsAndLinks) {
  SegmentChain chain;
  const double R = 0.7, sweep = 2.0;  // arc of radius R through `sweep` radians
  chain.segments = {FlexibleSegment{R * sweep, 1.0, {}, 1.0 / R},
                    RigidSegment{0.4, 0.5},
                    RigidSegment{0.0, -0.25},
                    FlexibleSegment{0.3, 1.0, {}, 0.0}};
  const std::vector<ChainPose> nodes = chain.unloaded_nodes();
  ASSERT_EQ(nodes.size(), 5u);
  // Circle of radius R tangent to +x at the origin, centre (0, R).
  EXPECT_NEAR(nodes[1].x, R * std::sin(sweep), kGeometryTolerance);
  EXPECT_NEAR(nodes[1].y, R * (1.0 - std::cos(sweep)), kGeometryTolerance);
  EXPECT_NEAR(nodes[1].theta, sweep, kGeometryTolerance);
  const double link = sweep + 0.5;
  EXPECT_NEAR(nodes[2].x, nodes[1].x + 0.4 * std::cos(link), kGeometryTolerance);
  EXPECT_NEAR(nodes[2].y, nodes[1].y + 0.4 * std::sin(link), kGeometryTolerance);
  EXPECT_NEAR(nodes[3].x, nodes[2].x, kGeometryTolerance);  // a zero-length kink
  EXPECT_NEAR(nodes[3].theta, link - 0.25, kGeometryTolerance);
  EXPECT_NEAR(nodes[4].x, nodes[3].x + 0.3 * std::cos(link - 0.25), kGeometryTolerance);
  EXPECT_NEAR(chain.total_length(), R * sweep + 0.4 + 0.3, kGeometryTolerance);
}

TEST(SegmentChain, ProportionalLoadingScalesLoadsAndMovesPrescribedTip) {
  SegmentChain chain;
  chain.segments = {FlexibleSegment{}, FlexibleSegment{}};
  chain.node_loads = {NodeLoad{1, 1.0, 2.0, 3.0}};
  chain.tip_load = TipLoad{0.0, 0.0, 4.0, 5.0};
  chain.end = EndCondition::kPinned;
  chain.prescribed.x = 1.5;  // y left unset: stays at the unloaded value 0
  const SegmentChain half = chain.at_load_factor(0.5);
  EXPECT_DOUBLE_EQ(half.node_loads[0].Fy, 1.0);
  EXPECT_DOUBLE_EQ(half.node_loads[0].M, 1.5);
  EXPECT_DOUBLE_EQ(half.tip_load.M, 2.0);
  EXPECT_DOUBLE_EQ(half.tip_load.follower, 2.5);
  // Unloaded tip at x = 2; halfway to the prescribed x = 1.5.
  EXPECT_DOUBLE_EQ(*half.prescribed.x, 1.75);
  EXPECT_DOUBLE_EQ(*half.prescribed.y, 0.0);
}

TEST(SegmentChain, EndConditionsMatchTheIssueTable) {
  const PrescribedMask guided = prescribed_mask(EndCondition::kGuided);
  EXPECT_TRUE(guided.theta && !guided.x && !guided.y);
  const PrescribedMask pinned = prescribed_mask(EndCondition::kPinned);
  EXPECT_TRUE(pinned.x && pinned.y && !pinned.theta);
  const PrescribedMask slider = prescribed_mask(EndCondition::kSlider);
  EXPECT_TRUE(slider.y && !slider.x && !slider.theta);
  const PrescribedMask fixed = prescribed_mask(EndCondition::kFixed);
  EXPECT_TRUE(fixed.x && fixed.y && fixed.theta);
  for (const char* name : {"free", "guided", "pinned", "slider", "fixed"}) {
    EXPECT_STREQ(to_string(end_condition_from_string(name)), name);
  }
  EXPECT_THROW(end_condition_from_string("clamped"), InvalidInput);
}

TEST(SegmentChain, UniformCantileverAndEIProfile) {
  const SegmentChain c = uniform_cantilever(EndLoad::howell(1.0, 2.0, 0.5));
  ASSERT_EQ(c.segment_count(), 1);
  EXPECT_DOUBLE_EQ(c.tip_load.Fx, -2.0);
  EXPECT_DOUBLE_EQ(c.tip_load.Fy, 2.0);
  EXPECT_DOUBLE_EQ(c.tip_load.M, 0.5);
  const FlexibleSegment tapered{2.0, 1.0, {1.0, 3.0, 2.0}, 0.0};
  EXPECT_DOUBLE_EQ(tapered.EI_at(0.5), 2.0);  // linear between stations 0 and 1
  EXPECT_DOUBLE_EQ(tapered.EI_at(1.5), 2.5);
  EXPECT_DOUBLE_EQ(tapered.EI_at(3.0), 2.0);  // clamped to the far end
}

}  // namespace
}  // namespace flexure
