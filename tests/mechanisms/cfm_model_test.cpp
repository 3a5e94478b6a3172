// What is checked against what:
//  * eq. 2.14 with the principal-angle spring rotations equals the printed eq. 2.14 evaluated
//    literally with theta3 measured in (3 pi/2, 2 pi] (the thesis code's convention), and equals
//    the derivative of the spring energy (virtual work, central differences) for every
//    configuration;
//  * the mirror identity of Howell §10.1 (r2 <-> r3, k1 <-> k3): Phi(1/R, ..)= Phi(R, ..) R/K2;
//  * the Delta x -> 0 limit of class 1A, Phi -> R/(1+R) (limit of Howell eq. 10.14);
//  * the toggle clamp: 37.04 % (R = 0.4323) and 26.62 % (R = 0.3000) (docs/cfm.md §1.3),
//    and at the clamp the coupler (R < 1) or the crank (R > 1) is perpendicular to the slider axis;
//  * lambda against the Table 5.1 closed forms; kinematics against the law of cosines;
//  * bad input is refused with InvalidInput;
//  * the result's warnings: a class 1A mechanism clamped at its toggle has a force that vanishes
//    there (the derivative of its spring energy is zero at the toggle, central differences), and
//    is flagged and warned; a clamped stroke whose force stays positive (K1 > 0) is warned as
//    clamped only; an unclamped lpp-b neither.
#include "flexure/mechanisms/cfm/cfm_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/solver/common/status.h"

namespace flexure::cfm {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRoundoff = 1e-12;         // closed-form identities, a few ulps of O(1) terms
constexpr double kFiniteDifference = 1e-7;  // central difference, h = 1e-5 in u: O(h^2)
constexpr double kToggleRounding = 0.005;   // toggle strokes given to 2 decimals
constexpr double kTable51Rounding = 1e-12;  // closed forms evaluated two ways

// Printed thesis eq. 2.14 / 2.19 taken literally, theta3 in (3 pi/2, 2 pi] (thesis code:
// `theta3 = 2*pi + asin(...)`).
double printed_equation_2_14(double R, double K1, double K2, bool class_1B, double u) {
  const double r1 = (1.0 + R) * (1.0 - u);
  const double theta2 = std::acos((r1 * r1 + 1.0 - R * R) / (2.0 * r1));
  const double theta3 = 2.0 * kPi + std::asin(-std::sin(theta2) / R);
  const double ground = class_1B ? 0.0 : theta2;
  return (R * std::cos(theta3) * (ground + K1 * (2.0 * kPi + theta2 - theta3)) +
          std::cos(theta2) * (K1 * (2.0 * kPi + theta2 - theta3) + K2 * (2.0 * kPi - theta3))) /
         (R * std::sin(theta2 - theta3));
}

// Spring energy V r2^0/k1 = (psi1^2 + K1 psi2^2 + K2 psi3^2)/2; with Delta x = u (1 + R) r2 the
// virtual-work force is Phi = dV/du/(1 + R). Angles from the law of cosines, independently of
// slider_crank_pose.
double spring_energy(double R, double K1, double K2, bool class_1B, double u) {
  const double r1 = (1.0 + R) * (1.0 - u);
  const double theta2 = std::acos((r1 * r1 + 1.0 - R * R) / (2.0 * r1));
  const double theta3 = std::asin(-std::sin(theta2) / R);
  const double psi1 = theta2, psi2 = theta2 - theta3, psi3 = -theta3;
  return 0.5 * ((class_1B ? 0.0 : psi1 * psi1) + K1 * psi2 * psi2 + K2 * psi3 * psi3);
}

TEST(CfmSliderCrank, PrincipalAngleFormEqualsPrintedTwoPiForm) {
  for (double R : {0.3, 0.8274, 1.0, 2.6633}) {
    for (double u : {0.01, 0.1, 0.2}) {
      if (u * 100.0 >= toggle_stroke_percent(R)) continue;
      const SliderCrankPose pose = slider_crank_pose(R, u);
      EXPECT_NEAR(force_function_phi(R, 0.7, 3.0, false, pose),
                  printed_equation_2_14(R, 0.7, 3.0, false, u),
                  1e-9)
          << "R = " << R << ", u = " << u;
      EXPECT_NEAR(force_function_phi(R, 1.0, 0.0, true, pose),
                  printed_equation_2_14(R, 1.0, 0.0, true, u),
                  1e-9)
          << "1B, R = " << R << ", u = " << u;
    }
  }
}

TEST(CfmSliderCrank, ForceIsTheDerivativeOfTheSpringEnergy) {
  const double h = 1e-5;
  for (const CfmConfiguration& c : cfm_configurations()) {
    const bool class_1B = c.is_class_1B();
    const double K1 = class_1B ? 1.0 : (c.has_spring(2) ? 0.4 : 0.0);
    const double K2 = c.has_spring(3) ? 2.5 : 0.0;
    for (double R : {0.5, 1.7}) {
      for (double u : {0.05, 0.15, 0.25}) {
        const double dV = (spring_energy(R, K1, K2, class_1B, u + h) -
                           spring_energy(R, K1, K2, class_1B, u - h)) /
                          (2.0 * h);
        const double phi = force_function_phi(R, K1, K2, class_1B, slider_crank_pose(R, u));
        EXPECT_NEAR(phi, dV / (1.0 + R), kFiniteDifference * std::max(1.0, std::abs(phi)))
            << c.name << " R = " << R << " u = " << u;
      }
    }
  }
}

TEST(CfmSliderCrank, MirrorInversionSwapsLinksAndEndSprings) {
  // Howell §10.1: the right-hand column is the left with r2 <-> r3 and k1 <-> k3. The force
  // between ground and slider is the same: (k1/r2) Phi(R, K1, K2) = (k3/r3) Phi(1/R, K1/K2, 1/K2).
  for (double R : {0.4, 0.7591, 2.0821}) {
    for (double u : {0.02, 0.1, 0.2}) {
      const double K1 = 0.6, K2 = 3.2;
      const double phi = force_function_phi(R, K1, K2, false, slider_crank_pose(R, u));
      const double mirrored =
          force_function_phi(1.0 / R, K1 / K2, 1.0 / K2, false, slider_crank_pose(1.0 / R, u));
      EXPECT_NEAR(mirrored, phi * R / K2, kRoundoff * 100.0) << "R = " << R << " u = " << u;
    }
    // Both toggle rules describe the same mechanism seen from either end.
    EXPECT_NEAR(toggle_stroke_percent(R), toggle_stroke_percent(1.0 / R), 1e-10);
  }
}

TEST(CfmSliderCrank, Class1AForceTendsToRover1PlusRAtZeroDeflection) {
  for (double R : {0.5, 0.8274, 1.9}) {
    const double phi = force_function_phi(R, 0.0, 0.0, false, slider_crank_pose(R, 1e-9));
    EXPECT_NEAR(phi, R / (1.0 + R), 1e-6) << "R = " << R;  // O(sqrt(u)) approach
  }
}

TEST(CfmSliderCrank, KinematicsSatisfyLawOfCosinesAndLoopClosure) {
  for (double R : {0.3, 1.0, 2.5}) {
    for (double u : {1e-6, 0.01, 0.1, 0.2}) {
      const SliderCrankPose pose = slider_crank_pose(R, u);
      const double r1 = (1.0 + R) * (1.0 - u);
      // Law of cosines for the triangle r1, r2 = 1, r3 = R (eq. 2.1).
      EXPECT_NEAR(R * R, r1 * r1 + 1.0 - 2.0 * r1 * std::cos(pose.theta2), 1e-13);
      EXPECT_LT(loop_closure_residual(R, pose), 1e-13);
      EXPECT_LE(pose.theta3, 0.0);
    }
  }
}

TEST(CfmToggle, ClampValuesOfTheThesis) {
  EXPECT_NEAR(toggle_stroke_percent(0.4323), 37.04, kToggleRounding);  // original 2A-b
  EXPECT_NEAR(toggle_stroke_percent(0.3000), 26.62, kToggleRounding);  // ssp-b94I
  EXPECT_EQ(toggle_stroke_percent(1.0), 100.0);
  const CfmResult r = CfmModel().evaluate({"ssp", 0.4323, 0.2237, std::nullopt, 40.0});
  EXPECT_TRUE(r.stroke_clamped);
  EXPECT_NEAR(r.stroke_percent, 37.04, kToggleRounding);
  EXPECT_EQ(r.requested_stroke_percent, 40.0);
}

TEST(CfmToggle, AtTheClampTheCouplerOrCrankIsPerpendicularToTheSliderAxis) {
  for (double R : {0.3, 0.4323, 0.9}) {  // coupler perpendicular: theta3 = -90 deg
    const SliderCrankPose pose = slider_crank_pose(R, toggle_stroke_percent(R) / 100.0);
    EXPECT_NEAR(pose.theta3, -kPi / 2.0, 1e-6) << "R = " << R;
  }
  for (double R : {1.5, 3.0}) {  // crank perpendicular: theta2 = 90 deg (thesis code, R > 1)
    const SliderCrankPose pose = slider_crank_pose(R, toggle_stroke_percent(R) / 100.0);
    EXPECT_NEAR(pose.theta2, kPi / 2.0, 1e-12) << "R = " << R;
  }
}

TEST(CfmModel, LambdaMatchesTable5_1ClosedForms) {
  const double g = 0.85;
  for (double R : {0.4, 0.8274, 2.1623}) {
    auto lambda = [R](const char* name) {
      return length_parameter_lambda(find_cfm_configuration(name), R);
    };
    EXPECT_NEAR(lambda("spp"), (R + 1.05) / (R + 1.0), kTable51Rounding);
    EXPECT_NEAR(lambda("lpp"), (R * g + 1.0) / (g * (R + 1.0)), kTable51Rounding);
    EXPECT_NEAR(lambda("psp"), 1.0, kTable51Rounding);
    EXPECT_NEAR(lambda("plp"), (R * g + 1.0) / (g * (R + 1.0)), kTable51Rounding);
    EXPECT_NEAR(lambda("ssp"), (R + 1.05) / (R + 1.0), kTable51Rounding);
    EXPECT_NEAR(lambda("slp"), (R + 1.05 * g) / (g * (R + 1.0)), kTable51Rounding);
    EXPECT_NEAR(lambda("sps"), 1.05, kTable51Rounding);
    EXPECT_NEAR(lambda("lps"), (1.05 * R * g + 1.0) / (g * (R + 1.0)), kTable51Rounding);
    EXPECT_NEAR(lambda("sss"), 1.05, kTable51Rounding);
  }
}

TEST(CfmModel, UniformSamplingUsesTheRequestedPointsAndReportsLoopClosure) {
  CfmOptions options;
  options.sampling = StrokeSampling::kUniform;
  options.points = 50;
  options.keep_curve = true;
  const CfmResult r = CfmModel(options).evaluate({"lpp", 0.8853, std::nullopt, std::nullopt, 40});
  ASSERT_EQ(r.curve.size(), 50u);
  EXPECT_EQ(r.iterations, 50);
  EXPECT_NEAR(r.curve.front().stroke_percent, 0.8, 1e-12);
  EXPECT_NEAR(r.curve.back().stroke_percent, 40.0, 1e-12);
  EXPECT_LT(r.residual, 1e-13);
  EXPECT_TRUE(r.converged());
}

TEST(CfmModel, RefusesBadInput) {
  const CfmModel model;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::optional<double> none;
  EXPECT_THROW(model.evaluate({"lpx", 0.8, none, none, 16}), InvalidInput);  // unknown config
  // Names match in any case: "LPP" is lpp.
  EXPECT_EQ(model.evaluate({"LPP", 0.8, none, none, 16}).Phi,
            model.evaluate({"lpp", 0.8, none, none, 16}).Phi);
  EXPECT_THROW(model.evaluate({"lpp", 0.0, none, none, 16}), InvalidInput);  // R <= 0
  EXPECT_THROW(model.evaluate({"lpp", -1.0, none, none, 16}), InvalidInput);
  EXPECT_THROW(model.evaluate({"lpp", nan, none, none, 16}), InvalidInput);
  EXPECT_THROW(model.evaluate({"lpp", 0.8, none, none, nan}), InvalidInput);
  EXPECT_THROW(model.evaluate({"lpp", 0.8, none, none, 0.0}), InvalidInput);   // d outside
  EXPECT_THROW(model.evaluate({"lpp", 0.8, none, none, -5.0}), InvalidInput);  // (0, 100]
  EXPECT_THROW(model.evaluate({"lpp", 0.8, none, none, 100.5}), InvalidInput);
  EXPECT_THROW(model.evaluate({"psp", 1.0, none, none, 100.0}), InvalidInput);  // folded flat
  EXPECT_THROW(model.evaluate({"ssp", 0.4, none, none, 16}), InvalidInput);     // K1 missing
  EXPECT_THROW(model.evaluate({"ssp", 0.4, -0.1, none, 16}), InvalidInput);     // K1 < 0
  EXPECT_THROW(model.evaluate({"ssp", 0.4, nan, none, 16}), InvalidInput);
  EXPECT_THROW(model.evaluate({"lpp", 0.8, 0.5, none, 16}), InvalidInput);   // no spring 2
  EXPECT_THROW(model.evaluate({"sps", 0.8, none, none, 16}), InvalidInput);  // K2 missing
  EXPECT_THROW(model.evaluate({"psp", 1.0, 2.0, none, 16}), InvalidInput);   // 1B: K1 = 1
  CfmOptions bad_points;
  bad_points.sampling = StrokeSampling::kUniform;
  bad_points.points = 0;
  EXPECT_THROW(CfmModel{bad_points}, InvalidInput);
  // Accepted: a zero ratio for a missing spring, K1 = 1 for class 1B, d = 100 below the toggle
  // is clamped rather than refused.
  EXPECT_NO_THROW(model.evaluate({"lpp", 0.8, 0.0, 0.0, 16}));
  EXPECT_NO_THROW(model.evaluate({"psp", 1.0, 1.0, none, 16}));
  EXPECT_TRUE(model.evaluate({"lpp", 0.8, none, none, 100}).stroke_clamped);
}

// Class 1A (lpp, k1 only) driven past its toggle at R = 0.3 is clamped at 26.62 %, where the
// coupler stands perpendicular to the slider: theta2 is stationary in Delta x, so the force
// dV/du/(1 + R) of the spring energy V = theta2^2/2 is zero there.
TEST(CfmModel, ForceVanishingAtTheToggleIsFlaggedAndWarned) {
  const std::optional<double> none;
  const CfmResult r = CfmModel().evaluate({"lpp", 0.3, none, none, 60});
  ASSERT_TRUE(r.converged());
  ASSERT_TRUE(r.stroke_clamped);
  EXPECT_NEAR(r.stroke_percent, 26.62, kToggleRounding);
  // The independent zero: the derivative of the spring energy at the clamped stroke.
  const double u = r.stroke_percent / 100.0, h = 1e-5;
  const double force =
      (spring_energy(0.3, 0.0, 0.0, false, u + h) - spring_energy(0.3, 0.0, 0.0, false, u - h)) /
      (2.0 * h) / 1.3;
  EXPECT_NEAR(force, 0.0, kFiniteDifference);
  EXPECT_NEAR(r.Phi_min, 0.0, kFiniteDifference);
  EXPECT_TRUE(r.force_vanishes);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(r.warnings[0].kind, WarningKind::kForceVanishes);
  EXPECT_NE(r.warnings[0].text.find("the force vanishes within the stroke"), std::string::npos)
      << r.warnings[0].text;
  EXPECT_EQ(r.warnings[1].kind, WarningKind::kStrokeClamped);
  EXPECT_NE(r.warnings[1].text.find("d = 60 % is past the toggle position of R = 0.3; clamped to "
                                    "26.62"),
            std::string::npos)
      << r.warnings[1].text;
  EXPECT_EQ(warning_kind_name(r.warnings[0].kind), "force_vanishes");

  // Clamped (thesis ssp-bIo, 37.04 %) but the middle spring keeps the force positive at the toggle.
  const CfmResult ssp = CfmModel().evaluate({"ssp", 0.4323, 0.2237, none, 40});
  ASSERT_TRUE(ssp.stroke_clamped);
  EXPECT_FALSE(ssp.force_vanishes);
  EXPECT_GT(ssp.Phi_min, 0.1 * ssp.Phi_max);
  ASSERT_EQ(ssp.warnings.size(), 1u);
  EXPECT_EQ(ssp.warnings[0].kind, WarningKind::kStrokeClamped);

  // lpp-b at its design stroke (thesis Table 7.2): within the toggle, force of one sign.
  const CfmResult lpp_b = CfmModel().evaluate({"lpp", 0.8853, none, none, 40});
  EXPECT_FALSE(lpp_b.stroke_clamped);
  EXPECT_FALSE(lpp_b.force_vanishes);
  EXPECT_TRUE(lpp_b.warnings.empty());
}

}  // namespace
}  // namespace flexure::cfm
