// What is checked against what: scripts/plot_mechanism.py on a small `flexure mechanism analyze
// --out` file -- it exits 0, leaves exactly one PNG (checked by its 8-byte signature, no
// temporary file left behind) and prints its path; every axis label ends with a unit in
// brackets (mm and MPa: the file's m and Pa, scaled for reading), and the stress panel shows
// the exact-model stresses and the yield limit (legend entries, read from an SVG of the same
// plot, where matplotlib keeps each text as a comment); on a file that is not a mechanism stroke,
// or an --out in a directory that does not exist, it exits 1 with a message (no Python
// traceback).
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

int run_script(const std::string& args, const ScratchDir& dir, bool print_labels = false) {
  return run_plot_script("plot_mechanism.py", args, dir, print_labels);
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
  EXPECT_EQ(read_text(dir / "out.txt"),
            "wrote " + std::filesystem::canonical(dir / "s.png").string() + "\n");
  // s.h5, s.png, out.txt, err.txt: no temporary image left.
  EXPECT_EQ(dir.entries().size(), 4u);
}

TEST(PlotMechanism, LabelsEveryAxisWithUnitsAndDrawsExactStressesAndTheYieldLimit) {
  if (!python_has_plot_modules()) GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py";
  ScratchDir dir;
  const CommandResult r =
      run_flexure("mechanism analyze 1A-spp --points 8 --method exact --out s.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(run_script("s.h5 --out s.png", dir, true), 0) << read_text(dir / "err.txt");
  const std::vector<std::string> labels = axis_labels(read_text(dir / "out.txt"));
  // Force, force error and stress panels (shared x axis: one x label), and the panel of the
  // exact stroke's shapes (x and y).
  EXPECT_EQ(labels.size(), 6u);
  for (const std::string& label : labels) {
    EXPECT_TRUE(std::regex_search(label, std::regex(R"(\[[^\[\]]+\]$)"))) << label;
  }
  EXPECT_NE(std::find(labels.begin(), labels.end(), "slider displacement Delta x [mm]"),
            labels.end());
  // The force axis says what the force is the force of (analyze's default: one half).
  EXPECT_NE(std::find(labels.begin(), labels.end(), "slider force F, one half [N]"), labels.end());
  EXPECT_NE(std::find(labels.begin(), labels.end(), "largest stress [MPa]"), labels.end());

  ASSERT_EQ(run_script("s.h5 --out s.svg", dir), 0) << read_text(dir / "err.txt");
  const std::string svg = read_text(dir / "s.svg");
  EXPECT_NE(svg.find("<!-- yield strength -->"), std::string::npos);
  EXPECT_NE(svg.find("<!-- pivot 1 exact -->"), std::string::npos);
  EXPECT_NE(svg.find("<!-- pivot 1 PRBM -->"), std::string::npos);
}

// A design written for the whole mechanism's force (`design mechanism --force-of whole`): its
// file says force_of = "whole", analyze reports the whole mechanism's forces, and the plot's force
// axis says so -- at twice the one-half forces of the same file analysed with --force-of half.
TEST(PlotMechanism, ForceAxisNamesTheWholeMechanismOfADesignFile) {
  if (!python_has_plot_modules()) GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py";
  ScratchDir dir;
  ASSERT_EQ(run_flexure("design mechanism --force 20N --force-of whole --stroke 10mm --E 200GPa "
                        "--yield-strength 1200MPa --safety-factor 1.5 --length-range 150mm "
                        "--config lpp --no-exact --out w.toml",
                        dir.path())
                .exit_code,
            0);
  ASSERT_EQ(run_flexure("mechanism analyze w.toml --points 8 --method prbm --out w.h5", dir.path())
                .exit_code,
            0);
  ASSERT_EQ(run_script("w.h5 --out w.png", dir, true), 0) << read_text(dir / "err.txt");
  const std::vector<std::string> labels = axis_labels(read_text(dir / "out.txt"));
  EXPECT_NE(
      std::find(labels.begin(), labels.end(), "slider force F, whole symmetric mechanism [N]"),
      labels.end());
}

TEST(PlotMechanism, RefusesAFileWithoutAStroke) {
  if (!python_has_plot_modules()) GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py";
  ScratchDir dir;
  std::ofstream(dir / "bad.h5") << "not hdf5";
  EXPECT_EQ(run_script("bad.h5 --out bad.png", dir), 1);
  EXPECT_NE(read_text(dir / "err.txt").find("is not an HDF5 file"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
}

TEST(PlotMechanism, RefusesAnOutputInAMissingDirectory) {
  if (!python_has_plot_modules()) GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py";
  ScratchDir dir;
  const CommandResult r = run_flexure("mechanism analyze 1A-spp --points 4 --out s.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(run_script("s.h5 --out missing/s.png", dir), 1);
  const std::string err = read_text(dir / "err.txt");
  EXPECT_NE(err.find("missing/s.png': the folder"), std::string::npos) << err;
  EXPECT_EQ(err.find("Traceback"), std::string::npos) << err;
}

}  // namespace
}  // namespace flexure::test
