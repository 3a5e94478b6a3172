// ExactMechanismSolver::solve_pinned_middle: sps and lps, a pin at pivot 2 between the crank
// (clamped at the ground) and the coupler (clamped into the slider by its s flexure).
#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/broyden_newton_2d.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/shooting/shooting_problem.h"

namespace flexure::mechanism {
namespace {

// Multiple-shooting parts for a chain under a pin force of magnitude `force` (the rule of
// shooting_problem.h, which cannot apply it itself: a pinned end's force is an unknown, not a
// given load): no flexible part longer than budget * sqrt(EI/|P|).
MultipleShootingOptions parts_for_force(const SegmentChain& chain,
                                        double force,
                                        MultipleShootingOptions o) {
  int parts = 1;
  for (const Segment& seg : chain.segments) {
    if (const auto* f = std::get_if<FlexibleSegment>(&seg)) {
      const double growth = f->length * std::sqrt(std::abs(force) / f->EI);
      // Clamp as a double before the int conversion (a NaN or huge trial force must not overflow).
      const double wanted = std::ceil(growth / o.amplification_budget);
      const double upper = std::max(1, o.max_parts_per_segment);
      parts = std::max(parts,
                       static_cast<int>(std::isfinite(wanted) ? std::min(wanted, upper) : upper));
    }
  }
  o.min_parts_per_segment =
      std::min(std::max(parts, o.min_parts_per_segment), std::max(1, o.max_parts_per_segment));
  return o;
}

// The pinned-middle mechanism as one shooting problem. Each cantilever is a pinned-end chain
// (ShootingProblem: unknowns m0, Nx, Ny, cut states; residuals m_tip, x - X, y - Y, continuity),
// the crank pinned at X = pivot2 in its frame, the coupler at the same point in its own frame
// (turned by pi about the slider: (xs - X, -Y)). Sharing the pin force between them (the coupler
// frame reads the crank's push -P as +P) and adding the two x and the two y rows makes the
// closure rows crank tip + coupler tip - (xs, 0) = 0 whatever pivot2 is. Unknowns
// u = [Px, Py, m0c, crank cuts, m0k, coupler cuts]; residuals G = [m_tip crank, crank
// continuity, m_tip coupler, coupler continuity, closure x, closure y].
class PinnedMiddleSystem {
 public:
  // `solver` supplies the work budget and the largest pin force worth integrating.
  PinnedMiddleSystem(const SegmentChain& crank,
                     const SegmentChain& coupler,
                     double xs,
                     const Eigen::Vector2d& pivot2,
                     double force,
                     const MultipleShootingOptions& ms,
                     const ExactMechanismSolver& solver)
      : crank_(pinned(crank, pivot2.x(), pivot2.y()), parts_for_force(crank, force, ms)),
        coupler_(pinned(coupler, xs - pivot2.x(), -pivot2.y()),
                 parts_for_force(coupler, force, ms)),
        solver_(solver) {}

  int size() const { return crank_.size() + coupler_.size() - 2; }
  int crank_offset() const { return 2; }
  int coupler_offset() const { return crank_.size(); }

  bool initial_unknowns(const Eigen::Vector2d& P,
                        double m0c,
                        double m0k,
                        ElasticaIntegrator& integrator,
                        Eigen::VectorXd& u,
                        std::string& error) const {
    Eigen::VectorXd zc, zk;
    if (!crank_.complete_guess(Eigen::Vector3d(m0c, P.x(), P.y()), 1.0, integrator, zc, error) ||
        !coupler_.complete_guess(Eigen::Vector3d(m0k, P.x(), P.y()), 1.0, integrator, zk, error)) {
      return false;
    }
    u.resize(size());
    u.head<2>() = P;
    u(crank_offset()) = zc(0);
    u.segment(crank_offset() + 1, zc.size() - 3) = zc.tail(zc.size() - 3);
    u(coupler_offset()) = zk(0);
    u.segment(coupler_offset() + 1, zk.size() - 3) = zk.tail(zk.size() - 3);
    return true;
  }

  struct Evaluation {
    bool ok = false;
    std::string error;
    Eigen::VectorXd G;
    Eigen::MatrixXd J;
    Eigen::Vector2d crank_tip = Eigen::Vector2d::Zero();
  };
  Evaluation evaluate(const Eigen::VectorXd& u, ElasticaIntegrator& integrator) const {
    Evaluation e;
    // Not integrated (a failed evaluation, so Newton damps its step): a trial pin force beyond
    // the solvers' domain, or the work budget is spent (ExactMechanismSolver::Options).
    if (solver_.out_of_time()) {
      e.error = solver_.budget_message();
      return e;
    }
    if (u.head<2>().norm() > solver_.max_force()) {
      e.error = "trial pin force beyond the solvers' domain of |F| L^2/EI";
      return e;
    }
    ShootingEvaluation ec, ek;
    const long steps_before = integrator.steps_taken();
    struct Charge {
      const ExactMechanismSolver& solver;
      const ElasticaIntegrator& integrator;
      long before;
      ~Charge() { solver.charge(integrator.steps_taken() - before); }
    } charge_on_return{solver_, integrator, steps_before};
    if (!crank_.evaluate(
            part(u, crank_offset(), crank_.size()), 1.0, true, false, integrator, ec) ||
        !coupler_.evaluate(
            part(u, coupler_offset(), coupler_.size()), 1.0, true, false, integrator, ek)) {
      e.error = ec.ok ? ek.error : ec.error;
      return e;
    }
    const int n = size();
    e.G.setZero(n);
    e.J.setZero(n, n);
    place(ec, crank_offset(), 0, e);
    place(ek, coupler_offset(), crank_.size() - 2, e);
    e.crank_tip << ec.tip.x, ec.tip.y;
    e.ok = e.G.allFinite() && e.J.allFinite();
    if (!e.ok) e.error = "non-finite residual";
    return e;
  }

 private:
  static SegmentChain pinned(SegmentChain c, double x, double y) {
    c.end = EndCondition::kPinned;
    c.tip_load = TipLoad{};
    c.prescribed = TipPrescription{};
    c.prescribed.x = x;
    c.prescribed.y = y;
    return c;
  }
  // Unknowns of one cantilever's problem (m0, Nx, Ny, cuts) from u.
  static Eigen::VectorXd part(const Eigen::VectorXd& u, int offset, int count) {
    Eigen::VectorXd z(count);
    z(0) = u(offset);
    z(1) = u(0);
    z(2) = u(1);
    z.tail(count - 3) = u.segment(offset + 1, count - 3);
    return z;
  }
  // Column of u of the cantilever unknown i.
  static int column(int i, int offset) {
    return i == 1 ? 0 : i == 2 ? 1 : i == 0 ? offset : offset + i - 2;
  }
  // Adds one cantilever's residuals: m_tip and continuity rows to rows from `row`, x and y rows to
  // the closure rows.
  void place(const ShootingEvaluation& s, int offset, int row, Evaluation& e) const {
    const int n = size();
    const int count = static_cast<int>(s.residual.size());
    for (int i = 0; i < count; ++i) {
      const int r = i == 0 ? row : i == 1 ? n - 2 : i == 2 ? n - 1 : row + i - 2;
      e.G(r) += s.residual(i);
      for (int j = 0; j < count; ++j) e.J(r, column(j, offset)) += s.jacobian(i, j);
    }
  }

  ShootingProblem crank_, coupler_;
  const ExactMechanismSolver& solver_;
};

struct PinnedMiddleNewton {
  bool ok = false;
  int iterations = 0;
  double residual = 0.0;  // max |G|, nondimensional
  std::string message;
  Eigen::Vector2d crank_tip = Eigen::Vector2d::Zero();
  double jacobian_determinant = 0.0;  // of dG/du at the returned point
};

// Damped Newton with the exact (sensitivity) Jacobian; the step is halved until max |G| falls.
// Below the noise floor a step that does not lower it ends the iteration as converged (the
// integrator's tolerance bounds the attainable residual).
PinnedMiddleNewton pinned_middle_newton(const PinnedMiddleSystem& system,
                                        ElasticaIntegrator& integrator,
                                        Eigen::VectorXd& u,
                                        double tolerance,
                                        double noise_floor,
                                        int max_iterations) {
  PinnedMiddleNewton out;
  PinnedMiddleSystem::Evaluation e = system.evaluate(u, integrator);
  if (!e.ok) {
    out.message = "integration failed at the starting guess: " + e.error;
    return out;
  }
  auto finish = [&](bool ok, std::string message) {
    out.ok = ok;
    out.message = std::move(message);
    out.residual = e.G.lpNorm<Eigen::Infinity>();
    out.crank_tip = e.crank_tip;
    out.jacobian_determinant = e.J.determinant();
    return out;
  };
  for (;; ++out.iterations) {
    const double r = e.G.lpNorm<Eigen::Infinity>();
    if (r <= tolerance) return finish(true, "");
    if (out.iterations >= max_iterations) {
      return finish(false, fmt::format("iteration limit {} reached", max_iterations));
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(e.J);
    if (!lu.isInvertible()) return finish(false, "singular Jacobian (a fold or bifurcation)");
    const Eigen::VectorXd step = lu.solve(-e.G);
    double t = 1.0;
    PinnedMiddleSystem::Evaluation trial = system.evaluate(u + step, integrator);
    for (int k = 0; k < 20 && !(trial.ok && trial.G.lpNorm<Eigen::Infinity>() < r); ++k) {
      if (r <= noise_floor) break;  // at the floor a failed full step already means convergence
      t *= 0.5;
      trial = system.evaluate(u + t * step, integrator);
    }
    if (!(trial.ok && trial.G.lpNorm<Eigen::Infinity>() < r)) {
      if (r <= noise_floor) return finish(true, "");
      return finish(false, "no decrease of the residual along the Newton step");
    }
    u += t * step;
    e = std::move(trial);
  }
}

}  // namespace

ExactPoint ExactMechanismSolver::solve_pinned_middle(double displacement,
                                                     const ExactPoint* previous) const {
  // One Newton iteration on all unknowns of both cantilevers at once (see PinnedMiddleSystem):
  // the pin force P = (Px, Py) (force of the coupler on the crank), the root moments at the
  // ground and slider clamps, and any multiple-shooting cut states; residuals: zero moment at
  // both tips (the pin) and the two tips meeting at pivot 2. Its Jacobian is the tangent
  // stiffness of the mechanism with the slider held, regular wherever the displacement-driven
  // mechanism is, so the pin force is not the controlling parameter. (Nesting -- Newton on P
  // around separate cantilever solves -- fails where a cantilever is loaded near its own buckling
  // load: the lps crank is a post-buckled fixed-free column at F ~ pi^2 EI/(4 l^2), and in sps
  // with R = 1 both links are; there the tip position is nearly singular in P and the inner
  // shooting has dm_tip/dm0 ~ 0; docs/mechanisms.md "Pinned middle".) Nondimensional units.
  ExactPoint p;
  p.displacement = displacement;
  const double xs = (physical_.slider_x0 - displacement) / length_scale_;
  Eigen::Vector2d P;
  double m0c = 0.0, m0k = 0.0;  // root moments, crank and coupler
  Eigen::Vector2d pivot2;       // guess of pivot 2 (crank frame): where the cantilevers are pinned
  if (previous != nullptr && previous->converged()) {
    P << previous->Nx / force_scale_, previous->Ny / force_scale_;
    m0c = previous->m0 / moment_scale_;
    m0k = previous->coupler_m0 / moment_scale_;
    pivot2 << 0.5 * xs, 0.0;  // any point: it cancels from the closure rows
  } else {
    const PrbmState s = prbm_state(design_, displacement);
    P << s.pin_force_x / force_scale_, s.pin_force_y / force_scale_;
    // PRB pivot 1: the centre of an s flexure, 0.15 l from the clamp of an l segment.
    const JointDesign& j1 = design_.joints[0];
    const double pivot1 = j1.type == PivotType::kLong
                              ? howell_average_fixed_pinned().geometry().pivot_x * j1.length
                              : 0.5 * j1.length;
    const double ax = (pivot1 + design_.r2 * std::cos(s.theta2)) / length_scale_;
    const double ay = design_.r2 * std::sin(s.theta2) / length_scale_;
    m0c = ax * P.y() - ay * P.x();
    const double lx = xs - ax, ly = -ay;  // pivot 2 in the coupler frame
    m0k = lx * P.y() - ly * P.x();
    pivot2 << ax, ay;
  }
  auto with_load = [](SegmentChain c, const Eigen::Vector2d& load) {
    c.end = EndCondition::kFree;
    c.tip_load.Fx = load.x();
    c.tip_load.Fy = load.y();
    return c;
  };
  ElasticaIntegrator integrator(options_.shooting.integrator_options());
  const PinnedMiddleSystem system(
      scaled_, scaled_coupler_, xs, pivot2, P.norm(), options_.shooting.multiple_shooting, *this);
  Eigen::VectorXd u;
  std::string error;
  if (!system.initial_unknowns(P, m0c, m0k, integrator, u, error)) {
    p.message = "integration from the starting guess failed: " + error;
    return p;
  }
  const PinnedMiddleNewton n = pinned_middle_newton(system,
                                                    integrator,
                                                    u,
                                                    options_.position_tolerance,
                                                    options_.noise_floor,
                                                    options_.max_newton_iterations);
  p.iterations = n.iterations;
  p.residual = n.residual;
  P = u.head<2>();
  if (!n.ok) {
    p.message = fmt::format(
        "Newton on the pin force and root moments stopped after {} steps at P = ({:.6g}, {:.6g}) "
        "N with residual {:.3g}: {}",
        n.iterations,
        P.x() * force_scale_,
        P.y() * force_scale_,
        n.residual,
        n.message);
    if (previous == nullptr && displacement > 0.0) {
      // No neighbour and the PRBM guess is too far: march from a small stroke, each step from
      // the last (a continuation in the slider position, which is the controlling parameter).
      // (`p`, unconverged, as `previous` means: start from the PRBM, do not march again.)
      constexpr int kSteps = 8;
      ExactPoint q = solve_pinned_middle(displacement / kSteps, &p);
      for (int k = 2; k <= kSteps && q.converged(); ++k) {
        ExactPoint next = solve_pinned_middle(displacement * k / kSteps, &q);
        next.iterations += q.iterations;
        q = std::move(next);
      }
      if (q.converged()) {
        q.message +=
            fmt::format(" ({} steps from Delta x = {:.6g} m)", kSteps, displacement / kSteps);
        return q;
      }
      p.message += "; marching from a small stroke failed too: " + q.message;
    }
    return p;
  }
  p.chain = with_load(scaled_, P);
  p.unknowns = {u(system.crank_offset())};
  p.coupler_chain = with_load(scaled_coupler_, P);
  p.coupler_unknowns = {u(system.coupler_offset())};
  p.length_scale = length_scale_;
  p.EI_scale = EI_scale_;
  p.Nx = P.x() * force_scale_;
  p.Ny = P.y() * force_scale_;
  p.m0 = u(system.crank_offset()) * moment_scale_;
  p.coupler_m0 = u(system.coupler_offset()) * moment_scale_;
  p.force = -p.Nx;
  // Coupler angle above the axis, from pivot 2 to the slider joint.
  p.phi = std::atan2(n.crank_tip.y(), xs - n.crank_tip.x());
  p.stiffness_determinant = n.jacobian_determinant;
  p.set_converged(true);
  p.message = fmt::format("Newton on the pin force and root moments, {} steps", n.iterations);
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
  if (previous != nullptr && previous->converged()) {
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
    // Not integrated (a failed evaluation, so the step is damped): a trial slider force beyond
    // the solvers' domain -- near the toggle of 1B-plp a step tried F L^2/EI = 2e8, where one
    // shooting solve took 21 s -- or the work budget is spent (ExactMechanismSolver::Options).
    if (std::abs(v(0)) > max_force() || out_of_time()) {
      e.sr.message = out_of_time() ? budget_message()
                                   : fmt::format("trial slider force beyond |F| L^2/EI = {:g}",
                                                 options_.max_load_parameter);
      return e;
    }
    // Continuation from zero load only for the very first evaluation of a stroke (see above).
    e.sr = solver.solve_from(make_chain(v), {m0});
    charge(e.sr.integrator_steps);
    if (!e.sr.converged() && fallback && !out_of_time()) {
      e.sr = solver.solve(make_chain(v));
      charge(e.sr.integrator_steps);
    }
    p.iterations += e.sr.iterations;
    if (!e.sr.converged()) return e;
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
  p.set_converged(e.r.norm() <= std::max(options_.position_tolerance, options_.noise_floor));
  p.message = p.converged() ? fmt::format("Newton on (F, alpha), {} steps", it)
                            : fmt::format(
                                  "Newton on (F, alpha) stopped after {} steps with "
                                  "|slider mismatch|/length = {:.3g}",
                                  it,
                                  p.residual);
  return p;
}

}  // namespace flexure::mechanism
