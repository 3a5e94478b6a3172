// `--stable` for general mechanisms (mechanisms/general/stable_selection.h; docs/mechanisms.md
// "Stable equilibria (--stable)"): Howell's bistable switch (docs/examples/howell_bistable_switch
// .toml, Table 11.1) under torque control, where the traced path crosses the torques between 0
// and its limit point 0.2676 N m three times (two stable branches and the unstable one between),
// and the inclined bistable beam, whose unbuckled branch is unstable between its bifurcations with
// no other branch traced.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/general/stable_selection.h"

namespace flexure::mechanism::general {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

GeneralMechanism example(const std::string& file) {
  return load_general_mechanism_toml(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/" + file);
}

GeneralMechanism switch_under_torque(double start, double stop) {
  GeneralMechanism m = example("howell_bistable_switch.toml");
  m.input.control = InputControl::kForce;
  m.input.start = start;
  m.input.stop = stop;
  m.input.count = 13;
  return m;
}

// Loading from 0 to 1.2 N m: the switch stays on its first branch (theta2 from -0.3 deg) while it
// exists and snaps to the second (beyond theta2 = 28.96 deg, the other limit point) after the
// limit point of the torque, which lies between the grid values 0.2 and 0.3 N m. Unloading from
// 1.2 N m to 0 it stays on the second branch all the way: the hysteresis of a bistable switch. The
// selected points are checked against a displacement-controlled solve of the same model at their
// angles (another control: the torque there must be the grid torque) and against the path's own
// limit points. Both models.
TEST(GeneralStable, BistableSwitchUnderTorqueControlSnapsAtItsLimitPoint) {
  for (const bool exact : {false, true}) {
    const GeneralMechanism up = switch_under_torque(0.0, 1.2);
    const GeneralPrbmResult path = exact ? solve_general_exact(up) : solve_general_prbm(up);
    ASSERT_TRUE(path.converged()) << path.message;
    ASSERT_EQ(path.limit_loads.size(), 2u);
    const double limit_load = path.limit_loads[0];  // 0.2676 (PRBM), 0.2661 N m (exact)
    const double first_end = path.limit_inputs[0], second_start = path.limit_inputs[1];
    ASSERT_GT(limit_load, 0.2);
    ASSERT_LT(limit_load, 0.3);
    const StableSelection s = select_stable_points(up, path);
    EXPECT_TRUE(s.stable) << s.search;
    EXPECT_EQ(s.snaps, 1) << s.search;
    EXPECT_NE(s.search.find("between 0.2 N m and 0.3 N m"), std::string::npos) << s.search;
    ASSERT_EQ(s.result.points.size(), 13u);
    for (int k = 0; k < 13; ++k) {
      const GeneralPrbmPoint& p = s.result.points[static_cast<std::size_t>(k)];
      EXPECT_NEAR(p.input_load, 0.1 * k, 1e-9) << k;
      EXPECT_EQ(p.force_control.kind, StabilityKind::kStable) << k;
      if (k <= 2) {
        EXPECT_LT(p.input, first_end) << k;
      } else {
        EXPECT_GT(p.input, second_start) << k;
      }
    }
    // The same model under displacement control at the selected angles holds them with the grid
    // torques.
    GeneralMechanism held = example("howell_bistable_switch.toml");
    held.input.start = s.result.points[3].input;
    held.input.stop = s.result.points[12].input;
    held.input.count = 2;
    const GeneralPrbmResult h = exact ? solve_general_exact(held) : solve_general_prbm(held);
    ASSERT_TRUE(h.converged()) << h.message;
    EXPECT_NEAR(h.points[0].input_load, 0.3, 1e-8);
    EXPECT_NEAR(h.points[1].input_load, 1.2, 1e-8);
    // Unloading from 1.2 N m: the second branch to the end.
    const GeneralMechanism down = switch_under_torque(1.2, 0.0);
    const GeneralPrbmResult back = exact ? solve_general_exact(down) : solve_general_prbm(down);
    ASSERT_TRUE(back.converged()) << back.message;
    const StableSelection b = select_stable_points(down, back);
    EXPECT_TRUE(b.stable) << b.search;
    EXPECT_EQ(b.snaps, 0) << b.search;
    ASSERT_EQ(b.result.points.size(), 13u);
    for (const GeneralPrbmPoint& p : b.result.points) EXPECT_GT(p.input, second_start);
    // At 0 N m it rests at the second stable position, 32.30150 deg (Table 11.2: 32 deg).
    EXPECT_NEAR(b.result.points.back().input, 32.30150 * kDeg, 1e-6);
  }
}

// Under displacement control every point of the switch's crank path is stable: nothing to do.
TEST(GeneralStable, NotNeededWhereThePathIsStable) {
  const GeneralMechanism m = example("howell_bistable_switch.toml");
  const GeneralPrbmResult r = solve_general_prbm(m);
  ASSERT_TRUE(r.converged()) << r.message;
  const StableSelection s = select_stable_points(m, r);
  EXPECT_TRUE(s.stable);
  EXPECT_EQ(s.result.points.size(), 77u);
  EXPECT_EQ(s.search.rfind("not needed", 0), 0u) << s.search;
}

// The inclined beam held at its shuttle: the exact model's unbuckled branch is unstable between
// the bifurcations at 1.289366 mm and about 7.6618 mm (general_exact_stability_test.cpp), and the
// buckled branch is not traced. The grid's travels 1.3 ... 7.6 mm (64 values) have no stable
// point.
TEST(GeneralStable, NoStableEquilibriumWhereOnlyTheUnstableBranchIsTraced) {
  GeneralMechanism m = example("inclined_bistable_beam.toml");
  const GeneralPrbmResult r = solve_general_exact(m);
  ASSERT_TRUE(r.converged()) << r.message;
  const StableSelection s = select_stable_points(m, r);
  EXPECT_FALSE(s.stable);
  EXPECT_EQ(s.without_stable, 64) << s.search;
  EXPECT_NE(s.search.find("does not switch branches"), std::string::npos) << s.search;
}

// GeneralPrbmOptions::progress and select_stable_points' progress on the switch under torque
// control: the path records 19 points at the 13 torques (three crossings of those below the limit
// point), one call each, done never decreasing and capped at 13; the selection calls once per
// torque. Neither changes the answer, and a hook that throws stops either call with its exception.
TEST(GeneralStable, ProgressOfThePrbmPathAndTheSelection) {
  struct Stop {};
  const GeneralMechanism up = switch_under_torque(0.0, 1.2);
  const GeneralPrbmResult plain = solve_general_prbm(up);
  ASSERT_TRUE(plain.converged()) << plain.message;
  ASSERT_EQ(plain.points.size(), 19u);
  std::vector<std::pair<std::size_t, std::size_t>> calls;
  GeneralPrbmOptions o;
  o.progress = [&](std::size_t done, std::size_t total) { calls.emplace_back(done, total); };
  const GeneralPrbmResult path = solve_general_prbm(up, o);
  ASSERT_EQ(path.points.size(), plain.points.size());
  for (std::size_t i = 0; i < path.points.size(); ++i) {
    EXPECT_EQ(path.points[i].input, plain.points[i].input) << i;
    EXPECT_EQ(path.points[i].input_load, plain.points[i].input_load) << i;
  }
  ASSERT_EQ(calls.size(), 19u);
  EXPECT_EQ(calls.front(), std::make_pair(std::size_t{1}, std::size_t{13}));
  EXPECT_EQ(calls.back(), std::make_pair(std::size_t{13}, std::size_t{13}));
  for (std::size_t i = 1; i < calls.size(); ++i) {
    EXPECT_EQ(calls[i].second, 13u);
    EXPECT_GE(calls[i].first, calls[i - 1].first) << i;
  }

  std::vector<std::size_t> grid;
  const StableSelection with =
      select_stable_points(up, path, [&](std::size_t done, std::size_t total) {
        EXPECT_EQ(total, 13u);
        grid.push_back(done);
      });
  const StableSelection without = select_stable_points(up, path);
  EXPECT_EQ(grid, (std::vector<std::size_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13}));
  EXPECT_EQ(with.search, without.search);
  ASSERT_EQ(with.result.points.size(), without.result.points.size());
  for (std::size_t i = 0; i < with.result.points.size(); ++i) {
    EXPECT_EQ(with.result.points[i].input, without.result.points[i].input) << i;
  }

  std::vector<std::size_t> seen;
  o.progress = [&](std::size_t done, std::size_t) {
    seen.push_back(done);
    if (done == 2) throw Stop{};
  };
  EXPECT_THROW(solve_general_prbm(up, o), Stop);
  EXPECT_EQ(seen, (std::vector<std::size_t>{1, 2}));
  EXPECT_THROW(select_stable_points(up,
                                    path,
                                    [](std::size_t done, std::size_t) {
                                      if (done == 3) throw Stop{};
                                    }),
               Stop);
}

}  // namespace
}  // namespace flexure::mechanism::general
