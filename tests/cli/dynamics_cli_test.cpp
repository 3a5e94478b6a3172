// What is checked against what (`flexure dynamics`, the built binary):
//  - --json prints the five documented arrays with one entry per --omega value; at omega = 0 the
//    peak-to-peak force and percent constant force equal those of the static PRBM force of
//    mechanisms/cfm (Weight eq. 2.14, dimensionalised) sampled at the same slider positions;
//  - --zero-inertia makes every statistic independent of omega (the paper's third curve);
//  - the HDF5 file holds the same sweep and one force history per --history frequency;
//  - bad input exits with code 2 and nothing on stdout.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/cfm/slider_crank.h"
#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;
using test::ScratchDir;

// The JSON numbers are printed with 17 significant digits; the static reference is the same
// closed form evaluated along a different code path (cfm pose and force function).
constexpr double kStaticTolerance = 1e-10;
constexpr int kSamples = 64;

TEST(DynamicsCli, JsonSweepMatchesStaticPrbmAtZeroFrequency) {
  ScratchDir dir;
  const auto r = run_flexure(fmt::format(
      "dynamics --mechanism 2B-lplm --omega 0:30:4 --samples {} --history 0,31.416 --out '{}' "
      "--json",
      kSamples,
      (dir / "sweep.h5").string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"omega", "mean_force", "median_force", "peak_to_peak_force", "percent_constant_force"}) {
    ASSERT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j[key].size(), 4u) << key;
  }
  EXPECT_DOUBLE_EQ(j["omega"][3].get<double>(), 30.0);

  // Static force of the whole mechanism at the sampled positions of one period.
  const dynamics::CfsmDesign& d = dynamics::find_cfsm_design("2B-lplm");
  const double r_tot = d.r2 + d.r3, R = d.r3 / d.r2;
  double lo = 1e300, hi = -1e300;
  for (int k = 0; k < kSamples; ++k) {
    const double dx =
        0.01 * r_tot + 0.2 * r_tot * (1.0 - std::cos(2.0 * std::numbers::pi * k / kSamples));
    const double F = 2.0 * d.k[0] / d.r2 *
                     cfm::force_function_phi(
                         R, 0.0, d.k[2] / d.k[0], false, cfm::slider_crank_pose(R, dx / r_tot));
    lo = std::min(lo, F);
    hi = std::max(hi, F);
  }
  EXPECT_NEAR(j["peak_to_peak_force"][0].get<double>(), hi - lo, kStaticTolerance * hi);
  EXPECT_NEAR(
      j["percent_constant_force"][0].get<double>(), 100.0 * lo / hi, kStaticTolerance * 100);

  const hid_t file = test::open_read_only(dir / "sweep.h5");
  ASSERT_GE(file, 0);
  const std::vector<double> p2p = test::read_doubles(file, "peak_to_peak_force");
  ASSERT_EQ(p2p.size(), 4u);
  EXPECT_DOUBLE_EQ(p2p[2], j["peak_to_peak_force"][2].get<double>());
  EXPECT_EQ(test::read_doubles(file, "history/1/force").size(), static_cast<size_t>(kSamples));
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file, "history/1", "omega"), 31.416);
  H5Fclose(file);
}

TEST(DynamicsCli, ZeroInertiaRemovesFrequencyDependence) {
  ScratchDir dir;
  const auto r = run_flexure(
      fmt::format("dynamics --mechanism 3A-lllm --omega 0:80:3 --zero-inertia --out '{}' --json",
                  (dir / "z.h5").string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"mean_force", "median_force", "peak_to_peak_force"}) {
    EXPECT_DOUBLE_EQ(j[key][0].get<double>(), j[key][2].get<double>()) << key;
  }
}

TEST(DynamicsCli, JsonWorksWithoutOutAndWritesNothing) {
  ScratchDir dir;
  const std::string args = "dynamics --mechanism 2B-lplm --omega 0:40:3 --history 20 --json";
  const auto without = run_flexure(args, dir.path());
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_TRUE(dir.entries().empty()) << "a file was written without --out";
  const auto with = run_flexure(args + " --out d.h5", dir.path());
  ASSERT_EQ(with.exit_code, 0) << with.err;
  const nlohmann::json a = nlohmann::json::parse(without.out);
  const nlohmann::json b = nlohmann::json::parse(with.out);
  EXPECT_TRUE(a["out"].is_null());
  EXPECT_EQ(a["force_of"], "whole symmetric mechanism");
  for (const char* key : {"mean_force", "peak_to_peak_force", "percent_constant_force"}) {
    EXPECT_EQ(a[key], b[key]) << key;
  }
  // The history printed is the one stored in the file.
  ASSERT_EQ(a["history"].size(), 1u);
  hid_t file = test::open_read_only(dir / "d.h5");
  ASSERT_GE(file, 0);
  EXPECT_EQ(a["history"][0]["force"].get<std::vector<double>>(),
            test::read_doubles(file, "history/0/force"));
  H5Fclose(file);
}

TEST(DynamicsCli, BadInputExitsWithTwo) {
  ScratchDir dir;
  const std::string out = (dir / "x.h5").string();
  const std::vector<std::string> bad_args{
      "dynamics --mechanism 9Z-none --omega 0:1:2 --out '" + out + "'",
      "dynamics --mechanism 2B-lplm --omega 0:1:2 --preload-percent 0 --out '" + out + "'",
      "dynamics --mechanism 2B-lplm --omega -1:1:2 --out '" + out + "'",
      "dynamics --mechanism 2B-lplm --omega 0:1:2 --friction 1,2 --out '" + out + "'",
      "dynamics --mechanism 2B-lplm --omega 0:1:2 --out '/nonexistent/dir/x.h5'"};
  for (const std::string& args : bad_args) {
    const auto r = run_flexure(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_TRUE(test::no_result_on_stdout(r)) << args;
  }
}

}  // namespace
}  // namespace flexure
