// chain_algorithm_check: Howell's chain algorithm (solver/chain/) as a second opinion on a solved
// exact point, for every topology of mechanism_exact.h.
//
// The chain algorithm reaches an equilibrium by proportional loading from the straight chain, so
// it finds the shooting solution only where that path leads there. Under the dead loads of a
// whole constant-force mechanism it often does not: along the slider the mechanism is neutrally
// stable by design (F nearly constant), the lps/sps cranks are post-buckled columns loaded from
// the far side (unstable under dead load), and a rigid link on a short flexure under a compressive
// force is a buckling problem of its own; prescribing the whole slider end instead starts the path
// at a bifurcation (the straight chain compressed along its axis). Measured on the built-in
// designs other than the two-force ones (spp, lpp, where the crank alone is a stable cantilever):
// the whole chains under their solved dead end loads land 1.2-7.2 r2 away from the solution.
//
// So every flexible segment of every chain of the exact model (the crank chain, the serial chain
// to the slider, the coupler chain of a middle pin) is cut into parts short enough that their
// equilibrium under dead loads is provably unique (dead_load_contraction below 1/2): each part is
// clamped at the solved pose of its root, carries at its tip the solved internal force and bending
// moment as dead loads, and the chain algorithm computes its deflection. The parts' tip poses,
// composed from the root with the rigid links in between (exact kinematics in both methods), give
// the chain's tip -- the slider joint, pivot 2 or the crank tip; its distance from the shooting tip
// is the reported tip error. It accumulates every part's discretisation error: O(N^-2) for the
// Howell variant, O(N^-3) for the corrected one (docs/theory-chain.md).
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/shooting/shooting_problem.h"

namespace flexure::mechanism {
namespace {

// Parts are cut until the contraction constant is below this: a margin below the bound's 1.
constexpr double kContractionTarget = 0.5;

double segment_length(const Segment& seg) {
  return std::holds_alternative<FlexibleSegment>(seg) ? std::get<FlexibleSegment>(seg).length
                                                      : std::get<RigidSegment>(seg).length;
}

// Lipschitz constant, in the max norm, of the map theta -> integral of m/EI for a uniform flexible
// part of length l under dead tip loads: a change of theta moves the tip of the part beyond s by at
// most (l - s) max|dtheta|, which changes m(s) by |N| times that, so the constant is
// |N| l^2/(2 EI). Below 1 the map is a contraction and the equilibrium unique for every load factor
// up to 1: the chain algorithm's load path cannot end anywhere else. (unique_equilibrium_bound of
// shooting_solver.h is the same integral for a whole chain; here rigid links are never part of a
// loaded piece.)
double dead_load_contraction(double force, double length, double EI) {
  return std::abs(force) * length * length / (2.0 * EI);
}

// A solved chain of the exact model: internal force (constant: the chains carry no node loads),
// root moment and the unknowns to integrate it again.
struct SolvedChain {
  bool ok = false;
  std::string message;
  Eigen::Vector2d N = Eigen::Vector2d::Zero();
  double m0 = 0.0;
  Eigen::VectorXd z;  // all shooting unknowns, in the layout of ShootingProblem(chain)
};

ShootingSolver::Options check_shooting_options() {
  return ShootingSolver::Options{};  // rk8pd at rtol 1e-12, as the stroke itself
}

SolvedChain solve_again(const SegmentChain& chain, const std::vector<double>& unknowns) {
  SolvedChain out;
  const ShootingResult s = ShootingSolver(check_shooting_options()).solve_from(chain, unknowns);
  if (!s.converged()) {
    out.message = "re-solving the shooting point failed: " + s.message;
    return out;
  }
  out.N << s.tip_load.Fx, s.tip_load.Fy;
  out.m0 = -s.reaction.M;
  out.z = Eigen::Map<const Eigen::VectorXd>(s.unknowns.data(), s.unknowns.size());
  out.ok = true;
  return out;
}

// Solved pose and bending moment at the ascending arc lengths `s`.
struct SolvedState {
  ChainPose pose;
  double m = 0.0;
};
bool solved_states(const SegmentChain& chain,
                   const SolvedChain& solved,
                   const std::vector<double>& s,
                   std::vector<SolvedState>& out,
                   std::string& error) {
  const ShootingSolver::Options so = check_shooting_options();
  const ShootingProblem problem(chain, so.multiple_shooting);  // solve_from's layout
  ElasticaIntegrator::Options io;
  io.backend = so.backend;
  io.rtol = so.rtol;
  io.atol = so.atol;
  ElasticaIntegrator integrator(io);
  TipState tip;
  std::vector<ShapePoint> shape;
  if (!problem.integrate_solution(solved.z, 1.0, integrator, tip, error, &s, &shape)) return false;
  if (shape.size() != s.size()) {
    error = "shape samples missing";
    return false;
  }
  out.clear();
  for (const ShapePoint& q : shape) {
    // m(s) = m(0) + N_x y - N_y x: statics of the distal part (segment_chain.h convention).
    out.push_back(SolvedState{ChainPose{q.x, q.y, q.theta},
                              solved.m0 + solved.N.x() * q.y - solved.N.y() * q.x});
  }
  return true;
}

// One chain of the exact model checked part by part (see the top of the file): tip_error (length
// units of the chain) and angle_error of the composed tip, which is returned in `tip`, with the
// chain's internal force in `N`.
ChainCheck check_chain(const SegmentChain& chain,
                       const std::vector<double>& unknowns,
                       const ChainAlgorithmSolver::Options& options,
                       ChainPose& tip,
                       Eigen::Vector2d& N) {
  ChainCheck c;
  const SolvedChain solved = solve_again(chain, unknowns);
  if (!solved.ok) {
    c.message = solved.message;
    return c;
  }
  // Cut points: every node, and each flexible segment into parts of equal length short enough
  // for the contraction target.
  struct Part {
    int segment = 0;
    double s0 = 0.0, length = 0.0;
  };
  std::vector<Part> parts;
  std::vector<double> s{0.0};
  double flexible_length = 0.0;
  for (int j = 0; j < chain.segment_count(); ++j) {
    const Segment& seg = chain.segments[j];
    const double len = segment_length(seg);
    if (const auto* f = std::get_if<FlexibleSegment>(&seg)) {
      double EI_min = f->EI;
      for (double v : f->EI_profile) EI_min = std::min(EI_min, v);
      const int count =
          std::max(1,
                   static_cast<int>(std::ceil(std::sqrt(
                       dead_load_contraction(solved.N.norm(), len, EI_min) / kContractionTarget))));
      for (int k = 0; k < count; ++k) {
        parts.push_back(Part{j, s.back(), len / count});
        s.push_back(s.back() + len / count);
      }
      flexible_length += len;
    } else {
      parts.push_back(Part{j, s.back(), len});
      s.push_back(s.back() + len);
    }
  }
  std::vector<SolvedState> state;
  std::string error;
  if (!solved_states(chain, solved, s, state, error)) {
    c.message = "integrating the shooting solution failed: " + error;
    return c;
  }
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // composed chain-algorithm tip
  double theta = 0.0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Segment& seg = chain.segments[parts[k].segment];
    if (const auto* rigid = std::get_if<RigidSegment>(&seg)) {
      // Exact kinematics, the same in both methods.
      theta += rigid->angle_offset;
      position += rigid->length * Eigen::Vector2d(std::cos(theta), std::sin(theta));
      continue;
    }
    // The part in the frame of its solved root (origin there, x along its tangent), loaded at its
    // tip by the solved internal force and moment.
    FlexibleSegment f = std::get<FlexibleSegment>(seg);
    if (!f.EI_profile.empty()) {
      c.message = "chain check: tabulated EI profiles are not supported";
      return c;
    }
    f.length = parts[k].length;
    SegmentChain part;
    part.segments.emplace_back(f);
    part.end = EndCondition::kFree;
    const ChainPose& a = state[k].pose;
    const Eigen::Rotation2D<double> to_part(-a.theta);
    const Eigen::Vector2d N = to_part * solved.N;
    part.tip_load = TipLoad{N.x(), N.y(), state[k + 1].m, 0.0};
    ChainAlgorithmSolver::Options o = options;
    // Elements shared in proportion to length, as the chain algorithm does over a whole chain.
    o.elements = std::max(
        1, static_cast<int>(std::lround(options.elements * parts[k].length / flexible_length)));
    o.refine_elements = false;  // a convergence study in N: each N is measured as it is
    const ChainResult r = solve_chain(part, o);
    ++c.pieces;
    if (!r.converged()) {
      c.message = fmt::format(
          "segment {}, part at s = {:.6g}: {}", parts[k].segment, parts[k].s0, r.message);
      return c;
    }
    // In the composed chain the part's root is the chain algorithm's tip of the parts before it.
    position += Eigen::Rotation2D<double>(theta) * Eigen::Vector2d(r.tip.x, r.tip.y);
    theta += r.tip.theta;
  }
  const ChainPose& exact = state.back().pose;
  tip = ChainPose{position.x(), position.y(), theta};
  N = solved.N;
  c.tip_error = std::hypot(position.x() - exact.x, position.y() - exact.y);
  c.angle_error = std::abs(theta - exact.theta);
  c.set_converged(true);
  return c;
}

// The pinned-ends chain (psp, plp) starts with a zero-length rigid kink, the crank angle at the
// ground pin (mechanism_exact.h); the two-force crank starts with its flexure.
bool starts_with_root_kink(const SegmentChain& chain) {
  const auto* kink = std::get_if<RigidSegment>(&chain.segments.front());
  return kink != nullptr && kink->length == 0.0;
}

}  // namespace

ChainCheck chain_algorithm_check(const ExactPoint& point, int elements) {
  return chain_algorithm_check(point, elements, ChainVariant::kCorrected);
}

ChainCheck chain_algorithm_check(const ExactPoint& point, int elements, ChainVariant variant) {
  ChainCheck c;
  c.force = point.force;
  ChainAlgorithmSolver::Options o;
  o.elements = elements;
  o.variant = variant;
  o.record_load_path = false;
  std::vector<std::pair<const SegmentChain*, const std::vector<double>*>> chains{
      {&point.chain, &point.unknowns}};
  if (!point.coupler_chain.segments.empty()) {
    chains.emplace_back(&point.coupler_chain, &point.coupler_unknowns);
  }
  std::vector<ChainPose> tips;
  Eigen::Vector2d N = Eigen::Vector2d::Zero();
  for (const auto& [chain, unknowns] : chains) {
    ChainPose tip;
    const ChainCheck one = check_chain(*chain, *unknowns, o, tip, N);
    c.pieces += one.pieces;
    if (!one.converged()) {
      c.message =
          (chains.size() > 1 && chain != chains.front().first ? "coupler: " : "") + one.message;
      return c;
    }
    tips.push_back(tip);
    c.tip_error = std::max(c.tip_error, one.tip_error * point.length_scale);
    c.angle_error = std::max(c.angle_error, one.angle_error);
  }
  // The joint the chain-algorithm tips must close on (nondimensional; length_scale is the
  // undeflected slider position, so the slider joint is at xs = 1 - Delta x/length_scale).
  const double xs = 1.0 - point.displacement / point.length_scale;
  const ChainPose& t = tips.front();
  double closure = 0.0;
  if (tips.size() == 2) {
    // Middle pin: crank tip and coupler tip (its frame turned by pi about the slider) meet.
    closure = std::hypot(t.x + tips[1].x - xs, t.y + tips[1].y);
  } else if (point.chain.end == EndCondition::kFree && !starts_with_root_kink(point.chain)) {
    // Two-force coupler: pivot 2 lies on the line of the coupler force through the slider joint.
    closure = std::abs((t.x - xs) * N.y() - t.y * N.x()) / N.norm();
  } else {
    // Serial chain to the slider, or pinned ends: the tip is the slider joint.
    closure = std::hypot(t.x - xs, t.y);
  }
  c.closure_error = closure * point.length_scale;
  c.set_converged(true);
  c.message = fmt::format(
      "chain algorithm ({}) converged on all {} flexible parts", to_string(variant), c.pieces);
  return c;
}

}  // namespace flexure::mechanism
