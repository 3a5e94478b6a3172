// What is checked: scripts/plot_dynamics.py on a small `flexure dynamics --out` file writes one PNG
// (8-byte signature) where --out says, prints its path, and labels every axis with a unit in
// brackets taken from the file (rad/s for omega, N for the forces).
// Skipped (GTEST_SKIP) when /usr/bin/python3 cannot import matplotlib and h5py (the Debian packages
// python3-matplotlib, python3-h5py).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <string>

#include "tests/support/plot_test_support.h"

namespace flexure::test {
namespace {

TEST(PlotDynamics, WritesThePngItNamesWithUnitsOnEveryAxis) {
  if (!python_has_plot_modules()) GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py";
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "dynamics --mechanism 2B-lplm --omega 0:30:4 --samples 64 --history 10,20 --out d.h5",
      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(run_plot_script("plot_dynamics.py", "d.h5 --out d.png", dir, true), 0)
      << read_text(dir / "err.txt");
  std::ifstream png(dir / "d.png", std::ios::binary);
  std::string signature(8, '\0');
  png.read(signature.data(), 8);
  EXPECT_EQ(signature, std::string("\x89PNG\r\n\x1a\n", 8));
  const std::string printed = read_text(dir / "out.txt");
  EXPECT_NE(printed.find("wrote " + std::filesystem::canonical(dir / "d.png").string()),
            std::string::npos)
      << printed;
  const std::vector<std::string> labels = axis_labels(printed);
  // Three sweep panels and two history panels, each with x and y labels.
  EXPECT_EQ(labels.size(), 10u);
  for (const std::string& label : labels) {
    EXPECT_TRUE(std::regex_search(label, std::regex(R"(\[[^\[\]]+\]$)"))) << label;
  }
  EXPECT_NE(std::find(labels.begin(), labels.end(), "drive frequency omega [rad/s]"), labels.end());
  // The force axes say what the force is the force of (dynamics' default: the whole mechanism).
  EXPECT_NE(std::find(labels.begin(), labels.end(), "mean force, whole symmetric mechanism [N]"),
            labels.end());
}

}  // namespace
}  // namespace flexure::test
