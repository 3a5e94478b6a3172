#pragma once
// A general mechanism solved over its input range by the PRBM and by the exact model, and what
// each solved point reports besides the input load, energy and stability.
#include <Eigen/Dense>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {

// What a general mechanism's solve reports at every point besides the input load, energy and
// stability (issue 31 item 2; docs/mechanisms.md "Reactions, stresses and shapes"): the joints'
// reactions and positions, the load the ground puts on the mechanism, and each flexure's end
// loads, its largest normal stress (bending plus axial, at both fibres, with the location) and
// its shape. SI throughout.

// A force (N) at a point and a moment (N m, counter-clockwise) about that point.
struct PointLoad {
  double fx = 0.0;
  double fy = 0.0;
  double moment = 0.0;
};

// A joint at one point: where its point of body b is (m), and the load body a puts on body b
// through it (the force at that point; the moment of a slider or weld, 0 for a pin). Body b puts
// the opposite on body a.
struct JointPointResult {
  double x = 0.0;
  double y = 0.0;
  PointLoad on_b;
};

// One flexure at one point.
struct FlexurePointResult {
  // The loads the flexure puts on its bodies: on body a at end a, on body b at end b (force at the
  // end, moment about it). For a flexure clamped into the ground the negated on_a is the ground's
  // reaction there.
  PointLoad on_a;
  PointLoad on_b;
  // The largest |sigma| over both fibres and the length (Pa), sigma = N_a/A -+ m c/I (c = h/2,
  // N_a = N . t tension positive, m the bending moment, a positive m compressing the fibre on the
  // +n side: n the normal left of the tangent); where it acts, from end a (m); the fibre (+1: the
  // +n side, -1 the other); the two fibres' stresses, the bending moment and the axial force at
  // that section.
  double max_stress = 0.0;
  double max_stress_at = 0.0;
  int max_stress_fibre = 1;
  double stress_pos_fibre = 0.0;
  double stress_neg_fibre = 0.0;
  double moment = 0.0;
  double axial_force = 0.0;
  // "shape": searched along the elastica's sampled shape (a parabola through the largest sample
  // and its neighbours); "ends": the larger of the two ends' (the PRBM and the ladder's models,
  // which give the end loads of Howell's characteristic-radius model, not the shape: Howell eqs.
  // 5.22-5.23 at the clamp).
  const char* max_from = "ends";
  // The shape in global coordinates (m), from end a to end b: the elastica sampled at equal arc
  // lengths (exact), the PRB linkage's joints (PRBM: end a, its pivots, end b), or the chord (a
  // model flexure of the mixed model).
  std::vector<double> shape_x, shape_y;
};

// The normal stresses of a section of `flexure` carrying bending moment m (N m) and axial force
// N_a (N, tension positive): {sigma at the +n fibre, at the -n fibre} = N_a/A -+ m c/I.
struct FibreStresses {
  double pos = 0.0;
  double neg = 0.0;
};
FibreStresses fibre_stresses(const Flexure& flexure, double moment, double axial);
// The same for the rectangle width x thickness (m) of a tapered flexure's section.
FibreStresses fibre_stresses(double width, double thickness, double moment, double axial);

// Keeps in `r` the section (at `s` m from end a, moment m, axial force N_a) whose |sigma| is
// largest; `first` replaces whatever `r` held.
void keep_most_stressed(
    FlexurePointResult& r, const Flexure& flexure, double s, double m, double axial, bool first);
// The same with the section width x thickness (m) there.
void keep_most_stressed(FlexurePointResult& r,
                        double width,
                        double thickness,
                        double s,
                        double m,
                        double axial,
                        bool first);

// The stress of a flexure whose end loads are known and whose shape is not (the PRBM, a ladder
// model): the sections at both ends, with the bending moment and axial force there. m_a, m_b:
// bending moments at end a and end b; axial_a, axial_b: N . t there.
void end_stresses(FlexurePointResult& r,
                  const Flexure& flexure,
                  double length,
                  double m_a,
                  double axial_a,
                  double m_b,
                  double axial_b);

class PrbmAssembly;
struct GeneralPrbmPoint;

// The joints' positions and reactions and the ground's reaction through the joints, the springs
// and the assembled flexures, at coordinates q and multipliers mu (scaled, the assembly's), into
// `point`; with `assembled_flexures`, every flexure's PRBM end loads, end stresses and PRB linkage
// too (the PRBM; the exact model fills its flexures itself and adds their loads on the ground).
void fill_point_results(const GeneralMechanism& mechanism,
                        const PrbmAssembly& assembly,
                        const Eigen::VectorXd& q,
                        const Eigen::VectorXd& mu,
                        bool assembled_flexures,
                        GeneralPrbmPoint& point);

// Adds to `ground` (the load the ground puts on the mechanism, moment about the origin) the
// opposite of `load` (what a flexure puts on the ground at the point (x, y)).
void add_ground_reaction(PointLoad& ground, const PointLoad& load, double x, double y);

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
  // Reactions, stresses and shapes (FlexurePointResult above; docs/mechanisms.md "Reactions,
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
// algorithm, solve_general_prbm above; the Jacobian linearised: the flexures' tips from the
// integrator's sensitivities). Equilibria of the unloaded mechanism: sign changes of the input
// load, refined by the secant method on s (displacement control) or Newton at zero load (force
// control). Every point and equilibrium is judged under both controls (exact_stability.h).

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
// the exact system above with each flexure under its own Flexure::model (general_mechanism.h,
// model_tip). A flexure set to `auto` starts on the cheapest rung of auto_ladder(); after each
// solve every auto flexure whose rung's mapped tip error at the loads it carries exceeds its
// tolerance at some point (or is not mapped there) moves to the cheapest higher rung within it at
// those loads (the exact elastica when none is), and the mechanism is solved again, until a solve
// changes no choice; a solve that fails moves every auto flexure below exact one rung up. The
// result's flexure_models say, per flexure, the model used, why, and its expected (mapped) error
// per length. Every flexure set to exact gives solve_general_exact's numbers exactly. Throws
// InvalidInput as solve_general_exact does, and for a fixed-guided flexure set to prbm.
GeneralPrbmResult solve_general_mixed(const GeneralMechanism& mechanism,
                                      const GeneralExactOptions& options = {});

}  // namespace flexure::mechanism::general
