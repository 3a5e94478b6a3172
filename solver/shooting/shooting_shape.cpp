#include <fmt/format.h>

#include <cmath>
#include <string>

#include "flexure/solver/chain_model/held_stability.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/path_point_stability.h"
#include "flexure/solver/shooting/shooting_problem.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

std::vector<ShapePoint> shooting_shape_at(const SegmentChain& chain,
                                          const ShootingResult& result,
                                          const std::vector<double>& s,
                                          const ShootingSolver::Options& options) {
  if (!result.converged()) {
    throw InvalidInput("cannot evaluate the shape of an unconverged shooting result");
  }
  const double total = chain.total_length();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!(s[i] >= 0.0 && s[i] <= total) || (i > 0 && s[i] < s[i - 1])) {
      throw InvalidInput(fmt::format(
          "arc length s = {} (point {}) is outside [0, {}] or out of order", s[i], i + 1, total));
    }
  }
  const ShootingProblem problem(chain, options.multiple_shooting);
  ElasticaIntegrator integrator(options.integrator_options());
  std::string error;
  // The result's unknowns when they fit this problem (its cut states keep large loads accurate);
  // otherwise (a two-stage solve keeps another layout) the root unknowns completed from the clamp.
  Eigen::VectorXd z;
  if (static_cast<int>(result.unknowns.size()) == problem.size()) {
    z = Eigen::Map<const Eigen::VectorXd>(result.unknowns.data(), problem.size());
  } else {
    Eigen::VectorXd root(problem.root_unknown_count());
    if (static_cast<int>(result.unknowns.size()) < root.size()) {
      throw InvalidInput("the shooting result has fewer unknowns than its chain's root loads");
    }
    for (int i = 0; i < root.size(); ++i) root[i] = result.unknowns[static_cast<std::size_t>(i)];
    if (!problem.complete_guess(root, 1.0, integrator, z, error)) {
      throw NoConvergence("integrating the shooting solution failed: " + error);
    }
  }
  TipState tip;
  std::vector<ShapePoint> shape;
  if (!problem.integrate_solution(z, 1.0, integrator, tip, error, &s, &shape)) {
    throw NoConvergence("integrating the shooting solution failed: " + error);
  }
  const double miss = std::hypot(tip.x - result.tip.x, tip.y - result.tip.y);
  if (!(miss <= 1e-8 * total) || shape.size() != s.size()) {
    throw NoConvergence(fmt::format(
        "the shooting solution integrated again ends {:.3g} from its tip: not this chain's result",
        miss));
  }
  return shape;
}

Stability path_point_stability(const SegmentChain& chain,
                               const PathPoint& point,
                               const PrescribedMask& held,
                               const ShootingSolver::Options& options,
                               const StabilityOptions& stability) {
  if (chain.tip_load.follower != 0.0) {
    return not_conservative_stability(
        fmt::format("a follower force of {:.6g} acts at the tip", chain.tip_load.follower));
  }
  // The same equilibrium with every tip load dead and given: the support's reactions act like dead
  // loads in the second variation (segment_chain.h), the held coordinates are its
  // constraints.
  SegmentChain free = chain;
  free.end = EndCondition::kFree;
  free.prescribed = TipPrescription{};
  free.tip_load = TipLoad{point.tip_load.Fx, point.tip_load.Fy, point.tip_load.M, 0.0};
  const double factor = point.stage == 1 ? point.lambda : 1.0;
  for (NodeLoad& load : free.node_loads) {
    load.Fx *= factor;
    load.Fy *= factor;
    load.M *= factor;
  }
  // The distributed loads at the point's load factor too (SegmentChain::at_load_factor).
  free.segments = chain.at_load_factor(factor).segments;
  ShootingSolver::Options o = options;
  o.shape_points = 0;
  o.count_inflections = false;
  // The clamp moment is the only root unknown of a free end: m(0) = -M_clamp.
  const ShootingResult r = ShootingSolver(o).solve_from(free, {-point.reaction.M});
  const double total = chain.total_length();
  const double miss = std::hypot(r.tip.x - point.tip.x, r.tip.y - point.tip.y);
  // (A loose bound: another equilibrium of the same loads lies far away; the point's loads carry
  // the path's corrector tolerance, which an ill-conditioned free end amplifies.)
  if (!r.converged() || !(miss <= 1e-6 * total)) {
    return not_checked_stability(
        r.converged()
            ? fmt::format("the point's equilibrium could not be reproduced (tip {:.3g} away)", miss)
            : "the point's equilibrium could not be reproduced: " + r.message);
  }
  const ShapeAtStations shape = [&](const std::vector<double>& s) {
    return shooting_shape_at(free, r, s, o);
  };
  try {
    return equilibrium_stability_held(free, Reaction{}, shape, held, stability);
  } catch (const NoConvergence& e) {
    return not_checked_stability(e.what());
  } catch (const InvalidInput& e) {
    return not_checked_stability(e.what());
  }
}

}  // namespace flexure
