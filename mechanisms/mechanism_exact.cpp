#include "flexure/mechanisms/mechanism_exact.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

// Distance of an l segment's characteristic pivot from its clamp, / l: 1 - gamma (Howell §5.2).
double long_segment_pivot() { return howell_average_fixed_pinned().geometry().pivot_x; }

bool is_pin(const MechanismDesign& d, int pivot) {
  return d.joints[pivot - 1].type == PivotType::kPin;
}

void add_flexible(PhysicalChain& pc, const MechanismDesign& d, int pivot, double length) {
  FlexibleSegment f;
  f.length = length;
  f.EI = d.joints[pivot - 1].flexural_rigidity(d.material);
  pc.chain.segments.emplace_back(f);
  pc.flexible_pivot.push_back(pivot);
}

void add_rigid(PhysicalChain& pc, double length) {
  if (length <= 0.0) return;  // a flexible segment replaces the whole link (Table 8.1: r' = 0)
  pc.chain.segments.emplace_back(RigidSegment{length, 0.0});
  pc.flexible_pivot.push_back(0);
}

}  // namespace

ExactSupport exact_support(const MechanismDesign& design) {
  if (is_pin(design, 1)) {
    return is_pin(design, 3) ? ExactSupport::kPinnedEnds : ExactSupport::kPrbmOnly;
  }
  if (is_pin(design, 2)) {
    return is_pin(design, 3) ? ExactSupport::kTwoForceCoupler : ExactSupport::kPinnedMiddle;
  }
  return ExactSupport::kDirectChain;
}

std::string exact_support_reason(const MechanismDesign& design) {
  if (exact_support(design) == ExactSupport::kPrbmOnly) {
    return "pin at the ground with a flexure at the slider: no chain root (PRBM only)";
  }
  return "";
}

PhysicalChain physical_chain(const MechanismDesign& d) {
  if (exact_support(d) == ExactSupport::kPrbmOnly) {
    throw InvalidInput(fmt::format(
        "configuration '{}' has no exact model: {}", d.config, exact_support_reason(d)));
  }
  const auto& cfg = d.configuration();
  const auto& j = d.joints;
  PhysicalChain pc;
  // Table 8.1 segment lengths; an s flexure is centred on its PRB pivot.
  const double f1 = j[0].length, f2 = j[1].length, f3 = j[2].length;
  if (exact_support(d) == ExactSupport::kPinnedEnds) {
    // psp, plp: from the ground pin, a root kink (the crank angle, set per point), the crank
    // (rigid for psp, the l segment for plp), the middle flexure's rest, the coupler.
    pc.chain.segments.emplace_back(RigidSegment{0.0, 0.0});
    pc.flexible_pivot.push_back(0);
    if (j[1].type == PivotType::kSmall) {
      add_rigid(pc, d.r2 - 0.5 * f2);
      add_flexible(pc, d, 2, f2);
      add_rigid(pc, d.r3 - 0.5 * f2);
    } else {  // plp: link 2 is the l segment, clamped into link 3 (Table 8.1: r3' = r3 - 0.15 f2)
      add_flexible(pc, d, 2, f2);
      add_rigid(pc, d.r3 - long_segment_pivot() * f2);
    }
    pc.slider_x0 = pc.chain.total_length();
    return pc;
  }
  add_flexible(pc, d, 1, f1);
  double r2_rigid = d.r2;
  if (j[0].type == PivotType::kLong) {
    r2_rigid = 0.0;
  } else {
    r2_rigid -= 0.5 * f1;
    if (j[1].type == PivotType::kSmall) r2_rigid -= 0.5 * f2;
    if (j[1].type == PivotType::kLong && !cfg.middle_long_on_r2) {
      r2_rigid -= long_segment_pivot() * f2;
    }
  }
  add_rigid(pc, r2_rigid);
  if (exact_support(d) == ExactSupport::kTwoForceCoupler) {
    pc.slider_x0 = pc.chain.total_length() + d.r3;
    return pc;
  }
  if (exact_support(d) == ExactSupport::kPinnedMiddle) {
    // Coupler chain from the slider clamp back to pivot 2: slider flexure, then the rigid rest.
    PhysicalChain coupler;
    add_flexible(coupler, d, 3, f3);
    add_rigid(coupler, d.r3 - 0.5 * f3);
    pc.coupler_chain = coupler.chain;
    pc.coupler_flexible_pivot = coupler.flexible_pivot;
    pc.slider_x0 = pc.chain.total_length() + coupler.chain.total_length();
    return pc;
  }
  double r3_rigid = d.r3;
  if (j[1].type == PivotType::kSmall) {
    add_flexible(pc, d, 2, f2);
    r3_rigid -= 0.5 * f2;
  } else {  // slp: link 3 is the long segment, pinned at the slider
    add_flexible(pc, d, 2, f2);
    r3_rigid = 0.0;
  }
  if (j[2].type == PivotType::kSmall) r3_rigid -= 0.5 * f3;
  add_rigid(pc, r3_rigid);
  if (j[2].type == PivotType::kSmall) add_flexible(pc, d, 3, f3);
  pc.slider_x0 = pc.chain.total_length();
  return pc;
}

ExactMechanismSolver::ExactMechanismSolver(MechanismDesign design)
    : ExactMechanismSolver(std::move(design), Options{}) {}

void ExactMechanismOptions::validate() const {
  shooting.validate();
  const auto positive = [](double value, const char* name) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw InvalidInput(
          fmt::format("ExactMechanismSolver::Options::{} must be > 0 (got {})", name, value));
    }
  };
  positive(position_tolerance, "position_tolerance");
  positive(max_load_parameter, "max_load_parameter");
  positive(work_budget, "work_budget");
  if (!(noise_floor >= 0.0) || !(work_budget_per_point >= 0.0) || !(work_limit >= 0.0)) {
    throw InvalidInput(fmt::format(
        "ExactMechanismSolver::Options: noise_floor ({}), work_budget_per_point ({}) and "
        "work_limit ({}) must be >= 0",
        noise_floor,
        work_budget_per_point,
        work_limit));
  }
  if (max_newton_iterations < 1) {
    throw InvalidInput(
        fmt::format("ExactMechanismSolver::Options::max_newton_iterations must be >= 1 (got {})",
                    max_newton_iterations));
  }
}

ExactMechanismSolver::ExactMechanismSolver(MechanismDesign design, Options options)
    : design_(std::move(design)), options_(options), support_(exact_support(design_)) {
  options_.validate();
  // The exact model has no spring rule; its PRBM start guesses are closest with k = EI/L.
  design_.spring_rule = SpringRule::kPureBending;
  physical_ = physical_chain(design_);
  length_scale_ = physical_.slider_x0;
  EI_scale_ = 0.0;
  for (const auto* c : {&physical_.chain, &physical_.coupler_chain}) {
    for (const Segment& seg : c->segments) {
      if (const auto* f = std::get_if<FlexibleSegment>(&seg)) {
        EI_scale_ = std::max(EI_scale_, f->EI);
      }
    }
  }
  force_scale_ = EI_scale_ / (length_scale_ * length_scale_);
  moment_scale_ = EI_scale_ / length_scale_;
  scaled_ = physical_.chain;
  scaled_coupler_ = physical_.coupler_chain;
  for (auto* c : {&scaled_, &scaled_coupler_}) {
    for (Segment& seg : c->segments) {
      if (auto* f = std::get_if<FlexibleSegment>(&seg)) {
        f->length /= length_scale_;
        f->EI /= EI_scale_;
        max_force_ =
            std::min(max_force_, options_.max_load_parameter * f->EI / (f->length * f->length));
      } else {
        std::get<RigidSegment>(seg).length /= length_scale_;
      }
    }
  }
}

bool ExactMechanismSolver::out_of_time() const {
  return options_.work_spent != nullptr && options_.work_limit > 0.0 &&
         static_cast<double>(*options_.work_spent) > options_.work_limit;
}

void ExactMechanismSolver::charge(long steps) const {
  if (options_.work_spent != nullptr) *options_.work_spent += steps;
}

std::string ExactMechanismSolver::budget_message() const {
  return fmt::format(
      "work budget exhausted (the exact model gives up after {:.3g} integrator steps: {:.3g} + "
      "{:.3g} per stroke point; docs/mechanisms.md \"Work budget\")",
      options_.work_limit,
      options_.work_budget,
      options_.work_budget_per_point);
}

double exact_work_limit(const ExactMechanismSolver::Options& options, std::size_t points) {
  return options.work_budget + options.work_budget_per_point * static_cast<double>(points);
}

SegmentChain ExactMechanismSolver::chain_at(double displacement, double phi) const {
  SegmentChain chain = scaled_;
  const double xs = (physical_.slider_x0 - displacement) / length_scale_;
  if (support_ == ExactSupport::kTwoForceCoupler) {
    chain.end = EndCondition::kPinned;
    chain.prescribed.x = xs - design_.r3 / length_scale_ * std::cos(phi);
    chain.prescribed.y = design_.r3 / length_scale_ * std::sin(phi);
  } else if (is_pin(design_, 3)) {
    chain.end = EndCondition::kPinned;
    chain.prescribed.x = xs;
    chain.prescribed.y = 0.0;
  } else {
    chain.end = EndCondition::kFixed;
    chain.prescribed.x = xs;
    chain.prescribed.y = 0.0;
    chain.prescribed.theta = 0.0;
  }
  return chain;
}

ExactPoint ExactMechanismSolver::solve(double displacement,
                                       const ExactPoint* previous,
                                       bool fall_back) const {
  require_finite(displacement, "slider displacement");
  if (displacement <= 0.0 || displacement > design_.toggle_stroke()) {
    throw InvalidInput(fmt::format(
        "slider displacement must be in (0, {:.6g}] m (the toggle position); got {:.6g}",
        design_.toggle_stroke(),
        displacement));
  }
  if (out_of_time()) {
    ExactPoint p;
    p.displacement = displacement;
    p.message = budget_message();
    return p;
  }
  switch (support_) {
    case ExactSupport::kTwoForceCoupler:
      return solve_two_force(displacement, previous);
    case ExactSupport::kPinnedMiddle:
      return solve_pinned_middle(displacement, previous);
    case ExactSupport::kPinnedEnds:
      return solve_pinned_ends(displacement, previous);
    default:
      return solve_direct(displacement, previous, fall_back);
  }
}

namespace {

// Root unknowns (m0, Nx, Ny) from the PRBM: N = the PRBM pin force (the chain carries one force,
// no node loads), m0 = m_tip + cross(tip, N) (statics of the whole chain about the clamp).
std::vector<double> prbm_guess(const PrbmState& s, double tip_x, double tip_y, double m_tip) {
  return {m_tip + tip_x * s.pin_force_y - tip_y * s.pin_force_x, s.pin_force_x, s.pin_force_y};
}

}  // namespace

ExactPoint ExactMechanismSolver::solve_direct(double displacement,
                                              const ExactPoint* previous,
                                              bool fall_back) const {
  ExactPoint p;
  p.displacement = displacement;
  p.chain = chain_at(displacement, 0.0);
  const ShootingSolver solver(options_.shooting);
  ShootingResult r;
  std::string history;
  if (previous != nullptr && previous->converged()) {
    r = solver.solve_from(p.chain, previous->unknowns);
    charge(r.integrator_steps);
    p.iterations += r.iterations;
    if (!r.converged()) history = "from the previous point: " + r.message + "; ";
    if (!r.converged() && !fall_back) {
      p.message = history + "no fall-back asked for";
      return p;
    }
  }
  if (!r.converged() && out_of_time()) history += budget_message() + "; ";
  if (!r.converged() && !out_of_time()) {
    const PrbmState s = prbm_state(design_, displacement);
    const double m_tip =
        is_pin(design_, 3) ? 0.0 : design_.spring_constant(3) * (-s.theta3);  // slider spring
    std::vector<double> g = prbm_guess(s, *p.chain.prescribed.x * length_scale_, 0.0, m_tip);
    g[0] /= moment_scale_, g[1] /= force_scale_, g[2] /= force_scale_;
    r = solver.solve_from(p.chain, g);
    charge(r.integrator_steps);
    p.iterations += r.iterations;
    if (!r.converged()) history += "from the PRBM guess: " + r.message + "; ";
  }
  // (The shooting solver's own iterations are not bounded by the budget: it is checked between
  // the three attempts. docs/mechanisms.md "Work budget".)
  if (!r.converged() && !out_of_time()) {
    r = solver.solve(p.chain);
    charge(r.integrator_steps);
    p.iterations += r.iterations;
  } else if (!r.converged()) {
    r.message = budget_message();
  }
  p.set_converged(r.converged());
  p.message = r.converged() ? r.method : history + "continuation: " + r.message;
  p.unknowns = r.unknowns;
  p.jacobian_sign = r.jacobian_sign;
  p.length_scale = length_scale_;
  p.EI_scale = EI_scale_;
  p.Nx = r.tip_load.Fx * force_scale_;
  p.Ny = r.tip_load.Fy * force_scale_;
  p.m0 = -r.reaction.M * moment_scale_;
  p.force = -p.Nx;
  p.residual = r.residual;
  return p;
}

ExactPoint ExactMechanismSolver::solve_two_force(double displacement,
                                                 const ExactPoint* previous) const {
  // Force control: the crank is a cantilever carrying the dead coupler force T = Q (-cos phi,
  // sin phi) (compression Q > 0) at its free end; Newton on (Q, phi) makes its tip land on
  // pivot 2 = slider - r3 (cos phi, -sin phi). Prescribing the tip instead (pinned end, secant on
  // phi) is ill-conditioned: near full extension a tiny change of phi changes T by orders of
  // magnitude.
  ExactPoint p;
  p.displacement = displacement;
  const ShootingSolver solver(options_.shooting);
  // Nondimensional: lengths / length_scale_, forces / force_scale_, moments / moment_scale_.
  const double xs = (physical_.slider_x0 - displacement) / length_scale_;
  const double r3 = design_.r3 / length_scale_;
  double Q = 0.0, phi = 0.0, m0 = 0.0;
  if (previous != nullptr && previous->converged()) {
    Q = std::hypot(previous->Nx, previous->Ny) / force_scale_;
    phi = previous->phi;
    m0 = previous->m0 / moment_scale_;
  } else {
    const PrbmState s = prbm_state(design_, displacement);
    Q = std::hypot(s.pin_force_x, s.pin_force_y) / force_scale_;
    phi = -s.theta3;
    const double tx = xs - r3 * std::cos(phi), ty = r3 * std::sin(phi);
    m0 = (tx * s.pin_force_y - ty * s.pin_force_x) / force_scale_;
  }
  auto make_chain = [&](double q, double f) {
    SegmentChain c = scaled_;
    c.end = EndCondition::kFree;
    c.tip_load.Fx = -q * std::cos(f);
    c.tip_load.Fy = q * std::sin(f);
    return c;
  };
  struct Eval {
    bool ok = false;
    Eigen::Vector2d r = Eigen::Vector2d::Zero();
    ShootingResult sr;
  };
  auto evaluate = [&](double q, double f) {
    Eval e;
    // Not integrated: a trial load beyond the solvers' domain (the damping then shortens the
    // step), or the work budget is spent.
    if (std::abs(q) > max_force_ || out_of_time()) {
      e.sr.message = out_of_time() ? budget_message()
                                   : fmt::format("trial coupler force beyond |F| L^2/EI = {:g}",
                                                 options_.max_load_parameter);
      return e;
    }
    e.sr = solver.solve_from(make_chain(q, f), {m0});
    charge(e.sr.integrator_steps);
    p.iterations += e.sr.iterations;
    if (!e.sr.converged()) return e;
    e.ok = true;
    e.r << e.sr.tip.x - (xs - r3 * std::cos(f)), e.sr.tip.y - r3 * std::sin(f);
    return e;
  };
  const double scale = 1.0;  // the slider position, nondimensional
  Eval e = evaluate(Q, phi);
  // Jacobian d(mismatch)/d(Q, phi): from the previous stroke point if there is one, refreshed by
  // finite differences when a step does not halve the mismatch, Broyden-updated after each step
  // (one cantilever solve per step in the usual case instead of three).
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  bool have_J = false, fresh_J = false;
  if (options_.reuse_jacobian && previous != nullptr && previous->converged() &&
      previous->jacobian[0] != 0.0) {
    J << previous->jacobian[0], previous->jacobian[1], previous->jacobian[2], previous->jacobian[3];
    have_J = true;
  }
  int it = 0;
  for (; e.ok && e.r.norm() > options_.position_tolerance * scale &&
         it < options_.max_newton_iterations;
       ++it) {
    m0 = -e.sr.reaction.M;
    if (!have_J) {
      const double dQ = 1e-7 * std::max(Q, 1e-12), dphi = 1e-7;
      const Eval eq = evaluate(Q + dQ, phi), ef = evaluate(Q, phi + dphi);
      if (!eq.ok || !ef.ok) {
        e = eq.ok ? ef : eq;
        break;
      }
      J.col(0) = (eq.r - e.r) / dQ;
      J.col(1) = (ef.r - e.r) / dphi;
      have_J = fresh_J = true;
    }
    const Eigen::Vector2d step = J.fullPivLu().solve(-e.r);
    Eval trial = evaluate(Q + step(0), phi + step(1));
    if (!fresh_J && !(trial.ok && trial.r.norm() < 0.5 * e.r.norm())) {
      have_J = false;  // stale Jacobian: refresh it and retry from the same point
      continue;
    }
    // Damped step with a fresh Jacobian: halve until the mismatch decreases.
    double t = 1.0;
    // (At the noise floor a failed full step already means convergence: no halving.)
    const bool at_floor = e.r.norm() <= options_.noise_floor * scale;
    for (int k = 0; k < 12 && !at_floor && !(trial.ok && trial.r.norm() < e.r.norm()); ++k) {
      t *= 0.5;
      trial = evaluate(Q + t * step(0), phi + t * step(1));
    }
    if (!trial.ok || trial.r.norm() >= e.r.norm()) {
      // No decrease: at the integrator's noise floor this is convergence, otherwise a failure.
      if (e.r.norm() > options_.noise_floor * scale) {
        p.message =
            fmt::format("no decrease of the pivot 2 mismatch {:.3g} m", e.r.norm() * length_scale_);
        e.ok = false;
      }
      break;
    }
    const Eigen::Vector2d dx = t * step;
    J += ((trial.r - e.r) - J * dx) * dx.transpose() / dx.squaredNorm();  // Broyden
    fresh_J = false;
    Q += dx(0);
    phi += dx(1);
    e = trial;
  }
  p.jacobian = {J(0, 0), J(0, 1), J(1, 0), J(1, 1)};
  p.phi = phi;
  if (!e.ok) {
    p.message = fmt::format(
        "force-controlled Newton on the coupler force stopped after {} steps at Q = {:.6g} N, "
        "phi = {:.6g} rad: {} {}",
        it,
        Q * force_scale_,
        phi,
        p.message,
        e.sr.message);
    return p;
  }
  p.chain = make_chain(Q, phi);
  p.unknowns = e.sr.unknowns;
  p.length_scale = length_scale_;
  p.EI_scale = EI_scale_;
  p.Nx = p.chain.tip_load.Fx * force_scale_;
  p.Ny = p.chain.tip_load.Fy * force_scale_;
  p.m0 = -e.sr.reaction.M * moment_scale_;
  p.force = -p.Nx;
  p.residual = e.r.norm() / scale;
  p.set_converged(e.r.norm() <=
                  std::max(options_.position_tolerance, options_.noise_floor) * scale);
  p.message = p.converged() ? fmt::format("force-controlled Newton on (Q, phi), {} steps", it)
                            : fmt::format(
                                  "force-controlled Newton on (Q, phi) stopped after {} steps with "
                                  "|pivot 2 mismatch|/length = {:.3g}",
                                  it,
                                  p.residual);
  return p;
}

ExactStrokeResult exact_stroke(const MechanismDesign& design,
                               const std::vector<double>& displacements) {
  return exact_stroke(design, displacements, ExactMechanismSolver::Options{});
}

namespace {

ExactStrokeResult stroke_from_start(const MechanismDesign& design,
                                    const std::vector<double>& displacements,
                                    const ExactMechanismSolver::Options& options_in,
                                    const StrokeProgress& progress);

}  // namespace

ExactStrokeResult exact_stroke(const MechanismDesign& design,
                               const std::vector<double>& displacements,
                               const ExactMechanismSolver::Options& options,
                               const StrokeProgress& progress) {
  ExactStrokeResult r = stroke_from_start(design, displacements, options, progress);
  if (!options.stable_start) return r;
  if (exact_support(design) != ExactSupport::kDirectChain) {
    r.stable_search =
        "not available: the stable search follows serial chains (ssp, slp, sss); the stroke from "
        "the PRBM start is returned";
    return r;
  }
  if (r.converged()) {
    // Judged in stroke order up to the first unstable point: on 3A-lssm and 3A-lslm the first.
    bool unstable = false;
    for (const ExactPoint& p : r.points) {
      try {
        unstable =
            exact_point_stability(design, p).displacement_control.kind == StabilityKind::kUnstable;
      } catch (const std::exception&) {
        unstable = false;
      }
      if (unstable) break;
    }
    if (!unstable) {
      r.stable_search =
          "not needed: no point of the stroke from the PRBM start is unstable with the slider "
          "held";
      return r;
    }
  }
  ExactStrokeResult s = exact_stable_stroke(design, displacements, options, progress);
  if (s.converged()) {
    s.integrator_steps += r.integrator_steps;
    return s;
  }
  r.stable_search = fmt::format(
      "no stable stroke found ({}); the stroke from the PRBM start is returned", s.message);
  return r;
}

namespace {

ExactStrokeResult stroke_from_start(const MechanismDesign& design,
                                    const std::vector<double>& displacements,
                                    const ExactMechanismSolver::Options& options_in,
                                    const StrokeProgress& progress) {
  // The work budget runs from here (docs/mechanisms.md "Work budget").
  ExactMechanismSolver::Options options = options_in;
  options.work_spent = std::make_shared<long>(0);
  options.work_limit = exact_work_limit(options_in, displacements.size());
  const ExactMechanismSolver solver(design, options);
  // The first attempt at a stroke point of a serial chain stops after kFirstTryIterations Newton
  // iterations: from the secant prediction Newton converges in at most 7 on every built-in design
  // (measured at 50 and 200 points), so a slower one means the stroke step is too long, which the
  // substeps below fix for less than the remaining iterations cost (3A-lssm's second point).
  constexpr int kFirstTryIterations = 10;
  ExactMechanismSolver::Options first_options = options;
  if (exact_support(design) == ExactSupport::kDirectChain) {
    first_options.shooting.newton.max_iterations =
        std::min(first_options.shooting.newton.max_iterations, kFirstTryIterations);
  }
  const ExactMechanismSolver first_try(design, first_options);
  ExactStrokeResult result;
  result.points.reserve(displacements.size());
  const ExactPoint* previous = nullptr;
  ExactPoint predicted;
  for (double dx : displacements) {
    const std::size_t k = result.points.size();
    if (k >= 2) {
      // Predictor: the polynomial through the last two points (secant in Delta x), or the last
      // three (quadratic) once there are three; warm starts that halve the Newton work.
      const ExactPoint& b = result.points[k - 1];
      const ExactPoint& a = result.points[k - 2];
      const ExactPoint* c = k >= 3 ? &result.points[k - 3] : nullptr;
      const bool same_size = a.unknowns.size() == b.unknowns.size() &&
                             (c == nullptr || c->unknowns.size() == b.unknowns.size());
      // Lagrange weights at dx of the nodes b, a (, c) (Burden & Faires, Numerical Analysis §3.1).
      const double xb = b.displacement, xa = a.displacement;
      double wb = 0.0, wa = 0.0, wc = 0.0;
      if (c != nullptr && same_size) {
        const double xc = c->displacement;
        wb = (dx - xa) * (dx - xc) / ((xb - xa) * (xb - xc));
        wa = (dx - xb) * (dx - xc) / ((xa - xb) * (xa - xc));
        wc = (dx - xb) * (dx - xa) / ((xc - xb) * (xc - xa));
      } else {
        wb = (dx - xa) / (xb - xa);
        wa = (dx - xb) / (xa - xb);
      }
      const ExactPoint& cc = c != nullptr ? *c : a;
      auto extrapolate = [&](double va, double vb, double vc) {
        return wb * vb + wa * va + wc * vc;
      };
      predicted = b;
      predicted.phi = extrapolate(a.phi, b.phi, cc.phi);
      predicted.Nx = extrapolate(a.Nx, b.Nx, cc.Nx);
      predicted.Ny = extrapolate(a.Ny, b.Ny, cc.Ny);
      predicted.m0 = extrapolate(a.m0, b.m0, cc.m0);
      predicted.coupler_m0 = extrapolate(a.coupler_m0, b.coupler_m0, cc.coupler_m0);
      if (same_size || a.unknowns.size() == b.unknowns.size()) {
        for (std::size_t i = 0; i < b.unknowns.size(); ++i) {
          predicted.unknowns[i] =
              extrapolate(a.unknowns[i], b.unknowns[i], same_size ? cc.unknowns[i] : 0.0);
        }
      }
      previous = &predicted;
    }
    // Newton from the previous point (or its secant prediction) alone first. When it fails, the
    // stroke step is divided into substeps, each from the last (large rotations per stroke step
    // can throw Newton onto another branch), before the serial chain's fall-backs -- the PRBM
    // start and continuation from zero load -- which start far from the path and cost more.
    ExactPoint point = k == 0 ? solver.solve(dx) : first_try.solve(dx, previous, false);
    if (!point.converged() && k == 0) {
      // No neighbour to start from and the PRBM start failed (mechanism_exact_start.cpp).
      ExactPoint started = exact_first_point(design, displacements, options);
      if (started.converged()) {
        point = std::move(started);
      } else {
        point.message += "; start strategies: " + started.message;
      }
    }
    auto substeps = [&](bool fall_back) {
      const ExactPoint last = result.points[k - 1];
      for (int m : {4, 16}) {
        ExactPoint current = last;
        bool ok = true;
        int iterations = 0;
        for (int i = 1; i <= m && ok; ++i) {
          const double x = last.displacement + (dx - last.displacement) * i / m;
          ExactPoint q = solver.solve(x, &current, fall_back);
          iterations += q.iterations;
          ok = q.converged();
          if (ok) current = std::move(q);
        }
        if (ok) {
          point = std::move(current);
          point.iterations += iterations;
          point.message += fmt::format(" ({} substeps from the previous point)", m);
          return true;
        }
      }
      return false;
    };
    if (!point.converged() && k >= 1 && !substeps(false)) {
      point = solver.solve(dx, previous);
      if (!point.converged()) substeps(true);
    }
    result.points.push_back(std::move(point));
    const ExactPoint& p = result.points.back();
    result.iterations += p.iterations;
    if (!p.converged()) {
      // Say first when the work budget ended it: the attempts' messages follow.
      result.message =
          fmt::format("exact model stopped at Delta x = {:.6g} m ({} of {} points): {}{}",
                      dx,
                      result.points.size(),
                      displacements.size(),
                      solver.out_of_time() ? solver.budget_message() + "; last attempts: " : "",
                      p.message);
      result.integrator_steps = *options.work_spent;
      return result;
    }
    previous = &result.points.back();
    if (progress) progress(result.points.size(), displacements.size());
  }
  result.set_converged(true);
  result.message = fmt::format("{} points converged", displacements.size());
  result.integrator_steps = *options.work_spent;
  return result;
}

}  // namespace

}  // namespace flexure::mechanism
