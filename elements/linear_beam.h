#pragma once
// Linear (small-deflection) Euler-Bernoulli theory of the uniform cantilever: the first rung of
// the model ladder (docs/models.md), the yardstick every student starts from.
//
// Equilibrium is taken in the undeformed configuration, so the bending moment along the beam is
// M(s) = Fy (1 - s) + M_tip and the axial force does nothing (no beam-column effect, a/l = 1):
//   theta(s) = Fy (s - s^2/2) + M_tip s,   y(s) = Fy (s^2/2 - s^3/6) + M_tip s^2/2,   x(s) = s.
// Free end (M_tip = mu): b/l = Fy/3 + mu/2, theta0 = Fy/2 + mu (Gere & Timoshenko, the cantilever
// table). Guided end (tip angle held at phi): M_tip = phi - Fy/2 is the guide's reaction, so
// b/l = Fy/12 + phi/2 (phi = 0: the fixed-guided beam, b = P l^3/(12 EI)).
// Exact in the limit of small loads; every other model of the ladder reduces to it there.
#include <vector>

#include "flexure/elements/cantilever_case.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct LinearBeamResult : SolveStatus {
  // iterations: 0 (closed form); residual: 0
  TipPose tip;
  double root_moment = 0.0;  // M(0) l/EI = Fy + M_tip (equilibrium in the undeformed beam)
  double end_moment = 0.0;   // M_tip l/EI: mu (free) or the guide's reaction (guided)
};

class LinearBeamSolver {
 public:
  struct Options {
    // Nothing to choose: the theory is closed form. validate() exists for the common interface.
    void validate() const {}
  };

  LinearBeamSolver() = default;
  explicit LinearBeamSolver(Options options);

  // Throws InvalidInput for what CantileverCase::validate refuses.
  LinearBeamResult solve(const CantileverCase& problem) const;
  // The deflected shape at `count` >= 2 equally spaced arc lengths.
  std::vector<ShapePoint> shape(const CantileverCase& problem,
                                const LinearBeamResult& result,
                                int count) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace flexure
