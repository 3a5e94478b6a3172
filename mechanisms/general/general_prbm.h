#pragma once
// The PRBM of a general mechanism over its input range: equilibrium path by pseudo-arclength
// continuation (through limit points of the input), the input load at each point from the
// energy's gradient (virtual work: the multiplier of the input's constraint, dV/ds along the
// constraint manifold; Howell eqs. 6.53, 11.11), the stability of each point under displacement
// and force control (the Hessian of the energy on the constraint manifold; Howell §11.2,
// docs/stability.md "Mechanisms"), and the equilibria of the unloaded mechanism (zero input load,
// from the path's sign changes refined by Newton). docs/mechanisms.md "General mechanisms".
//
// The equations, in the assembly's scaled variables z = (q, mu, lambda, s):
//   grad V(q) - lambda grad c(q) - J_g(q)^T mu = 0,   g(q) = 0,   c(q) - s = 0,
// one equation fewer than unknowns: a curve, followed in arclength. Displacement control fixes s
// at each grid value, force control fixes lambda. The Hessian of the Lagrangian
// H = d/dq (grad V - lambda grad c - J_g^T mu) projected on the admissible directions -- the
// null space of J_g (force control: the input free under its dead load lambda) or of [J_g; grad c]
// (displacement control) -- gives the verdict: index = its negative eigenvalues, margin = the
// lowest eigenvalue relative to the springs' unloaded stiffness B (1 unloaded, 0 critical).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "flexure/mechanisms/general/flexure_models.h"
#include "flexure/mechanisms/general/flexure_point_results.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/solver/common/stability.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {

struct GeneralPrbmOptions {
  double tolerance = 1e-11;  // Newton: max residual of the scaled equations
  int max_newton_iterations = 25;
  int max_steps = 20000;   // arclength steps before giving up
  double max_step = 0.05;  // arclength step, scaled units (lengths / size, rad)
  double critical_tolerance = kCriticalMarginTolerance;
  // Called after each recorded point of the path: (done, count), count the input's grid values,
  // done never decreasing and at most count (GeneralExactOptions::progress's convention). For a
  // progress display; a caller stops a long solve by throwing from it (the exception propagates;
  // the Python module does on Ctrl-C). Empty: no calls.
  std::function<void(std::size_t done, std::size_t total)> progress;
  // Throws InvalidInput naming the field.
  void validate() const;
};

struct GeneralPrbmPoint {
  double input = 0.0;          // the input coordinate, m or rad (absolute, see general_mechanism.h)
  double input_load = 0.0;     // the force (N) or moment (N m) that holds it: dV/ds
  double energy = 0.0;         // potential energy V (springs minus the dead loads' work), J
  double spring_energy = 0.0;  // the springs' stored energy alone, J
  Stability displacement_control;
  Stability force_control;
  // Poses of the described moving bodies (x, y displacement in m, rotation in rad, from the
  // described configuration), in body_names order.
  std::vector<double> body_x, body_y, body_phi;
  // Reactions, stresses and shapes (flexure_point_results.h; docs/mechanisms.md "Reactions,
  // stresses and shapes"): each joint in description order, each flexure in description order,
  // and the load the ground puts on the mechanism through everything attached to it (joints,
  // flexures, springs): force, and moment about the global origin. With the input load and the
  // dead loads it balances: ground + input + dead loads = 0 (force and moment).
  std::vector<JointPointResult> joints;
  std::vector<FlexurePointResult> flexures;
  PointLoad ground_reaction;
};

struct GeneralEquilibrium {
  double input = 0.0;   // m or rad
  double energy = 0.0;  // J
  // The unloaded mechanism with its input free (force control at zero load): a minimum of the
  // energy (stable) or not.
  Stability stability;
};

struct GeneralPrbmResult : SolveStatus {
  // iterations: arclength steps; residual: largest scaled residual of the recorded points.
  std::vector<std::string> body_names;   // described moving bodies
  std::vector<GeneralPrbmPoint> points;  // at each grid value of the controlled quantity, in path
                                         // order (a value crossed twice after a limit point twice)
  std::vector<GeneralEquilibrium> equilibria;  // in path order
  // Limit points of the controlled quantity along the path (the input coordinate under
  // displacement control, the load under force control: where a dead load makes it snap): the
  // input coordinate and the input load there, located to about 1e-12 of arclength.
  std::vector<double> limit_inputs;
  std::vector<double> limit_loads;
  int degrees_of_freedom = 0;  // of the PRB linkage with the input free
  // The mixed model (solve_general_mixed): per flexure, the model used, why, and its expected
  // error; empty for the PRBM and the all-exact model.
  std::vector<FlexureModelReport> flexure_models;
};

// The structural checks both models make before solving, on the PRB linkage in the described
// configuration; returns its degrees of freedom with the input free. Throws InvalidInput for
// redundant joints, a linkage that cannot move, an input that cannot move to first order without a
// start_rotation (a dead point), and a body that moves with the input held without straining any
// spring (naming it).
int check_general_mechanism(const GeneralMechanism& mechanism);

// A value of the input coordinate for messages, with its unit: "0.0125 m", or for an angle
// "0.582571 rad (33.379 deg)".
std::string input_value_text(const Input& input, double value);

// Solves the PRBM of `mechanism` over its input range. Throws InvalidInput for a bad description
// (GeneralMechanism::validate), for redundant constraints, for a body or direction that moves with
// no stiffness while the input is held (naming the body), and for a flexure whose model is
// not prbm (a model per flexure is solve_general_mixed's). A path that cannot be followed ends with
// kNoConvergence or, when it turns back at a limit point and never reaches the range's end,
// kLimitPoint; the points reached are returned.
GeneralPrbmResult solve_general_prbm(const GeneralMechanism& mechanism,
                                     const GeneralPrbmOptions& options = {});

}  // namespace flexure::mechanism::general
