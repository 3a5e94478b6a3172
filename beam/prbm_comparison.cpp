#include "flexure/beam/prbm_comparison.h"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"

namespace flexure {
namespace {

// Throws InvalidInput naming `what` and the allowed range unless lo <= value <= hi and finite.
void require_in_range(double value, const char* what, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InvalidInput(
        fmt::format("{} = {} is outside the allowed range [{}, {}]", what, value, lo, hi));
  }
}

// The errors of a comparison whose load, tips, Theta and load_prbm_at_exact are set.
void finish(PrbmComparison& c, double gamma, const ValidityLimits& limits) {
  const double deflection = std::hypot(1.0 - c.exact.a_over_l, c.exact.b_over_l);
  if (!std::isfinite(deflection)) {
    throw NoConvergence(fmt::format(
        "exact tip deflection came out as {}; no converged solution to report", deflection));
  }
  const PathSample sample{c.exact.theta0, c.exact.a_over_l, c.exact.b_over_l, c.load};
  c.Theta_exact = prb_angle(sample, gamma);
  c.path_error = relative_position_error(sample, gamma);
  c.position_error =
      std::hypot(c.prbm.a_over_l - c.exact.a_over_l, c.prbm.b_over_l - c.exact.b_over_l) /
      deflection;
  c.force_error = (c.load_prbm_at_exact - c.load) / c.load;
  c.inside_position = c.Theta <= limits.theta_max_position;
  c.inside_force = c.Theta <= limits.theta_max_force;
}

PrbmComparison fixed_pinned_at(const FixedPinnedSegment& element,
                               const ValidityLimits& limits,
                               double alpha2) {
  require_in_range(alpha2, "load alpha2 (P l^2/EI)", 1e-9, 1e4);
  const double n = element.constants().load_ratio_n;
  const EllipticResult exact = EllipticSolver().solve(EndLoad::howell(n, alpha2));
  if (!exact.converged()) throw NoConvergence("exact elliptic solve failed: " + exact.message);
  const PrbEquilibrium eq = element.solve(EndLoad::howell(n, alpha2));
  if (!eq.converged()) throw NoConvergence("PRBM equilibrium failed: " + eq.message);
  PrbmComparison c;
  c.load = alpha2;
  c.exact = exact.tip;
  c.prbm = eq.tip;
  c.Theta = eq.Theta;
  const double gamma = element.constants().gamma;
  c.load_prbm_at_exact = element.alpha2_at(
      prb_angle({exact.tip.theta0, exact.tip.a_over_l, exact.tip.b_over_l, alpha2}, gamma));
  finish(c, gamma, limits);
  return c;
}

PrbmComparison end_moment_at(const EndMomentSegment& element,
                             const ValidityLimits& limits,
                             double mu) {
  require_in_range(mu, "end moment mu (M l/EI)", 1e-9, 6.0);
  PrbmComparison c;
  c.load = mu;
  c.exact = {std::sin(mu) / mu, (1.0 - std::cos(mu)) / mu, mu};  // circle, eqs. 2.59, 2.64
  const PrbEquilibrium eq = element.solve(EndLoad{0.0, 0.0, mu});
  if (!eq.converged()) throw NoConvergence("PRBM equilibrium failed: " + eq.message);
  c.prbm = eq.tip;
  c.Theta = eq.Theta;
  const double gamma = element.constants().gamma;
  c.load_prbm_at_exact = element.stiffness_coefficient() *
                         prb_angle({mu, c.exact.a_over_l, c.exact.b_over_l, mu}, gamma);
  finish(c, gamma, limits);
  return c;
}

}  // namespace

const char* to_string(PrbmConstantsSource source) {
  return kPrbmConstantsSourceNames[static_cast<int>(source)];
}

PrbmConstantsSource prbm_constants_source_from_string(std::string_view name) {
  for (std::size_t i = 0; i < kPrbmConstantsSourceNames.size(); ++i) {
    if (name == kPrbmConstantsSourceNames[i]) return static_cast<PrbmConstantsSource>(i);
  }
  throw InvalidInput(fmt::format("PRBM constants source '{}' is unknown (allowed: {})",
                                 name,
                                 fmt::join(kPrbmConstantsSourceNames, ", ")));
}

PrbmComparator::PrbmComparator(Element element, std::string constants_source)
    : element_(std::move(element)), constants_source_(std::move(constants_source)) {
  limits_ = std::visit([](const auto& e) { return e.limits(); }, element_);
}

PrbmComparator PrbmComparator::fixed_pinned(double load_ratio_n,
                                            PrbmConstantsSource source,
                                            const PrbmDerivationOptions& options) {
  require_in_range(load_ratio_n, "load ratio n", -5.0, 10.0);
  FixedPinnedConstants constants;
  switch (source) {
    case PrbmConstantsSource::kTable:
      constants = FixedPinnedConstants::from_table(load_ratio_n);
      break;
    case PrbmConstantsSource::kCurveFits:
      constants = FixedPinnedConstants::from_curve_fits(load_ratio_n);
      break;
    case PrbmConstantsSource::kDerived: {
      const PrbmDerivation d = derive_fixed_pinned(load_ratio_n, options);
      if (!d.converged()) throw NoConvergence("PRB derivation did not converge: " + d.message);
      constants = {load_ratio_n,
                   d.gamma,
                   d.c_theta,
                   d.K_theta,
                   d.theta_max_gamma,
                   d.theta_max_K,
                   "derived from the exact solution"};
      break;
    }
  }
  std::string described = constants.source;
  return PrbmComparator(FixedPinnedSegment(std::move(constants)), std::move(described));
}

PrbmComparator PrbmComparator::end_moment() {
  return PrbmComparator(EndMomentSegment(), "eqs. 5.107-5.110");
}

PrbmComparator::Segment PrbmComparator::segment() const {
  return std::holds_alternative<FixedPinnedSegment>(element_) ? Segment::kFixedPinned
                                                              : Segment::kEndMoment;
}

PrbmComparison PrbmComparator::at(double load) const {
  if (const auto* e = std::get_if<FixedPinnedSegment>(&element_)) {
    return fixed_pinned_at(*e, limits_, load);
  }
  return end_moment_at(std::get<EndMomentSegment>(element_), limits_, load);
}

}  // namespace flexure
