#include "flexure/solver/chain/chain_algorithm_solver.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "flexure/solver/chain/chain_constrained.h"
#include "flexure/solver/chain/chain_discretisation.h"
#include "flexure/solver/chain/chain_fixed_point.h"
#include "flexure/solver/chain/chain_pass.h"
#include "flexure/solver/chain/chain_transfer.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/chain_model/tip_reach.h"
#include "flexure/solver/common/status.h"

namespace flexure {

const char* to_string(ChainVariant variant) {
  switch (variant) {
    case ChainVariant::kHowell:
      return "howell";
    case ChainVariant::kCorrected:
      return "corrected";
  }
  return "unknown";
}

ChainVariant chain_variant_from_string(const std::string& name) {
  if (name == "howell") return ChainVariant::kHowell;
  if (name == "corrected") return ChainVariant::kCorrected;
  throw InvalidInput(
      fmt::format("chain variant '{}' is unknown; allowed: howell, corrected", name));
}

namespace {

// Everything that stays fixed during one solve.
struct Problem {
  ChainDiscretisation d;
  std::vector<int> unknowns;  // tip reaction components found by shooting: 0 Fx, 1 Fy, 2 M
  ChainPose start;            // stress-free tip (prescribed values at lambda = 0)
  ChainPose target;           // prescribed tip values at lambda = 1
  double length = 1.0;        // total chain length: scale of positions
  double unknown_scale[3] = {1.0, 1.0, 1.0};  // EI/l^2, EI/l^2, EI/l: finite-difference scale
};

// How one shooting evaluation turns reactions into a geometry.
struct Evaluation {
  bool single_pass = false;  // Howell's increment: one pass from the base geometry (eq. 7.24-7.27)
  FixedPointOptions fixed_point;
};

struct Trial {
  bool ok = false;
  ChainGeometry geometry;
  Eigen::VectorXd residual;  // tip coordinate minus prescribed value, positions over length
  double norm = INFINITY;
  int passes = 0;
  double change = 0.0;
  std::string failure;
};

ChainNodeLoads loads_at(const Problem& p, double lambda, const Eigen::Vector3d& z) {
  ChainNodeLoads loads = p.d.loads;
  for (double& v : loads.fx) v *= lambda;
  for (double& v : loads.fy) v *= lambda;
  for (double& v : loads.m) v *= lambda;
  loads.follower *= lambda;
  const int E = p.d.element_count();
  loads.fx[E] += z[0];
  loads.fy[E] += z[1];
  loads.m[E] += z[2];
  return loads;
}

Trial with_residual(const Problem& p, double lambda, Trial t);

Trial evaluate(const Problem& p,
               const Evaluation& how,
               double lambda,
               const Eigen::Vector3d& z,
               const ChainGeometry& base) {
  Trial t;
  const ChainNodeLoads loads = loads_at(p, lambda, z);
  t.geometry = base;
  if (how.single_pass) {
    const ChainPassReport r = chain_pass(p.d, loads, base, how.fixed_point.pass, t.geometry);
    t.passes = 1;
    t.change = std::max(r.position_change / p.length, r.angle_change);
    if (!r.ok) {
      t.failure = fmt::format("element {} buckled (eq. 7.30 has no inverse)", r.failed_element);
      return t;
    }
  } else {
    const FixedPointReport r = converge_chain(p.d, loads, t.geometry, how.fixed_point);
    t.passes = r.passes;
    t.change = r.change;
    if (!r.converged()) {
      t.failure =
          r.failed_element >= 0
              ? fmt::format("element {} buckled (eq. 7.30 has no inverse)", r.failed_element)
              : fmt::format("chain passes did not converge in {} passes (change {:.3g})",
                            r.passes,
                            r.change);
      return t;
    }
  }
  return with_residual(p, lambda, std::move(t));
}

// The tip residual (eq. 7.37) of a trial's geometry at load factor lambda.
Trial with_residual(const Problem& p, double lambda, Trial t) {
  const int E = p.d.element_count();
  const double tip[3] = {t.geometry.x[E], t.geometry.y[E], t.geometry.theta[E]};
  const double start[3] = {p.start.x, p.start.y, p.start.theta};
  const double target[3] = {p.target.x, p.target.y, p.target.theta};
  t.residual.resize(static_cast<int>(p.unknowns.size()));
  for (int k = 0; k < static_cast<int>(p.unknowns.size()); ++k) {
    const int c = p.unknowns[k];
    // Eq. 7.37, with the prescribed value moved proportionally with the load factor.
    const double wanted = start[c] + lambda * (target[c] - start[c]);
    t.residual[k] = (tip[c] - wanted) / (c == 2 ? 1.0 : p.length);
  }
  t.norm = t.residual.size() > 0 ? t.residual.lpNorm<Eigen::Infinity>() : 0.0;
  if (!std::isfinite(t.norm)) {
    t.failure = "non-finite tip coordinates";
    return t;
  }
  t.ok = true;
  return t;
}

struct StepOutcome {
  bool ok = false;
  Trial trial;
  Eigen::Vector3d z = Eigen::Vector3d::Zero();
  int passes = 0;
  int newton_iterations = 0;
  std::string failure;
};

// The shooting method of §7.2.1: Newton-Raphson on the tip reactions (eqs. 7.37-7.40) with a
// forward-difference Jacobian and a backtracking line search. Without unknowns it is one
// evaluation.
StepOutcome solve_step(const Problem& p,
                       const Evaluation& how,
                       double lambda,
                       const Eigen::Vector3d& z_guess,
                       const ChainGeometry& base,
                       const ChainAlgorithmSolver::Options& options) {
  StepOutcome out;
  out.z = z_guess;
  if (!p.unknowns.empty() && !how.single_pass && options.constrained_passes) {
    // Passes that meet the tip conditions as they go (chain_constrained.h).
    ConstrainedTip tip;
    tip.unknowns = p.unknowns;
    const double start[3] = {p.start.x, p.start.y, p.start.theta};
    const double target[3] = {p.target.x, p.target.y, p.target.theta};
    for (int c = 0; c < 3; ++c) {
      tip.wanted[c] = start[c] + lambda * (target[c] - start[c]);  // eq. 7.37, moved with lambda
      tip.unknown_scale[c] = p.unknown_scale[c];
    }
    tip.tolerance = options.shooting_tolerance;
    ChainGeometry geometry = base;
    const ConstrainedReport r = converge_constrained_chain(
        p.d, loads_at(p, lambda, Eigen::Vector3d::Zero()), tip, out.z, geometry, how.fixed_point);
    out.passes = r.passes;
    out.newton_iterations = r.iterations;  // each iteration corrects the reactions
    if (!r.converged()) {
      out.failure = r.failure;
      return out;
    }
    Trial converged;
    converged.geometry = std::move(geometry);
    converged.passes = r.passes;
    converged.change = r.change;
    out.trial = with_residual(p, lambda, std::move(converged));
    out.ok = out.trial.ok;
    if (!out.ok) out.failure = out.trial.failure;
    return out;
  }
  Trial current = evaluate(p, how, lambda, out.z, base);
  out.passes += current.passes;
  if (!current.ok) {
    out.failure = current.failure;
    return out;
  }
  const int n = static_cast<int>(p.unknowns.size());
  while (current.norm > options.shooting_tolerance) {
    if (out.newton_iterations >= options.max_newton_iterations) {
      out.failure =
          fmt::format("shooting: {} Newton iterations left the boundary residual at {:.3g}",
                      out.newton_iterations,
                      current.norm);
      return out;
    }
    ++out.newton_iterations;
    // Converged evaluations restart from the current solution, which keeps every evaluation a
    // few passes; a single-pass evaluation must always start from the increment's base geometry.
    const ChainGeometry& from = how.single_pass ? base : current.geometry;
    Eigen::MatrixXd J(n, n);
    for (int k = 0; k < n; ++k) {
      const int c = p.unknowns[k];
      const double h = 1e-6 * std::max(std::abs(out.z[c]), p.unknown_scale[c]);
      Eigen::Vector3d zh = out.z;
      zh[c] += h;
      const Trial th = evaluate(p, how, lambda, zh, from);
      out.passes += th.passes;
      if (!th.ok) {
        out.failure = "shooting: Jacobian evaluation failed: " + th.failure;
        return out;
      }
      J.col(k) = (th.residual - current.residual) / h;
    }
    // Eq. 7.39 as a minimum-norm least-squares step: at a straight, inextensible configuration
    // the axial reaction does not move the tip (a zero column of J), and the pseudo-inverse still
    // corrects the other unknowns until bending makes J regular.
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const double kRankThreshold = 1e-9;
    svd.setThreshold(kRankThreshold);
    if (svd.rank() == 0) {
      out.failure = "shooting: the tip does not respond to the reactions (zero Jacobian, eq. 7.38)";
      return out;
    }
    const Eigen::VectorXd dz = svd.solve(-current.residual);
    double step = 1.0;
    bool accepted = false;
    for (int halving = 0; halving < 8 && !accepted; ++halving, step *= 0.5) {
      Eigen::Vector3d trial_z = out.z;
      for (int k = 0; k < n; ++k) trial_z[p.unknowns[k]] += step * dz[k];  // eq. 7.40
      Trial trial = evaluate(p, how, lambda, trial_z, from);
      out.passes += trial.passes;
      if (trial.ok && trial.norm < current.norm) {
        out.z = trial_z;
        current = std::move(trial);
        accepted = true;
      }
    }
    if (!accepted) {
      out.failure = fmt::format("shooting: no Newton step reduced the boundary residual {:.3g}",
                                current.norm);
      return out;
    }
  }
  out.ok = true;
  out.trial = std::move(current);
  return out;
}

Problem make_problem(const SegmentChain& chain, int elements) {
  Problem p;
  p.d = discretise(chain, elements);
  const PrescribedMask mask = prescribed_mask(chain.end);
  if (mask.x) p.unknowns.push_back(0);
  if (mask.y) p.unknowns.push_back(1);
  if (mask.theta) p.unknowns.push_back(2);
  p.start = chain.unloaded_tip();
  p.target = chain.prescribed_tip();
  p.length = chain.total_length();
  if (!(p.length > 0.0)) throw InvalidInput("segment chain: total length must be > 0");
  double EI = 0.0;
  for (const ChainElement& e : p.d.elements) {
    if (!e.rigid) EI = std::max(EI, e.EI);
  }
  if (EI == 0.0) EI = 1.0;
  p.unknown_scale[0] = EI / (p.length * p.length);
  p.unknown_scale[1] = EI / (p.length * p.length);
  p.unknown_scale[2] = EI / p.length;
  return p;
}

}  // namespace

void ChainAlgorithmSolver::Options::validate() const {
  const Options& o = *this;
  if (o.elements < 1) {
    throw InvalidInput(fmt::format("elements must be >= 1 (got {})", o.elements));
  }
  if (o.increments < 1) {
    throw InvalidInput(fmt::format("increments must be >= 1 (got {})", o.increments));
  }
  if (!(o.tolerance > 0.0) || !std::isfinite(o.tolerance)) {
    throw InvalidInput(fmt::format("chain tolerance must be > 0 (got {})", o.tolerance));
  }
  if (!(o.path_tolerance > 0.0) || !std::isfinite(o.path_tolerance)) {
    throw InvalidInput(fmt::format("chain path_tolerance must be > 0 (got {})", o.path_tolerance));
  }
  if (o.max_iterations < 1) {
    throw InvalidInput(fmt::format("chain max_iterations must be >= 1 (got {})", o.max_iterations));
  }
  if (!(o.min_load_step > 0.0) || !(o.min_load_step <= 1.0)) {
    throw InvalidInput(
        fmt::format("chain min_load_step must be in (0, 1] (got {})", o.min_load_step));
  }
  if (!(o.shooting_tolerance > 0.0) || !std::isfinite(o.shooting_tolerance)) {
    throw InvalidInput(
        fmt::format("chain shooting_tolerance must be > 0 (got {})", o.shooting_tolerance));
  }
  if (o.max_newton_iterations < 1) {
    throw InvalidInput(
        fmt::format("chain max_newton_iterations must be >= 1 (got {})", o.max_newton_iterations));
  }
  if (!(o.max_angle_step > 0.0)) {
    throw InvalidInput(fmt::format("chain max_angle_step must be > 0 (got {})", o.max_angle_step));
  }
  if (o.anderson_depth < 0 || o.anderson_depth > 50) {
    throw InvalidInput(
        fmt::format("chain anderson_depth must be in [0, 50] (got {})", o.anderson_depth));
  }
}

namespace {

// Flexible elements of the coarse chain whose load path predicts the requested one, or 0 when
// there is none: an eighth of the requested count, at least four per flexible segment, and only
// when that is at most half the requested count.
constexpr double kCoarseTolerance = 1e-6;  // passes and tip conditions of the coarse path

int coarse_element_count(const ChainAlgorithmSolver::Options& o, const ChainDiscretisation& d) {
  if (!o.coarse_path) return 0;
  int flexible_segments = 0;
  for (std::size_t j = 0; j + 1 < d.model_node.size(); ++j) {
    const int first = d.model_node[j];
    if (first < d.element_count() && !d.elements[first].rigid) ++flexible_segments;
  }
  const int coarse = std::max(4 * flexible_segments, o.elements / 8);
  return 2 * coarse <= o.elements ? coarse : 0;
}

ChainPose tip_of(const Problem& p, const ChainGeometry& g) {
  const int E = p.d.element_count();
  return ChainPose{g.x[E], g.y[E], g.theta[E]};
}

// Fills the shape, the tip and the reactions from a geometry at load factor `lambda`.
void fill_state(const Problem& p,
                const ChainGeometry& g,
                double lambda,
                const Eigen::Vector3d& z,
                ChainResult& r) {
  const int E = p.d.element_count();
  r.tip = tip_of(p, g);
  r.tip_pose = TipPose{r.tip.x / p.length, r.tip.y / p.length, r.tip.theta};
  r.tip_reaction = Reaction{z[0], z[1], z[2]};
  const ChainNodeLoads loads = loads_at(p, lambda, z);
  double Fx = 0.0, Fy = 0.0, M = 0.0;
  for (int j = 1; j <= E; ++j) {
    Fx += loads.fx[j];
    Fy += loads.fy[j];
    M += loads.m[j] + g.x[j] * loads.fy[j] - g.y[j] * loads.fx[j];
  }
  const double qx = -loads.follower * std::sin(g.theta[E]);
  const double qy = loads.follower * std::cos(g.theta[E]);
  Fx += qx;
  Fy += qy;
  M += g.x[E] * qy - g.y[E] * qx;
  r.root_reaction = Reaction{-Fx, -Fy, -M};
  r.root_moment = M;
  r.nodes.clear();
  r.nodes.reserve(E + 1);
  r.nodes.push_back(ShapePoint{0.0, g.x[0], g.y[0], g.theta[0]});
  for (int i = 1; i <= E; ++i) {
    const ChainElement& el = p.d.elements[i - 1];
    r.nodes.push_back(ShapePoint{el.s_start + el.length, g.x[i], g.y[i], g.theta[i]});
  }
}

// Whether the discretisation represents the converged shape (docs/theory-chain.md,
// "Self-checks"): no flexible element may turn by more than max_element_rotation beyond its
// stress-free curvature, and no element's chord may exceed its arc length by more than
// max_element_rotation^2 / 8 of it (an inextensible beam; a single element under alpha2 = 5 put
// the tip 1.8 lengths from the clamp). Returns the reason when not, empty otherwise.
std::string representation_problem(const SegmentChain& chain,
                                   const ChainResult& r,
                                   double max_element_rotation) {
  std::vector<double> ends;
  double s = 0.0;
  for (const Segment& segment : chain.segments) {
    s += std::visit([](const auto& seg) { return seg.length; }, segment);
    ends.push_back(s);
  }
  double worst_turn = 0.0, worst_stretch = 0.0;
  for (std::size_t i = 0; i + 1 < r.nodes.size(); ++i) {
    const ShapePoint& a = r.nodes[i];
    const ShapePoint& b = r.nodes[i + 1];
    const double h = b.s - a.s;
    if (!(h > 0.0)) continue;
    const std::size_t k = static_cast<std::size_t>(std::min<std::ptrdiff_t>(
        std::upper_bound(ends.begin(), ends.end(), 0.5 * (a.s + b.s)) - ends.begin(),
        static_cast<std::ptrdiff_t>(ends.size()) - 1));
    const auto* flexible = std::get_if<FlexibleSegment>(&chain.segments[k]);
    if (flexible == nullptr) continue;
    worst_turn = std::max(worst_turn, std::fabs(b.theta - a.theta - flexible->kappa0 * h));
    worst_stretch = std::max(worst_stretch, std::hypot(b.x - a.x, b.y - a.y) / h - 1.0);
  }
  // Howell's variant does not keep element lengths (no foreshortening): its chords exceed the arc
  // length by O(rotation^2); only a stretch beyond what max_element_rotation allows is a failure.
  if (worst_stretch > 0.125 * max_element_rotation * max_element_rotation) {
    return fmt::format(
        "an element's chord exceeds its arc length by {:.3g} of it: the elements are too long "
        "for this load",
        worst_stretch);
  }
  if (worst_turn > max_element_rotation) {
    return fmt::format("an element turns by {:.3g} rad > max_element_rotation {:.3g}",
                       worst_turn,
                       max_element_rotation);
  }
  return {};
}

// The flexible elements that represent the load (the self-check of representation_problem), as
// predicted from the coarse chain's answer: the elements are refined by doublings of the requested
// count, as a failed check would, but before the requested chain is solved, so that it is solved
// once. Each coarse element's curvature beyond the stress-free one is its turn over its length;
// the peak inside it is extrapolated from its neighbours' (half the difference: the curvature of a
// cantilever peaks at the clamp, where an element average lies below it), and a fine element turns
// by that curvature times its length, which must stay within max_element_rotation (as the check
// asks; where the prediction falls short, the check still fails and doubles).
int predicted_elements(const SegmentChain& chain,
                       const std::vector<ShapePoint>& coarse_nodes,
                       const ChainAlgorithmSolver::Options& o) {
  std::vector<double> ends;
  double s = 0.0, flexible_length = 0.0;
  for (const Segment& segment : chain.segments) {
    const double length = std::visit([](const auto& seg) { return seg.length; }, segment);
    s += length;
    ends.push_back(s);
    if (std::holds_alternative<FlexibleSegment>(segment)) flexible_length += length;
  }
  // Signed curvature beyond kappa0 of each coarse element and its segment (-1: rigid).
  std::vector<double> kappa;
  std::vector<int> segment_of;
  for (std::size_t i = 0; i + 1 < coarse_nodes.size(); ++i) {
    const ShapePoint& a = coarse_nodes[i];
    const ShapePoint& b = coarse_nodes[i + 1];
    const double h = b.s - a.s;
    const std::size_t k = static_cast<std::size_t>(std::min<std::ptrdiff_t>(
        std::upper_bound(ends.begin(), ends.end(), 0.5 * (a.s + b.s)) - ends.begin(),
        static_cast<std::ptrdiff_t>(ends.size()) - 1));
    const auto* flexible = std::get_if<FlexibleSegment>(&chain.segments[k]);
    if (flexible == nullptr || !(h > 0.0)) {
      kappa.push_back(0.0);
      segment_of.push_back(-1);
      continue;
    }
    kappa.push_back((b.theta - a.theta - flexible->kappa0 * h) / h);
    segment_of.push_back(static_cast<int>(k));
  }
  double peak = 0.0;
  for (std::size_t i = 0; i < kappa.size(); ++i) {
    if (segment_of[i] < 0) continue;
    double here = std::fabs(kappa[i]);
    for (std::size_t j : {i - 1, i + 1}) {  // i - 1 wraps to a huge index at i = 0
      if (j < kappa.size() && segment_of[j] == segment_of[i]) {
        here = std::max(here, std::fabs(kappa[i]) + 0.5 * std::fabs(kappa[i] - kappa[j]));
      }
    }
    peak = std::max(peak, here);
  }
  const double needed = peak * flexible_length / o.max_element_rotation;
  int elements = o.elements;
  while (elements < needed && 2 * elements <= o.max_elements) elements *= 2;
  return elements;
}

}  // namespace

ChainResult ChainAlgorithmSolver::solve(const SegmentChain& chain) const {
  options_.validate();
  chain.validate();
  require_reachable_tip(chain);
  Options o = options_;
  for (;;) {
    ChainResult r = solve_once(chain, o);
    // The count the coarse path predicted, if it refined (solve_once).
    if (r.elements > o.elements) o.elements = r.elements;
    if (!r.converged()) return r;
    const std::string problem = representation_problem(chain, r, o.max_element_rotation);
    if (!problem.empty()) {
      if (o.refine_elements && 2 * o.elements <= o.max_elements) {
        o.elements *= 2;  // refine and solve again
        continue;
      }
      r.set_converged(false);
      r.message =
          fmt::format("the chain with {} elements cannot represent this load: {}{}",
                      o.elements,
                      problem,
                      o.refine_elements ? fmt::format(" even at max_elements = {}", o.max_elements)
                                        : " (refinement is off)");
      return r;
    }
    if (o.elements != options_.elements) {
      r.message += fmt::format(" (refined from {} to {} elements, which represent this load)",
                               options_.elements,
                               o.elements);
    }
    // The chain algorithm's passes follow no limit point, so its answer must be a stable state of
    // the load path; an unstable one may lie off the path: the passes also converge to unstable
    // equilibria that the path never reaches (tests/solver/chain_self_check_test.cpp: tip angle
    // -1.02 where the path ends at 2.27), and they cannot tell the two apart.
    try {
      r.stability = equilibrium_stability(chain, r.tip_reaction, r.nodes);
    } catch (const InvalidInput& e) {
      r.stability = not_checked_stability(e.what());
    }
    if (r.stability.kind == StabilityKind::kUnstable) {
      r.set_converged(false);
      r.message = fmt::format(
          "the chain's passes converged to an unstable equilibrium (index {}, stability margin "
          "{:.6g}), which may not be the one the load path from zero reaches (the passes also "
          "settle on unstable equilibria off the path); the shooting method follows the path and "
          "labels its answer's stability, and a stable equilibrium can be asked for instead",
          r.stability.index,
          r.stability.margin);
    }
    return r;
  }
}

ChainResult ChainAlgorithmSolver::solve_once(const SegmentChain& chain,
                                             const Options& requested) const {
  Options o = requested;
  Problem p = make_problem(chain, o.elements);
  const bool corrected = o.variant == ChainVariant::kCorrected;

  Evaluation how;
  how.fixed_point.max_passes = o.max_iterations;
  how.fixed_point.tolerance = o.tolerance;
  how.fixed_point.length_scale = p.length;
  how.fixed_point.anderson_depth = o.accelerate ? o.anderson_depth : 0;
  how.fixed_point.pass.foreshortening = corrected;
  how.fixed_point.pass.curved_and_tapered_terms = corrected;
  how.fixed_point.pass.implicit_rotation = o.accelerate;

  ChainResult r;
  r.elements = p.d.flexible_elements;
  ChainGeometry geometry = unloaded_geometry(p.d);
  Eigen::Vector3d z = Eigen::Vector3d::Zero();
  double lambda = 0.0;
  auto record = [&](double load, const ChainGeometry& g, int passes) {
    if (o.record_load_path) r.load_path.push_back(ChainLoadPathPoint{load, tip_of(p, g), passes});
  };
  auto stop = [&](const std::string& why) {
    fill_state(p, geometry, lambda, z, r);
    r.load_factor = lambda;
    r.set_converged(false);
    r.message = fmt::format("{} variant stopped at load factor {:.6g} after {} increments: {}",
                            to_string(o.variant),
                            lambda,
                            r.increments,
                            why);
    return r;
  };

  if (!corrected && p.unknowns.empty()) {
    // Howell's load increments (eqs. 7.24-7.27): one plain pass each, arms from the previous
    // increment's geometry.
    Evaluation increment = how;
    increment.single_pass = true;
    increment.fixed_point.pass.implicit_rotation = false;
    for (int k = 1; k <= o.increments; ++k) {
      const double next = static_cast<double>(k) / o.increments;
      StepOutcome s = solve_step(p, increment, next, z, geometry, o);  // no unknowns: one pass
      r.iterations += s.passes;
      r.newton_iterations += s.newton_iterations;
      if (!s.ok) return stop(s.failure);
      geometry = std::move(s.trial.geometry);
      z = s.z;
      lambda = next;
      r.residual = s.trial.change;
      r.boundary_residual = s.trial.norm;
      ++r.increments;
      record(lambda, geometry, s.passes);
    }
    if (o.iterate_at_full_load) {
      StepOutcome s = solve_step(p, how, 1.0, z, geometry, o);
      r.iterations += s.passes;
      r.newton_iterations += s.newton_iterations;
      if (!s.ok) return stop("iteration at full load: " + s.failure);
      geometry = std::move(s.trial.geometry);
      z = s.z;
      r.residual = s.trial.change;
      r.boundary_residual = s.trial.norm;
    }
    fill_state(p, geometry, 1.0, z, r);
    r.load_factor = 1.0;
    r.set_converged(true);
    r.message = o.iterate_at_full_load
                    ? fmt::format("converged: {} increments, {} passes, last change {:.3g}",
                                  r.increments,
                                  r.iterations,
                                  r.residual)
                    : fmt::format(
                          "load increments only, no iteration at full load: {} passes; the "
                          "last pass still changed the geometry by {:.3g} (error O(1/increments))",
                          r.iterations,
                          r.residual);
    return r;
  }

  // The load path on a coarse chain, then the requested chain in one increment from its answer:
  // the path needs steps small enough to stay on its branch (max_angle_step), and on the coarse
  // chain they cost a fraction of the passes; the fine answer is the same discrete equilibrium as
  // the fine path's, reached from the coarse one's shape (docs/theory-chain.md §4).
  const int coarse = coarse_element_count(o, p.d);
  if (coarse > 0) {
    Options co = o;
    co.elements = coarse;
    co.coarse_path = false;
    // A predictor only: its own discretisation error (about 5e-4 at alpha2 = 10 for 12 elements,
    // §3) is far above these tolerances, which the fine increment then meets.
    co.tolerance = std::max(o.tolerance, kCoarseTolerance);
    co.path_tolerance = std::max(o.path_tolerance, kCoarseTolerance);
    co.shooting_tolerance = std::max(o.shooting_tolerance, kCoarseTolerance);
    const ChainResult c = solve_once(chain, co);
    r.iterations += c.iterations;
    if (c.converged() && o.refine_elements && o.predict_elements) {
      // Enough elements for this load from the start (predicted_elements), instead of solving
      // on the requested count, failing the representation check and solving again.
      const int elements = predicted_elements(chain, c.nodes, o);
      if (elements > o.elements) {
        o.elements = elements;
        p = make_problem(chain, elements);
        r.elements = p.d.flexible_elements;
        geometry = unloaded_geometry(p.d);
      }
    }
    if (c.converged()) {
      ChainGeometry coarse_geometry;
      for (const ShapePoint& q : c.nodes) {
        coarse_geometry.x.push_back(q.x);
        coarse_geometry.y.push_back(q.y);
        coarse_geometry.theta.push_back(q.theta);
      }
      const ChainGeometry start =
          transfer_geometry(discretise(chain, coarse), coarse_geometry, p.d);
      const Eigen::Vector3d z_coarse(c.tip_reaction.Fx, c.tip_reaction.Fy, c.tip_reaction.M);
      StepOutcome s = solve_step(p, how, 1.0, z_coarse, start, o);
      r.iterations += s.passes;
      r.newton_iterations += c.newton_iterations + s.newton_iterations;
      double turn = 0.0;
      for (std::size_t i = 0; s.ok && i < start.theta.size(); ++i) {
        turn = std::max(turn, std::abs(s.trial.geometry.theta[i] - start.theta[i]));
      }
      if (s.ok && turn <= o.max_angle_step) {
        geometry = std::move(s.trial.geometry);
        z = s.z;
        r.residual = s.trial.change;
        r.boundary_residual = s.trial.norm;
        // The path is the coarse chain's; its last point is the requested chain's answer.
        r.increments = c.increments;
        r.failed_increments = c.failed_increments;
        r.load_path = c.load_path;
        if (!r.load_path.empty()) r.load_path.pop_back();
        record(1.0, geometry, s.passes);
        fill_state(p, geometry, 1.0, z, r);
        r.load_factor = 1.0;
        r.set_converged(true);
        r.message = fmt::format(
            "converged: {} increments ({} retried) on a chain of {} elements, then one on the "
            "requested chain from its answer; {} passes in all, last change {:.3g}",
            c.increments,
            c.failed_increments,
            coarse,
            r.iterations,
            r.residual);
        return r;
      }
    }
    // Otherwise the path on the requested chain itself, as if there were no coarse one.
  }

  // Proportional loading with adaptive steps, converged at every step: the corrected variant, and
  // Howell's variant with tip conditions. (Shooting on the tip of an unconverged single pass puts
  // the increment error into the reactions; for stiff, nearly straight chains it grows without
  // bound, and fixed increments without retries jump between equilibria of pinned/fixed ends.)
  const double max_step = 1.0 / o.increments;
  double step = max_step;
  Eigen::Vector3d z_prev = Eigen::Vector3d::Zero();
  double lambda_prev = 0.0;
  ChainGeometry geometry_prev = geometry;
  ChainGeometry predicted = geometry;
  std::string last_failure;
  while (lambda < 1.0) {
    // Snap to full load when within rounding of it (ten steps of 0.1 do not sum to 1).
    const double next = lambda + step > 1.0 - 1e-12 ? 1.0 : lambda + step;
    // Predictor: reactions and geometry extrapolated linearly along the load path (secant).
    Eigen::Vector3d guess = z;
    const ChainGeometry* start = &geometry;
    if (lambda > lambda_prev) {
      const double w = (next - lambda) / (lambda - lambda_prev);
      guess = z + (z - z_prev) * w;
      for (std::size_t i = 0; i < geometry.x.size(); ++i) {
        predicted.x[i] = geometry.x[i] + w * (geometry.x[i] - geometry_prev.x[i]);
        predicted.y[i] = geometry.y[i] + w * (geometry.y[i] - geometry_prev.y[i]);
        predicted.theta[i] = geometry.theta[i] + w * (geometry.theta[i] - geometry_prev.theta[i]);
      }
      start = &predicted;
    }
    // Intermediate points only have to keep the path on its branch and give good predictions:
    // converge them to path_tolerance and only the last step to the full tolerances.
    Evaluation step_how = how;
    Options step_options = o;
    if (next < 1.0) {
      step_how.fixed_point.tolerance = std::max(o.tolerance, o.path_tolerance);
      step_options.shooting_tolerance = std::max(o.shooting_tolerance, 1e2 * o.path_tolerance);
    }
    StepOutcome s = solve_step(p, step_how, next, guess, *start, step_options);
    r.iterations += s.passes;
    r.newton_iterations += s.newton_iterations;
    double turn = 0.0;
    if (s.ok) {
      for (std::size_t i = 0; i < geometry.theta.size(); ++i) {
        turn = std::max(turn, std::abs(s.trial.geometry.theta[i] - geometry.theta[i]));
      }
      if (turn > o.max_angle_step) {
        s.ok = false;
        s.failure = fmt::format(
            "the step turned a node by {:.3g} rad > max_angle_step {:.3g}", turn, o.max_angle_step);
      }
    }
    if (!s.ok) {
      ++r.failed_increments;
      last_failure = s.failure;
      step *= 0.5;
      if (step < o.min_load_step) {
        return stop(fmt::format("a step of {:.3g} failed ({})", 2.0 * step, last_failure));
      }
      continue;
    }
    z_prev = z;
    lambda_prev = lambda;
    geometry_prev = geometry;
    geometry = std::move(s.trial.geometry);
    z = s.z;
    lambda = next;
    r.residual = s.trial.change;
    r.boundary_residual = s.trial.norm;
    ++r.increments;
    record(lambda, geometry, s.passes);
    // Grow the step again after an easy increment (few passes, small turn), never beyond
    // 1/increments.
    if (s.passes < o.max_iterations / 4 && turn < 0.5 * o.max_angle_step) {
      step = std::min(max_step, 1.5 * step);
    }
  }
  fill_state(p, geometry, 1.0, z, r);
  r.load_factor = 1.0;
  r.set_converged(true);
  r.message = fmt::format("converged: {} increments ({} retried), {} passes, last change {:.3g}",
                          r.increments,
                          r.failed_increments,
                          r.iterations,
                          r.residual);
  return r;
}

ChainResult ChainAlgorithmSolver::solve(const EndLoad& load) const {
  require_finite(load.Fx, "end load Fx");
  require_finite(load.Fy, "end load Fy");
  require_finite(load.mu, "end load mu");
  return solve(uniform_cantilever(load));
}

ChainResult solve_chain(const SegmentChain& chain, const ChainAlgorithmSolver::Options& options) {
  return ChainAlgorithmSolver(options).solve(chain);
}

}  // namespace flexure
