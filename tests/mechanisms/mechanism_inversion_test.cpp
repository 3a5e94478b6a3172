// What is checked against what: the inversions (mechanisms/inversion.h; thesis §3.2.4, Howell
// §10.1.2 mirrored column) against their originals, through different code paths:
//  * the PRBM force of an inversion -- general virtual work F = sum k_i psi_i dpsi_i/dDelta x on
//    the MIRRORED mechanism (r2' = r3, r3' = r2, k' = (k3, k2, k1), a "ppl" with only k3) -- equals
//    the original's force from the thesis's Phi function (eq. 2.14) at every stroke point to 1e-12
//    relative, for every inverted built-in design (thesis, Howell) and every thesis sub-class of
//    the six type-asymmetric configurations (a symmetry: the same relative motion);
//  * the general virtual-work formula against a central difference of its own energy
//    V = sum k_i psi_i^2/2 (a convergence-rate-checked derivative, independent of the rates);
//  * the described (mirrored) form: pivot string reversed, r2 <-> r3, pivot i -> 4 - i; the CLI's
//    per-pivot stresses and HDF5 stress datasets of an inversion are the original's renumbered;
//  * the exact model of an inversion is the original's (identical by construction: same chain);
//  * names and aliases (1A-lpp', 1A-lpp-inv, lpp-b', ppl), and no inversion for psp, sps, sss.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/prbm_virtual_work.h"
#include "flexure/solver/common/status.h"
#include "tests/support/cli_test_support.h"

namespace flexure::mechanism {
namespace {

// Two closed forms of the same force in double precision (different kinematics and algebra).
constexpr double kSymmetry = 1e-12;
// Central difference with step h: error ~ h^2 V'''/6; with h = 1e-5 r_tot about 1e-10 relative,
// rounding ~ eps V/(h F) ~ 1e-11. 1e-8 leaves room and still catches a wrong rate (O(1)).
constexpr double kFiniteDifference = 1e-8;

void expect_same_force(const MechanismDesign& original) {
  const MechanismDesign inverse = invert(original);
  const PrbmStrokeResult a = prbm_stroke(original, 50);
  const PrbmStrokeResult b = prbm_stroke(inverse, 50);
  ASSERT_TRUE(a.converged() && b.converged()) << original.name;
  for (std::size_t k = 0; k < a.force.size(); ++k) {
    EXPECT_NEAR(b.force[k], a.force[k], kSymmetry * std::abs(a.force[k]))
        << inverse.name << " point " << k;
  }
}

TEST(MechanismInversion, PrbmForceEqualsTheOriginalsForEveryInvertedBuiltinDesign) {
  int count = 0;
  for (const auto* list : {&builtin_mechanisms(), &howell_mechanisms()}) {
    for (const MechanismDesign& d : *list) {
      if (!config_has_inversion(d.config)) continue;
      expect_same_force(d);  // the paper's modified designs too (lppm, llpm, slpm)
      if (d.paper_config.empty()) ++count;
    }
  }
  EXPECT_EQ(count, 6 + 5);  // thesis spp, lpp, plp, ssp, slp, lps; Howell spp x2, lpp, ssp x2
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    if (!config_has_inversion(row.config)) continue;
    expect_same_force(find_builtin_mechanism(row.name));
  }
}

TEST(MechanismInversion, VirtualWorkForceIsTheDerivativeOfTheSpringEnergy) {
  const double r2 = 0.06, r3 = 0.04;
  for (const std::array<double, 3> k :
       {std::array<double, 3>{0.0, 0.0, 2.0}, {1.0, 0.5, 0.0}, {0.3, 0.0, 4.0}, {1.0, 1.0, 1.0}}) {
    for (double u : {0.02, 0.1, 0.18}) {
      const double dx = u * (r2 + r3), h = 1e-5 * (r2 + r3);
      const double F = virtual_work_state(r2, r3, k, dx).force;
      const double dV = (virtual_work_state(r2, r3, k, dx + h).energy -
                         virtual_work_state(r2, r3, k, dx - h).energy) /
                        (2.0 * h);
      EXPECT_NEAR(F, dV, kFiniteDifference * std::abs(F)) << k[0] << k[1] << k[2] << " u " << u;
    }
  }
  EXPECT_THROW(virtual_work_state(r2, r3, {1, 0, 0}, 0.0), InvalidInput);
  EXPECT_THROW(virtual_work_state(r2, r3, {-1, 0, 0}, 0.01), InvalidInput);
  // R = 2/3 toggles at 100 (1 - sqrt(0.2)) = 55.3 % of r2 + r3.
  EXPECT_THROW(virtual_work_state(r2, r3, {1, 0, 0}, 0.56 * (r2 + r3)), InvalidInput);
  EXPECT_NO_THROW(virtual_work_state(r2, r3, {1, 0, 0}, 0.55 * (r2 + r3)));
}

TEST(MechanismInversion, DescribedInTheMirroredForm) {
  const MechanismDesign lpp = find_builtin_mechanism("1A-lpp");
  const MechanismDesign inv = find_builtin_mechanism("1A-lpp'");
  EXPECT_TRUE(inv.inverted);
  EXPECT_EQ(inv.name, "1A-lpp'");
  const DescribedDesign m = described_form(inv);
  EXPECT_EQ(m.config, "ppl");
  EXPECT_EQ(m.r2, lpp.r3);
  EXPECT_EQ(m.r3, lpp.r2);
  EXPECT_EQ(m.joints[2].type, PivotType::kLong);  // the ground flexure is now at the slider side
  EXPECT_EQ(m.joints[0].type, PivotType::kPin);
  EXPECT_EQ(m.fixed_body, "slider block");
  EXPECT_EQ(described_pivot(inv, 1), 3);
  EXPECT_EQ(mirrored_config("plp"), "pl3p");  // the middle beam becomes link 3
  EXPECT_EQ(mirrored_config("lps"), "spl");
  EXPECT_EQ(mirrored_config("slp"), "pls");
  const MechanismDesign back = invert(inv);
  EXPECT_FALSE(back.inverted);
  EXPECT_EQ(back.name, lpp.name);
  EXPECT_EQ(back.note, lpp.note);
}

TEST(MechanismInversion, NamesAndAliases) {
  EXPECT_EQ(find_builtin_mechanism("1A-lpp-inv").name, "1A-lpp'");
  EXPECT_EQ(find_builtin_mechanism("lpp'").name, "1A-lpp'");
  EXPECT_EQ(find_builtin_mechanism("ppl").name, "1A-lpp'");
  EXPECT_EQ(find_builtin_mechanism("2B-spl").name, "2B-lps'");
  const MechanismDesign b = find_builtin_mechanism("lpp-b'");
  EXPECT_TRUE(b.inverted);
  EXPECT_EQ(b.name, "lpp-b'");
  EXPECT_EQ(find_builtin_mechanism("LPP-B-INV").name, "lpp-b'");
  EXPECT_TRUE(find_builtin_mechanism("howell-ex1'").inverted);
  for (const char* symmetric : {"3A-sss'", "1B-psp-inv", "sps-a'"}) {
    EXPECT_THROW(find_builtin_mechanism(symmetric), InvalidInput) << symmetric;
  }
}

TEST(MechanismInversion, ExactModelIsTheOriginalsByConstruction) {
  AnalysisOptions o;
  o.points = 5;
  o.exact_stress = false;
  const MechanismAnalysis a = analyze_mechanism(find_builtin_mechanism("1A-spp"), o);
  const MechanismAnalysis b = analyze_mechanism(find_builtin_mechanism("1A-spp'"), o);
  ASSERT_TRUE(a.exact.converged() && b.exact.converged());
  for (std::size_t k = 0; k < a.force_exact.size(); ++k) {
    EXPECT_EQ(b.force_exact[k], a.force_exact[k]);
  }
}

TEST(MechanismInversion, CliStressesAndHdf5DatasetsAreRenumbered) {
  using nlohmann::json;
  const auto run = [](const std::string& name) {
    const test::CommandResult r =
        test::run_flexure("mechanism analyze \"" + name + "\" --points 12 --method prbm --json");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return json::parse(r.out);
  };
  const json lps = run("2B-lps");
  const json inv = run("2B-lps'");
  EXPECT_EQ(inv["design"]["config"], "spl");
  EXPECT_EQ(inv["design"]["inverted"], true);
  EXPECT_EQ(inv["design"]["r2"], lps["design"]["r3"]);
  EXPECT_EQ(inv["design"]["joints"][0]["type"], "s");
  EXPECT_EQ(inv["design"]["joints"][2]["type"], "l");
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(inv["max_stress_per_pivot"][i], lps["max_stress_per_pivot"][2 - i]) << i;
  }
  const std::vector<double> F = lps["force_prbm"], G = inv["force_prbm"];
  for (std::size_t k = 0; k < F.size(); ++k) EXPECT_NEAR(G[k], F[k], kSymmetry * F[k]);

  test::ScratchDir dir;
  ASSERT_EQ(
      test::run_flexure("mechanism analyze 1A-lpp --points 8 --method prbm --out a.h5", dir.path())
          .exit_code,
      0);
  ASSERT_EQ(test::run_flexure("mechanism analyze 1A-lpp-inv --points 8 --method prbm --out b.h5",
                              dir.path())
                .exit_code,
            0);
  const hid_t fa = test::open_read_only(dir / "a.h5");
  const hid_t fb = test::open_read_only(dir / "b.h5");
  EXPECT_EQ(test::read_doubles(fb, "stress_prbm_pivot3"),
            test::read_doubles(fa, "stress_prbm_pivot1"));
  EXPECT_EQ(test::read_string_attribute(fb, "/", "config"), "ppl");
  EXPECT_EQ(test::read_int_attribute(fb, "/", "inverted"), 1);
  H5Fclose(fa);
  H5Fclose(fb);
}

}  // namespace
}  // namespace flexure::mechanism
