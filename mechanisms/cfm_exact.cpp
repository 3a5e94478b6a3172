#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/mechanisms/cfm/constant_force.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::cfm {
namespace {

// Reference flexure thickness / (r2 + r3). The forces of the inextensible elastica depend on the
// flexural rigidities only, so this merely keeps the (unreported) stresses of the equivalent
// design plausible; widths are 1.
constexpr double kReferenceThickness = 0.01;

}  // namespace

mechanism::MechanismDesign cfm_equivalent_design(
    const std::string& config, double R, double K1, double K2, double stroke_percent) {
  const CfmConfiguration& cfg = find_cfm_configuration(config);
  if (!std::isfinite(R) || R <= 0.0) {
    throw InvalidInput(fmt::format("R = r3/r2 must be finite and > 0 (got {})", R));
  }
  mechanism::MechanismDesign d;
  d.config = cfg.name;
  d.name = fmt::format("{}-{} (nondimensional)", cfg.class_name, cfg.name);
  d.note =
      fmt::format("equivalent of R = {}, K1 = {}, K2 = {}, d = {} %: r2 + r3 = 1, E = 1, b = 1",
                  R,
                  K1,
                  K2,
                  stroke_percent);
  d.r2 = 1.0 / (R + 1.0);
  d.r3 = R / (R + 1.0);
  d.material.E = 1.0;
  d.material.yield_strength = 1.0;  // stresses are not reported
  d.stroke = stroke_percent / 100.0;
  // The model clamps at the toggle position exactly; keep rounding from tripping finalise().
  d.stroke = std::min(d.stroke, d.toggle_stroke());
  mechanism::size_flexures_for_spring_ratios(d, 1.0, kReferenceThickness, K1, K2);
  return d;
}

void CfmExactOptions::validate() const {
  if (points < 2 || points > 100000) {
    throw InvalidInput(
        fmt::format("CfmExactOptions::points must be in [2, 100000] (got {})", points));
  }
  solver.validate();
}

CfmExactResult solve_cfm_exact(const CfmResult& prbm, const CfmExactOptions& options) {
  options.validate();
  CfmExactResult r;
  r.design = cfm_equivalent_design(prbm.config, prbm.R, prbm.K1, prbm.K2, prbm.stroke_percent);
  const mechanism::MechanismDesign& d = r.design;
  const auto& cfg = d.configuration();
  r.reference_stiffness = d.spring_constant(cfg.is_class_1B() ? 2 : 1);
  // Phi = F r2/k_ref (thesis eq. 2.13; 1B eq. 2.19).
  const double to_Phi = d.r2 / r.reference_stiffness;
  const double r_tot = d.r2 + d.r3;

  const mechanism::PrbmStrokeResult p = mechanism::prbm_stroke(d, options.points);
  double psum = 0.0;
  for (std::size_t k = 0; k < p.force.size(); ++k) {
    r.stroke_percent.push_back(100.0 * p.displacement[k] / r_tot);
    const double Phi = p.force[k] * to_Phi;
    r.Phi_prbm.push_back(Phi);
    psum += Phi;
  }
  r.Phi_prbm_mean = psum / static_cast<double>(p.force.size());
  r.percent_constant_force_prbm = mechanism::constant_force_measure(r.Phi_prbm).percent;

  const mechanism::ExactStrokeResult e =
      mechanism::exact_stroke(d, p.displacement, options.solver, options.progress);
  r.set_converged(e.converged());
  r.message = e.message;
  r.iterations = e.iterations;
  for (const mechanism::ExactPoint& q : e.points) r.residual = std::max(r.residual, q.residual);
  if (!e.converged() || e.points.size() != p.force.size()) {
    r.set_converged(false);
    if (r.message.empty()) r.message = "exact model did not converge over the whole stroke";
    return r;
  }
  double esum = 0.0;
  for (std::size_t k = 0; k < e.points.size(); ++k) {
    const double F = e.points[k].force;
    const double Phi = F * to_Phi;
    r.Phi_exact_curve.push_back(Phi);
    esum += Phi;
    const double err = std::abs(p.force[k] - F) / std::abs(F);
    if (err > r.max_force_error) {
      r.max_force_error = err;
      r.max_force_error_at_percent = r.stroke_percent[k];
    }
  }
  r.Phi_exact = esum / static_cast<double>(e.points.size());
  const mechanism::ConstantForceMeasure m = mechanism::constant_force_measure(r.Phi_exact_curve);
  r.percent_constant_force_exact = m.percent;
  r.force_vanishes_exact = m.vanishes;
  r.force_changes_sign_exact = m.changes_sign;
  if (!std::isfinite(r.Phi_exact) || !std::isfinite(r.max_force_error)) {
    r.set_converged(false);
    r.message = "exact model returned a non-finite force";
    return r;
  }
  if (r.force_vanishes_exact) {
    // Its min/max would be meaningless (negative when it changes sign): reported as 0
    // (docs/mechanisms.md "Percent constant force").
    r.warn(WarningKind::kForceVanishes,
           fmt::format("the exact force {} within the stroke (Phi_exact from {:.3g} to {:.3g}): "
                       "percent_constant_force_exact is reported as 0",
                       r.force_changes_sign_exact ? "changes sign" : "vanishes",
                       m.min_force,
                       m.max_force));
  }
  return r;
}

}  // namespace flexure::cfm
