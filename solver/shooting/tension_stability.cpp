#include "flexure/solver/shooting/tension_stability.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

namespace flexure {

namespace {

// Relative slack on max m^2 < 2 EI (C + |F|) (tension_stability.h): the shooting solution meets
// the first integral to about 1e-11 and its interpolated moment is as accurate.
constexpr double kFirstIntegralSlack = 1e-6;

}  // namespace

bool tension_verdict_applies(const SegmentChain& chain) {
  if (chain.end != EndCondition::kFree || chain.tip_load.follower != 0.0 ||
      !chain.node_loads.empty() || chain.segments.size() != 1) {
    return false;
  }
  const auto* f = std::get_if<FlexibleSegment>(&chain.segments.front());
  return f != nullptr && f->EI_profile.empty() && f->kappa0 == 0.0 && !f->beyond_elastica();
}

std::optional<Stability> tensioned_cantilever_stability(const SegmentChain& chain,
                                                        const ShootingResult& result,
                                                        const StabilityOptions& options) {
  if (!tension_verdict_applies(chain) || !result.converged()) return std::nullopt;
  options.validate();
  const double EI = std::get<FlexibleSegment>(chain.segments.front()).EI;
  const double Fx = chain.tip_load.Fx, Fy = chain.tip_load.Fy, M = chain.tip_load.M;
  const double F = std::hypot(Fx, Fy);
  const auto stable = [&] {
    return classify_stability(0, 1.0, options.critical_tolerance, "the beam");
  };
  // No force: N . t = 0 everywhere, the second variation is the bending stiffness itself.
  if (F == 0.0) return stable();
  const double largest_m = EI * result.largest_curvature;
  const double theta_tip = result.tip.theta;
  if (!std::isfinite(largest_m) || !std::isfinite(theta_tip)) return std::nullopt;
  // F . t at the clamp (theta = 0) and at the tip.
  const double root_tension = Fx;
  const double tip_tension = Fx * std::cos(theta_tip) + Fy * std::sin(theta_tip);
  if (!(root_tension >= 0.0) || !(tip_tension >= 0.0)) return std::nullopt;
  const double C = M * M / (2.0 * EI) + tip_tension;
  // t antiparallel to F somewhere needs m^2 = 2 EI (C + |F|) there.
  if (!(largest_m * largest_m < (1.0 - kFirstIntegralSlack) * 2.0 * EI * (C + F))) {
    return std::nullopt;
  }
  return stable();
}

std::optional<Stability> tensioned_cantilever_stability(const SegmentChain& chain,
                                                        double tip_angle,
                                                        int inflection_points,
                                                        const StabilityOptions& options) {
  if (!tension_verdict_applies(chain) || inflection_points != 0 || !std::isfinite(tip_angle)) {
    return std::nullopt;
  }
  options.validate();
  const double Fx = chain.tip_load.Fx, Fy = chain.tip_load.Fy;
  const auto stable = [&] {
    return classify_stability(0, 1.0, options.critical_tolerance, "the beam");
  };
  if (Fx == 0.0 && Fy == 0.0) return stable();
  if (!std::isfinite(Fx) || !std::isfinite(Fy)) return std::nullopt;
  // F . t at the clamp (theta = 0) and at the tip.
  if (!(Fx >= 0.0) || !(Fx * std::cos(tip_angle) + Fy * std::sin(tip_angle) >= 0.0)) {
    return std::nullopt;
  }
  // The antiparallel angle theta_F + pi, the first of its copies above the lower end of the range.
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const double lower = std::min(0.0, tip_angle), upper = std::max(0.0, tip_angle);
  const double antiparallel = std::atan2(Fy, Fx) + std::numbers::pi;
  const double first_above = antiparallel + kTwoPi * std::ceil((lower - antiparallel) / kTwoPi);
  if (first_above <= upper) return std::nullopt;
  return stable();
}

}  // namespace flexure
