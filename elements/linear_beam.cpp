#include "flexure/elements/ladder_models.h"
#include "flexure/solver/common/status.h"

namespace flexure {

LinearBeamSolver::LinearBeamSolver(Options options) : options_(options) { options_.validate(); }

LinearBeamResult LinearBeamSolver::solve(const CantileverCase& problem) const {
  problem.validate("linear");
  const double Fy = problem.load.Fy;
  LinearBeamResult r;
  r.end_moment =
      problem.end == EndCondition::kGuided ? problem.guided_tip_angle - Fy / 2.0 : problem.load.mu;
  r.tip.a_over_l = 1.0;
  r.tip.b_over_l = Fy / 3.0 + r.end_moment / 2.0;
  r.tip.theta0 = Fy / 2.0 + r.end_moment;
  r.root_moment = Fy + r.end_moment;
  r.termination = Termination::kConverged;
  r.message = "closed form (linear theory)";
  return r;
}

std::vector<ShapePoint> LinearBeamSolver::shape(const CantileverCase& problem,
                                                const LinearBeamResult& result,
                                                int count) const {
  if (count < 2) throw InvalidInput("the linear model's shape needs at least 2 points");
  const double Fy = problem.load.Fy;
  const double M = result.end_moment;
  std::vector<ShapePoint> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double s = static_cast<double>(i) / (count - 1);
    out.push_back({s,
                   s,
                   Fy * (s * s / 2.0 - s * s * s / 6.0) + M * s * s / 2.0,
                   Fy * (s - s * s / 2.0) + M * s});
  }
  return out;
}

}  // namespace flexure
