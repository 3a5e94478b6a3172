#pragma once
// The stability verdict of an equilibrium of the exact (or mixed) model of a general mechanism
// (general_analysis.h; docs/mechanisms.md "Stability of the exact model", docs/stability.md
// "Mechanisms").
//
// The total potential energy Pi(q, u) of the mechanism -- the bodies' coordinates q and the
// flexures' shapes u -- splits its second variation on the constraint manifold in two
// (Haynsworth's inertia additivity, the same bordered-matrix argument as Maddocks 1987, Thm. 1):
//   * each flexure with both ends held where its bodies put them: the elastica's own second
//     variation (equilibrium_stability, a clamped-clamped or clamped-pinned chain loaded by the
//     end loads its far body puts on it);
//   * the Schur complement: the mechanism's condensed stiffness K in its admissible directions
//     (the null space of the joints' constraint Jacobian, and of the input's gradient when the
//     input is held), every flexure relaxed to its equilibrium for each motion of its ends.
// index = the flexures' indices + the negative eigenvalues of K. K itself is not formed: an
// inextensible flexure is infinitely stiff along its chord when straight. Its inverse, the
// compliance C = Z^T dq/df of the linearised equilibrium under small generalised loads f = Z a, is
// finite everywhere (0 in those directions) and has the same inertia where K is finite.
#include <Eigen/Dense>

namespace flexure::mechanism::general {

// Orthonormal basis of the null space of A (rows: constraints) from its SVD; singular values
// below 1e-9 of the largest (or of 1) count as zero. A without rows: the identity.
Eigen::MatrixXd exact_null_space(const Eigen::MatrixXd& A, int cols);

struct CondensedVerdict {
  int index = 0;        // negative eigenvalues of the condensed stiffness
  double margin = 1.0;  // its lowest generalised eigenvalue against `reference`, at most 1
};

// From the compliance C (k x k, symmetrised here) in the admissible directions and a positive
// definite reference stiffness R in the same directions (the unloaded flexures and springs): the
// generalised eigenvalues mu of K v = mu R v are the reciprocals of the eigenvalues nu of
// L^T C L (R = L L^T; where R is singular in some direction, a toggle, C times its largest
// eigenvalue, as the PRBM verdict measures it). index: nu < -1e-9 max(1, |nu|max), a negative
// stiffness; margin: min(1, min mu) (1: no direction softer than the reference; at most 1, as the
// beam's margin); a compliance that is not finite (a singular linearisation: a critical state)
// gives margin 0.
CondensedVerdict condensed_verdict(const Eigen::MatrixXd& compliance,
                                   const Eigen::MatrixXd& reference);

}  // namespace flexure::mechanism::general
