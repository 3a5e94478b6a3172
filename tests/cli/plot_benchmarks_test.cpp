// What is checked: scripts/plot_benchmarks.py on a quick `flexure bench` file writes its figures
// into a folder beside the input (never into docs/ unless told to), as PNG files, and prints the
// path of each one it wrote.
// Skipped (GTEST_SKIP) when /usr/bin/python3 cannot import matplotlib and h5py (the Debian packages
// python3-matplotlib, python3-h5py).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

const std::string kPython = "/usr/bin/python3";

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
}

}  // namespace
}  // namespace flexure::test
