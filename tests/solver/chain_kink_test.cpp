// What is checked against what (rigid segments of length 0):
// - a zero-length rigid link is a pure kink (docs/chain-toml.md): a chain of two flexible halves
//   with kinks at the root, between the halves and at the tip, under a pure end moment M, is two
//   circular arcs of curvature M/EI joined at the kinks; the tip pose and a/l, b/l from
//   `flexure beam --chain` with --method shooting, chain and auto, and from `flexure path`,
//   against that closed form (the solvers know nothing about arcs);
// - a chain of kinks only (total length 0) is invalid input for every method: the library solvers
//   (shooting, its load path, the chain algorithm) throw InvalidInput, and every `--method` of
//   `beam --chain` and `path --chain` exits 2 with the same message naming the total length (it
//   was "a/l came out as -nan", exit 3, with shooting and auto); so is a flexible segment of
//   length 0 and a prescribed tip on a chain of rigid links only.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"
#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using Json = nlohmann::json;
using test::run_flexure;
using test::ScratchDir;

// The kinked chain: root kink beta, flexible 0.5, kink phi, flexible 0.5, tip kink psi; EI = 1,
// total length 1, tip moment M.
constexpr double kBeta = 0.25, kPhi = 0.4, kPsi = -0.3, kMoment = 1.2;

const char* kKinkedChainToml = R"(# kinks at the root, in the middle and at the tip
[[segment]]
type = "rigid"
length = 0
angle_offset = 0.25
[[segment]]
type = "flexible"
length = 0.5
[[segment]]
type = "rigid"
length = 0
angle_offset = 0.4
[[segment]]
type = "flexible"
length = 0.5
[[segment]]
type = "rigid"
length = 0.0
angle_offset = -0.3
[tip_load]
M = 1.2
)";

// Closed form: with no force, the bending moment is M everywhere, so each flexible half is an arc
// of curvature kappa = M/EI turning by kappa/2; a kink turns the tangent in place.
ChainPose kinked_tip() {
  const double kappa = kMoment;
  ChainPose p;
  p.theta = kBeta;
  auto arc = [&](double length) {
    const double end = p.theta + kappa * length;
    p.x += (std::sin(end) - std::sin(p.theta)) / kappa;
    p.y += (std::cos(p.theta) - std::cos(end)) / kappa;
    p.theta = end;
  };
  arc(0.5);
  p.theta += kPhi;
  arc(0.5);
  p.theta += kPsi;
  return p;
}

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(ChainKink, ZeroLengthKinksGiveTheTwoArcTipWithEveryMethod) {
  ScratchDir dir;
  write(dir / "kinked.toml", kKinkedChainToml);
  const ChainPose expected = kinked_tip();
  // Shooting integrates to 1e-12; the chain algorithm's third-order error at 200 elements is
  // below 1e-6 (docs/theory-chain.md).
  const struct {
    const char* args;
    const char* method;
    double tolerance;
  } runs[] = {{"--method shooting", "shooting", 1e-9},
              {"--method auto", "shooting", 1e-9},
              {"--method chain --elements 200", "chain", 1e-6}};
  for (const auto& run : runs) {
    const test::CommandResult r = run_flexure("beam --json " + std::string(run.args) + " --chain " +
                                              (dir / "kinked.toml").string());
    ASSERT_EQ(r.exit_code, 0) << run.args << "\n" << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_EQ(j["method"], run.method) << run.args;
    // Total length 1: a/l and b/l are the tip coordinates.
    EXPECT_NEAR(j["a_over_l"].get<double>(), expected.x, run.tolerance) << run.args;
    EXPECT_NEAR(j["b_over_l"].get<double>(), expected.y, run.tolerance) << run.args;
    EXPECT_NEAR(j["theta0"].get<double>(), expected.theta, run.tolerance) << run.args;
  }
  for (const char* method : {"shooting", "chain --elements 200"}) {
    const std::string out = (dir / "path.h5").string();
    const test::CommandResult r =
        run_flexure("path --json --method " + std::string(method) + " --chain " +
                    (dir / "kinked.toml").string() + " --out " + out);
    ASSERT_EQ(r.exit_code, 0) << method << "\n" << r.err;
    const hid_t file = test::open_read_only(out);
    ASSERT_GE(file, 0);
    const std::vector<double> x = test::read_doubles(file, "tip_x");
    const std::vector<double> y = test::read_doubles(file, "tip_y");
    const std::vector<double> theta = test::read_doubles(file, "tip_theta");
    H5Fclose(file);
    ASSERT_FALSE(x.empty());
    EXPECT_NEAR(x.back(), expected.x, 1e-6) << method;
    EXPECT_NEAR(y.back(), expected.y, 1e-6) << method;
    EXPECT_NEAR(theta.back(), expected.theta, 1e-6) << method;
    // The unloaded start: a straight chain turned by the three kinks, tip at (cos b + cos(b+p))/2.
    EXPECT_NEAR(x.front(), 0.5 * (std::cos(kBeta) + std::cos(kBeta + kPhi)), 1e-12) << method;
    EXPECT_NEAR(theta.front(), kBeta + kPhi + kPsi, 1e-12) << method;
  }
}

SegmentChain kinks_only() {
  SegmentChain chain;
  chain.segments = {RigidSegment{0.0, 0.5}, RigidSegment{0.0, -0.2}};
  chain.tip_load.Fy = 1.0;
  return chain;
}

TEST(ChainKink, EverySolverRefusesAChainOfKinksOnly) {
  const SegmentChain chain = kinks_only();
  auto expect_invalid = [](auto&& solve, const char* who) {
    try {
      solve();
      ADD_FAILURE() << who << " accepted a chain of total length 0";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("total length is 0"), std::string::npos)
          << who << ": " << e.what();
    }
  };
  expect_invalid([&] { return ShootingSolver().solve(chain); }, "ShootingSolver::solve");
  expect_invalid([&] { return ShootingSolver().load_path(chain); }, "ShootingSolver::load_path");
  expect_invalid([&] { return ChainAlgorithmSolver().solve(chain); }, "ChainAlgorithmSolver");
}

TEST(ChainKink, EveryMethodExitsTwoForInvalidLengths) {
  ScratchDir dir;
  const struct {
    const char* file;
    const char* text;
    const char* message;
  } cases[] = {
      {"kinks.toml",
       "[[segment]]\ntype = \"rigid\"\nlength = 0\nangle_offset = 0.5\n[tip_load]\nFy = 1\n",
       "total length is 0"},
      {"flexible0.toml",
       "[[segment]]\ntype = \"flexible\"\nlength = 0\n[[segment]]\ntype = \"rigid\"\nlength = 1\n",
       "segment 1 (flexible): length must be > 0 (got 0)"},
      {"rigid_pinned.toml",
       "boundary = \"pinned\"\n[[segment]]\ntype = \"rigid\"\nlength = 1\n[tip]\ny = 0.1\n",
       "a pinned end needs a flexible segment"},
  };
  for (const auto& c : cases) {
    write(dir / c.file, c.text);
    const std::string file = (dir / c.file).string();
    for (const char* method : {"auto", "shooting", "chain", "elliptic", "prbm"}) {
      const test::CommandResult r =
          run_flexure("beam --json --method " + std::string(method) + " --chain " + file);
      EXPECT_EQ(r.exit_code, 2) << c.file << " " << method << "\n" << r.err;
      EXPECT_NE(r.err.find(c.message), std::string::npos)
          << c.file << " " << method << ": " << r.err;
      EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
      EXPECT_TRUE(test::no_result_on_stdout(r)) << r.out;
    }
    for (const char* method : {"shooting", "chain"}) {
      const test::CommandResult r =
          run_flexure("path --method " + std::string(method) + " --chain " + file + " --out " +
                      (dir / "p.h5").string());
      EXPECT_EQ(r.exit_code, 2) << c.file << " path " << method << "\n" << r.err;
      EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
      EXPECT_FALSE(std::filesystem::exists(dir / "p.h5")) << "path wrote a file for bad input";
    }
  }
}

}  // namespace
}  // namespace flexure
