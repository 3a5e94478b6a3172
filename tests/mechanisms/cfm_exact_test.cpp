// What is checked against what: `flexure cfm --exact` (nondimensional mechanism, exact model)
// against `flexure mechanism analyze FILE.toml` (the dimensional assembler) run on an equivalent
// design that this test sizes itself from the PRBM rules (thesis Table 8.1: an s pivot 0.1 r
// long, k = EI/l, Howell eq. 5.14; an l segment r/gamma long, k = gamma K_theta EI/l, eq. 5.72,
// gamma = 0.85, K_theta = 2.65; r2 + r3 = 1, E = 1): its mean exact force scaled by r2/k_ref must
// equal Phi_exact (and the percent constant force and max force error must agree), and its mean
// PRBM force scaled the same way must equal the nondimensional model's Phi on the same equally
// spaced points (two independent PRBM implementations: closed-form nondimensional eq. 2.14 vs the
// dimensional virtual-work model), also for two middle-pin rows the earlier solver could not
// solve. The documented JSON keys exist; all 68 thesis rows converge; a capped, unconverged exact
// solve exits 3; --exact-points without --exact exits 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using Json = nlohmann::json;

// Both sides run the same exact solver on the same chain; only the sizing route (and the TOML
// round trip at 17 digits) differs, so they agree to far below the solver tolerance.
constexpr double kSameSolverTolerance = 1e-6;
// The two PRBM implementations agree to rounding (closed form, same stroke points).
constexpr double kPrbmTolerance = 1e-9;

constexpr double kGamma = 0.85;   // fixed-pinned characteristic radius factor (thesis §2.2)
constexpr double kKtheta = 2.65;  // fixed-pinned stiffness coefficient (thesis §2.2)
constexpr int kPoints = 20;

struct Case {
  const char* config;
  double R, K1, K2;   // K1 = k2/k1, K2 = k3/k1 (class 1B: K2 = k3/k2); 0 = no spring
  const char* cli_K;  // the --K1/--K2 arguments
};

// Pivot p (1..3) of a configuration string: 's', 'l' or 'p'.
char pivot(const Case& c, int p) { return c.config[p - 1]; }

// Associated link of a pivot (thesis Table 8.1): r2 at the ground, r3 at the slider, r_ave for a
// middle s pivot.
double link(double r2, double r3, int p) { return p == 1 ? r2 : p == 3 ? r3 : 0.5 * (r2 + r3); }

// The equivalent design sized here, independently of mechanisms/cfm_exact.cpp: unit widths,
// the reference flexure 0.002 thick (a different choice than the CLI's: forces depend on EI
// ratios only; 0.02 made the sss ground flexure 0.73 times as thick as long, which the mechanism
// model now refuses as outside slender-beam theory, docs/mechanisms.md "Geometry limits"), the
// others so that k_i/k_ref = K. Returns r2/k_ref.
double write_design(const Case& c, const std::string& path) {
  const double r2 = 1.0 / (c.R + 1.0), r3 = c.R / (c.R + 1.0);
  auto length = [&](int p) {
    return pivot(c, p) == 'l' ? link(r2, r3, p) / kGamma : 0.1 * link(r2, r3, p);
  };
  // k per unit I (E = 1).
  auto k_per_I = [&](int p) { return (pivot(c, p) == 'l' ? kGamma * kKtheta : 1.0) / length(p); };
  const int ref = pivot(c, 1) == 'p' ? 2 : 1;
  const double h_ref = 0.002, I_ref = h_ref * h_ref * h_ref / 12.0;
  const double k_ref = k_per_I(ref) * I_ref;
  std::ofstream out(path);
  out.precision(17);
  out << "name = \"equivalent\"\nconfig = \"" << c.config << "\"\nr2 = " << r2 << "\nr3 = " << r3
      << "\nstroke = 0.16\n[material]\nE = 1.0\nyield_strength = 1.0\n";
  const char* section[3] = {"ground", "middle", "slider"};
  for (int p = 1; p <= 3; ++p) {
    if (pivot(c, p) == 'p') continue;
    const double K = p == ref ? 1.0 : (p == 2 ? c.K1 : c.K2);
    const double I = K * k_ref / k_per_I(p);
    out << "[" << section[p - 1] << "]\nthickness = " << std::cbrt(12.0 * I) << "\nwidth = 1.0\n";
    if (pivot(c, p) == 's') out << "length = " << length(p) << "\n";
  }
  return r2 / k_ref;
}

std::string cfm_exact_args(const Case& c) {
  return std::string("cfm --config ") + c.config + " --R " + std::to_string(c.R) + " " + c.cli_K +
         " --d 16 --sampling uniform --points " + std::to_string(kPoints) +
         " --exact --exact-points " + std::to_string(kPoints) + " --json";
}

class CfmExact : public ::testing::TestWithParam<Case> {};

TEST_P(CfmExact, MatchesTheDimensionalMechanismAnalysis) {
  const Case& c = GetParam();
  ScratchDir dir;
  const std::string toml = (dir / "equivalent.toml").string();
  const double to_Phi = write_design(c, toml);
  const CommandResult m = run_flexure("mechanism analyze '" + toml + "' --points " +
                                      std::to_string(kPoints) + " --json");
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const Json mj = Json::parse(m.out);
  ASSERT_TRUE(mj["mean_force_exact"].is_number()) << mj["exact_note"];

  const CommandResult r = run_flexure(cfm_exact_args(c));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = Json::parse(r.out);
  for (const char* key : {"percent_constant_force_exact", "Phi_exact", "max_force_error"}) {
    ASSERT_TRUE(j.contains(key) && j[key].is_number()) << key;
  }
  EXPECT_NEAR(j["Phi_exact"].get<double>(),
              mj["mean_force_exact"].get<double>() * to_Phi,
              kSameSolverTolerance * j["Phi_exact"].get<double>());
  EXPECT_NEAR(j["percent_constant_force_exact"].get<double>(),
              mj["percent_constant_force_exact"].get<double>(),
              kSameSolverTolerance * 100.0);
  EXPECT_NEAR(j["max_force_error"].get<double>(),
              mj["max_force_error"].get<double>(),
              kSameSolverTolerance);
  // PRBM: the nondimensional model (uniform sampling, same points) vs the dimensional PRBM.
  EXPECT_NEAR(j["Phi"].get<double>(),
              mj["mean_force_prbm"].get<double>() * to_Phi,
              kPrbmTolerance * j["Phi"].get<double>());
  EXPECT_NEAR(j["Phi"].get<double>(),
              j["Phi_prbm_exact_grid"].get<double>(),
              kPrbmTolerance * j["Phi"].get<double>());
}

INSTANTIATE_TEST_SUITE_P(
    SubclassA,
    CfmExact,
    ::testing::Values(Case{"sss", 2.6633, 1.0, 12.67, "--K1 1 --K2 12.67"},  // sss-a
                      Case{"lps", 0.7591, 0.0, 1.0029, "--K2 1.0029"},       // lps-aIo
                      Case{"psp", 1.0, 0.0, 0.0, ""}),                       // psp-a (1B)
    [](const auto& info) { return std::string(info.param.config); });

// Two of the nine middle-pin thesis rows the earlier nested pin-force Newton could not solve
// (docs/mechanisms.md "Pinned middle"): lps-a90 (R = 2.096, K2 = 2.0313) and sps-b86IO (R = 1,
// K2 = 1), d = 16 % here.
INSTANTIATE_TEST_SUITE_P(FormerlyUnconverged,
                         CfmExact,
                         ::testing::Values(Case{"lps", 2.0960, 0.0, 2.0313, "--K2 2.0313"},
                                           Case{"sps", 1.0, 0.0, 1.0, "--K2 1"}),
                         [](const auto& info) { return std::string(info.param.config); });

// Every thesis sub-class has a converged exact model (exit 0; a row that does not converge makes
// the table exit 3).
TEST(CfmExactCli, EveryThesisRowConverges) {
  const CommandResult r = run_flexure("cfm --table --exact --exact-rows all --markdown");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("not converged"), std::string::npos);
}

TEST(CfmExactCli, UnconvergedExactSolveExits3) {
  const CommandResult r =
      run_flexure("cfm --subclass sss-a --exact --exact-max-iterations 1 --json");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.err.find("exact model"), std::string::npos) << r.err;
}

// lpp-b's R clamped at its toggle (class 1A: the PRBM force is zero there): the exact force turns
// negative before the end, and its percent constant force was printed as 100 min/max = -5.33 %.
// The sign change is read off the printed curve; the percentage must be 0, flagged and warned.
TEST(CfmExactCli, ExactForceChangingSignHasNoPercentConstantForce) {
  const CommandResult r =
      run_flexure("cfm --config lpp --R 0.8853 --d 75.4 --exact --exact-points 20 --curve --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = Json::parse(r.out);
  const std::vector<double> phi = j["exact_curve"]["Phi_exact"];
  ASSERT_LT(*std::min_element(phi.begin(), phi.end()), 0.0);
  ASSERT_GT(*std::max_element(phi.begin(), phi.end()), 0.0);
  EXPECT_EQ(j["percent_constant_force_exact"].get<double>(), 0.0);
  EXPECT_TRUE(j["force_changes_sign_exact"].get<bool>());
  EXPECT_TRUE(j["force_vanishes_exact"].get<bool>());
  EXPECT_NE(r.err.find("exact force changes sign"), std::string::npos) << r.err;
  // At 16 % the same mechanism is a constant-force one: 100 min/max of its printed curve.
  const CommandResult ok =
      run_flexure("cfm --config lpp --R 0.8853 --d 16 --exact --exact-points 20 --curve --json");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const Json k = Json::parse(ok.out);
  const std::vector<double> fine = k["exact_curve"]["Phi_exact"];
  EXPECT_FALSE(k["force_vanishes_exact"].get<bool>());
  EXPECT_NEAR(k["percent_constant_force_exact"].get<double>(),
              100.0 * *std::min_element(fine.begin(), fine.end()) /
                  *std::max_element(fine.begin(), fine.end()),
              1e-12);
}

TEST(CfmExactCli, ExactOptionsNeedExact) {
  EXPECT_EQ(run_flexure("cfm --subclass sss-a --exact-points 10").exit_code, 2);
}

}  // namespace
}  // namespace flexure::test
