#pragma once
// The exact model of a general mechanism (issue 31; docs/mechanisms.md "General mechanisms"):
// every flexure an inextensible elastica (or, with Flexure::extensible, Reissner's beam with
// EA = E b h) between its two bodies -- clamped at both ends, or pinned at the far end for a
// flexure whose PRBM is fixed-pinned -- integrated from its root loads by the shooting method's
// integrator (solver/shooting/elastica_integrator.h, Prince-Dormand 8(7) at rtol 1e-12), and one
// Newton system for the whole mechanism (mixed formulation):
//
//   grad V(q) - lambda grad c(q) - J_g(q)^T mu - Q(q, w) = 0,   g(q) = 0,   c(q) = s,
//   tip_f(w_f) = pose of body b's end of flexure f in the frame of its root (3 per flexure),
//
// w_f = (m0, Nx, Ny) the root loads of flexure f, Q the generalised force of the flexures' end
// loads on the bodies, V the springs and dead loads. Displacement control: over the input grid by
// natural-parameter continuation with a secant predictor (forward-difference Jacobian), and where
// that stops (a limit point of the input) by pseudo-arclength continuation from the start. Force
// control: pseudo-arclength continuation through the limit points of the load (the PRBM path's
// algorithm, general_prbm.h; the Jacobian linearised: the flexures' tips from the integrator's
// sensitivities). Equilibria of the unloaded mechanism: sign changes of the input load, refined
// by the secant method on s (displacement control) or Newton at zero load (force control). Every
// point and equilibrium is judged under both controls (exact_stability.h).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "flexure/mechanisms/general/flexure_models.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/general/general_prbm.h"

namespace flexure::mechanism::general {

struct GeneralExactOptions {
  double tolerance = 1e-10;  // Newton: max residual of the scaled equations
  int max_newton_iterations = 40;
  int max_step_halvings = 12;  // of the input step when Newton fails
  // Force control (pseudo-arclength continuation): steps before giving up, and the largest step
  // (scaled: the bodies' coordinates in lengths / size and rad, the input load, the input).
  int max_steps = 20000;
  double max_step = 0.05;
  // solve_general_mixed: measure each flexure's model against the exact elastica under the loads
  // it carries at every point (FlexureModelReport::measured_error; an elliptic solve each).
  bool measure_flexure_errors = false;
  // Judge every recorded point and equilibrium (exact_stability.h): on by default; |margin| <=
  // critical_tolerance is critical.
  bool judge_stability = true;
  double critical_tolerance = kCriticalMarginTolerance;
  // Called after each recorded point of the path: (done, count), count the input's grid values,
  // done never decreasing and at most count (the mixed model's later passes report (count,
  // count)). For a progress display; a caller stops a long solve by throwing from it (the Python
  // module does on Ctrl-C). Empty: no calls.
  std::function<void(std::size_t done, std::size_t total)> progress;
  // Throws InvalidInput naming the field.
  void validate() const;
};

// The same result type as the PRBM's: points (input, input_load, energy = the flexures' strain
// energy plus the springs' minus the loads' work; the verdicts of exact_stability.h), equilibria
// (judged with the input free), limit points of the controlled quantity. iterations: Newton
// iterations in all; residual: the largest scaled residual of the recorded points.
GeneralPrbmResult solve_general_exact(const GeneralMechanism& mechanism,
                                      const GeneralExactOptions& options = {});

// The mixed model (`mechanism analyze --model mixed`, docs/mechanisms.md "A model per flexure"):
// the exact system above with each flexure under its own Flexure::model (flexure_models.h). A
// flexure set to `auto` starts on the cheapest rung of auto_ladder(); after each solve every auto
// flexure whose rung's mapped tip error at the loads it carries exceeds its tolerance at some
// point (or is not mapped there) moves to the cheapest higher rung within it at those loads (the
// exact elastica when none is), and the mechanism is solved again, until a solve changes no
// choice; a solve that fails moves every auto flexure below exact one rung up. The result's
// flexure_models say, per flexure, the model used, why, and its expected (mapped) error per
// length. Every flexure set to exact gives solve_general_exact's numbers exactly. Throws
// InvalidInput as solve_general_exact does, and for a fixed-guided flexure set to prbm.
GeneralPrbmResult solve_general_mixed(const GeneralMechanism& mechanism,
                                      const GeneralExactOptions& options = {});

}  // namespace flexure::mechanism::general
