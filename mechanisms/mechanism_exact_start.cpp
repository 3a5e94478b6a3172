// exact_first_point: starting the exact stroke when the PRBM start guess fails
// (mechanism_exact.h).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/mechanisms/mechanism_exact.h"

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

}  // namespace flexure::mechanism
