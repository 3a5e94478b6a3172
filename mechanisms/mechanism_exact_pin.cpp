// ExactMechanismSolver::solve_pinned_middle: sps and lps, a pin at pivot 2 between the crank
// (clamped at the ground) and the coupler (clamped into the slider by its s flexure).
#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>

#include "mechanisms/broyden_newton_2d.h"
#include "mechanisms/mechanism_exact.h"
#include "mechanisms/mechanism_prbm.h"

namespace flexure::mechanism {
namespace {

constexpr double kGamma = 0.85;  // fixed-pinned characteristic radius factor (thesis §2.2)

}  // namespace

ExactPoint ExactMechanismSolver::solve_pinned_middle(double displacement,
                                                     const ExactPoint* previous) const {
  // Force control on the pin force P = (Px, Py) (force of the coupler on the crank): the crank is
  // a cantilever from the ground clamp with dead tip load P; the coupler a cantilever from the
  // slider clamp whose frame is turned by pi, where the crank's push -P reads +P. Both tips carry
  // no moment (the pin). Newton on P makes the tips meet at pivot 2. Nondimensional units.
  ExactPoint p;
  p.displacement = displacement;
  const ShootingSolver solver(options_.shooting);
  const double xs = (physical_.slider_x0 - displacement) / length_scale_;
  Eigen::Vector2d P;
  double m0c = 0.0, m0k = 0.0;  // root moments, crank and coupler
  if (previous != nullptr && previous->converged) {
    P << previous->Nx / force_scale_, previous->Ny / force_scale_;
    m0c = previous->m0 / moment_scale_;
    m0k = previous->coupler_m0 / moment_scale_;
  } else {
    const PrbmState s = prbm_state(design_, displacement);
    P << s.pin_force_x / force_scale_, s.pin_force_y / force_scale_;
    // PRB pivot 1: the centre of an s flexure, 0.15 l from the clamp of an l segment.
    const JointDesign& j1 = design_.joints[0];
    const double pivot1 =
        j1.type == PivotType::kLong ? (1.0 - kGamma) * j1.length : 0.5 * j1.length;
    const double ax = (pivot1 + design_.r2 * std::cos(s.theta2)) / length_scale_;
    const double ay = design_.r2 * std::sin(s.theta2) / length_scale_;
    m0c = ax * P.y() - ay * P.x();
    const double lx = xs - ax, ly = -ay;  // pivot 2 in the coupler frame
    m0k = lx * P.y() - ly * P.x();
  }
  bool fallback = previous == nullptr;
  auto with_load = [](SegmentChain c, const Eigen::Vector2d& load) {
    c.end = EndCondition::kFree;
    c.tip_load.Fx = load.x();
    c.tip_load.Fy = load.y();
    return c;
  };
  struct Eval {
    bool ok = false;
    Eigen::Vector2d r = Eigen::Vector2d::Zero();
    ShootingResult crank, coupler;
  };
  auto evaluate = [&](const Eigen::Vector2d& load) {
    Eval e;
    // Continuation from zero load only for the very first evaluation of a stroke (no neighbour
    // to start from): later it is slow and may wander to another branch; a failed Newton step is
    // handled by the damping below.
    e.crank = solver.solve_from(with_load(scaled_, load), {m0c});
    if (!e.crank.converged && fallback) e.crank = solver.solve(with_load(scaled_, load));
    e.coupler = solver.solve_from(with_load(scaled_coupler_, load), {m0k});
    if (!e.coupler.converged && fallback)
      e.coupler = solver.solve(with_load(scaled_coupler_, load));
    p.iterations += e.crank.iterations + e.coupler.iterations;
    if (!e.crank.converged || !e.coupler.converged) return e;
    e.ok = true;
    e.r << e.crank.tip.x - (xs - e.coupler.tip.x), e.crank.tip.y + e.coupler.tip.y;
    return e;
  };
  Eval e = evaluate(P);
  fallback = false;
  // Jacobian d(mismatch)/dP: the previous point's (Broyden-updated) one when there is one --
  // nondimensional, so it carries over -- refreshed by finite differences when a step fails.
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  bool have_J = false;
  if (previous != nullptr && previous->converged && previous->jacobian[0] != 0.0) {
    J << previous->jacobian[0], previous->jacobian[1], previous->jacobian[2], previous->jacobian[3];
    have_J = true;
  }
  const BroydenNewtonOutcome outcome = broyden_newton_2d<Eval>(
      evaluate,
      P,
      e,
      J,
      have_J,
      [](const Eigen::Vector2d& x) {
        const double h = 1e-7 * std::max(x.norm(), 1e-12);
        return Eigen::Vector2d(h, h);
      },
      [&](const Eval& current) {
        m0c = -current.crank.reaction.M;
        m0k = -current.coupler.reaction.M;
      },
      BroydenNewtonOptions{
          options_.position_tolerance, options_.noise_floor, options_.max_newton_iterations});
  const int it = outcome.iterations;
  if (outcome.stalled) {
    p.message =
        fmt::format("no decrease of the pivot 2 mismatch {:.3g} m", e.r.norm() * length_scale_);
    e.ok = false;
  }
  p.jacobian = {J(0, 0), J(0, 1), J(1, 0), J(1, 1)};
  if (!e.ok) {
    p.message = fmt::format(
        "Newton on the pin force stopped after {} steps at P = ({:.6g}, {:.6g}) N: {} {} {}",
        it,
        P.x() * force_scale_,
        P.y() * force_scale_,
        p.message,
        e.crank.message,
        e.coupler.message);
    return p;
  }
  p.chain = with_load(scaled_, P);
  p.unknowns = e.crank.unknowns;
  p.coupler_chain = with_load(scaled_coupler_, P);
  p.coupler_unknowns = e.coupler.unknowns;
  p.length_scale = length_scale_;
  p.EI_scale = EI_scale_;
  p.Nx = P.x() * force_scale_;
  p.Ny = P.y() * force_scale_;
  p.m0 = -e.crank.reaction.M * moment_scale_;
  p.coupler_m0 = -e.coupler.reaction.M * moment_scale_;
  p.force = -p.Nx;
  // Coupler angle above the axis, from pivot 2 to the slider joint.
  p.phi = std::atan2(e.crank.tip.y, xs - e.crank.tip.x);
  p.residual = e.r.norm();
  p.converged = e.r.norm() <= std::max(options_.position_tolerance, options_.noise_floor);
  p.message = p.converged ? fmt::format("Newton on the pin force, {} steps", it)
                          : fmt::format(
                                "Newton on the pin force stopped after {} steps with "
                                "|pivot 2 mismatch|/length = {:.3g}",
                                it,
                                p.residual);
  return p;
}

}  // namespace flexure::mechanism

namespace flexure::mechanism {

ExactPoint ExactMechanismSolver::solve_pinned_ends(double displacement,
                                                   const ExactPoint* previous) const {
  // psp, plp: a cantilever clamped at the ground pin at the unknown crank angle alpha (the root
  // kink) under the dead slider force (-F, 0); Newton on (F, alpha) puts its tip on the slider
  // joint (x_s, 0). Then the root moment m(0) = F y_tip is zero: the ground pin. Nondimensional.
  ExactPoint p;
  p.displacement = displacement;
  const ShootingSolver solver(options_.shooting);
  const double xs = (physical_.slider_x0 - displacement) / length_scale_;
  Eigen::Vector2d u;  // (F, alpha)
  double m0 = 0.0;
  if (previous != nullptr && previous->converged) {
    u << previous->force / force_scale_, previous->phi;
    m0 = previous->m0 / moment_scale_;
  } else {
    const PrbmState s = prbm_state(design_, displacement);
    u << s.force / force_scale_, s.theta2;
  }
  bool fallback = previous == nullptr;
  auto make_chain = [&](const Eigen::Vector2d& v) {
    SegmentChain c = scaled_;
    std::get<RigidSegment>(c.segments[0]).angle_offset = v(1);
    c.end = EndCondition::kFree;
    c.tip_load.Fx = -v(0);
    c.tip_load.Fy = 0.0;
    return c;
  };
  struct Eval {
    bool ok = false;
    Eigen::Vector2d r = Eigen::Vector2d::Zero();
    ShootingResult sr;
  };
  auto evaluate = [&](const Eigen::Vector2d& v) {
    Eval e;
    // Continuation from zero load only for the very first evaluation of a stroke (see above).
    e.sr = solver.solve_from(make_chain(v), {m0});
    if (!e.sr.converged && fallback) e.sr = solver.solve(make_chain(v));
    p.iterations += e.sr.iterations;
    if (!e.sr.converged) return e;
    e.ok = true;
    e.r << e.sr.tip.x - xs, e.sr.tip.y;
    return e;
  };
  Eval e = evaluate(u);
  fallback = false;
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  const BroydenNewtonOutcome outcome = broyden_newton_2d<Eval>(
      evaluate,
      u,
      e,
      J,
      false,
      [](const Eigen::Vector2d& x) {
        return Eigen::Vector2d(1e-7 * std::max(std::abs(x(0)), 1e-12), 1e-7);
      },
      [&](const Eval& current) { m0 = -current.sr.reaction.M; },
      BroydenNewtonOptions{
          options_.position_tolerance, options_.noise_floor, options_.max_newton_iterations});
  const int it = outcome.iterations;
  if (outcome.stalled) {
    p.message =
        fmt::format("no decrease of the slider mismatch {:.3g} m", e.r.norm() * length_scale_);
    e.ok = false;
  }
  p.phi = u(1);
  if (!e.ok) {
    p.message = fmt::format(
        "Newton on (F, alpha) stopped after {} steps at F = {:.6g} N, alpha = {:.6g} rad: {} {}",
        it,
        u(0) * force_scale_,
        u(1),
        p.message,
        e.sr.message);
    return p;
  }
  p.chain = make_chain(u);
  p.unknowns = e.sr.unknowns;
  p.length_scale = length_scale_;
  p.EI_scale = EI_scale_;
  p.Nx = -u(0) * force_scale_;
  p.Ny = 0.0;
  p.m0 = -e.sr.reaction.M * moment_scale_;
  p.force = u(0) * force_scale_;
  p.residual = e.r.norm();
  p.converged = e.r.norm() <= std::max(options_.position_tolerance, options_.noise_floor);
  p.message = p.converged ? fmt::format("Newton on (F, alpha), {} steps", it)
                          : fmt::format(
                                "Newton on (F, alpha) stopped after {} steps with "
                                "|slider mismatch|/length = {:.3g}",
                                it,
                                p.residual);
  return p;
}

}  // namespace flexure::mechanism
