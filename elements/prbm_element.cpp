#include "flexure/elements/prbm_element.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "flexure/solver/common/status.h"

namespace flexure {

double PrbmElement::spring_constant(double EI, double length) const {
  if (!std::isfinite(EI) || EI <= 0.0) {
    throw InvalidInput(fmt::format("flexural rigidity EI = {} must be a finite number > 0", EI));
  }
  if (!std::isfinite(length) || length <= 0.0) {
    throw InvalidInput(fmt::format("segment length l = {} must be a finite number > 0", length));
  }
  return stiffness_coefficient() * EI / length;
}

double PrbmElement::load_factor_at(double Theta, const EndLoad& unit_load) const {
  require_finite(Theta, "PRB angle Theta");
  const double work = generalized_load(Theta, unit_load);
  if (std::abs(work) < 1e-14) {
    throw InvalidInput(fmt::format(
        "the load (Fx = {}, Fy = {}, mu = {}) does no virtual work at Theta = {} rad, so no load "
        "factor holds the {} there",
        unit_load.Fx,
        unit_load.Fy,
        unit_load.mu,
        Theta,
        name()));
  }
  return spring_moment(Theta) / work;
}

PrbEquilibrium PrbmElement::solve(const EndLoad& load) const {
  require_finite(load.Fx, "tip force Fx");
  require_finite(load.Fy, "tip force Fy");
  require_finite(load.mu, "tip moment mu");
  constexpr double kTolerance = 1e-13;  // on the virtual-work residual, nondimensional
  constexpr double kScanStep = 0.5 * std::numbers::pi / 180.0;  // rad, bracket search step
  constexpr int kMaxIterations = 200;
  // Proportional loading from the unloaded angle: walk Theta in the direction the load pushes until
  // the residual changes sign, then refine the bracket. Newton from Theta_i can run to the wrong
  // side for compressive loads (the residual is not monotone there).
  const auto residual = [&](double Theta) {
    return spring_moment(Theta) - generalized_load(Theta, load);
  };
  PrbEquilibrium result;
  const double start = initial_angle();
  const double r0 = residual(start);
  result.Theta = start;
  result.residual = std::abs(r0);
  result.set_converged(std::abs(r0) <= kTolerance);
  if (!result.converged()) {
    const double direction = r0 < 0.0 ? 1.0 : -1.0;
    double lo = start, r_lo = r0, hi = start, r_hi = r0;
    bool bracketed = false;
    for (int i = 1; std::abs(hi - start) < std::numbers::pi; ++i) {
      hi = start + direction * i * kScanStep;
      r_hi = residual(hi);
      ++result.iterations;
      if ((r_hi > 0.0) != (r0 > 0.0) || r_hi == 0.0) {
        bracketed = true;
        break;
      }
      lo = hi;
      r_lo = r_hi;
    }
    if (bracketed) {
      // Illinois (modified regula falsi) on [lo, hi].
      int side = 0;
      double x = hi, r = r_hi;
      for (int it = 0; it < kMaxIterations && std::abs(r) > kTolerance; ++it) {
        x = (lo * r_hi - hi * r_lo) / (r_hi - r_lo);
        r = residual(x);
        ++result.iterations;
        if ((r > 0.0) == (r_hi > 0.0)) {
          hi = x;
          r_hi = r;
          if (side == 1) r_lo /= 2.0;
          side = 1;
        } else {
          lo = x;
          r_lo = r;
          if (side == -1) r_hi /= 2.0;
          side = -1;
        }
        if (hi == lo) break;
      }
      result.Theta = x;
      result.residual = std::abs(r);
      result.set_converged(std::isfinite(r) && result.residual <= kTolerance);
    } else {
      result.Theta = hi;
      result.residual = std::abs(r_hi);
    }
  }
  result.tip = tip(result.Theta);
  result.message =
      result.converged()
          ? fmt::format("virtual-work residual {:.2e} <= {:.0e} after {} evaluations",
                        result.residual,
                        kTolerance,
                        result.iterations)
          : fmt::format(
                "no PRB equilibrium within |Theta - Theta_i| < pi: residual {:.3e} at Theta = "
                "{:.6f} rad after {} evaluations",
                result.residual,
                result.Theta,
                result.iterations);
  return result;
}

double PrbmElement::max_moment(double Theta, const EndLoad& load) const {
  const TipPose t = tip(Theta);
  return load.mu + t.a_over_l * load.Fy - t.b_over_l * load.Fx;  // Howell eq. 5.21 with a couple
}

double PrbmElement::axial_force(double /*Theta*/, const EndLoad& load) const { return load.Fx; }

SectionStress PrbmElement::max_stress(double Theta,
                                      const EndLoad& load,
                                      const Section& section,
                                      const Material& material,
                                      double length) const {
  const double EI = flexural_rigidity(section, material);  // validates both
  const std::optional<double> area = section.area();
  if (!area || !(section.thickness > 0.0)) {
    throw InvalidInput(
        "the stress of a PRB element needs the section's area and thickness (N/A and M c/I with "
        "c = h/2): give a rectangle (Section::rectangle)");
  }
  if (!std::isfinite(length) || length <= 0.0) {
    throw InvalidInput(fmt::format("segment length l = {} must be a finite number > 0", length));
  }
  SectionStress s;
  s.bending_moment = max_moment(Theta, load) * EI / length;
  s.axial_force = axial_force(Theta, load) * EI / (length * length);
  const double c = section.thickness / 2.0;
  const double I = section.second_moment();
  // Howell eqs. 5.22-5.25: the top fibre is compressed by a positive (counter-clockwise) moment.
  s.sigma_top = -s.bending_moment * c / I + s.axial_force / *area;
  s.sigma_bottom = s.bending_moment * c / I + s.axial_force / *area;
  s.sigma_max = std::max(std::abs(s.sigma_top), std::abs(s.sigma_bottom));
  return s;
}

}  // namespace flexure
