#include "flexure/mechanisms/mechanism_analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/elements/fixed_pinned_segment.h"
#include "flexure/mechanisms/constant_force.h"
#include "flexure/solver/common/errors.h"

namespace flexure::mechanism {
namespace {

// Checks the long segments of the PRBM at one state against Howell Table 5.1; returns a reason
// when the state is outside the range, empty otherwise.
std::string validity_violation(const MechanismDesign& d, const PrbmState& s) {
  const auto& cfg = d.configuration();
  for (int p = 1; p <= 3; ++p) {
    if (d.joints[p - 1].type != PivotType::kLong) continue;
    // Beam axis u at the clamp and PRB angle Theta of the segment (relative rotation of its
    // pseudo-rigid link), and the force on its pinned end.
    double ux = 1.0, uy = 0.0, Theta = s.theta2;
    double Fx = s.pin_force_x, Fy = s.pin_force_y;  // on the crank's tip (lpp, lps)
    if (p == 2 && !cfg.middle_long_on_r2) {         // slp: clamped to link 2, pin at the slider
      ux = std::cos(s.theta2), uy = std::sin(s.theta2), Theta = s.theta3 - s.theta2;
    } else if (p == 2) {  // plp: clamped into link 3, pinned at the ground; seen from the clamp
      ux = -std::cos(s.theta3), uy = -std::sin(s.theta3), Theta = s.theta2 - s.theta3;
      Fx = -Fx, Fy = -Fy;  // the ground pin's force on the beam
    }
    // Normal v on the side the segment deflects to.
    const double sign = Theta >= 0.0 ? 1.0 : -1.0;
    const double vx = -uy * sign, vy = ux * sign;
    const double Pt = Fx * vx + Fy * vy, Pa = Fx * ux + Fy * uy;
    if (Pt <= 0.0) {
      return fmt::format(
          "l segment at pivot {}: the pin force points to the far side of the beam axis (load "
          "angle phi > 180 deg, outside Howell Table 5.1)",
          p);
    }
    const double n = -Pa / Pt;  // Howell eq. 5.37 sense: compressive axial force for n > 0
    ValidityLimits limits;
    try {
      limits = FixedPinnedSegment(FixedPinnedConstants::from_table(n)).limits();
    } catch (const std::exception&) {
      return fmt::format(
          "l segment at pivot {}: load ratio n = {:.3g} outside Howell Table 5.1", p, n);
    }
    if (!limits.contains_force(Theta)) {
      return fmt::format(
          "l segment at pivot {}: Theta = {:.1f} deg > Theta_max(K_theta) = {:.1f} deg at "
          "n = {:.3g} (Howell Table 5.1)",
          p,
          std::abs(Theta) * 180.0 / M_PI,
          limits.theta_max_force * 180.0 / M_PI,
          n);
    }
  }
  return "";
}

}  // namespace

void AnalysisOptions::validate() const {
  if (points < 2 || points > 100000) {
    throw InvalidInput(
        fmt::format("AnalysisOptions::points must be in [2, 100000] (got {})", points));
  }
}

MechanismAnalysis analyze_mechanism(const MechanismDesign& design, const AnalysisOptions& options) {
  options.validate();
  MechanismAnalysis a;
  a.design = design;
  a.design.finalise();
  const MechanismDesign& d = a.design;
  a.prbm = prbm_stroke(d, options.points);
  // A non-finite PRBM force (a singular pose that finalise() did not catch) must not pass on as a
  // truncated curve with a percent constant force of 0.
  if (!a.prbm.converged()) throw NoConvergence(fmt::format("{}: {}", d.name, a.prbm.message));
  for (double dx : a.prbm.displacement) {
    const std::string why = validity_violation(d, prbm_state(d, dx));
    if (!why.empty()) {
      a.prbm_validity_limit = dx;
      a.prbm_validity_reason = why;
      break;
    }
  }
  if (options.stability) {
    std::vector<Stability> dc, fc;
    for (double dx : a.prbm.displacement) {
      PointStability v = prbm_point_stability(d, dx);
      dc.push_back(std::move(v.displacement_control));
      fc.push_back(std::move(v.force_control));
    }
    a.stability_prbm.displacement_control = summarise_stroke_stability(
        std::move(dc), a.prbm.displacement, "PRBM", SliderControl::kDisplacement);
    a.stability_prbm.force_control =
        summarise_stroke_stability(std::move(fc),
                                   a.prbm.displacement,
                                   "PRBM",
                                   SliderControl::kForce,
                                   &a.stability_prbm.displacement_control.points);
  }
  a.max_stress = a.prbm.max_stress;
  a.has_exact = exact_support(d) != ExactSupport::kPrbmOnly;
  if (!a.has_exact) {
    a.exact_note = exact_support_reason(d);
  } else if (options.exact) {
    const std::size_t n = a.prbm.displacement.size();
    const std::size_t passes = 1 + (options.exact_stress ? 1 : 0) + (options.stability ? 1 : 0);
    const std::size_t total = passes * n;
    StrokeProgress stroke_progress;
    if (options.progress) {
      stroke_progress = [&](std::size_t done, std::size_t) { options.progress(done, total); };
    }
    a.exact =
        exact_stroke(d, a.prbm.displacement, ExactMechanismSolver::Options{}, stroke_progress);
    a.exact_note = a.exact.message;
    if (a.exact.converged()) {
      double sum = 0.0;
      for (std::size_t k = 0; k < a.exact.points.size(); ++k) {
        const ExactPoint& p = a.exact.points[k];
        a.force_exact.push_back(p.force);
        sum += p.force;
        // Relative to a zero exact force the error is undefined (inf would reach the JSON).
        const double err =
            p.force != 0.0 ? std::abs(a.prbm.force[k] - p.force) / std::abs(p.force) : 0.0;
        if (err > a.max_force_error) {
          a.max_force_error = err;
          a.max_force_error_at = p.displacement;
        }
        if (options.exact_stress) {
          // From the stroke's solution: one integration, no re-solve.
          const ExactSegmentState st = exact_segment_state(d, p);
          if (options.progress) options.progress(n + k + 1, total);
          for (int i = 0; i < 3; ++i) {
            a.max_stress_exact[i] = std::max(a.max_stress_exact[i], st.max_stress[i]);
            if (d.joints[i].type != PivotType::kPin) a.stress_exact[i].push_back(st.max_stress[i]);
          }
        }
      }
      a.has_exact_stress = options.exact_stress;
      if (options.stability) {
        std::vector<Stability> dc, fc;
        const std::size_t done = (passes - 1) * n;
        for (std::size_t k = 0; k < a.exact.points.size(); ++k) {
          PointStability v;
          try {
            v = exact_point_stability(d, a.exact.points[k]);
          } catch (const std::exception& e) {
            // Not a verdict: say why at this point (the shape could not be integrated again).
            v.displacement_control = v.force_control =
                not_checked_stability(fmt::format("the verdict failed: {}", e.what()));
          }
          dc.push_back(std::move(v.displacement_control));
          fc.push_back(std::move(v.force_control));
          if (options.progress) options.progress(done + k + 1, total);
        }
        a.stability_exact.displacement_control = summarise_stroke_stability(
            std::move(dc), a.prbm.displacement, "exact", SliderControl::kDisplacement);
        a.stability_exact.force_control =
            summarise_stroke_stability(std::move(fc),
                                       a.prbm.displacement,
                                       "exact",
                                       SliderControl::kForce,
                                       &a.stability_exact.displacement_control.points);
        a.has_exact_stability = true;
      }
      const ConstantForceMeasure cf = constant_force_measure(a.force_exact);
      a.percent_constant_force_exact = cf.percent;
      a.force_vanishes_exact = cf.vanishes;
      a.force_changes_sign_exact = cf.changes_sign;
      a.mean_force_exact = sum / static_cast<double>(a.force_exact.size());
      for (int i = 0; i < 3; ++i)
        a.max_stress[i] = std::max(a.max_stress[i], a.max_stress_exact[i]);
    }
  }
  for (int i = 0; i < 3; ++i) {
    a.max_stress_all = std::max(a.max_stress_all, a.max_stress[i]);
    if (d.joints[i].type != PivotType::kPin && a.max_stress[i] >= d.yield_strength) {
      a.yielding_pivots.push_back(i + 1);
    }
  }
  a.safety_factor = d.yield_strength / a.max_stress_all;
  return a;
}

void report_forces_of(MechanismAnalysis& a, ForceOf of) {
  const double factor = force_of_factor(a.force_of, of);
  for (double& f : a.prbm.force) f *= factor;
  for (double& f : a.force_exact) f *= factor;
  a.prbm.mean_force *= factor;
  a.mean_force_exact *= factor;
  a.force_of = of;
}

}  // namespace flexure::mechanism
