// The file of `flexure mechanism analyze --out` through its writer class
// (io/mechanism_stroke_file.h MechanismStrokeFile), read back with the plain HDF5 C API: the
// stroke's displacement and PRBM force equal the analysis bit for bit; a path that cannot be
// written fails in the constructor (before any stroke is solved) with the --out message, and a
// writer dropped before write() leaves nothing behind.
#include "flexure/io/mechanism_stroke_file.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"
#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

TEST(MechanismStrokeFile, DatasetsEqualTheAnalysis) {
  mechanism::AnalysisOptions o;
  o.points = 12;
  o.exact = false;
  const mechanism::MechanismAnalysis a =
      mechanism::analyze_mechanism(mechanism::find_builtin_mechanism("1A-spp"), o);
  ScratchDir dir;
  const auto path = dir / "stroke.h5";
  {
    io::MechanismStrokeFile file(path.string());
    file.write(a, nullptr, false, "");
    EXPECT_THROW(file.write(a, nullptr, false, ""), std::logic_error);
  }
  ASSERT_EQ(dir.entries(), std::vector<std::string>{"stroke.h5"});
  const hid_t f = open_read_only(path);
  ASSERT_GE(f, 0);
  EXPECT_EQ(read_doubles(f, "displacement"), a.prbm.displacement);
  EXPECT_EQ(read_doubles(f, "force_prbm"), a.prbm.force);
  H5Fclose(f);
}

TEST(MechanismStrokeFile, UnwritablePathFailsInTheConstructorAndNothingIsLeft) {
  try {
    io::MechanismStrokeFile file("/nonexistent/dir/stroke.h5");
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("--out: ", 0), 0u) << m;
    EXPECT_NE(m.find("/nonexistent/dir"), std::string::npos) << m;
  }
  ScratchDir dir;
  { io::MechanismStrokeFile dropped((dir / "s.h5").string()); }
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace flexure::test
