// `flexure map cfm` (docs/cli.md, docs/hdf5-schema.md): every point of the map equals the single
// evaluation `flexure cfm` (and `--exact`) gives at the same R, d, K; the stroke limit is flagged
// where d is past the toggle position; shapes, status codes and bad input.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

TEST(CliMap, EveryPointEqualsTheSingleEvaluation) {
  ScratchDir dir;
  const std::string path = (dir / "map.h5").string();
  const CommandResult r = run_flexure(
      "map cfm --config lps --R 0.4:2.0:5 --d 16:40:3 --K2 0.5:2:2 --model exact --exact-points 20 "
      "--json --out " +
      path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["dims"], (json{5, 3, 1, 2}));
  const hid_t file = open_read_only(path);
  ASSERT_GE(file, 0);
  const std::vector<double> R = read_doubles(file, "/R"), d = read_doubles(file, "/d"),
                            K2 = read_doubles(file, "/K2");
  const std::vector<double> pcf = read_doubles(file, "/percent_constant_force");
  const std::vector<double> exact = read_doubles(file, "/percent_constant_force_exact");
  const std::vector<double> toggle = read_doubles(file, "/toggle_stroke_percent");
  const std::vector<int> clamped = read_ints(file, "/stroke_clamped");
  const std::vector<int> status = read_ints(file, "/status");
  EXPECT_EQ(read_int_attribute(file, "/", "mpi_ranks"), 1);
  H5Fclose(file);
  ASSERT_EQ(pcf.size(), 30u);
  // A few points against `flexure cfm`, row-major with K2 fastest.
  // R = 0.4 reaches only 34.5 % before its toggle position: d = 40 (k = 4, 5) is clamped.
  EXPECT_EQ(clamped[4], 1);
  EXPECT_LT(toggle[4], 40.0);
  EXPECT_EQ(clamped[0], 0);
  for (std::size_t k : {0u, 4u, 7u, 13u, 29u}) {
    const std::size_t i = k / 6, jd = (k / 2) % 3, b = k % 2;
    const json one = json::parse(
        run_flexure(
            fmt::format("cfm --config lps --R {} --d {} --K2 {} --exact --exact-points 20 --json",
                        json(R[i]).dump(),
                        json(d[jd]).dump(),
                        json(K2[b]).dump()))
            .out);
    EXPECT_EQ(status[k], 0) << k;
    EXPECT_NEAR(pcf[k], one["percent_constant_force"].get<double>(), 1e-12) << k;
    EXPECT_NEAR(exact[k], one["percent_constant_force_exact"].get<double>(), 1e-9) << k;
    EXPECT_NEAR(toggle[k], one["toggle_stroke_percent"].get<double>(), 1e-12) << k;
    EXPECT_EQ(clamped[k] == 1, d[jd] > toggle[k]) << k;
  }
}

// The exact model may refuse a point the PRBM takes (its equivalent design outside the
// slender-beam limits): status 1, the PRBM values kept.
TEST(CliMap, AnExactRefusalKeepsThePrbmValues) {
  ScratchDir dir;
  const std::string path = (dir / "m.h5").string();
  const CommandResult r =
      run_flexure("map cfm --config slp --R 10 --d 25 --K1 500 --model exact --out " + path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const hid_t file = open_read_only(path);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_ints(file, "/status")[0], 1);
  const json one = json::parse(run_flexure("cfm --config slp --R 10 --d 25 --K1 500 --json").out);
  EXPECT_NEAR(read_doubles(file, "/percent_constant_force")[0],
              one["percent_constant_force"].get<double>(),
              1e-12);
  H5Fclose(file);
}

TEST(CliMap, BadInputIsExitTwoAndWritesNothing) {
  ScratchDir dir;
  const std::string out = " --out " + (dir / "m.h5").string();
  for (const char* args : {"map cfm --config lps --R 1 --d 16",         // K2 missing
                           "map cfm --config lpp --R 1 --d 16 --K1 1",  // no K1 in 1A
                           "map cfm --config psp --R 1 --d 16 --K1 1",  // 1B: K1 = 1
                           "map cfm --config lpp --R 0:2:3 --d 16",     // R = 0
                           "map cfm --config lpp --R 1 --d 16:120:3",   // d > 100
                           "map cfm --config lpp --R 1 --d 16 --model fem",
                           "map cfm --config xyz --R 1 --d 16",
                           "map cfm --config sss --R 0.5:2:65536 --d 1:40:65536 --K1 0.5:2:65536 "
                           "--K2 0.5:2:65536"}) {
    const CommandResult r = run_flexure(std::string(args) + out + " --json");
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
  }
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace flexure::test
