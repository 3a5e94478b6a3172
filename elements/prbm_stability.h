#pragma once
// The pseudo-rigid-body model's own stability verdict (docs/stability.md, "The PRBM").
//
// A PRB element is one degree of freedom, the PRB angle Theta. Its total potential energy under a
// dead tip load is the energy of its springs (Howell eq. 11.1: V = K Theta^2 / 2 for one spring)
// less the work of the load,
//     V(Theta) = int (spring_moment - generalized_load) dTheta,
// whose first derivative is the virtual-work equilibrium (Howell eq. 5.35 / 6.53). The
// equilibrium is stable where the second derivative is positive and unstable where it is
// negative (Howell §11.1: "Differentiate the energy equations again ... A positive value of the
// second derivative at the equilibrium positions means that it is a stable equilibrium
// position"). For a tip force on a PRB link of length gamma l (the fixed-pinned segment, §5.2;
// the fixed-guided segment, §5.3, both of its springs turning by Theta):
//     V(Theta) = k Theta^2 / 2 - gamma (Fx cos Theta + Fy sin Theta),
//     V''(Theta) = k + gamma (Fx cos Theta + Fy sin Theta),
// k the springs' stiffness d(spring_moment)/dTheta (gamma K_Theta for the fixed-pinned segment,
// 4 gamma K_Theta for the fixed-guided one, in EI/l); for the end moment (§5.4) V'' = k.
//
// The margin is V'' measured against the unloaded stiffness k, the same scaling as the beam's
// margin (the second variation against the unloaded bending stiffness): 1 unloaded and under a
// moment alone, and for an axial compression P at Theta = 0, 1 - P / K_Theta (fixed-pinned) or
// 1 - P / (4 K_Theta) (fixed-guided): 1 - P/P_cr with the PRBM's own critical loads K_Theta EI/l^2
// and 4 K_Theta EI/l^2 (the exact ones are pi^2/4 and pi^2 EI/l^2; K_Theta = 2.65 at n = 0).
#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct PrbmEnergyCurvature {
  double second_derivative = 0.0;  // V''(Theta), nondimensional (EI/l per rad^2)
  double spring_stiffness = 0.0;   // k = d(spring_moment)/dTheta, the unloaded V''
};

// V'' at Theta under `load`: analytic for the fixed-pinned, fixed-guided and end-moment segments
// (above); other elements by a central difference of their virtual-work functions (step 1e-4
// rad, exact for linear springs, O(1e-8) relative for the load term).
PrbmEnergyCurvature prbm_energy_curvature(const PrbmElement& element,
                                          double Theta,
                                          const EndLoad& load);

// The verdict: margin = V'' / k; index 1 where the margin is below -critical_tolerance,
// classified as status.h says (subject "the PRBM").
Stability prbm_stability(const PrbmElement& element,
                         double Theta,
                         const EndLoad& load,
                         double critical_tolerance = kCriticalMarginTolerance);

}  // namespace flexure
