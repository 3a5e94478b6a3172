#include "flexure/solver/shooting/control_points.h"

#include <algorithm>
#include <cmath>

#include "flexure/solver/common/scalar_root.h"

namespace flexure {

const char* to_string(ForcePointKind kind) {
  switch (kind) {
    case ForcePointKind::kZero:
      return "force_zero";
    case ForcePointKind::kMaximum:
      return "force_maximum";
    case ForcePointKind::kMinimum:
      return "force_minimum";
  }
  return "unknown";
}

double conjugate_load(const Reaction& load, TipCoordinate coordinate) {
  return coordinate == TipCoordinate::kX   ? load.Fx
         : coordinate == TipCoordinate::kY ? load.Fy
                                           : load.M;
}

double coordinate_value(const ChainPose& tip, TipCoordinate coordinate) {
  return coordinate == TipCoordinate::kX   ? tip.x
         : coordinate == TipCoordinate::kY ? tip.y
                                           : tip.theta;
}

namespace {

// A point of the path corrected onto the hyperplane normal to the chord a-b at a + t (b - a).
struct OnPath {
  bool ok = false;
  Eigen::VectorXd z;
  double lambda = 0.0;
  TipState tip;
};

class ChordLocator {
 public:
  ChordLocator(const ShootingProblem& problem,
               ElasticaIntegrator& integrator,
               const NewtonOptions& newton,
               TipCoordinate coordinate,
               int& corrections)
      : problem_(problem),
        integrator_(integrator),
        newton_(newton),
        coordinate_(coordinate),
        corrections_(corrections) {}

  // Chooses the chord between two recorded points (scaled by the larger of their unknowns, at
  // least 1, as the continuation scales its own).
  void set_chord(const PathPoint& a, const PathPoint& b) {
    const int nz = problem_.size();
    scale_ = a.z.cwiseAbs().cwiseMax(b.z.cwiseAbs()).cwiseMax(1.0);
    ua_.resize(nz + 1);
    ub_.resize(nz + 1);
    ua_.head(nz) = a.z.cwiseQuotient(scale_);
    ua_[nz] = a.lambda;
    ub_.head(nz) = b.z.cwiseQuotient(scale_);
    ub_[nz] = b.lambda;
  }

  OnPath at(double t) {
    const int nz = problem_.size();
    const Eigen::VectorXd chord = ub_ - ua_;
    const double length = chord.norm();
    OnPath out;
    const Eigen::VectorXd predicted = ua_ + t * chord;
    out.z = predicted.head(nz).cwiseProduct(scale_);
    out.lambda = predicted[nz];
    if (!(length > 0.0)) return out;
    const ArclengthConstraint constraint{chord / length, predicted, scale_};
    ++corrections_;
    const NewtonOutcome nw =
        newton_solve(problem_, integrator_, newton_, out.z, out.lambda, &constraint);
    Eigen::VectorXd u(nz + 1);
    u.head(nz) = out.z.cwiseQuotient(scale_);
    u[nz] = out.lambda;
    // A corrector that left the neighbourhood of the chord found another branch.
    out.ok = nw.converged() && (u - predicted).norm() <= 0.5 * length;
    out.tip = nw.last.tip;
    return out;
  }

  double force(const OnPath& p) const {
    return conjugate_load(Reaction{p.tip.N.x(), p.tip.N.y(), p.tip.m}, coordinate_);
  }
  double coordinate(const OnPath& p) const {
    return coordinate_value(ChainPose{p.tip.x, p.tip.y, p.tip.theta}, coordinate_);
  }

  ForcePoint make(ForcePointKind kind, const OnPath& p, int index_before, const PathPoint& b) {
    ForcePoint f;
    f.kind = kind;
    f.lambda = p.lambda;
    f.tip = ChainPose{p.tip.x, p.tip.y, p.tip.theta};
    f.coordinate = coordinate(p);
    f.tip_load = Reaction{p.tip.N.x(), p.tip.N.y(), p.tip.m};
    f.force = conjugate_load(f.tip_load, coordinate_);
    f.reaction = problem_.reaction(p.z, p.lambda);
    f.index_before = index_before;
    f.stage = b.stage;
    f.branch = b.branch;
    return f;
  }

 private:
  const ShootingProblem& problem_;
  ElasticaIntegrator& integrator_;
  const NewtonOptions& newton_;
  TipCoordinate coordinate_;
  int& corrections_;
  Eigen::VectorXd scale_, ua_, ub_;
};

ForcePoint from_sample(
    ForcePointKind kind, const PathPoint& p, int index, TipCoordinate coordinate, bool located) {
  ForcePoint f;
  f.kind = kind;
  f.lambda = p.lambda;
  f.tip = p.tip;
  f.coordinate = coordinate_value(p.tip, coordinate);
  f.tip_load = p.tip_load;
  f.force = conjugate_load(p.tip_load, coordinate);
  f.reaction = p.reaction;
  f.index_before = index;
  f.stage = p.stage;
  f.branch = p.branch;
  f.located = located;
  return f;
}

// Golden-section search for the largest sign * force on the chord; returns the chord parameter
// and fills `best` (ok false when a correction failed).
double golden_extremum(ChordLocator& locator, double sign, OnPath& best) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = 0.0, b = 1.0;
  double c = b - g * (b - a), d = a + g * (b - a);
  OnPath pc = locator.at(c), pd = locator.at(d);
  bool ok = pc.ok && pd.ok;
  double fc = sign * locator.force(pc), fd = sign * locator.force(pd);
  // 1e-9 of the chord: the force at the extremum is then exact to ~1e-18 relative (it is flat).
  while (ok && b - a > 1e-9) {
    if (fc >= fd) {
      b = d;
      d = c;
      pd = pc;
      fd = fc;
      c = b - g * (b - a);
      pc = locator.at(c);
      ok = pc.ok;
      fc = sign * locator.force(pc);
    } else {
      a = c;
      c = d;
      pc = pd;
      fc = fd;
      d = a + g * (b - a);
      pd = locator.at(d);
      ok = pd.ok;
      fd = sign * locator.force(pd);
    }
  }
  best = fc >= fd ? pc : pd;
  best.ok = ok;
  return fc >= fd ? c : d;
}

}  // namespace

std::vector<ForcePoint> locate_force_points(const ShootingProblem& problem,
                                            ElasticaIntegrator& integrator,
                                            const NewtonOptions& newton,
                                            const LoadPath& path,
                                            TipCoordinate coordinate,
                                            int& corrections) {
  struct Keyed {
    double key;
    ForcePoint point;
  };
  std::vector<Keyed> found;
  const std::vector<PathPoint>& pts = path.points;
  const int n = static_cast<int>(pts.size());
  const int nz = problem.size();
  auto usable = [&](int i) { return static_cast<int>(pts[i].z.size()) == nz; };
  auto force = [&](int i) { return conjugate_load(pts[i].tip_load, coordinate); };
  ChordLocator locator(problem, integrator, newton, coordinate, corrections);

  // Zero crossings between consecutive points (the start, an equilibrium by construction when
  // the chain is unloaded, is not a crossing).
  for (int i = 0; i + 1 < n; ++i) {
    if (!usable(i) || !usable(i + 1)) continue;
    const double fa = force(i), fb = force(i + 1);
    if (!((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0) || (fb == 0.0 && fa != 0.0))) continue;
    if (fb == 0.0) {
      found.push_back(
          {i + 1.0, from_sample(ForcePointKind::kZero, pts[i + 1], i + 1, coordinate, true)});
      continue;
    }
    locator.set_chord(pts[i], pts[i + 1]);
    bool ok = true;
    OnPath last;
    const auto f = [&](double t) {
      last = locator.at(t);
      ok = ok && last.ok;
      return locator.force(last);
    };
    ScalarRootOptions ro;
    ro.x_tolerance = 1e-14;
    ro.max_iterations = 100;
    const ScalarRootResult root = brent_root(f, 0.0, 1.0, fa, fb, ro);
    const OnPath at = locator.at(root.x);
    if (!ok || !at.ok || !root.converged()) {
      const int nearer = std::fabs(fa) <= std::fabs(fb) ? i : i + 1;
      found.push_back(
          {i + 0.5, from_sample(ForcePointKind::kZero, pts[nearer], i, coordinate, false)});
      continue;
    }
    ForcePoint z = locator.make(ForcePointKind::kZero, at, i, pts[i + 1]);
    // The stiffness d force / d coordinate at the zero, by a central difference along the chord.
    const double h = std::min({1e-4, root.x, 1.0 - root.x});
    if (h > 1e-8) {
      const OnPath lo = locator.at(root.x - h), hi = locator.at(root.x + h);
      const double dc = locator.coordinate(hi) - locator.coordinate(lo);
      z.slope = lo.ok && hi.ok && dc != 0.0 ? (locator.force(hi) - locator.force(lo)) / dc
                                            : std::numeric_limits<double>::quiet_NaN();
    } else {
      z.slope = std::numeric_limits<double>::quiet_NaN();
    }
    found.push_back({i + root.x, z});
  }

  // Extrema: the sampled force rises then falls (a maximum) or falls then rises (a minimum).
  for (int i = 1; i + 1 < n; ++i) {
    if (!usable(i - 1) || !usable(i) || !usable(i + 1)) continue;
    const double left = force(i) - force(i - 1), right = force(i + 1) - force(i);
    const bool maximum = left > 0.0 && right < 0.0;
    const bool minimum = left < 0.0 && right > 0.0;
    if (!maximum && !minimum) continue;
    const ForcePointKind kind = maximum ? ForcePointKind::kMaximum : ForcePointKind::kMinimum;
    if (pts[i - 1].branch != pts[i + 1].branch) {
      // The path switched branch at point i (a bifurcation): the force has a corner there. A
      // one-way restart past a fold (shooting_solver.cpp) joins two parts at a point just apart
      // (1e-6 of the travel or more): no extremum is read from that junction.
      if (pts[i].status == PathStatus::kBifurcation) {
        found.push_back({static_cast<double>(i), from_sample(kind, pts[i], i, coordinate, true)});
      }
      continue;
    }
    const double sign = maximum ? 1.0 : -1.0;
    OnPath left_best, right_best;
    locator.set_chord(pts[i - 1], pts[i]);
    const double tl = golden_extremum(locator, sign, left_best);
    ForcePoint fl = locator.make(kind, left_best, i - 1, pts[i]);
    locator.set_chord(pts[i], pts[i + 1]);
    const double tr = golden_extremum(locator, sign, right_best);
    ForcePoint fr = locator.make(kind, right_best, i, pts[i + 1]);
    if (!left_best.ok || !right_best.ok) {
      found.push_back({static_cast<double>(i), from_sample(kind, pts[i], i, coordinate, false)});
      continue;
    }
    const bool use_left = sign * fl.force >= sign * fr.force;
    ForcePoint best = use_left ? fl : fr;
    best.slope = 0.0;
    found.push_back({use_left ? i - 1 + tl : i + tr, best});
  }
  std::stable_sort(
      found.begin(), found.end(), [](const Keyed& a, const Keyed& b) { return a.key < b.key; });
  std::vector<ForcePoint> out;
  for (Keyed& k : found) out.push_back(std::move(k.point));
  return out;
}

}  // namespace flexure
