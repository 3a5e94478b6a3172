// What is checked against what: the segment state of a solved exact point taken from one
// integration of its solution (exact_segment_state(design, point), what `mechanism analyze`
// reports) against the independent sampled-shape evaluation (the shape re-solved and sampled at
// 16001 equally spaced arc lengths) and the Richardson-extrapolated energy (exact_strain_energy),
// on one built-in design per exact-model topology plus 3A-lssm (strips 0.045 mm against 0.53 mm):
//   * strain energy: within 1e-7 relative of exact_strain_energy (measured <= 1.3e-8; the
//     quadrature of the sampled rule has that accuracy, docs/mechanisms.md);
//   * max stress per pivot: within 2e-5 relative of the 16001-sample maximum, whose own sampling
//     error is O(ds^2) (measured <= 3.5e-6, on 3A-lssm);
//   * rotations: the fixed-fixed serial chains (3A) return to theta = 0 at the slider clamp with
//     rigid links in between, so the pivot rotations sum to zero (closed form): 1e-9 rad.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/gsl_guard.h"

namespace flexure::mechanism {
namespace {

constexpr double kEnergyTolerance = 1e-7;    // relative
constexpr double kStressTolerance = 2e-5;    // relative
constexpr double kRotationTolerance = 1e-9;  // rad

class ExactSegments : public ::testing::TestWithParam<std::string> {};

TEST_P(ExactSegments, FromTheSolutionAgreeWithTheSampledShape) {
  disable_gsl_abort();
  const MechanismDesign d = find_builtin_mechanism(GetParam());
  const ExactStrokeResult r = exact_stroke(d, stroke_displacements(d, 10));
  ASSERT_TRUE(r.converged()) << r.message;
  for (std::size_t k : {std::size_t{0}, std::size_t{9}}) {
    const ExactPoint& p = r.points[k];
    const ExactSegmentState fast = exact_segment_state(d, p);
    const ExactSegmentState sampled = exact_segment_state(d, p, 16001);
    const double U = exact_strain_energy(d, p);
    EXPECT_NEAR(fast.strain_energy / U, 1.0, kEnergyTolerance) << "point " << k;
    double rotation_sum = 0.0;
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(fast.has_pivot[i], sampled.has_pivot[i]) << "pivot " << i + 1;
      if (!fast.has_pivot[i]) continue;
      EXPECT_NEAR(fast.max_stress[i] / sampled.max_stress[i], 1.0, kStressTolerance)
          << "point " << k << ", pivot " << i + 1;
      EXPECT_GT(fast.pivot_strain_energy[i], 0.0);
      rotation_sum += fast.pivot_rotation[i];
    }
    if (d.name.rfind("3A-", 0) == 0) {  // class 3A: flexures at all three pivots
      EXPECT_NEAR(rotation_sum, 0.0, kRotationTolerance) << "point " << k;
    }
  }
}

// Two-force coupler, pins at both ends, serial chain, middle pin; then the thin-strip 3A-lssm and
// the all-long 3A-lllm (serial, fixed-fixed).
INSTANTIATE_TEST_SUITE_P(
    Topologies,
    ExactSegments,
    ::testing::Values("1A-lpp", "1B-plp", "2A-ssp", "2B-lps", "3A-sss", "3A-lssm", "3A-lllm"),
    [](const ::testing::TestParamInfo<std::string>& info) {
      std::string name = info.param;
      for (char& c : name) {
        if (c == '-') c = '_';
      }
      return name;
    });

}  // namespace
}  // namespace flexure::mechanism
