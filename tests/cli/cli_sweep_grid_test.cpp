// `flexure sweep beam` over any parameter and over grids, checked against single solves of
// `flexure beam --json` at the same inputs (another command, one point at a time) and against the
// inverse's own target (a sweep over theta0 or b/l must hit every target):
//  * a grid alpha2 x n is stored [count1, count2], row-major, with its axes in /axes and the root
//    attribute axes; each point equals beam's answer to 1e-12;
//  * a sweep over n alone keeps alpha2 fixed (root given_value) and stores no load_ratio_n
//    attribute (it is an axis);
//  * a sweep over theta0 x mu finds loads whose tip angle is the target to 1e-10, equal to beam
//    --theta0 --mu; a sweep over b/l the same for the deflection;
//  * a 1-D alpha2 sweep keeps its old layout (no /axes: /alpha2 is the axis);
//  * bad combinations are exit 2 naming the flags, and write nothing.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::read_doubles;
using test::run_flexure;
using Json = nlohmann::json;

std::vector<hsize_t> dims_of(hid_t file, const char* name) {
  hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  hid_t space = H5Dget_space(dataset);
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  H5Dclose(dataset);
  return dims;
}

bool has_attribute(hid_t file, const char* name) { return H5Aexists(file, name) > 0; }

Json beam_json(const std::string& args) {
  const test::CommandResult r = run_flexure("beam " + args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << r.err;
  return Json::parse(r.out);
}

TEST(CliSweepGrid, AlphaByNGridEqualsSingleSolves) {
  test::ScratchDir dir;
  const auto out = dir / "grid.h5";
  const test::CommandResult r = run_flexure(
      "sweep beam --alpha2 0.5:4.5:5 --n -1:2:4 --mu 0.3 "
      "--method elliptic --json --out '" +
      out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json summary = Json::parse(r.out);
  EXPECT_EQ(summary["axes"], "alpha2,load_ratio_n");
  EXPECT_EQ(summary["shape"], Json::array({5, 4}));
  const hid_t f = test::open_read_only(out);
  ASSERT_GE(f, 0);
  for (const char* name : {"alpha2", "a_over_l", "b_over_l", "theta0", "status"}) {
    EXPECT_EQ(dims_of(f, name), (std::vector<hsize_t>{5, 4})) << name;
  }
  const std::vector<double> axis_a = read_doubles(f, "axes/alpha2");
  const std::vector<double> axis_n = read_doubles(f, "axes/load_ratio_n");
  ASSERT_EQ(axis_a.size(), 5u);
  ASSERT_EQ(axis_n.size(), 4u);
  EXPECT_EQ(axis_n.back(), 2.0);
  EXPECT_EQ(test::read_string_attribute(f, "/", "axes"), "alpha2,load_ratio_n");
  EXPECT_FALSE(has_attribute(f, "load_ratio_n"));  // an axis, not a fixed value
  EXPECT_EQ(test::read_double_attribute(f, "/", "mu"), 0.3);
  const std::vector<double> alpha2 = read_doubles(f, "alpha2");
  const std::vector<double> b = read_doubles(f, "b_over_l");
  const std::vector<double> theta0 = read_doubles(f, "theta0");
  for (const auto& [i, j] : {std::pair{0, 0}, std::pair{2, 1}, std::pair{4, 3}, std::pair{3, 2}}) {
    const std::size_t k = static_cast<std::size_t>(i * 4 + j);  // row-major, n fastest
    EXPECT_EQ(alpha2[k], axis_a[i]);
    const Json one =
        beam_json(fmt::format("--alpha2 {:.17g} --n {:.17g} --mu 0.3 --method "
                              "elliptic",
                              axis_a[i],
                              axis_n[j]));
    EXPECT_NEAR(b[k], one["b_over_l"].get<double>(), 1e-12) << i << "," << j;
    EXPECT_NEAR(theta0[k], one["theta0"].get<double>(), 1e-12) << i << "," << j;
  }
  H5Fclose(f);
}

TEST(CliSweepGrid, SweepOverNAloneKeepsAlpha2Fixed) {
  test::ScratchDir dir;
  const auto out = dir / "n.h5";
  ASSERT_EQ(run_flexure("sweep beam --alpha2 2 --n 0:3:4 --out '" + out.string() + "'").exit_code,
            0);
  const hid_t f = test::open_read_only(out);
  EXPECT_EQ(read_doubles(f, "alpha2"), (std::vector<double>{2, 2, 2, 2}));
  EXPECT_EQ(test::read_double_attribute(f, "/", "given_value"), 2.0);
  EXPECT_EQ(test::read_string_attribute(f, "/", "given"), "alpha2");
  const std::vector<double> b = read_doubles(f, "b_over_l");
  const Json one = beam_json("--alpha2 2 --n 3");
  EXPECT_NEAR(b[3], one["b_over_l"].get<double>(), 1e-12);
  H5Fclose(f);
}

TEST(CliSweepGrid, InverseSweepsHitEveryTarget) {
  test::ScratchDir dir;
  const auto out = dir / "inverse.h5";
  ASSERT_EQ(
      run_flexure("sweep beam --theta0 0.2:1.2:6 --mu -0.5:0.5:3 --out '" + out.string() + "'")
          .exit_code,
      0);
  hid_t f = test::open_read_only(out);
  const std::vector<double> targets = read_doubles(f, "axes/theta0");
  const std::vector<double> mus = read_doubles(f, "axes/mu");
  const std::vector<double> theta0 = read_doubles(f, "theta0");
  const std::vector<double> alpha2 = read_doubles(f, "alpha2");
  ASSERT_EQ(theta0.size(), 18u);
  for (std::size_t i = 0; i < 6; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_NEAR(theta0[i * 3 + j], targets[i], 1e-10);  // the inverse hits its target
    }
  }
  const Json one = beam_json(fmt::format("--theta0 {:.17g} --mu {:.17g}", targets[4], mus[2]));
  EXPECT_NEAR(alpha2[4 * 3 + 2], one["alpha2"].get<double>(), 1e-9);
  H5Fclose(f);

  const auto out_b = dir / "b.h5";
  ASSERT_EQ(
      run_flexure("sweep beam --b-over-l 0.1:0.7:4 --n 1 --out '" + out_b.string() + "'").exit_code,
      0);
  f = test::open_read_only(out_b);
  const std::vector<double> b_targets = read_doubles(f, "axes/b_over_l");
  const std::vector<double> b = read_doubles(f, "b_over_l");
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(b[i], b_targets[i], 1e-10);
  EXPECT_EQ(test::read_string_attribute(f, "/", "given"), "b_over_l");
  H5Fclose(f);
}

TEST(CliSweepGrid, BadCombinationsAreExitTwoAndWriteNothing) {
  test::ScratchDir dir;
  const std::string out = " --out '" + (dir / "x.h5").string() + "'";
  const struct {
    const char* args;
    const char* says;
  } cases[] = {
      {"--alpha2 0:1:3 --theta0 1", "exactly one of --alpha2"},
      {"--n 0:1:3", "exactly one of --alpha2"},
      {"--alpha2 1", "one or two"},
      {"--alpha2 0:1:3 --n 0:1:2 --mu 0:1:2", "one or two"},
      {"--b-over-l 0:1.5:3", "[-1, 1]"},
      {"--alpha2 0:1:4000 --n 0:1:4000", "more than 10000000 points"},
      {"--alpha2 0:1:3 --n abc", "--n = 'abc'"},
  };
  for (const auto& c : cases) {
    const test::CommandResult r = run_flexure(std::string("sweep beam ") + c.args + out);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.h5")) << c.args;
  }
}

}  // namespace
}  // namespace flexure
