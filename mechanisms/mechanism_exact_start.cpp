// exact_first_point: starting the exact stroke when the PRBM start guess fails
// (mechanism_exact.h).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_problem.h"

namespace flexure::mechanism {
namespace {

// Walks from the converged point `from` to displacement `to` in `steps` equal substeps.
ExactPoint walk(const ExactMechanismSolver& solver, ExactPoint from, double to, int steps) {
  const double x0 = from.displacement;
  for (int i = 1; i <= steps; ++i) {
    ExactPoint q = solver.solve(x0 + (to - x0) * i / steps, &from);
    if (!q.converged()) return q;
    from = std::move(q);
  }
  return from;
}

// Geometric interpolation of every flexure thickness from the largest one (t = 0) to its own
// (t = 1): EI ratios go from 1 to the design's, while the largest EI (the solver's EI scale) and
// all lengths stay fixed, so nondimensional unknowns carry over between steps.
MechanismDesign thickness_homotopy(const MechanismDesign& d, double t) {
  MechanismDesign out = d;
  double h_max = 0.0;
  for (const auto& j : d.joints) h_max = std::max(h_max, j.thickness);
  for (auto& j : out.joints) {
    if (j.type == PivotType::kPin) continue;
    j.thickness = std::pow(h_max, 1.0 - t) * std::pow(j.thickness, t);
  }
  return out;
}

}  // namespace

ExactPoint exact_first_point(const MechanismDesign& design,
                             const std::vector<double>& displacements,
                             const ExactMechanismSolver::Options& options) {
  const double first = displacements.front();
  const double last = *std::max_element(displacements.begin(), displacements.end());
  const ExactMechanismSolver solver(design, options);
  std::string history;
  // (1) Far from the straight position the PRBM force exceeds the exact buckling load of the
  // crank, so the start lands on the deflected branch; then back to the first point.
  if (last > first) {
    ExactPoint end = solver.solve(last);
    if (end.converged()) {
      for (int steps : {8, 32}) {
        ExactPoint p = walk(solver, end, first, steps);
        if (p.converged()) {
          p.message += fmt::format(" (started at Delta x = {:.6g} m, {} steps back)", last, steps);
          return p;
        }
        history = fmt::format("walk back from the stroke end: {}; ", p.message);
      }
    } else {
      history = fmt::format("stroke end from the PRBM: {}; ", end.message);
    }
  }
  // (2) Thickness homotopy at the first displacement, halving the step on failure.
  ExactPoint current = ExactMechanismSolver(thickness_homotopy(design, 0.0), options).solve(first);
  if (!current.converged()) {
    current.message = history + "equal thicknesses: " + current.message;
    return current;
  }
  double t = 0.0, dt = 0.25;
  while (t < 1.0) {
    const double next = std::min(1.0, t + dt);
    ExactPoint q =
        ExactMechanismSolver(thickness_homotopy(design, next), options).solve(first, &current);
    if (q.converged()) {
      current = std::move(q);
      t = next;
      dt = std::min(0.5, 2.0 * dt);
    } else if ((dt *= 0.5) < 1e-3) {
      q.message =
          history + fmt::format("thickness homotopy stalled at t = {:.4g}: ", t) + q.message;
      return q;
    }
  }
  // Re-solve with the design's own solver so that the point carries its chain and scales.
  ExactPoint p = solver.solve(first, &current);
  if (p.converged()) p.message += " (thickness homotopy from equal flexures)";
  return p;
}

namespace {

// The linearised problem of the straight chain under the axial compression P (nondimensional):
// the far-end residuals that the slider holds besides x -- the tip angle (fixed end) or the tip
// moment (pinned end), and y -- against the root unknowns m(0) and N_y(0), from the shooting
// Jacobian at m(0) = N_y(0) = 0, N_x(0) = -P. At the straight state x does not move to first
// order, so the chain buckles where this 2 x 2 block is singular. Single shooting: the thinnest
// strip's growth factor exp(L sqrt(P/EI)) stays below e^7 for the loads scanned here.
class StraightChain {
 public:
  StraightChain(const SegmentChain& chain, const ShootingSolver::Options& o)
      : problem_(chain, single_shooting()), integrator_(o.integrator_options()) {
    const auto& names = problem_.unknown_names();
    for (int i = 0; i < problem_.size(); ++i) {
      if (names[i] == "Nx0") nx_ = i;
      if (names[i] == "Ny0") ny_ = i;
    }
    if (nx_ < 0 || ny_ < 0 || problem_.size() != 3) {
      throw InvalidInput("the lowest buckling mode needs a serial chain with the tip x and y held");
    }
  }
  // The block at compression P; false when the integration fails.
  bool block(double P, Eigen::Matrix2d& D) {
    ShootingEvaluation e;
    if (!problem_.evaluate(root(0.0, P, 0.0), 1.0, true, false, integrator_, e)) return false;
    // Residual rows: 0 the tip angle (or moment), 1 x, 2 y.
    D << e.jacobian(0, 0), e.jacobian(0, ny_), e.jacobian(2, 0), e.jacobian(2, ny_);
    return true;
  }
  bool det(double P, double& d) {
    Eigen::Matrix2d D;
    if (!block(P, D)) return false;
    d = D.determinant();
    return true;
  }
  // The tip and the angle at arc length s_probe for the root unknowns (m0, -P, Ny).
  bool shape(double m0, double P, double Ny, double s_probe, TipState& tip, double& theta) {
    std::string error;
    const std::vector<double> s{s_probe};
    std::vector<ShapePoint> sh;
    if (!problem_.integrate_solution(root(m0, P, Ny), 1.0, integrator_, tip, error, &s, &sh) ||
        sh.empty()) {
      return false;
    }
    theta = sh.front().theta;
    return true;
  }

  static MultipleShootingOptions single_shooting() {
    MultipleShootingOptions m;
    m.amplification_budget = 1e3;  // never cut
    m.max_parts_per_segment = 1;
    return m;
  }

 private:
  Eigen::VectorXd root(double m0, double P, double Ny) const {
    Eigen::VectorXd z = Eigen::VectorXd::Zero(problem_.size());
    z[0] = m0;
    z[nx_] = -P;
    z[ny_] = Ny;
    return z;
  }
  ShootingProblem problem_;
  ElasticaIntegrator integrator_;
  int nx_ = -1, ny_ = -1;
};

// Arc length of the end of the first flexible segment (the ground flexure), nondimensional.
double ground_flexure_end(const SegmentChain& chain) {
  double s = 0.0;
  for (const Segment& seg : chain.segments) {
    if (const auto* f = std::get_if<FlexibleSegment>(&seg)) return s + f->length;
    s += std::get<RigidSegment>(seg).length;
  }
  return s;
}

}  // namespace

ExactBucklingMode exact_lowest_buckling_mode(const MechanismDesign& design,
                                             const ExactMechanismSolver::Options& options,
                                             double max_load) {
  ExactBucklingMode out;
  if (exact_support(design) != ExactSupport::kDirectChain) {
    out.message = "the lowest buckling mode is computed for serial chains (ssp, slp, sss) only";
    return out;
  }
  const ExactMechanismSolver solver(design, options);
  const double fs = solver.force_scale();
  // Scan bound: three times the PRBM's buckling load (its force at the straight position), which
  // is the linkage mode's; a lower mode of a flexure of its own lies below it.
  const double tiny = 1e-6 * design.toggle_stroke();
  if (!(max_load > 0.0)) max_load = 3.0 * std::abs(prbm_state(design, tiny).force);
  const SegmentChain chain = solver.scaled_chain(tiny);
  StraightChain straight(chain, options.shooting);
  // det D(P) is an entire function of P (the linear ODE depends analytically on it); its zeros
  // are the buckling loads. 400 samples: the thinnest strip turns through at most a few half
  // waves below the bound, so no pair of zeros hides between two samples.
  constexpr int kSamples = 400;
  const double P_max = max_load / fs;
  std::vector<double> roots;
  double P_prev = 0.0, d_prev = 0.0;
  if (!straight.det(0.0, d_prev)) {
    out.message = "integrating the straight chain failed";
    return out;
  }
  for (int i = 1; i <= kSamples && roots.size() < 2; ++i) {
    const double P = P_max * i / kSamples;
    double d = 0.0;
    if (!straight.det(P, d)) {
      out.message = fmt::format("integrating the straight chain under P = {:.6g} N failed", P * fs);
      return out;
    }
    if ((d < 0.0) != (d_prev < 0.0)) {
      // Bisection to the rounding of P (60 halvings of the sample interval).
      double a = P_prev, b = P, da = d_prev;
      for (int k = 0; k < 60 && b - a > 1e-15 * b; ++k) {
        const double c = 0.5 * (a + b);
        double dc = 0.0;
        if (!straight.det(c, dc)) break;
        if ((dc < 0.0) == (da < 0.0)) {
          a = c, da = dc;
        } else {
          b = c;
        }
      }
      roots.push_back(0.5 * (a + b));
    }
    P_prev = P, d_prev = d;
  }
  if (roots.empty()) {
    out.message = fmt::format("no buckling load of the straight chain below {:.6g} N", max_load);
    return out;
  }
  const double P1 = roots.front();
  Eigen::Matrix2d D;
  if (!straight.block(P1, D)) {
    out.message = "integrating the straight chain at its buckling load failed";
    return out;
  }
  // Null vector: orthogonal to the block's larger row.
  const int r = D.row(0).norm() >= D.row(1).norm() ? 0 : 1;
  Eigen::Vector2d v(-D(r, 1), D(r, 0));
  v.normalize();
  // Sign: the ground flexure turns the way the PRBM's crank does.
  TipState tip;
  double theta = 0.0;
  if (!straight.shape(1e-6 * v[0], P1, 1e-6 * v[1], ground_flexure_end(chain), tip, theta)) {
    out.message = "integrating the buckling mode failed";
    return out;
  }
  if ((theta < 0.0) != (prbm_state(design, tiny).theta2 < 0.0)) v = -v;
  out.load = P1 * fs;
  out.m0 = v[0];
  out.Ny = v[1];
  out.next_load = roots.size() > 1 ? roots[1] * fs : 0.0;
  out.set_converged(true);
  out.message = fmt::format("lowest buckling load {:.10g} N", out.load);
  return out;
}

ExactPoint exact_lowest_mode_point(const MechanismDesign& design,
                                   double displacement,
                                   const ExactMechanismSolver::Options& options) {
  ExactPoint failed;
  failed.displacement = displacement;
  const ExactBucklingMode mode = exact_lowest_buckling_mode(design, options);
  if (!mode.converged()) {
    failed.message = mode.message;
    return failed;
  }
  const ExactMechanismSolver solver(design, options);
  const double fs = solver.force_scale(), P = mode.load / fs;
  const SegmentChain chain = solver.scaled_chain(displacement);
  StraightChain straight(chain, options.shooting);
  // Post-buckling amplitude: the slider's travel is the chain's end shortening, quadratic in the
  // mode's amplitude a near the straight state (Delta x = c a^2), so a = a0 sqrt(Delta x / c a0^2).
  // Start where the flexures turn by about 1e-3 rad: close enough to the bifurcation for the
  // linear mode to lie in Newton's basin of the branch, far enough for its shape to be resolved.
  constexpr double a0 = 1e-4;
  TipState tip;
  double theta = 0.0;
  if (!straight.shape(a0 * mode.m0, P, a0 * mode.Ny, chain.total_length(), tip, theta)) {
    failed.message = "integrating the buckling mode failed";
    return failed;
  }
  const double shortening = chain.total_length() - tip.x;  // nondimensional, at amplitude a0
  if (!(shortening > 0.0)) {
    failed.message = "the buckling mode does not shorten the chain";
    return failed;
  }
  // First point at a slider travel of 1e-5 of the slider's distance (flexure rotations of a few
  // 1e-3 rad; Newton from the mode converges in 3-4 iterations there on 3A-lssm), then doubling.
  const double x0 = physical_chain(design).slider_x0;
  const double start = std::min(displacement, 1e-5 * x0);
  const double a = a0 * std::sqrt(start / x0 / shortening);
  ExactPoint guess;
  guess.set_converged(true);
  guess.unknowns = {a * mode.m0, -P, a * mode.Ny};
  ExactPoint current = solver.solve(start, &guess, false);
  if (!current.converged()) {
    failed.message = fmt::format(
        "Newton from the lowest buckling mode (P1 = {:.6g} N) at Delta x = "
        "{:.3g} m: {}",
        mode.load,
        start,
        current.message);
    return failed;
  }
  int steps = 1;
  ExactPoint walked = exact_adaptive_walk(design, current, displacement, start, options, &steps);
  if (!walked.converged()) {
    failed.message = "walking the branch of the lowest buckling mode: " + walked.message;
    return failed;
  }
  current = std::move(walked);
  current.message += fmt::format(
      " (on the branch of the straight chain's lowest buckling mode, P1 = {:.6g} N: from "
      "Delta x = {:.3g} m in {} steps)",
      mode.load,
      start,
      steps);
  return current;
}

ExactPoint exact_adaptive_walk(const MechanismDesign& design,
                               const ExactPoint& from,
                               double to,
                               double first_step,
                               const ExactMechanismSolver::Options& options,
                               int* steps) {
  const ExactMechanismSolver solver(design, options);
  ExactPoint current = from;
  double h = first_step;
  const double h_min = 1e-6 * physical_chain(design).slider_x0;
  int n = 0;
  while (current.displacement < to) {
    const double next = std::min(to, current.displacement + h);
    ExactPoint q = solver.solve(next, &current, false);
    ++n;
    const bool jumped = q.converged() && q.jacobian_sign != 0 && current.jacobian_sign != 0 &&
                        q.unknowns.size() == current.unknowns.size() &&
                        q.jacobian_sign != current.jacobian_sign;
    if (q.converged() && !jumped) {
      current = std::move(q);
      h *= 2.0;
      continue;
    }
    if (jumped) {
      // A fold or bifurcation lies between: where the branch turns unstable (a pitchfork), a
      // stable branch leaves it.
      ExactPoint near = exact_stable_neighbour(design, current, next, options);
      if (near.converged()) {
        current = std::move(near);
        continue;
      }
    }
    if ((h *= 0.5) < h_min || solver.out_of_time()) {
      ExactPoint failed;
      failed.displacement = to;
      failed.message = fmt::format("stalled at Delta x = {:.6g} m: {}",
                                   current.displacement,
                                   jumped ? "the shooting Jacobian changes sign (a fold or "
                                            "bifurcation) and no stable branch was found next to it"
                                          : q.message);
      return failed;
    }
  }
  if (steps != nullptr) *steps += n;
  return current;
}

ExactPoint exact_stable_neighbour(const MechanismDesign& design,
                                  const ExactPoint& from,
                                  double displacement,
                                  const ExactMechanismSolver::Options& options) {
  ExactPoint failed;
  failed.displacement = displacement;
  if (exact_support(design) != ExactSupport::kDirectChain || !from.converged() ||
      from.unknowns.size() != 3) {
    failed.message = "no stable neighbour searched (serial chains with single shooting only)";
    return failed;
  }
  // The null direction of the shooting Jacobian at `from` (its smallest singular vector): near a
  // pitchfork it is the direction in which the new branch leaves.
  ShootingProblem problem(from.chain, StraightChain::single_shooting());
  ElasticaIntegrator integrator(options.shooting.integrator_options());
  ShootingEvaluation e;
  const Eigen::VectorXd z = Eigen::Map<const Eigen::VectorXd>(from.unknowns.data(), 3);
  if (problem.size() != 3 || !problem.evaluate(z, 1.0, true, false, integrator, e)) {
    failed.message = "evaluating the shooting Jacobian at the previous point failed";
    return failed;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(e.jacobian, Eigen::ComputeFullV);
  const Eigen::Vector3d v = svd.matrixV().col(2);
  const ExactMechanismSolver solver(design, options);
  for (double t : {0.01, 0.02, 0.05, 0.1, 0.2, 0.4}) {
    for (double side : {1.0, -1.0}) {
      ExactPoint guess = from;
      const Eigen::Vector3d g = z + side * t * z.norm() * v;
      guess.unknowns = {g[0], g[1], g[2]};
      ExactPoint q = solver.solve(displacement, &guess, false);
      if (!q.converged()) continue;
      try {
        if (exact_point_stability(design, q).displacement_control.kind != StabilityKind::kStable) {
          continue;
        }
      } catch (const std::exception&) {
        continue;
      }
      q.message += fmt::format(
          " (a stable equilibrium next to the previous point, off its branch along the shooting "
          "Jacobian's null direction: the branch lost its stability between them)");
      return q;
    }
  }
  failed.message = "no stable equilibrium found next to the previous point";
  return failed;
}

}  // namespace flexure::mechanism
