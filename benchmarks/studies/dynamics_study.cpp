#include "flexure/benchmarks/studies/dynamics_study.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

void require_in(double value, const std::string& what, double lo, double hi, bool open_lo) {
  require_finite(value, what);
  if ((open_lo ? value <= lo : value < lo) || value > hi) {
    throw InvalidInput(
        fmt::format("{} = {} is outside {}{}, {}]", what, value, open_lo ? "(" : "[", lo, hi));
  }
}

}  // namespace

void DynamicsStudyOptions::validate() const {
  if (omegas.empty()) throw InvalidInput("omegas: at least one frequency is needed");
  for (double w : omegas) require_in(w, "omegas (rad/s)", 0.0, 1e300, false);
  for (double w : history_omegas) require_in(w, "history_omegas (rad/s)", 0.0, 1e300, false);
  if (stroke_percent) require_in(*stroke_percent, "stroke_percent", 0.0, 100.0, true);
  require_in(preload_percent, "preload_percent", 0.0, 100.0, true);
  dynamics::InverseDynamicsOptions{.samples_per_period = samples}.validate();
  for (std::size_t i = 0; i < friction.size(); ++i) {
    require_in(friction[i], fmt::format("friction C{} (N m)", i + 1), 0.0, 1e300, false);
  }
  require_finite(axial_alpha, "axial_alpha");
  if (zero_slider_mass && zero_inertia) {
    throw InvalidInput("zero_slider_mass and zero_inertia exclude each other");
  }
  if (static_force_points < 1) {
    throw InvalidInput(fmt::format("static_force_points = {} must be >= 1", static_force_points));
  }
}

DynamicsStudySetup dynamics_study_setup(const dynamics::DynamicsDesign& d,
                                        const DynamicsStudyOptions& o) {
  o.validate();
  DynamicsStudySetup s;
  dynamics::DynamicsParameters& p = s.parameters;
  p = dynamics::from_bar_links(d.r2, d.r3, d.m2, d.m3, d.m_slider, d.k);
  if (o.zero_slider_mass) p.m_slider = 0.0;
  if (o.zero_inertia) p.m2 = p.m3 = p.m_slider = p.J_C2 = p.J_C3 = 0.0;
  p.coulomb = o.friction;
  p.axial_alpha = o.axial_alpha;
  const dynamics::SliderCrankDynamics model(p);
  const double r_tot = model.r_tot();
  // A design's own stroke (a mechanism file's) unless one is asked for; built-ins: 40 %, Table 6.
  const double stroke =
      d.stroke && !o.stroke_percent ? *d.stroke : o.stroke_percent.value_or(40.0) / 100.0 * r_tot;
  s.motion = {o.preload_percent / 100.0 * r_tot, stroke, 0.0};
  model.theta2_at(s.motion.preload + s.motion.stroke);  // throws past the toggle position
  return s;
}

DynamicsStudy run_dynamics_study(const dynamics::DynamicsDesign& design,
                                 const DynamicsStudyOptions& o) {
  const DynamicsStudySetup setup = dynamics_study_setup(design, o);
  DynamicsStudy study;
  study.design = design;
  study.parameters = setup.parameters;
  study.motion = setup.motion;
  study.force_of = o.force_of;
  study.samples = o.samples;
  study.zero_slider_mass = o.zero_slider_mass;
  study.zero_inertia = o.zero_inertia;
  study.omegas = o.omegas;
  study.static_force_points = o.static_force_points;
  // The model computes the whole mechanism; one half is exactly half of it (mechanism.h).
  const double to_reported =
      mechanism::force_of_factor(mechanism::ForceOf::kWholeMechanism, o.force_of);

  const dynamics::SliderCrankDynamics model(setup.parameters);
  const dynamics::InverseDynamics inverse(model, {.samples_per_period = o.samples});
  const auto start = std::chrono::steady_clock::now();
  study.rows = inverse.sweep(setup.motion, o.omegas, o.progress);
  study.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (dynamics::ForceStatistics& s : study.rows) {
    for (const auto& [value, what] :
         {std::pair{s.mean, "mean force"}, std::pair{s.peak_to_peak, "peak-to-peak force"}}) {
      if (!std::isfinite(value)) {
        study.termination = Termination::kNoConvergence;
        study.message = fmt::format(
            "{} at omega = {} came out as {}; no converged solution to "
            "report",
            what,
            s.omega,
            value);
        return study;
      }
    }
    for (double* f : {&s.mean, &s.median, &s.min, &s.max, &s.peak_to_peak}) *f *= to_reported;
  }
  study.static_nominal_force = to_reported * dynamics::static_nominal_force(
                                                 model, setup.motion.stroke, o.static_force_points);
  if (design.F_nom_paper > 0.0) study.paper_nominal_force = to_reported * design.F_nom_paper;
  // Small oscillations about the straight, unloaded mechanism; no inertia: no oscillation.
  const bool has_inertia = model.terms(0.0).M > 0.0;
  study.natural_frequency = has_inertia ? dynamics::linearise(model, 0.0).omega_n : 0.0;

  dynamics::SinusoidalMotion motion = setup.motion;
  for (double w : o.history_omegas) {
    motion.omega = w;
    DynamicsForceHistory h{w, {}, {}, {}, {}, {}};
    for (const dynamics::ForceSample& sample : inverse.history(motion)) {
      h.t.push_back(sample.t);
      h.delta_x.push_back(sample.delta_x);
      h.theta2.push_back(sample.theta2);
      h.force.push_back(to_reported * sample.force);
      h.static_force.push_back(to_reported * sample.static_force);
    }
    study.histories.push_back(std::move(h));
  }
  study.set_converged(true);
  return study;
}

}  // namespace flexure
