#pragma once
// What to try after a beam solve found no converged solution: advice that names a method only where
// it is measured to reach further than the ones that failed, and otherwise what to change in the
// problem. The library names methods and quantities; the tool adds its flags
// (docs/architecture.md).
//
// Never in circles. Each problem falls in one regime (free uniform cantilever with dead loads;
// other dead-load problems; prescribed tip coordinates; follower force), and each regime ranks the
// methods by how far they are measured to reach in it. After a method X fails, a method Y is
// suggested only when Y has not been tried, the problem is within Y's measured reach, and Y ranks
// above X or X was outside its own reach. Two methods within reach are only ever suggested from
// the lower to the higher rank, and a method outside its reach is never suggested, so following
// the advice never leads back to a method that already failed. (docs/cli.md, "When a solve fails".)
#include <string>
#include <vector>

#include "flexure/beam/beam_problem.h"

namespace flexure {

// Loads the methods are measured to solve (|F| l^2/EI of the end force, follower force F l^2/EI),
// on Howell's cantilever at this version (docs/cli.md "When a solve fails" lists the runs):
// * the elliptic solver's range is |F| <= 1e4 and |mu| <= 1e4 (EllipticSolver::kMaxForce);
// * the shooting method converged at |F| = 3.5e4 and failed at 4e4 for a tip force across the beam
//   (n = 0; with an axial component, n = +-1, it reached 5e4): beyond it its 64 multiple-shooting
//   parts per segment no longer hold the growth of the solution;
// * the chain algorithm converged at |F| = 3e4 (11 s) and failed at 4e4: its first load step would
//   turn a node by more than 0.25 rad however short;
// * follower force: the shooting continuation converged at 100 and ran out of steps at 150; the
//   chain algorithm converged at 500 (10 s) and had not finished at 1000 after two minutes.
inline constexpr double kEllipticForceRange = 1e4;
inline constexpr double kShootingForceReach = 3.5e4;
inline constexpr double kChainForceReach = 3e4;
inline constexpr double kShootingFollowerReach = 100.0;
inline constexpr double kChainFollowerReach = 500.0;

struct BeamFailureAdvice {
  std::vector<BeamMethod> methods;   // to try next, most capable first; empty: none is known to
  std::vector<std::string> reasons;  // per method: "the elliptic solver" and why it may answer
  std::vector<std::string> names;    // per method: "the elliptic solver", "the chain algorithm"
  std::string text;                  // one or two sentences: why those, or what to change
  bool load_path_helps = false;      // the text suggests following the load path to where it stops
};

// `failed`: the result that did not converge (its method and, for an inverse problem, the load
// reached); `tried`: every method already tried on this problem (auto tries more than one).
// A load for people: 35000 as "3.5e4", 500 as "500".
std::string load_text(double value);

BeamFailureAdvice advise_after_failure(const BeamProblem& problem,
                                       const BeamSolution& failed,
                                       const std::vector<BeamMethod>& tried);

}  // namespace flexure
