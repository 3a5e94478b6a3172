#pragma once
// Method dispatch for the cantilever-with-end-load problem (`flexure beam`, `flexure sweep beam`).
//
// To plug in a new method (shooting, chain): add its name to kBeamMethodNames, and a branch in
// solve_beam() (beam_methods.cpp) that fills a BeamSolution from that solver's result. Nothing
// else in the CLI needs to change; `auto` picks the method used when none is named.
#include <CLI/CLI.hpp>
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {

// Names accepted by --method (CLI11 rejects anything else with exit 2).
inline constexpr std::array<const char*, 5> kBeamMethodNames = {
    "auto", "elliptic", "shooting", "chain", "prbm"};

// What the user fixed: the load alpha2, the tip angle theta0 or the tip deflection b/l, with
// Howell's load ratio n and end moment mu held fixed (Howell eqs. 2.67, 2.83).
struct BeamProblem {
  enum class Given { kAlpha2, kTheta0, kBOverL };
  Given given = Given::kAlpha2;
  double value = 0.0;         // alpha2, theta0 [rad] or b/l, as selected by `given`
  double load_ratio_n = 0.0;  // n > 0 compressive
  double mu = 0.0;            // end moment M l/EI
  int shape_points = 0;       // 0: no shape; otherwise >= 2 points from s = 0 to s = 1
  // The far end and the numerical methods (shooting, chain).
  EndCondition boundary = EndCondition::kFree;
  TipPrescription prescribed;  // unset = the stress-free tip value (e.g. guided: theta = 0)
  double follower = 0.0;       // follower tip force F l^2/EI along the tip normal
  int elements = 100;          // chain algorithm: N elements
  int increments = 10;         // chain algorithm: load increments
  std::string chain_variant = "corrected";  // chain algorithm: howell | corrected
  std::optional<SegmentChain> chain;        // from --chain FILE.toml (overrides the loads above)
  // `--method auto` picks the cheapest method whose relative error is within this
  // (benchmarks/studies/method_selector.h).
  double tolerance = 1e-6;

  // The segment chain this problem describes (the TOML chain, or Howell's uniform cantilever with
  // Fx = -n alpha2, Fy = alpha2, M = mu, the follower force and the end condition).
  SegmentChain to_chain(double alpha2) const;
  bool is_plain_cantilever() const {
    return !chain && boundary == EndCondition::kFree && follower == 0.0;
  }
};

// Loads the clamp exerts on the beam (root frame), Fx, Fy, M (nondimensional).
struct Reactions {
  double Fx = 0.0;
  double Fy = 0.0;
  double M = 0.0;
};

// A method-independent summary of one solve, with the keys `flexure beam --json` prints.
struct BeamSolution : SolveStatus {
  std::string method;         // the method actually used (what "auto" resolved to)
  std::string method_reason;  // why that method: the --method given, or auto's reasoning
  double alpha2 = 0.0;
  TipPose tip;
  std::string branch;
  int inflection_points = 0;
  double root_moment = 0.0;
  std::string family;
  double tolerance = 0.0;  // the method's convergence tolerance (recorded in output files)
  std::vector<ShapePoint> shape;
  Reactions reactions;       // at the root
  int elements = 0;          // chain algorithm only (0 otherwise)
  int increments = 0;        // chain algorithm only: increments taken
  double load_factor = 1.0;  // load factor reached (1 when converged)
  // Inverse problems (--theta0, --b-over-l): |tip quantity - target| at the returned load; NaN for
  // a forward problem. A converged inverse always has it within the method's stated tolerance.
  double target_residual = std::numeric_limits<double>::quiet_NaN();
  // Folds of the load factor on the path from the unloaded beam (snap-through under load
  // control at the first); elliptic and shooting only.
  int limit_points = 0;
  double first_limit_load_factor = 0.0;
};

// Adds `--method` (default "auto", restricted to kBeamMethodNames) to a subcommand.
void add_method_option(CLI::App& command, std::string& method);
// Adds `--tol` (relative error allowed to `--method auto`, default 1e-6, > 0).
void add_tolerance_option(CLI::App& command, double& tolerance);

// A sentence for non-convergence messages: which other method may work.
std::string other_methods_hint(const std::string& failed_method);

// The method `auto` resolves to for this problem: the cheapest whose error is within
// problem.tolerance (PRBM inside its validity limits and measured accuracy, else elliptic for
// Howell's free cantilever, else shooting), with the reason (benchmarks/studies/method_selector.h).
struct MethodResolution {
  std::string method;
  std::string reason;
};
MethodResolution resolve_beam_method_with_reason(const std::string& method,
                                                 const BeamProblem& problem);
std::string resolve_beam_method(const std::string& method, const BeamProblem& problem);
// Without a problem (sweeps over alpha2): auto = elliptic.
std::string resolve_beam_method(const std::string& method);

// Solves `problem` with `method` (one of kBeamMethodNames). Throws InvalidInput for bad input or a
// method not available in this build; a failed solve returns converged == false and a message.
BeamSolution solve_beam(const std::string& method, const BeamProblem& problem);

// The convergence tolerance the method uses (for file attributes).
double beam_method_tolerance(const std::string& method);

}  // namespace flexure::cli
