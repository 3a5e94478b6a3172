#include "flexure/mechanisms/mechanism_analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/mechanisms/cfm/constant_force.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/mechanisms/mechanism_warnings.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

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
  a.prbm_validity = prbm_stroke_validity(d, a.prbm.displacement);
  a.prbm_validity_limit = a.prbm_validity.limit;
  a.prbm_validity_reason = a.prbm_validity.reason;
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
    // With --stable the stroke can be solved twice: from the PRBM start, then (where that one is
    // unstable) on the stable branch. Each run reports its points from 1 to n, so the second
    // continues the count from n instead of counting the same points again; it has a pass of its
    // own in the total, which the counter skips when the stable stroke is not needed.
    const std::size_t stroke_passes = options.stable ? 2 : 1;
    const std::size_t passes =
        stroke_passes + (options.exact_stress ? 1 : 0) + (options.stability ? 1 : 0);
    const std::size_t total = passes * n;
    StrokeProgress stroke_progress;
    if (options.progress) {
      stroke_progress = [&, last = std::size_t{0}, offset = std::size_t{0}](std::size_t done,
                                                                            std::size_t) mutable {
        if (done < last && offset + n < stroke_passes * n) offset += n;  // a new run
        last = done;
        options.progress(std::min(offset + done, stroke_passes * n), total);
      };
    }
    ExactMechanismSolver::Options exact_options;
    exact_options.stable_start = options.stable;
    a.exact = exact_stroke(d, a.prbm.displacement, exact_options, stroke_progress);
    a.exact_note = a.exact.message;
    if (options.stable) a.stable_search = a.exact.stable_search;
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
          if (options.progress) options.progress(stroke_passes * n + k + 1, total);
          for (int i = 0; i < 3; ++i) {
            a.max_stress_exact[i] = std::max(a.max_stress_exact[i], st.max_stress[i]);
            if (d.joints[i].type != PivotType::kPin) a.stress_exact[i].push_back(st.max_stress[i]);
          }
        }
      }
      a.has_exact_stress = options.exact_stress;
      // How large the PRBM's error is where it is outside its table, and where it is inside.
      add_force_errors(a.prbm_validity, a.prbm.force, a.force_exact);
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
    if (d.joints[i].type != PivotType::kPin &&
        a.max_stress[i] >= d.material.yield_strength.value_or(0.0)) {
      a.yielding_pivots.push_back(i + 1);
    }
  }
  a.safety_factor = d.material.yield_strength.value_or(0.0) / a.max_stress_all;
  const bool exact_ran = a.has_exact && options.exact;
  const SolveStatus& last = exact_ran ? static_cast<const SolveStatus&>(a.exact) : a.prbm;
  a.termination = last.termination;
  a.iterations = last.iterations;
  a.residual = last.residual;
  if (!a.converged()) a.message = fmt::format("{}: {}", d.name, last.message);
  a.warnings = analysis_warnings(a);
  return a;
}

void report_forces_of(MechanismAnalysis& a, ForceOf of) {
  const double factor = force_of_factor(a.force_of, of);
  for (double& f : a.prbm.force) f *= factor;
  for (double& f : a.force_exact) f *= factor;
  a.prbm.mean_force *= factor;
  a.mean_force_exact *= factor;
  a.force_of = of;
  // The force-vanishing warnings quote the forces and say whose force they are: renewed (the
  // analysis's warnings are exactly analysis_warnings()).
  a.warnings = analysis_warnings(a);
}

std::vector<StrokeStabilityEntry> stroke_stability_entries(const MechanismAnalysis& a) {
  std::vector<StrokeStabilityEntry> out;
  if (a.stability_prbm.displacement_control.points.empty()) return out;
  const bool exact = a.has_exact && a.exact.converged() && a.has_exact_stability;
  out.push_back({"displacement_control", "prbm", &a.stability_prbm.displacement_control});
  out.push_back(
      {"displacement_control", "exact", exact ? &a.stability_exact.displacement_control : nullptr});
  out.push_back({"force_control", "prbm", &a.stability_prbm.force_control});
  out.push_back({"force_control", "exact", exact ? &a.stability_exact.force_control : nullptr});
  return out;
}

}  // namespace flexure::mechanism
