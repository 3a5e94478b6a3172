#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/elements/ladder_models.h"
#include "flexure/solver/common/status.h"

namespace flexure {

void BcmSolver::Options::validate() const {
  if (!std::isfinite(slenderness) || slenderness < 0.0) {
    throw InvalidInput(fmt::format(
        "the slenderness l/t must be 0 (inextensible) or finite and > 0 (got {})", slenderness));
  }
}

double BcmSolver::Options::inverse_axial_stiffness() const {
  return slenderness > 0.0 ? 1.0 / (12.0 * slenderness * slenderness) : 0.0;
}

BcmSolver::BcmSolver(Options options) : options_(options) { options_.validate(); }

BcmResult BcmSolver::solve(const CantileverCase& problem) const {
  problem.validate("bcm");
  const bool guided = problem.end == EndCondition::kGuided;
  BcmResult r;
  r.p = problem.load.Fx;
  r.f = problem.load.Fy;
  const bcm::Symmetric2 K = bcm::stiffness(r.p);
  // The element must be stable under p: guided, f/y = K11 > 0; free, K positive definite (the
  // buckling loads of the header). Past them one element has no meaningful equilibrium.
  const bool stable = guided ? K.a11 > 0.0 : K.positive_definite();
  if (!stable) {
    const std::string why =
        r.p < 0.0
            ? fmt::format("beyond the element's buckling load (p = {})",
                          guided ? "-9.884, the clamped-guided column's -pi^2"
                                 : "-2.468, the "
                                   "cantilever's -pi^2/4")
            : std::string(
                  "a tension beyond the range of the expansion in p (the p^2 Q term overtakes "
                  "near p = 96)");
    throw OutsideMethodDomain(fmt::format(
        "the BCM's stiffness G + p P + p^2 Q is not positive definite at the axial load p = "
        "{:.6g}: {}; one element cannot represent this beam. The chained BCM (cbcm, several "
        "elements) and the exact methods (elliptic, shooting) can",
        r.p,
        why));
  }
  if (guided) {
    r.theta = problem.guided_tip_angle;
    r.y = (r.f - K.a12 * r.theta) / K.a11;
    r.m = K.a12 * r.y + K.a22 * r.theta;
    r.residual = std::fabs(K.a11 * r.y + K.a12 * r.theta - r.f);
  } else {
    r.m = problem.load.mu;
    const double det = K.determinant();
    r.y = (K.a22 * r.f - K.a12 * r.m) / det;
    r.theta = (K.a11 * r.m - K.a12 * r.f) / det;
    r.residual = std::max(std::fabs(K.a11 * r.y + K.a12 * r.theta - r.f),
                          std::fabs(K.a12 * r.y + K.a22 * r.theta - r.m));
  }
  r.x = bcm::axial_displacement(r.y, r.theta, r.p, options_.inverse_axial_stiffness());
  r.tip = {1.0 + r.x, r.y, r.theta};
  r.end_moment = r.m;
  r.root_moment = root_moment_of(r.tip, problem.load, r.m);
  r.inside_validity = std::fabs(r.y) <= bcm::kValidDeflection;
  r.termination = Termination::kConverged;
  r.message = "closed form (one BCM element)";
  if (!r.inside_validity) {
    r.warn(WarningKind::kOutsideValidity,
           fmt::format("the BCM's transverse deflection |y| = {:.3g} l exceeds its stated range "
                       "of about 0.1 l (Awtar et al. 2007); the chained BCM (cbcm) follows larger "
                       "deflections",
                       std::fabs(r.y)));
  }
  return r;
}

std::vector<ShapePoint> BcmSolver::shape(const BcmResult& result, int count) const {
  if (count < 2) throw InvalidInput("the BCM's shape needs at least 2 points");
  std::vector<ShapePoint> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double s = static_cast<double>(i) / (count - 1);
    // Hermite cubic through y(0) = y'(0) = 0, y(1) = y, y'(1) = theta.
    const double y = result.y * (3 * s * s - 2 * s * s * s) + result.theta * (s * s * s - s * s);
    const double slope = result.y * (6 * s - 6 * s * s) + result.theta * (3 * s * s - 2 * s);
    out.push_back({s, s * (1.0 + result.x), y, slope});  // theta: the BCM rotation
  }
  return out;
}

}  // namespace flexure
