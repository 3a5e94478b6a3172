#include "flexure/mechanisms/cfm/cfm_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "flexure/mechanisms/cfm/constant_force.h"
#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/solver/common/status.h"

namespace flexure::cfm {
namespace {

// Psi normalisers (thesis eq. 5.20): raw Psi of lpp-a at 16 % is the code's `fgoal`; the 40 %
// value is not printed and was back-computed from lpp-b's printed 1.002 (thesis Table 7.2;
// docs/cfm.md §1.4).
constexpr double kPsiNormaliser16 = 0.4518;
constexpr double kPsiNormaliser40 = 0.1032;
constexpr int kMaxUniformPoints = 10'000'000;

// Spring ratio as used: `given` for a spring that exists, 0 for one that does not.
double resolve_ratio(const std::optional<double>& given,
                     bool spring_exists,
                     const std::string& what,
                     const CfmConfiguration& c) {
  if (!spring_exists) {
    if (given && *given != 0.0) {
      throw InvalidInput(
          fmt::format("{} = {} but configuration {} has no spring there; omit {} "
                      "or set it to 0",
                      what,
                      *given,
                      c.name,
                      what));
    }
    return 0.0;
  }
  if (!given) {
    throw InvalidInput(
        fmt::format("{} is required for configuration {} (a finite value >= 0)", what, c.name));
  }
  require_finite(*given, what);
  if (*given < 0.0) {
    throw InvalidInput(
        fmt::format("{} = {} must be >= 0 (spring ratios k_i/k1 are not negative)", what, *given));
  }
  return *given;
}

}  // namespace

double length_parameter_lambda(const CfmConfiguration& c, double R) {
  const double gamma = segment_constants(PivotType::kLong).gamma;
  const bool link2_long =
      c.pivots[0] == PivotType::kLong || (c.pivots[1] == PivotType::kLong && c.middle_long_on_r2);
  const bool link3_long =
      c.pivots[2] == PivotType::kLong || (c.pivots[1] == PivotType::kLong && !c.middle_long_on_r2);
  // Thesis eqs. 5.1-5.8 / Table 5.1: a long segment spans r_i/gamma, an end s-pivot adds half of
  // its 0.1 r_i flexure beyond the pivot; a middle s-pivot adds nothing.
  const double l2 = link2_long ? 1.0 / gamma : (c.pivots[0] == PivotType::kSmall ? 1.05 : 1.0);
  const double l3 = link3_long ? R / gamma : (c.pivots[2] == PivotType::kSmall ? 1.05 * R : R);
  return (l2 + l3) / (1.0 + R);
}

std::array<double, 3> pivot_kappa(const CfmConfiguration& c, double R) {
  // zeta = r_tot/r_i, thesis eqs. 4.8-4.12.
  double zeta2 = 2.0;
  if (c.pivots[1] == PivotType::kLong) zeta2 = c.middle_long_on_r2 ? R + 1.0 : 1.0 + 1.0 / R;
  const std::array<double, 3> zeta = {R + 1.0, zeta2, 1.0 + 1.0 / R};
  std::array<double, 3> kappa{};
  for (int i = 0; i < 3; ++i) {
    const SegmentConstants s = segment_constants(c.pivots[i]);
    kappa[i] = s.gamma * zeta[i] * s.K_theta / s.rho;  // eq. 4.51
  }
  return kappa;
}

void CfmOptions::validate() const {
  if (sampling == StrokeSampling::kUniform && (points < 1 || points > kMaxUniformPoints)) {
    throw InvalidInput(
        fmt::format("CfmOptions::points = {} must be between 1 and {}", points, kMaxUniformPoints));
  }
  if (stride < 1) {
    throw InvalidInput(fmt::format("CfmOptions::stride = {} must be >= 1", stride));
  }
}

CfmModel::CfmModel(CfmOptions options) : options_(options) { options_.validate(); }

CfmResult CfmModel::evaluate(const CfmParameters& p) const {
  const CfmConfiguration& c = find_cfm_configuration(p.config);
  require_finite(p.R, "R (r3/r2)");
  if (p.R <= 0.0) {
    throw InvalidInput(fmt::format("R (r3/r2) = {} must be > 0", p.R));
  }
  require_finite(p.stroke_percent, "d (stroke, % of r2 + r3)");
  if (!(p.stroke_percent > 0.0 && p.stroke_percent <= 100.0)) {
    throw InvalidInput(
        fmt::format("d (stroke, % of r2 + r3) = {} must be in (0, 100]", p.stroke_percent));
  }
  if (p.R == 1.0 && p.stroke_percent == 100.0) {
    throw InvalidInput(
        "d = 100 % with R = 1 folds crank and coupler onto the ground pivot, where the PRBM "
        "force is 0/0; use d < 100");
  }

  CfmResult r;
  r.config = c.name;
  r.class_name = c.class_name;
  r.R = p.R;
  const bool reference_k2 = c.is_class_1B();
  if (reference_k2) {
    // Class 1B: k1 = 0, so k2 is the reference stiffness and K1 := 1 (thesis §2.6, eq. 2.19).
    if (p.K1 && *p.K1 != 1.0) {
      throw InvalidInput(fmt::format(
          "K1 = {} but class 1B ({}) takes k2 as the reference stiffness, so K1 is 1 by "
          "definition (thesis eq. 2.19); omit K1 or set it to 1",
          *p.K1,
          c.name));
    }
    r.K1 = 1.0;
  } else {
    r.K1 = resolve_ratio(p.K1, c.has_spring(2), "K1 (k2/k1)", c);
  }
  r.K2 = resolve_ratio(p.K2, c.has_spring(3), "K2 (k3/k1)", c);

  r.requested_stroke_percent = p.stroke_percent;
  r.toggle_stroke_percent = toggle_stroke_percent(p.R);
  r.stroke_clamped = p.stroke_percent > r.toggle_stroke_percent;
  r.stroke_percent = r.stroke_clamped ? r.toggle_stroke_percent : p.stroke_percent;
  r.lambda = length_parameter_lambda(c, p.R);
  r.kappa = pivot_kappa(c, p.R);

  // Stroke sampling in u = Delta x/r_tot.
  const double d = r.stroke_percent / 100.0;
  double u0 = 0.0;
  double step = 0.0;
  long count = 0;
  if (options_.sampling == StrokeSampling::kThesisCode) {
    // deltax = 0.001 : 0.001 ri d : ri d with ri = r_tot = l_tot/lambda, l_tot = 1; the colon
    // operator gives floor((b - a)/h) + 1 points (with Matlab's small tolerance).
    u0 = 0.001 * r.lambda;
    step = 0.001 * d;
    count = u0 < d ? static_cast<long>(std::floor((d - u0) / step + 1e-10)) + 1 : 1;
  } else {
    u0 = d / options_.points;
    step = u0;
    count = options_.points;
  }
  if (options_.keep_curve) r.curve.reserve(static_cast<std::size_t>(count));

  // min over the stroke of alpha_j/alpha_i for every pair, since the primary pivot j is known only
  // at the end of the stroke.
  std::array<std::array<double, 3>, 3> ratio_min;
  for (auto& row : ratio_min) row.fill(std::numeric_limits<double>::infinity());
  // Only pairs of distinct sprung pivots: a pin is never primary nor subject to a ratio.
  std::array<std::pair<int, int>, 6> pairs{};
  int pair_count = 0;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      if (i != j && r.kappa[i] > 0.0 && r.kappa[j] > 0.0) pairs[pair_count++] = {j, i};
    }
  }
  double sum = 0.0;
  double phi_min = std::numeric_limits<double>::infinity();
  double phi_max = -std::numeric_limits<double>::infinity();
  SliderCrankPose pose;
  long evaluated = 0;
  const long stride = options_.stride;
  long k_prev = 0;  // stride > 1: the previous evaluated point
  double u_prev = 0.0, phi_prev = 0.0;
  // k runs over 0, stride, 2 stride, ... and always ends on count - 1 (the end of the stroke).
  for (long k = 0; k < count; k = (k + 1 == count || k + stride < count) ? k + stride : count - 1) {
    ++evaluated;
    // The last point is exactly the (clamped) stroke, as the thesis code forces it.
    const double u = k + 1 == count ? d : u0 + static_cast<double>(k) * step;
    pose = slider_crank_pose(p.R, u);
    const double phi = force_function_phi(p.R, r.K1, r.K2, reference_k2, pose);
    if (!std::isfinite(phi)) {
      r.set_converged(false);
      r.iterations = static_cast<int>(evaluated);
      r.message = fmt::format(
          "Phi is not finite at stroke {:.6g} % (theta2 = {:.6g}, theta3 = "
          "{:.6g}); the slider-crank is singular there",
          100.0 * u,
          pose.theta2,
          pose.theta3);
      return r;
    }
    if (stride == 1) {
      sum += phi;
    } else {
      // The stroke points skipped since the previous evaluated one (indices k_prev .. k - 1, the
      // previous one included) enter the mean through the straight line between the two: the
      // mean then stands for the full sampling's to O((stride step)^2), not O(stride step).
      if (evaluated > 1) {
        const double skipped = static_cast<double>(k - k_prev);
        const double slope = (phi - phi_prev) / (u - u_prev);
        sum += skipped * phi_prev + slope * step * skipped * (skipped - 1.0) / 2.0;
      }
      if (k + 1 == count) sum += phi;
      k_prev = k;
      u_prev = u;
      phi_prev = phi;
    }
    phi_min = std::min(phi_min, phi);
    phi_max = std::max(phi_max, phi);
    r.residual = std::max(r.residual, loop_closure_residual(p.R, pose));
    const std::array<double, 3> alpha = {
        r.kappa[0] * pose.psi1(), r.kappa[1] * pose.psi2(), r.kappa[2] * pose.psi3()};
    for (int k = 0; k < pair_count; ++k) {
      const auto [j, i] = pairs[k];
      if (alpha[i] > 0.0) ratio_min[j][i] = std::min(ratio_min[j][i], alpha[j] / alpha[i]);
    }
    if (options_.keep_curve) r.curve.push_back({100.0 * u, pose.theta2, pose.theta3, phi});
  }
  r.iterations = static_cast<int>(evaluated);
  // Thesis `average_phi`, Howell "average of Phi" (with a stride, over all `count` points).
  r.Phi = sum / static_cast<double>(stride == 1 ? evaluated : count);
  r.Phi_min = phi_min;
  r.Phi_max = phi_max;
  r.Xi = phi_max / phi_min;                              // eq. 2.17
  r.percent_constant_force = 100.0 * phi_min / phi_max;  // eq. 5.22 (thesis code `xi`)
  r.force_vanishes = phi_min <= mechanism::kForceVanishesRelative * std::abs(phi_max);

  // beta = gamma K_theta (R+1)^2 Phi/rho = kappa_ref (R+1) Phi (eq. 4.43; class 1B eq. 4.55 with
  // the middle pivot as reference); linear in Phi, so its stroke average uses the mean Phi.
  const int ref = reference_k2 ? 1 : 0;
  r.beta = r.kappa[ref] * (p.R + 1.0) * r.Phi;

  // Stress parameters at the end of the stroke (eq. 4.16: alpha = kappa * rotation) and the
  // primary pivot: highest stress with equal widths, alpha_i h_i with h_i ~ (K_{i-1}/kappa_i)^(1/3)
  // (thesis code `stress(i,:)`, App. B.1.3).
  const std::array<double, 3> rotation = {pose.psi1(), pose.psi2(), pose.psi3()};
  const std::array<double, 3> K_prev = {1.0, r.K1, r.K2};  // K_0 = 1, K_1, K_2 (eq. 4.52)
  std::array<double, 3> stress{};
  for (int i = 0; i < 3; ++i) {
    r.alpha_end[i] = r.kappa[i] * rotation[i];
    stress[i] = r.kappa[i] > 0.0 ? r.alpha_end[i] * std::cbrt(K_prev[i] / r.kappa[i]) : 0.0;
  }
  if (stress[0] >= stress[1] && stress[0] >= stress[2]) {
    r.primary_pivot = 1;
  } else {
    r.primary_pivot = stress[1] > stress[2] ? 2 : 3;
  }
  const int pp = r.primary_pivot - 1;
  r.alpha_ratio_min = ratio_min;
  // Eq. 5.19: Psi = beta kappa_p (1/alpha_p)^3/(lambda kappa_ref K_{p-1}) at the end of stroke.
  r.Psi_raw =
      r.beta * r.kappa[pp] / std::pow(r.alpha_end[pp], 3) / (r.lambda * r.kappa[ref] * K_prev[pp]);
  if (p.stroke_percent == 16.0) r.Psi = r.Psi_raw / kPsiNormaliser16;
  if (p.stroke_percent == 40.0) r.Psi = r.Psi_raw / kPsiNormaliser40;
  for (int i = 0; i < 3; ++i) {
    if (r.kappa[i] <= 0.0) continue;
    r.C[i] = i == pp ? 1.0 : ratio_min[pp][i];
    r.D_equal[i] = K_prev[i] * r.kappa[pp] / (K_prev[pp] * r.kappa[i]);  // eq. 5.36
    r.D_min[i] = *r.D_equal[i] / std::pow(*r.C[i], 3);                   // eq. 5.35
  }
  r.d_N_max = 100.0 * std::sin(pose.theta2) / (1.0 + p.R);  // eq. 5.45: Delta y = r2 sin theta2

  r.set_converged(true);
  r.message = r.stroke_clamped
                  ? fmt::format("stroke clamped from {:g} % to the toggle position {:.4f} %",
                                p.stroke_percent,
                                r.toggle_stroke_percent)
                  : "closed form";
  if (r.force_vanishes) {
    r.warn(WarningKind::kForceVanishes,
           fmt::format("the force vanishes within the stroke (Phi_min = {:.3g} against Phi_max = "
                       "{:.3g}, zero to rounding): Xi is unbounded and not printed",
                       r.Phi_min,
                       r.Phi_max));
  }
  if (r.stroke_clamped) {
    r.warn(WarningKind::kStrokeClamped,
           fmt::format("stroke d = {:g} % is past the toggle position of R = {:g}; clamped to "
                       "{:.4f} % as in the thesis (stroke_percent)",
                       r.requested_stroke_percent,
                       r.R,
                       r.stroke_percent));
  }
  return r;
}

}  // namespace flexure::cfm
