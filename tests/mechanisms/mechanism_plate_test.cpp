// The plate modulus of a mechanism's strips (mechanisms/mechanism_plate.h,
// docs/plate-modulus.md), checked against:
//  * the exact scaling of a displacement-controlled stroke: with plate on every slider force,
//    PRBM and exact, is 1/(1 - nu^2) times plate off's (Weight's design example 1A-lpp, a
//    127 mm x 1.236 mm steel strip; nu = 0.3: 1.0989), to 1e-11 relative;
//  * auto against the Searle parameter by hand: b^2 kappa/h with kappa = 2 sigma_max/(E h) from
//    the analysis' largest stress of the strip; 1A-lpp bends to R ~ 0.12 m, beta ~ 111: a plate;
//  * errors: plate on without nu names the design.
#include "flexure/mechanisms/mechanism_plate.h"

#include <gtest/gtest.h>

#include <string>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

TEST(MechanismPlate, StrokeForcesScaleByOneOverOneMinusNuSquared) {
  MechanismDesign off = find_builtin_mechanism("1A-lpp");
  off.set_nu(0.3);
  MechanismDesign on = off;
  on.plate = PlateRule::kOn;
  AnalysisOptions o;
  o.points = 12;
  const MechanismAnalysis a = analyze_mechanism_with_modulus(off, o);
  const MechanismAnalysis b = analyze_mechanism_with_modulus(on, o);
  ASSERT_TRUE(a.has_exact && a.exact.converged() && b.exact.converged());
  ASSERT_EQ(a.prbm.force.size(), b.prbm.force.size());
  for (std::size_t i = 0; i < a.prbm.force.size(); ++i) {
    EXPECT_NEAR(b.prbm.force[i] / a.prbm.force[i], 1.0 / 0.91, 1e-11);
    EXPECT_NEAR(b.force_exact[i] / a.force_exact[i], 1.0 / 0.91, 1e-11);
  }
  EXPECT_EQ(b.design.modulus.at(0).E, off.material.E);
  EXPECT_NEAR(b.design.material.E, off.material.E / 0.91, 1e-15 * off.material.E);
  EXPECT_FALSE(a.design.modulus.at(0).plate);
}

TEST(MechanismPlate, AutoByTheSearleParameterOfTheStrip) {
  MechanismDesign d = find_builtin_mechanism("1A-lpp");
  d.set_nu(0.3);
  d.plate = PlateRule::kAuto;
  AnalysisOptions o;
  o.points = 12;
  MechanismDesign plain = d;
  plain.plate = PlateRule::kOff;
  const MechanismAnalysis beam = analyze_mechanism(plain, o);
  const MechanismAnalysis a = analyze_mechanism_with_modulus(d, o);
  const JointDesign& j = d.joints[0];
  const double kappa = 2.0 * beam.max_stress[0] / (d.material.E * j.thickness);
  const double beta = j.width * j.width * kappa / j.thickness;
  ASSERT_EQ(a.design.modulus.size(), 1u);  // one flexible strip (lpp)
  EXPECT_NEAR(*a.design.modulus[0].beta, beta, 1e-9 * beta);
  EXPECT_GT(beta, 50.0);
  EXPECT_TRUE(a.design.modulus[0].plate);
  EXPECT_NEAR(a.design.material.E, d.material.E / 0.91, 1e-15 * d.material.E);
}

TEST(MechanismPlate, PlateWithoutNuIsAnError) {
  MechanismDesign d = find_builtin_mechanism("1A-lpp");
  d.set_nu(std::nullopt);
  d.plate = PlateRule::kOn;
  try {
    analyze_mechanism_with_modulus(d, AnalysisOptions{});
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("1A-lpp: plate = on needs Poisson's ratio nu"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace flexure::mechanism
