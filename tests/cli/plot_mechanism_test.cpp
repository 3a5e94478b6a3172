// What is checked against what: scripts/plot_mechanism.py on a small `flexure mechanism analyze
// --out` file -- it exits 0 and leaves exactly one PNG (checked by its 8-byte signature, no
// temporary file left behind); on a file that is not a mechanism stroke, or an --out in a directory
// that does not exist, it exits 1 with a message (no Python traceback).
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

bool python_has_plot_modules() {
  const std::string probe = kPython + " -c 'import matplotlib, h5py' >/dev/null 2>&1";
  return std::system(probe.c_str()) == 0;
}

int run_script(const std::string& args, const ScratchDir& dir) {
  const std::string command = "cd '" + dir.path().string() + "' && " + kPython + " '" +
                              FLEXURE_SOURCE_DIR + "/scripts/plot_mechanism.py' " + args +
                              " >out.txt 2>err.txt";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(PlotMechanism, WritesOnePngFromAnAnalyzeFile) {
  if (!python_has_plot_modules()) GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py";
  ScratchDir dir;
  const CommandResult r =
      run_flexure("mechanism analyze 1A-spp --points 8 --method exact --out s.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(run_script("s.h5 --stress --out s.png", dir), 0) << read_text(dir / "err.txt");
  std::ifstream png(dir / "s.png", std::ios::binary);
  std::string signature(8, '\0');
  png.read(signature.data(), 8);
  EXPECT_EQ(signature, std::string("\x89PNG\r\n\x1a\n", 8));
  // s.h5, s.png, out.txt, err.txt: no temporary image left.
  EXPECT_EQ(dir.entries().size(), 4u);
}

TEST(PlotMechanism, RefusesAFileWithoutAStroke) {
  if (!python_has_plot_modules()) GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py";
  ScratchDir dir;
  std::ofstream(dir / "bad.h5") << "not hdf5";
  EXPECT_EQ(run_script("bad.h5 --out bad.png", dir), 1);
  EXPECT_NE(read_text(dir / "err.txt").find("cannot read"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
}

TEST(PlotMechanism, RefusesAnOutputInAMissingDirectory) {
  if (!python_has_plot_modules()) GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py";
  ScratchDir dir;
  const CommandResult r = run_flexure("mechanism analyze 1A-spp --points 4 --out s.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(run_script("s.h5 --out missing/s.png", dir), 1);
  const std::string err = read_text(dir / "err.txt");
  EXPECT_NE(err.find("cannot write missing/s.png"), std::string::npos) << err;
  EXPECT_EQ(err.find("Traceback"), std::string::npos) << err;
}

}  // namespace
}  // namespace flexure::test
