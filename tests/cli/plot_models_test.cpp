// What is checked: scripts/plot_models.py on a small `flexure models map --out` file writes the two
// PNGs (8-byte signature) it names, labels every axis with a unit in brackets taken from the file,
// and its --table rows count the points within 1 % as the file holds them; a file of another kind
// is refused (exit 2). Skipped (GTEST_SKIP) when /usr/bin/python3 cannot import matplotlib and
// h5py (the Debian packages python3-matplotlib, python3-h5py).
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <string>

#include "tests/support/plot_test_support.h"

namespace flexure::test {
namespace {

bool is_png(const std::filesystem::path& path) {
  std::ifstream png(path, std::ios::binary);
  std::string signature(8, '\0');
  png.read(signature.data(), 8);
  return signature == std::string("\x89PNG\r\n\x1a\n", 8);
}

TEST(PlotModels, WritesTheMapsAndTheChartWithUnitsOnEveryAxis) {
  if (!python_has_plot_modules()) GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py";
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "models map --n 0 --alpha2 0.2:3:4 --mu -0.5:0.5:3 --models linear,prbm,cbcm "
      "--min-seconds 0 --out m.h5",
      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(run_plot_script("plot_models.py", "m.h5 --out-dir figs --table", dir, true), 0)
      << read_text(dir / "err.txt");
  EXPECT_TRUE(is_png(dir / "figs" / "m_error_maps.png"));
  EXPECT_TRUE(is_png(dir / "figs" / "m_error_time.png"));
  const std::string printed = read_text(dir / "out.txt");
  EXPECT_NE(printed.find("m_error_maps.png"), std::string::npos) << printed;
  const std::vector<std::string> labels = axis_labels(printed);
  EXPECT_GE(labels.size(), 8u);  // 3 maps with colour bars, the chart
  for (const std::string& label : labels) {
    EXPECT_TRUE(std::regex_search(label, std::regex(R"(\[[^\[\]]+\]$)"))) << label;
  }
  // The 1R model answers only at mu = 0: 4 of 12 points.
  EXPECT_NE(printed.find("| prbm |  | 4 / 12 |"), std::string::npos) << printed;

  const CommandResult other = run_flexure("sweep beam --alpha2 0:1:3 --out s.h5", dir.path());
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_EQ(run_plot_script("plot_models.py", "s.h5", dir), 2);
}

}  // namespace
}  // namespace flexure::test
