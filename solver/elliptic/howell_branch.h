#pragma once
// The cantilever with an end force and no end moment (Howell eqs. 2.89-2.98, generalised to any
// force angle), on the branch reached by proportional loading.
//
// With mu = 0 the tip is a turning point of the pendulum, k = sin(chi1/2), and the load follows
// from the tip angle explicitly (Howell eq. 2.90, corrected phi1 = atan2(1, -n)):
//   sqrt(F) = K(k) - F(beta, k),  sin(beta) = sin(chi0/2)/k.
// The right side grows monotonically from 0 (k = sin(chi0/2), unloaded) to infinity (k -> 1), so
// every load has exactly one solution on this branch with 0 < theta0 < psi: the branch of
// proportional loading. K - F(beta, k) is evaluated as F(beta*, k) with tan(beta) tan(beta*) = 1/k'
// (DLMF 19.11.4 with phi + psi = K), in terms of p = k'^2 and q = k^2 - sin^2(chi0/2), each formed
// without cancellation, so that the solution keeps full precision both at small loads (q -> 0) and
// near the separatrix (p -> 0, large loads, tension).
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elastica_closed_form.h"

namespace flexure::elliptic {

struct HowellBranchSolution : SolveStatus {
  // residual: (G - sqrt F) + ln(G / sqrt F) at the last evaluated point, G = K - F(beta)
  ElasticaParameters parameters;
  TipPose tip;  // normalised frame (force angle psi in (0, pi))
  double root_moment = 0.0;
};

// Forward: the tip for force F > 0 at angle psi in (0, pi), mu = 0.
HowellBranchSolution solve_howell_branch(double force, double psi, double x_tolerance);

// Inverse: the force F that gives tip angle theta0 in (0, psi) at force angle psi; explicit.
HowellBranchSolution howell_branch_from_tip_angle(double psi, double theta0);

}  // namespace flexure::elliptic
