// What is checked: scripts/plot_benchmarks.py on a quick `flexure bench` file writes its figures
// into a folder beside the input (never into docs/ unless told to), as PNG files, and prints the
// path of each one it wrote; every axis label it draws ends with a unit in brackets, and the
// time axis of the accuracy charts is in s (the `units` of the file's `seconds`).
// Skipped (GTEST_SKIP) when /usr/bin/python3 cannot import matplotlib and h5py (the Debian packages
// python3-matplotlib, python3-h5py).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <string>

#include "tests/support/plot_test_support.h"

namespace flexure::test {
namespace {

TEST(PlotBenchmarks, WritesBesideTheInputAndSaysWhere) {
  if (std::system((kPython + " -c 'import matplotlib, h5py' >/dev/null 2>&1").c_str()) != 0) {
    GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py";
  }
  ScratchDir dir;
  const CommandResult bench = run_flexure(
      "bench --quick --problems cantilever_force,post_buckled_column --out b.h5", dir.path());
  ASSERT_EQ(bench.exit_code, 0) << bench.err;
  const std::string command = "cd '" + dir.path().string() + "' && " + kPython + " '" +
                              FLEXURE_SOURCE_DIR + "/scripts/plot_benchmarks.py' b.h5 >out.txt " +
                              "2>err.txt";
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(dir / "err.txt");
  EXPECT_FALSE(std::filesystem::exists(dir / "docs"));
  const std::string printed = read_text(dir / "out.txt");
  for (const char* name :
       {"bench_pareto.png", "bench_stability.png", "bench_prbm_map.png", "bench_column.png"}) {
    const auto path = dir / "bench_figures" / name;
    std::ifstream png(path, std::ios::binary);
    std::string signature(8, '\0');
    png.read(signature.data(), 8);
    EXPECT_EQ(signature, std::string("\x89PNG\r\n\x1a\n", 8)) << name;
    EXPECT_NE(printed.find("wrote " + std::filesystem::canonical(path).string()), std::string::npos)
        << printed;
  }

  ASSERT_EQ(run_plot_script("plot_benchmarks.py", "b.h5 --out-dir labelled", dir, true), 0)
      << read_text(dir / "err.txt");
  const std::vector<std::string> labels = axis_labels(read_text(dir / "out.txt"));
  // Two accuracy charts (x and y), the stability maps and the PRBM map (x, y, colour bar), the
  // column chart (x, y): at least 13 labels.
  EXPECT_GE(labels.size(), 13u);
  for (const std::string& label : labels) {
    EXPECT_TRUE(std::regex_search(label, std::regex(R"(\[[^\]]+\]$)"))) << label;
  }
  EXPECT_NE(std::find(labels.begin(), labels.end(), "median time per solve [s]"), labels.end());
}

}  // namespace
}  // namespace flexure::test
