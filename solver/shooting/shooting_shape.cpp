#include "flexure/solver/shooting/shooting_shape.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "flexure/solver/common/errors.h"

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

}  // namespace flexure
