#pragma once
// A beam request as a front end receives it (flags of `flexure beam`, keywords of the Python
// `flexure.beam`): every value optional, checked here once so that every front end refuses the
// same things with the same words. make_beam_input() turns it into the BeamProblem and method
// that solve_beam() (or BeamSolver) takes.
//
// Messages name each value the way the caller names it (BeamRequestNames): the command line passes
// its flags ("--alpha2"), so its messages stay its own; a C++ caller gets the quantity names
// ("alpha2"), which name no flag.
#include <optional>
#include <string>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/physical_beam.h"
#include "flexure/solver/common/status.h"

namespace flexure {

// What the caller gave; a value left unset keeps the documented default (docs/cli.md, `beam`).
struct BeamRequest {
  // Exactly one of the load alpha2 = P l^2/EI, the tip angle theta0 (radians, or text with an
  // angle unit: "30deg") or the tip deflection b/l (-1..1), unless the beam is given whole below.
  std::optional<double> alpha2;
  std::optional<std::string> theta0;
  std::optional<double> b_over_l;
  double load_ratio_n = 0.0;  // Howell's n (eq. 2.67), n > 0 compressive
  double mu = 0.0;            // end moment M l/EI (eq. 2.83)
  // The far end: free, guided, pinned, slider or fixed, and its prescribed tip values (x/l, y/l,
  // or metres for a physical beam; the angle as text like theta0); each only where the end
  // prescribes it.
  std::string boundary = "free";
  std::optional<double> tip_x;
  std::optional<double> tip_y;
  std::optional<std::string> tip_angle;
  double follower = 0.0;  // follower tip force F l^2/EI
  // The method and its settings (BeamSolver::Options holds the same, checked).
  std::string method = "auto";
  std::optional<double> tolerance;  // auto only: the relative error allowed (default 1e-6)
  std::optional<int> elements;      // chain algorithm N (default 100), or the chained BCM's
  int increments = 1;               // chain algorithm: load increments to start with
  std::string chain_variant = "corrected";
  std::optional<std::string> integrator;  // shooting and auto: rk8pd, cvodes, dormand-prince
  std::optional<int> shape_points;        // >= 2 points of the deflected shape
  std::optional<std::string> constants;   // PR-3R constants (prbm3r only)
  std::optional<double> slenderness;      // L/t of the BCM and chained BCM (bcm, cbcm only)
  bool stable = false;                    // return a stable equilibrium (docs/stability.md)
  bool judge_stability = true;            // the stability verdict of the answer
  // The beam given whole, in SI units or as a chain: the caller reads it after make_beam_input has
  // refused a combination with the nondimensional loads above, and adds it with
  // add_physical_beam() or add_chain() (a reader's own errors thus come after the combination's).
  bool physical = false;
  bool chain = false;
};

// How the caller names each value in messages. The defaults are the quantity names of
// BeamRequest; command_line() gives `flexure beam`'s flags (the Python module uses them too, so
// that its messages are the tool's).
struct BeamRequestNames {
  std::string alpha2 = "alpha2";
  std::string theta0 = "theta0";
  std::string b_over_l = "b_over_l";
  std::string load_ratio_n = "load_ratio_n";
  std::string mu = "mu";
  std::string boundary = "boundary";
  std::string tip_x = "tip_x";
  std::string tip_y = "tip_y";
  std::string tip_angle = "tip_angle";
  std::string follower = "follower";
  std::string method = "method";
  std::string tolerance = "tolerance";
  std::string elements = "elements";
  std::string increments = "increments";
  std::string integrator = "integrator";
  std::string shape_points = "shape_points";
  std::string constants = "constants";
  std::string slenderness = "slenderness";
  std::string chain = "chain";
  std::string stable = "stable";
  // The values of a beam given in SI units (its section is named in words).
  std::string length = "length";
  std::string E = "E";
  std::string Fx = "Fx";
  std::string Fy = "Fy";
  std::string M = "M";
  static BeamRequestNames command_line();
};

// A checked request: Howell's problem with the method's settings, the method, and the beam given
// whole (after add_physical_beam / add_chain). `warnings`: values that are valid but probably a
// unit mistake (an angle in radians above a full turn).
struct BeamInput {
  BeamProblem problem;
  BeamMethod method = BeamMethod::kAuto;
  std::optional<PhysicalCantilever> physical;
  std::optional<PhysicalChain> chain;
  bool chain_in_si = false;  // the chain is in SI units (results in metres, newtons, pascals)
  std::vector<Warning> warnings;
  bool is_physical() const { return physical || (chain && chain_in_si); }
};

// Checks `request` in the tool's order and builds the input (without the beam given whole when
// request.physical or request.chain). Throws InvalidInput naming the value by `names`.
BeamInput make_beam_input(const BeamRequest& request, const BeamRequestNames& names = {});

// The beam given whole: a cantilever in SI units (its problem keeps input's settings), or a chain
// (in SI units when `in_si`; its end condition becomes the problem's).
void add_physical_beam(BeamInput& input, PhysicalCantilever beam);
void add_chain(BeamInput& input, PhysicalChain chain, bool in_si);

// Refuses (NoConvergence) an answer that reports convergence but misses what was asked, as every
// front end refuses it: a value that came out NaN or infinite (Howell's alpha2 of a beam that has
// it, the tip a/l, b/l, theta0, a physical beam's largest moment and stress), or a deflected shape
// of another number of points than problem.shape_points. The messages name the value as the JSON
// key of `flexure beam` does.
void require_complete_answer(const BeamProblem& problem,
                             const BeamSolution& solution,
                             const PhysicalResults* physical = nullptr);

// The warnings of an answer, as every front end reports them (stderr and the JSON key `warnings`
// of `flexure beam`, FlexureWarning in Python), in this order: the solver's own (e.g. the BCM
// beyond its stated deflection range), a PRBM outside its validity limits (kOutsideValidity,
// pointing to the exact methods by `names.method`), an equilibrium that is unstable or critical
// (kOther, pointing to `names.stable`).
std::vector<Warning> beam_answer_warnings(const BeamProblem& problem,
                                          const BeamSolution& solution,
                                          const BeamRequestNames& names = {});

}  // namespace flexure
