// What is checked against what: displacement-controlled paths (ShootingSolver::controlled_path)
// and the force points located on them (control_points.h), against independent solves.
//  * The inclined bistable beam of issue 31 (70 mm, clamped at 5.5 deg, 12.55 x 1.5 mm,
//    E = 1.379 GPa, extensible), its shuttle moved 12 mm across with x and angle held, leaving the
//    straight-compressed path at its first bifurcation: the shuttle force changes sign exactly
//    twice, and each located zero against a zero found independently by fixed-displacement solves
//    (Newton at fixed tip y from the neighbouring solution, the Dormand-Prince 5(4) integrator
//    instead of rk8pd, bisection on y), to 1e-9 m; the force minimum against fixed-displacement
//    solves on both sides of it; every path point's reactions against a fixed-displacement solve
//    at its tip (Dormand-Prince, from a perturbed guess) to 1e-8 N.
//  * Seeded random cross-check: random end conditions (guided, slider, pinned, fixed), moved
//    coordinates, inclinations and stiffness ratios EA L^2/EI in [1e2, 1e6] (and inextensible):
//    every point of the displacement-controlled path is an equilibrium of the free-ended beam
//    loaded by the path's tip loads (force control, Dormand-Prince, Newton on m(0) alone from a
//    perturbed guess): its tip lands on the path's tip to 1e-8 of the length.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "flexure/solver/shooting/control_points.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;

// Issue 31's inclined beam in SI units: the clamp turned by alpha0 (a zero-length rigid kink),
// so the root frame is the ground frame and the shuttle moves along y.
struct InclinedBeam {
  double L = 0.070, b = 12.55e-3, h = 1.5e-3, E = 1.379e9, alpha0 = 5.5 * kPi / 180.0;
  double EI() const { return E * b * h * h * h / 12.0; }
  double EA() const { return E * b * h; }
  SegmentChain chain() const {
    SegmentChain c;
    c.segments.push_back(RigidSegment{0.0, alpha0});
    FlexibleSegment f(L, EI());
    f.EA = EA();
    c.segments.push_back(f);
    c.end = EndCondition::kFixed;
    return c;
  }
  double y0() const { return L * std::sin(alpha0); }
};

ShootingSolver::Options dormand_prince() {
  ShootingSolver::Options o;
  o.backend = ElasticaIntegrator::Backend::kDormandPrince;
  o.rtol = 1e-12;
  return o;
}

// The fixed-end beam held at tip y (x and angle at their stress-free values), solved by Newton
// from the root unknowns `guess` with the Dormand-Prince integrator.
ShootingResult held_at(const InclinedBeam& beam, double y, const std::vector<double>& guess) {
  SegmentChain c = beam.chain();
  c.prescribed.y = y;
  return ShootingSolver(dormand_prince()).solve_from(c, guess);
}

std::vector<double> root_unknowns(const Eigen::VectorXd& z, int count) {
  return std::vector<double>(z.data(), z.data() + count);
}

LoadPath inclined_path(const InclinedBeam& beam) {
  ShootingSolver::Options o;
  o.continuation.switch_at_bifurcation = 1;
  o.continuation.max_load_step = 1.0 / 60.0;
  DisplacementControl control{TipCoordinate::kY, beam.y0() - 0.012};
  control.one_way = true;
  return ShootingSolver(o).controlled_path(beam.chain(), control);
}

TEST(DisplacementPath, InclinedBistableBeamForceChangesSignTwice) {
  const InclinedBeam beam;
  const LoadPath path = inclined_path(beam);
  ASSERT_TRUE(path.converged()) << path.message;
  ASSERT_TRUE(path.switched_branch);
  std::vector<const ForcePoint*> zeros;
  for (const ForcePoint& f : path.force_points) {
    EXPECT_TRUE(f.located) << to_string(f.kind) << " at " << f.coordinate;
    if (f.kind == ForcePointKind::kZero) zeros.push_back(&f);
  }
  // The sampled force's sign changes, counted independently of the located points.
  int changes = 0;
  for (std::size_t i = 2; i < path.points.size(); ++i) {
    const double a = path.points[i - 1].tip_load.Fy, b = path.points[i].tip_load.Fy;
    if ((a < 0.0 && b > 0.0) || (a > 0.0 && b < 0.0)) ++changes;
  }
  EXPECT_EQ(changes, 2);
  ASSERT_EQ(zeros.size(), 2u);
  // Every zero: x and the angle held, the force zero, and the crossing against bisection on
  // fixed-displacement solves started from the path point before it.
  for (const ForcePoint* z : zeros) {
    EXPECT_NEAR(z->tip.x, beam.L * std::cos(beam.alpha0), 1e-12);
    EXPECT_NEAR(z->tip.theta, beam.alpha0, 1e-12);
    EXPECT_NEAR(z->force, 0.0, 1e-9);
    const PathPoint& before = path.points[z->index_before];
    // Step from the sample before the zero to a y past it at fixed displacement.
    double y_lo = before.tip.y;
    std::vector<double> guess = root_unknowns(before.z, 3);
    ShootingResult r = held_at(beam, y_lo, guess);
    ASSERT_TRUE(r.converged()) << r.message;
    const double f_lo = r.tip_load.Fy;
    const double dy = (z->coordinate - y_lo) / 4.0;
    double y_hi = y_lo;
    std::vector<double> lo_guess =
        root_unknowns(Eigen::Map<const Eigen::VectorXd>(r.unknowns.data(), r.unknowns.size()), 3);
    std::vector<double> hi_guess = lo_guess;
    for (int k = 0; k < 8; ++k) {
      y_hi += dy;
      r = held_at(beam, y_hi, hi_guess);
      ASSERT_TRUE(r.converged()) << r.message;
      hi_guess.assign(r.unknowns.begin(), r.unknowns.begin() + 3);
      if (r.tip_load.Fy * f_lo < 0.0) break;
      y_lo = y_hi;
      lo_guess = hi_guess;
    }
    ASSERT_LT(r.tip_load.Fy * f_lo, 0.0) << "no sign change by fixed-displacement stepping";
    for (int k = 0; k < 60 && std::fabs(y_hi - y_lo) > 1e-13; ++k) {
      const double mid = 0.5 * (y_lo + y_hi);
      const ShootingResult m = held_at(beam, mid, lo_guess);
      ASSERT_TRUE(m.converged()) << m.message;
      if (m.tip_load.Fy * f_lo > 0.0) {
        y_lo = mid;
        lo_guess.assign(m.unknowns.begin(), m.unknowns.begin() + 3);
      } else {
        y_hi = mid;
      }
    }
    EXPECT_NEAR(z->coordinate, 0.5 * (y_lo + y_hi), 1e-9);
  }
  // The pushed shuttle (moved to -y): the pushing force -Fy is positive, then negative between
  // the zeros (it pulls: the beam snaps on its own), then positive past the second stable state.
  // The first zero: both ends at the same height (y = 0), where the beam is point-symmetric
  // about its midpoint and the transverse force vanishes exactly.
  EXPECT_NEAR(zeros[0]->coordinate, 0.0, 1e-12);
  // slope = dFy/dy = d(-Fy)/d(push): negative at the first zero (unstable when released), positive
  // at the second (the second stable position).
  EXPECT_LT(zeros[0]->slope, 0.0);
  EXPECT_GT(zeros[1]->slope, 0.0);
}

TEST(DisplacementPath, InclinedBeamForceMinimumAndReactionsAgainstFixedDisplacementSolves) {
  const InclinedBeam beam;
  const LoadPath path = inclined_path(beam);
  ASSERT_TRUE(path.converged()) << path.message;
  // Every path point of the moving stage against a fixed-displacement solve from a perturbed
  // guess with another integrator.
  // Points within 1e-3 of a bifurcation are skipped: there the residual (1e-10 m) is divided by
  // a small singular value, and a perturbed guess may land on the other branch through it.
  // The one-way restart next to the second bifurcation (where the branch number changes) counts
  // as one.
  std::vector<double> singular;
  for (const SpecialPoint& sp : path.special_points) singular.push_back(sp.lambda);
  for (std::size_t i = 1; i < path.points.size(); ++i) {
    if (path.points[i].branch != path.points[i - 1].branch) {
      singular.push_back(path.points[i].lambda);
    }
  }
  auto near_bifurcation = [&](double lambda) {
    for (double at : singular) {
      if (std::fabs(at - lambda) < 1e-3) return true;
    }
    return false;
  };
  int compared = 0;
  for (const PathPoint& p : path.points) {
    if (p.lambda == 0.0 || near_bifurcation(p.lambda)) continue;
    ++compared;
    std::vector<double> guess = root_unknowns(p.z, 3);
    for (double& g : guess) g *= 1.0 + 1e-3;
    const ShootingResult r = held_at(beam, p.tip.y, guess);
    ASSERT_TRUE(r.converged()) << r.message;
    // The Newton tolerance is 1e-10 on the tip position; the axial stiffness EA/L = 3.7e5 N/m
    // turns it into up to 4e-5 N: 1e-6 N (2.5e-8 of the 39 N compression) and 1e-8 N m hold.
    EXPECT_NEAR(r.tip_load.Fx, p.tip_load.Fx, 1e-6) << "y = " << p.tip.y;
    EXPECT_NEAR(r.tip_load.Fy, p.tip_load.Fy, 1e-6) << "y = " << p.tip.y;
    EXPECT_NEAR(r.tip_load.M, p.tip_load.M, 1e-8) << "y = " << p.tip.y;
    EXPECT_NEAR(r.reaction.M, p.reaction.M, 1e-8) << "y = " << p.tip.y;
  }
  EXPECT_GT(compared, 50);
  // The force extrema: no sample beyond them, and fixed-displacement solves on both sides.
  int extrema = 0;
  for (const ForcePoint& f : path.force_points) {
    if (f.kind == ForcePointKind::kZero) continue;
    ++extrema;
    const double sign = f.kind == ForcePointKind::kMaximum ? 1.0 : -1.0;
    // A local extremum: the samples next to it (two on each side) do not exceed it.
    for (int i = f.index_before - 1; i <= f.index_before + 2; ++i) {
      if (i < 0 || i >= static_cast<int>(path.points.size())) continue;
      EXPECT_LE(sign * path.points[i].tip_load.Fy, sign * f.force + 1e-12) << "row " << i;
    }
    if (path.points[f.index_before].status == PathStatus::kBifurcation) continue;  // a corner
    const std::vector<double> guess = root_unknowns(path.points[f.index_before].z, 3);
    for (double h : {-1e-5, 1e-5}) {
      const ShootingResult r = held_at(beam, f.coordinate + h, guess);
      ASSERT_TRUE(r.converged()) << r.message;
      EXPECT_LE(sign * r.tip_load.Fy, sign * f.force + 1e-12) << "h = " << h;
    }
  }
  // The buckling peak (at the bifurcation) and the snap-through minimum between the zeros.
  EXPECT_EQ(extrema, 2);
}

TEST(DisplacementPath, InclinedBeamNeedsTheExtensibleModel) {
  // The same beam inextensible: held at both ends, its straight start is a bifurcation (any
  // shortening needs buckling), so the path cannot start; the message says why.
  const InclinedBeam beam;
  SegmentChain chain = beam.chain();
  std::get<FlexibleSegment>(chain.segments[1]).EA = std::numeric_limits<double>::infinity();
  const LoadPath path =
      ShootingSolver().controlled_path(chain, {TipCoordinate::kY, beam.y0() - 0.012});
  EXPECT_FALSE(path.converged());
  EXPECT_TRUE(path.singular_start);
  EXPECT_NE(path.message.find("cannot start"), std::string::npos) << path.message;
}

// A random beam: inclination, stiffness ratio (or inextensible), end condition, moved coordinate
// and target.
struct RandomCase {
  SegmentChain chain;
  DisplacementControl control;
};

RandomCase random_case(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RandomCase c;
  const double alpha0 = (u(rng) - 0.5) * 0.4;
  c.chain.segments.push_back(RigidSegment{0.0, alpha0});
  FlexibleSegment f(0.5 + u(rng), 0.5 + 2.0 * u(rng));
  const bool extensible = u(rng) < 0.75;
  if (extensible) f.EA = f.EI / (f.length * f.length) * std::pow(10.0, 2.0 + 4.0 * u(rng));
  const int kind = static_cast<int>(4.0 * u(rng));
  // Both x and y held (pinned, fixed): a straight inextensible beam cannot start (its start is a
  // bifurcation, InclinedBeamNeedsTheExtensibleModel), so those are extensible.
  if (kind >= 2 && !f.extensible()) {
    f.EA = f.EI / (f.length * f.length) * std::pow(10.0, 2.0 + 4.0 * u(rng));
  }
  c.chain.segments.push_back(f);
  const double L = f.length;
  const ChainPose tip{L * std::cos(alpha0), L * std::sin(alpha0), alpha0};
  switch (kind) {
    case 0:  // guided: move y
      c.chain.end = EndCondition::kGuided;
      c.control = {TipCoordinate::kY, tip.y + (u(rng) - 0.5) * 0.5 * L};
      break;
    case 1:  // slider: move the angle
      c.chain.end = EndCondition::kSlider;
      c.control = {TipCoordinate::kTheta, alpha0 + (u(rng) - 0.5) * 1.5};
      break;
    case 2:  // pinned: move y (x held) towards the root's height, never farther than the length
      // (a bar pulled past its length stretches under forces ~EA, which the continuation,
      // scaled at its start, follows only in thousands of steps: a limit of the step control)
      c.chain.end = EndCondition::kPinned;
      c.control = {
          TipCoordinate::kY,
          tip.y - std::copysign(u(rng) * std::min(0.3 * L, 1.9 * std::fabs(tip.y)), tip.y)};
      break;
    default:  // fixed: move y (x and angle held) across the root's height, as the bistable beam
      c.chain.end = EndCondition::kFixed;
      c.control = {
          TipCoordinate::kY,
          tip.y - std::copysign(u(rng) * std::min(0.3 * L, 1.9 * std::fabs(tip.y)), tip.y)};
      break;
  }
  return c;
}

TEST(DisplacementPath, SeededRandomPathPointsAreEquilibriaUnderForceControl) {
  std::mt19937 rng(2931);
  int checked = 0, crossings = 0;
  for (int trial = 0; trial < 16; ++trial) {
    const RandomCase c = random_case(rng);
    const LoadPath path = ShootingSolver().controlled_path(c.chain, c.control);
    const FlexibleSegment& f = std::get<FlexibleSegment>(c.chain.segments[1]);
    ASSERT_TRUE(path.converged()) << "trial " << trial << " (" << to_string(c.chain.end) << ", "
                                  << to_string(c.control.coordinate) << ", L " << f.length
                                  << ", EI " << f.EI << ", EA " << f.EA << ", alpha0 "
                                  << std::get<RigidSegment>(c.chain.segments[0]).angle_offset
                                  << "): " << path.message;
    const double L = c.chain.total_length();
    for (const PathPoint& p : path.points) {
      if (p.lambda == 0.0) continue;
      // The free-ended beam under the path's tip loads (dead), from a perturbed root moment.
      SegmentChain free = c.chain;
      free.end = EndCondition::kFree;
      free.prescribed = {};
      free.tip_load = TipLoad{p.tip_load.Fx, p.tip_load.Fy, p.tip_load.M, 0.0};
      const double m0 = -p.reaction.M;
      const ShootingResult r =
          ShootingSolver(dormand_prince()).solve_from(free, {m0 + 1e-6 * (1.0 + std::fabs(m0))});
      ASSERT_TRUE(r.converged()) << "trial " << trial << ": " << r.message;
      EXPECT_NEAR(r.tip.x, p.tip.x, 1e-8 * L) << "trial " << trial << ", lambda " << p.lambda;
      EXPECT_NEAR(r.tip.y, p.tip.y, 1e-8 * L) << "trial " << trial << ", lambda " << p.lambda;
      EXPECT_NEAR(r.tip.theta, p.tip.theta, 1e-8) << "trial " << trial << ", lambda " << p.lambda;
      ++checked;
    }
    // Each located zero: the support's load on the moved coordinate vanishes there.
    for (const ForcePoint& f : path.force_points) {
      if (f.kind != ForcePointKind::kZero || !f.located) continue;
      ++crossings;
      EXPECT_NEAR(conjugate_load(f.tip_load, c.control.coordinate), 0.0, 1e-9);
    }
  }
  EXPECT_GT(checked, 100);
  RecordProperty("crossings", crossings);
}

}  // namespace
}  // namespace flexure
