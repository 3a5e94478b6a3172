// `flexure mechanism export NAME --out FILE.toml` (docs/mechanisms.md "The catalogue as general
// mechanisms"): a built-in design written as a general mechanism file, which `flexure mechanism
// analyze FILE --model both` solves to the numbers `flexure mechanism analyze NAME` prints for the
// design (its closed-form PRBM and its own exact chains): the round trip through the TOML text and
// the general models: the PRBM to 1e-9 relative; the exact model to 2e-9, as `mechanism analyze
// FILE` solves it with the general exact model's default Newton tolerance (1e-10 of its scaled
// equations; measured 1.1e-9 at the first point of 2A-slp -- catalogue_general_test tightens that
// tolerance to 1e-12 and gets 4.3e-10 over all 40 designs).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

double relative(double a, double b) { return std::fabs(a - b) / std::max(std::fabs(b), 1e-300); }

// An slp design (long segment at pivot 2), a plp inversion, the thesis's lpp example, a modified
// design of paper 004 and one of Howell's.
TEST(MechanismExportCli, ExportedDesignsSolveToTheCatalogueForces) {
  for (const std::string name : {"2A-slp", "1B-plp'", "1A-lpp", "2B-lplm", "howell-3A-sss-a"}) {
    SCOPED_TRACE(name);
    ScratchDir dir;
    const std::string file = (dir / "design.toml").string();
    const CommandResult e =
        run_flexure("mechanism export \"" + name + "\" --points 10 --out '" + file + "'");
    ASSERT_EQ(e.exit_code, 0) << e.err;
    EXPECT_NE(e.out.find("general mechanism written to"), std::string::npos) << e.out;
    const CommandResult g = run_flexure("mechanism analyze '" + file + "' --model both --json");
    ASSERT_EQ(g.exit_code, 0) << g.err;
    const auto gj = nlohmann::json::parse(g.out);
    EXPECT_EQ(gj["form"], "general");
    const CommandResult c = run_flexure("mechanism analyze \"" + name + "\" --points 10 --json");
    ASSERT_EQ(c.exit_code, 0) << c.err;
    const auto cj = nlohmann::json::parse(c.out);
    ASSERT_EQ(gj["models"]["prbm"]["input_load"].size(), 10u);
    ASSERT_EQ(gj["models"]["exact"]["input_load"].size(), 10u);
    ASSERT_EQ(cj["force_prbm"].size(), 10u);
    ASSERT_EQ(cj["force_exact"].size(), 10u);
    for (std::size_t k = 0; k < 10; ++k) {
      // The design's force pushes the slider inwards; the general input load holds it.
      EXPECT_LE(relative(-gj["models"]["prbm"]["input_load"][k].get<double>(),
                         cj["force_prbm"][k].get<double>()),
                1e-9)
          << "PRBM at point " << k;
      EXPECT_LE(relative(-gj["models"]["exact"]["input_load"][k].get<double>(),
                         cj["force_exact"][k].get<double>()),
                2e-9)
          << "exact at point " << k;
      // The input is the moving block's x: Delta x = x0 - input.
      EXPECT_NEAR(gj["models"]["prbm"]["input"][0].get<double>() -
                      gj["models"]["prbm"]["input"][k].get<double>(),
                  cj["displacement"][k].get<double>() - cj["displacement"][0].get<double>(),
                  1e-15);
    }
  }
}

TEST(MechanismExportCli, WritesToStandardOutputAndRefusesUnknownNames) {
  const CommandResult r = run_flexure("mechanism export 1A-spp --points 5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("[[body]]"), std::string::npos);
  EXPECT_NE(r.out.find("start_rotation = { crank = "), std::string::npos);
  const CommandResult bad = run_flexure("mechanism export no-such-design");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("unknown mechanism 'no-such-design'"), std::string::npos) << bad.err;
  const CommandResult points = run_flexure("mechanism export 1A-spp --points 1");
  EXPECT_EQ(points.exit_code, 2);
}

}  // namespace
}  // namespace flexure::test
