// What is checked against what: `flexure mechanism analyze FILE --out F.h5` stores the design and
// the exact-model stresses along the stroke, read back with the plain HDF5 C API:
//  - /design holds the numbers of a TOML design written by this test (E, yield strength, r2, r3,
//    stroke, every thickness, width and the given flexure length) exactly as written, with units;
//  - stress_exact_pivotN has one value per stroke point, and its maximum equals the per-pivot
//    `max_stress_exact` of the --json output of the same run; the largest stored stress (PRBM
//    and exact) equals the JSON `max_stress`, and yield_strength / max_stress the JSON
//    `safety_factor` (to 1e-12: the same doubles, one division);
//  - without the exact model there are no exact stresses; an inversion's /design reads like the
//    JSON `design` (described pivot order).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

// The sss example of docs/examples with its own material numbers (so that nothing here can come
// from a built-in design).
constexpr const char* kDesign = R"(name = "sss-test"
config = "sss"
r2 = 0.0273
r3 = 0.0727
stroke = 0.016

[material]
E = 190e9
yield_strength = 1.1e9

[ground]
thickness = 0.1e-3
width = 5e-3
length = 2.73e-3

[middle]
thickness = 0.1170e-3
width = 5e-3

[slider]
thickness = 0.3177e-3
width = 5e-3
)";

constexpr int kPoints = 6;

double scalar(hid_t file, const char* name) {
  const std::vector<double> v = read_doubles(file, name);
  EXPECT_EQ(v.size(), 1u) << name;
  return v.empty() ? std::nan("") : v.front();
}

double maximum(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

TEST(MechanismHdf5, StoresTheDesignAndTheExactStresses) {
  ScratchDir dir;
  std::ofstream(dir / "sss.toml") << kDesign;
  const CommandResult r =
      run_flexure("mechanism analyze sss.toml --points " + std::to_string(kPoints) +
                      " --method exact --json --out m.h5",
                  dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const hid_t file = open_read_only(dir / "m.h5");
  ASSERT_GE(file, 0);

  EXPECT_EQ(scalar(file, "/design/E"), 190e9);
  EXPECT_EQ(read_string_attribute(file, "/design/E", "units"), "Pa");
  EXPECT_EQ(scalar(file, "/design/yield_strength"), 1.1e9);
  EXPECT_EQ(scalar(file, "/design/r2"), 0.0273);
  EXPECT_EQ(scalar(file, "/design/r3"), 0.0727);
  EXPECT_EQ(scalar(file, "/design/stroke"), 0.016);
  EXPECT_EQ(read_string_attribute(file, "/design", "config"), "sss");
  EXPECT_EQ(read_strings(file, "/design/joints/type"), (std::vector<std::string>{"s", "s", "s"}));
  EXPECT_EQ(read_doubles(file, "/design/joints/thickness"),
            (std::vector<double>{0.1e-3, 0.1170e-3, 0.3177e-3}));
  EXPECT_EQ(read_doubles(file, "/design/joints/width"), (std::vector<double>{5e-3, 5e-3, 5e-3}));
  const std::vector<double> length = read_doubles(file, "/design/joints/length");
  ASSERT_EQ(length.size(), 3u);
  EXPECT_EQ(length[0], 2.73e-3);
  // Default middle flexure: 0.1 (r2 + r3)/2 (thesis Table 8.1, docs/mechanisms.md).
  EXPECT_NEAR(length[1], 0.1 * (0.0273 + 0.0727) / 2.0, 1e-15);
  EXPECT_EQ(read_string_attribute(file, "/design/joints/length", "units"), "m");

  double largest = 0.0;
  for (int pivot = 1; pivot <= 3; ++pivot) {
    const std::string exact = "stress_exact_pivot" + std::to_string(pivot);
    const std::string prbm = "stress_prbm_pivot" + std::to_string(pivot);
    const std::vector<double> sigma = read_doubles(file, exact.c_str());
    ASSERT_EQ(sigma.size(), static_cast<std::size_t>(kPoints)) << exact;
    for (double s : sigma) EXPECT_TRUE(std::isfinite(s) && s > 0.0) << exact;
    EXPECT_EQ(read_string_attribute(file, exact.c_str(), "units"), "Pa");
    EXPECT_DOUBLE_EQ(maximum(sigma), j["max_stress_exact"][pivot - 1].get<double>()) << exact;
    largest = std::max({largest, maximum(sigma), maximum(read_doubles(file, prbm.c_str()))});
  }
  const double max_stress = j["max_stress"].get<double>();
  EXPECT_DOUBLE_EQ(largest, max_stress);
  EXPECT_DOUBLE_EQ(read_double_attribute(file, "/", "max_stress"), max_stress);
  EXPECT_NEAR(scalar(file, "/design/yield_strength") / largest,
              j["safety_factor"].get<double>(),
              1e-12 * j["safety_factor"].get<double>());
  H5Fclose(file);
}

TEST(MechanismHdf5, PrbmOnlyHasNoExactStressesAndAnInversionReadsLikeItsJson) {
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "mechanism analyze \"1A-lpp'\" --points 5 --method prbm --json --out i.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json design = json::parse(r.out)["design"];
  const hid_t file = open_read_only(dir / "i.h5");
  ASSERT_GE(file, 0);
  for (int pivot = 1; pivot <= 3; ++pivot) {
    const std::string exact = "stress_exact_pivot" + std::to_string(pivot);
    EXPECT_TRUE(read_doubles(file, exact.c_str()).empty()) << exact;
  }
  std::vector<std::string> types;
  for (const json& joint : design["joints"]) types.push_back(joint["type"]);
  EXPECT_EQ(read_strings(file, "/design/joints/type"), types);
  EXPECT_EQ(scalar(file, "/design/r2"), design["r2"].get<double>());
  EXPECT_EQ(scalar(file, "/design/E"), design["E"].get<double>());
  EXPECT_EQ(read_int_attribute(file, "/design", "inverted"), 1);
  H5Fclose(file);
}

}  // namespace
}  // namespace flexure::test
