// What is checked against what:
//  * the dimensional PRBM force (virtual work, thesis eq. 2.14 scaled by eq. 2.13) against the
//    derivative of the spring energy that the test computes itself (its own slider-crank
//    kinematics, a finite difference), and against the library's statics of the two PRB links;
//  * the built-in sub-class designs against the thesis's nondimensional model (CfmModel, 50 equally
//    spaced points): mean F r2/k_ref = Phi and the spring ratios K1, K2 of the sub-class;
//  * the thesis design example 1 (1A-lpp, Weight 2001 Table 8.4): required force F = 25 lbf;
//  * bad input (unknown names, negative sizes, strokes past the toggle position) and the TOML
//    loader's messages (key and line).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm/constant_force.h"
#include "flexure/mechanisms/cfm_comparison.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

// Closed forms in double precision, different algebra: rounding only.
constexpr double kClosedForm = 1e-10;

// The spring energy of the PRB slider-crank at slider displacement dx, from the test's own
// kinematics: r1 = r2 + r3 - dx, the crank angle from the law of cosines in its cancellation-free
// form 1 - cos theta2 = dx (r1 + r3 - r2)/(2 r2 r1), the coupler at theta3 = -asin(r2 sin theta2
// / r3), springs turned by psi1 = theta2, psi2 = theta2 - theta3, psi3 = -theta3 (thesis eqs.
// 2.8-2.12; zero in the straight position).
double spring_energy(const MechanismDesign& d, double dx) {
  const double r1 = d.r2 + d.r3 - dx;
  const double theta2 = 2.0 * std::asin(std::sqrt(dx * (r1 + d.r3 - d.r2) / (4.0 * d.r2 * r1)));
  const double theta3 = -std::asin(d.r2 * std::sin(theta2) / d.r3);
  const double psi[3] = {theta2, theta2 - theta3, -theta3};
  double V = 0.0;
  for (int p = 1; p <= 3; ++p) V += 0.5 * d.spring_constant(p) * psi[p - 1] * psi[p - 1];
  return V;
}

TEST(MechanismPrbm, ForceIsTheDerivativeOfTheSpringEnergy) {
  // Virtual work done by the test: F = dV/d(dx) by a fourth-order central difference of the
  // energy above (step 1e-3 dx: truncation ~1e-12, rounding ~1e-13 relative), independent of the
  // library's closed-form derivative (thesis eq. 2.14) and of its link statics. Inversions (the
  // slider block fixed, inversion.h) have their own tests.
  constexpr double kDifferenceTolerance = 1e-8;
  int designs = 0;
  for (const MechanismDesign& d : builtin_mechanisms()) {
    if (d.inverted) continue;
    const PrbmStrokeResult r = prbm_stroke(d, 50);
    ASSERT_TRUE(r.converged()) << d.name;
    EXPECT_LT(r.residual, kClosedForm) << d.name;  // the library's two routes agree
    for (std::size_t i = 0; i < r.displacement.size(); ++i) {
      const double x = r.displacement[i], h = 1e-3 * x;
      const double dV = (spring_energy(d, x - 2 * h) - 8 * spring_energy(d, x - h) +
                         8 * spring_energy(d, x + h) - spring_energy(d, x + 2 * h)) /
                        (12 * h);
      EXPECT_NEAR(r.force[i], dV, kDifferenceTolerance * std::abs(dV))
          << d.name << " at dx = " << x << " m";
    }
    ++designs;
  }
  EXPECT_GE(designs, 20);
}

TEST(MechanismPrbm, SubclassDesignsReproduceTheNondimensionalModel) {
  for (const MechanismDesign& d : builtin_mechanisms()) {
    if (d.name == "1A-lpp") continue;       // the thesis example, checked below
    if (!d.paper_config.empty()) continue;  // paper 004 designs: mechanism_modified_test.cpp
    const auto& cfg = d.configuration();
    const cfm::CfmSubclass& row = cfm::find_thesis_subclass(d.config + "-a");
    const double k_ref = d.spring_constant(cfg.is_class_1B() ? 2 : 1);
    if (!cfg.is_class_1B() && cfg.has_spring(2)) {
      EXPECT_NEAR(d.spring_constant(2) / k_ref, row.K1, kClosedForm) << d.name;
    }
    if (cfg.has_spring(3)) EXPECT_NEAR(d.spring_constant(3) / k_ref, row.K2, kClosedForm);
    cfm::CfmOptions o;
    o.sampling = cfm::StrokeSampling::kUniform;
    o.points = 50;
    cfm::CfmParameters p = cfm::parameters_of(row);
    p.stroke_percent = 100.0 * d.stroke / (d.r2 + d.r3);
    const cfm::CfmResult ref = cfm::CfmModel(o).evaluate(p);
    const PrbmStrokeResult r = prbm_stroke(d, 50);
    EXPECT_NEAR(r.mean_force * d.r2 / k_ref, ref.Phi, kClosedForm * ref.Phi) << d.name;
    EXPECT_NEAR(r.percent_constant_force, ref.percent_constant_force, 1e-8) << d.name;
  }
}

TEST(MechanismPrbm, ThesisDesignExampleDeliversTwentyFivePounds) {
  // Table 8.4: F = 25 lbf. The thesis sized h with lambda = 1.097 (lpp-a's value) and rounded h to
  // 0.04865 in; lpp-b's own lambda is 1.094, so F moves by (1.094/1.097)^2 ~ 0.5 %: 1 % tolerance.
  const MechanismDesign d = find_builtin_mechanism("1A-lpp");
  const PrbmStrokeResult r = prbm_stroke(d, 50);
  const double lbf = 4.4482216152605;
  EXPECT_NEAR(r.mean_force / lbf, 25.0, 0.25);
}

// A stroke of exactly the toggle position is allowed; its last point must not round past it
// ((stroke*K)/K was one ulp above the stroke for 1B-plpm, and the exact model refused it).
TEST(MechanismPrbm, LastStrokePointIsTheStrokeItself) {
  for (const MechanismDesign& original : builtin_mechanisms()) {
    MechanismDesign d = original;
    d.stroke = d.toggle_stroke();
    for (int points : {7, 49, 50, 51}) {
      const std::vector<double> dx = stroke_displacements(d, points);
      EXPECT_EQ(dx.back(), d.stroke) << d.name << " " << points;
      EXPECT_LE(dx.back(), d.toggle_stroke()) << d.name << " " << points;
    }
  }
}

TEST(MechanismPrbm, BadInputIsRefused) {
  EXPECT_THROW(find_builtin_mechanism("4Z-xyz"), InvalidInput);
  MechanismDesign d = find_builtin_mechanism("3A-sss");
  d.joints[1].thickness = -1e-4;
  EXPECT_THROW(d.finalise(), InvalidInput);
  d = find_builtin_mechanism("3A-sss");
  d.r3 = -0.01;
  EXPECT_THROW(d.finalise(), InvalidInput);
  d = find_builtin_mechanism("1A-lpp");
  d.stroke = 1.01 * d.toggle_stroke();
  try {
    d.finalise();
    FAIL() << "a stroke past the toggle position was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("toggle"), std::string::npos) << e.what();
  }
  // R = 1 (1B-psp): the toggle is r2 + r3 itself, folded flat with a PRBM force of 0/0. It was
  // accepted and gave a force curve one point short and a percent constant force of 0.
  d = find_builtin_mechanism("1B-psp");
  ASSERT_EQ(d.R(), 1.0);
  d.stroke = d.r2 + d.r3;
  try {
    d.finalise();
    FAIL() << "a stroke folding an R = 1 design flat was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("0/0"), std::string::npos) << e.what();
  }
  d.stroke = 0.999 * (d.r2 + d.r3);
  EXPECT_NO_THROW(d.finalise());
}

// Slender-beam limits (SlenderBeamLimits, docs/mechanisms.md "Geometry limits") at their
// boundaries, on the sss example: each rule accepts the limit itself and refuses just past it,
// naming the segment and the ratio. The ratios are recomputed here from the design's numbers.
std::string refusal(MechanismDesign d) {
  try {
    d.finalise();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(MechanismPrbm, GeometryOutsideSlenderBeamTheoryIsRefused) {
  const MechanismDesign sss =
      load_mechanism_toml(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/mechanism_sss.toml");
  // thickness/length <= 0.5 (ground flexure 2.73 mm long).
  MechanismDesign d = sss;
  d.joints[0].thickness = 0.5 * d.joints[0].length;
  EXPECT_EQ(refusal(d), "");
  d.joints[0].thickness *= 1.01;
  std::string why = refusal(d);
  EXPECT_NE(why.find("ground pivot 1 segment [ground]: thickness/length = 0.505"),
            std::string::npos)
      << why;
  // width >= thickness (slider flexure 0.3177 mm thick).
  d = sss;
  d.joints[2].width = d.joints[2].thickness;
  EXPECT_EQ(refusal(d), "");
  d.joints[2].width *= 0.99;
  why = refusal(d);
  EXPECT_NE(why.find("slider pivot 3 segment [slider]: width/thickness = 0.99"), std::string::npos)
      << why;
  // |P| L^2/EI <= 1e3: a thin ground strip carries the pin force the stiff middle and slider
  // flexures set, P nearly independent of its own thickness (k1 << k2, k3), so alpha^2 ~ 1/h^3.
  // Find the printed alpha^2 at h = 5 um, check it against P L^2/(E b h^3/12) from the printed P,
  // and that 0.95 and 1.05 times the predicted limiting thickness fall on either side.
  d = sss;
  d.joints[0].thickness = 5e-6;
  why = refusal(d);
  const auto number_after = [&](const std::string& key) {
    const std::size_t at = why.find(key);
    EXPECT_NE(at, std::string::npos) << key << " in " << why;
    return at == std::string::npos ? 0.0 : std::stod(why.substr(at + key.size()));
  };
  const double alpha2 = number_after("load parameter |P| L^2/(EI) = ");
  const double P = number_after("largest PRBM pin force ");
  const double EI = d.material.E * d.joints[0].width * std::pow(5e-6, 3) / 12.0;
  EXPECT_NEAR(alpha2, P * std::pow(d.joints[0].length, 2) / EI, 1e-3 * alpha2);
  EXPECT_NE(why.find("ground pivot 1 segment [ground]"), std::string::npos) << why;
  const double h_limit = 5e-6 * std::cbrt(alpha2 / SlenderBeamLimits::kMaxLoadParameter);
  d.joints[0].thickness = 1.05 * h_limit;
  EXPECT_EQ(refusal(d), "");
  d.joints[0].thickness = 0.95 * h_limit;
  EXPECT_NE(refusal(d).find("load parameter"), std::string::npos);
  // |P|/(EA) <= 0.05: a 10 um, 0.3 mm ground flexure against a 2 mm thick slider flexure
  // (alpha^2 within its limit, h/L = 0.033; only the axial strain is out of range).
  d = sss;
  d.joints[0].thickness = 10e-6;
  d.joints[0].length = 0.3e-3;
  d.joints[2].thickness = 2e-3;
  d.joints[2].length = 4e-3;
  why = refusal(d);
  const double strain = number_after("axial strain |P|/(EA) = ");
  EXPECT_NEAR(strain,
              number_after("largest PRBM pin force ") / (d.material.E * d.joints[0].width * 10e-6),
              1e-3 * strain);
  EXPECT_GT(strain, SlenderBeamLimits::kMaxAxialStrain);
  // Every built-in design, Howell design and thesis sub-class lies inside all four limits.
  for (const MechanismDesign& b : builtin_mechanisms()) EXPECT_EQ(refusal(b), "") << b.name;
  for (const MechanismDesign& b : howell_mechanisms()) EXPECT_EQ(refusal(b), "") << b.name;
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    EXPECT_NO_THROW(find_builtin_mechanism(row.name)) << row.name;
  }
}

// Percent constant force (thesis eq. 5.22, 100 min/max) on hand-made curves: a force of one sign
// gives the ratio of its extreme magnitudes; a force that reaches zero or changes sign is flagged
// and reported as 0 (it was -5.45 % for a force changing sign, issue 11).
TEST(ConstantForce, PercentOnlyForAForceOfOneSign) {
  ConstantForceMeasure m = constant_force_measure({2.0, 1.0, 4.0});
  EXPECT_EQ(m.percent, 25.0);
  EXPECT_FALSE(m.vanishes);
  EXPECT_FALSE(m.changes_sign);
  m = constant_force_measure({-2.0, -4.0});  // pulling throughout: as constant as its mirror
  EXPECT_EQ(m.percent, 50.0);
  EXPECT_FALSE(m.vanishes);
  m = constant_force_measure({0.43, 0.2, -0.0234});
  EXPECT_EQ(m.percent, 0.0);
  EXPECT_TRUE(m.vanishes);
  EXPECT_TRUE(m.changes_sign);
  EXPECT_EQ(m.min_force, -0.0234);
  EXPECT_EQ(m.max_force, 0.43);
  m = constant_force_measure({1.0, 0.5, 1e-12});  // zero to rounding (cfm's force_vanishes)
  EXPECT_EQ(m.percent, 0.0);
  EXPECT_TRUE(m.vanishes);
  EXPECT_FALSE(m.changes_sign);
  m = constant_force_measure({1.0, 1e-8});  // small but real: 1e-6 %
  EXPECT_FALSE(m.vanishes);
  EXPECT_NEAR(m.percent, 1e-6, 1e-20);
  m = constant_force_measure({0.0, 0.0});
  EXPECT_TRUE(m.vanishes);
  EXPECT_EQ(m.percent, 0.0);
  EXPECT_THROW(constant_force_measure({}), InvalidInput);
}

TEST(MechanismToml, ExampleFileLoads) {
  const MechanismDesign d =
      load_mechanism_toml(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/mechanism_sss.toml");
  EXPECT_EQ(d.config, "sss");
  EXPECT_DOUBLE_EQ(d.joints[0].length, 2.73e-3);         // given
  EXPECT_NEAR(d.joints[1].length, 0.1 * 0.05, 1e-15);    // default 0.1 r_ave
  EXPECT_NEAR(d.joints[2].length, 0.1 * 0.0727, 1e-15);  // default 0.1 r3
  EXPECT_DOUBLE_EQ(d.material.E, 207e9);
}

void expect_error(const std::string& text, const std::string& needle) {
  try {
    parse_mechanism_toml(text, "t.toml");
    FAIL() << "accepted: " << text;
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(MechanismToml, ErrorsNameKeyAndLine) {
  const std::string head =
      "config = \"lpp\"\nr2 = 0.05\nr3 = 0.04\nstroke = 0.01\n[material]\nE = 1e9\n"
      "yield_strength = 3e7\n";
  expect_error(head + "[ground]\nthickness = -1e-3\nwidth = 0.01\n", "t.toml:9: ground.thickness");
  expect_error(head + "[ground]\nthickness = 1e-3\nwidht = 0.01\n",
               "t.toml:10: unknown key 'widht'");
  expect_error(head + "[ground]\nthickness = 1e-3\nwidth = 0.01\n[middle]\nthickness = 1e-3\n",
               "t.toml:11: [middle]");
  expect_error("config = \"xyz\"\n", "t.toml:1: config");
  expect_error(head + "[ground]\nthickness = 1e-3\nwidth = 0.01\nlength = 0.1\n",
               "t.toml:11: unknown key 'length'");
  std::string far = head;
  far.replace(far.find("stroke = 0.01"), 13, "stroke = 0.08");
  expect_error(far + "[ground]\nthickness = 1e-3\nwidth = 0.01\n", "toggle");
  // Optional strings of another type were silently replaced by their defaults.
  const std::string ground = "[ground]\nthickness = 1e-3\nwidth = 0.01\n";
  expect_error("name = 5\n" + head + ground, "t.toml:1: name must be a string");
  expect_error("note = true\n" + head + ground, "t.toml:1: note must be a string");
  std::string material = head;
  material.replace(material.find("E = 1e9"), 7, "E = 1e9\nname = 7");
  expect_error(material + ground, "t.toml:7: material.name must be a string");
  // Each value finite and > 0, but h^3 underflows: E b h^3/12 = 0, the PRBM force would be 0/0
  // (it exited 3, "PRBM force not finite", for what is an input error).
  expect_error(head + "[ground]\nthickness = 1e-200\nwidth = 0.01\n",
               "ground pivot 1 segment [ground]: flexural rigidity E b h^3/12 = 0");
}

}  // namespace
}  // namespace flexure::mechanism
