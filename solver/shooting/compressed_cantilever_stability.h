#pragma once
// The stability verdict of a uniform cantilever under a dead tip load from the continuous Jacobi
// (accessory) equation of its second variation, integrated along the equilibrium from the clamp:
// the fast verdict of compressed cantilevers (docs/stability.md, "A compressed cantilever: the
// Jacobi equation along the solution").
//
// The second variation Q[eta] = int EI eta'^2 + (F . t) eta^2 ds (eta(0) = 0, free tip angle;
// segment_chain.h) has, relative to B[eta] = int EI eta'^2 ds, an eigenvalue lambda < 1
// where B + sigma W is singular, sigma = 1 / (1 - lambda), W[eta] = int (F . t) eta^2 ds: where the
// Jacobi equation (EI u')' = sigma (F . t) u has a solution with u(0) = 0 and EI u'(L) = 0 (the
// natural condition of the free tip). By Sturm oscillation (the count of Method 2 in
// docs/stability.md) the number of eigenvalues below 1 - 1/sigma follows from the Pruefer angle
// phi = atan2(u, EI u') of one solution:
//   * integrated from the clamp (u(0) = 0, phi(0) = 0): floor((phi(L) + pi/2) / pi);
//   * integrated from the tip (EI u'(L) = 0, phi(L) = pi/2) down to the clamp: 0 while phi(0) > 0,
//     else floor(-phi(0) / pi) + 1.
// The index is that count at lambda = -critical_tolerance (one integration; left out when a guess
// is given and the margin found is above -critical_tolerance: then it is 0). The margin lambda_1
// is the first sigma where the count reaches 1: Newton's method in sqrt(sigma) on the eigen-
// condition (phi = pi/2 at the tip, or phi = 0 at the clamp) with the exact derivative from the
// sensitivities du/dsigma, d(EI u')/dsigma integrated alongside, kept inside the bracket the signs
// give (bisection otherwise), started from the straight column's sqrt(sigma) int sqrt(max(0,
// -F . t) / EI) ds = pi/2. The condition is read on Pruefer's scaled angle atan2(S u, EI u'), S =
// (1 + (sigma F . t)^2)^(1/4) at that end (same zeros, nearly linear in sqrt(sigma) where the end
// is compressed), which takes Newton there in 3-5 integrations; from a sweep's margin predicted
// from its neighbours, in one or two (beam_sweep_solver.h). The direction matters: the
// eigen-condition at an end in tension is ill-conditioned (the Jacobi solutions grow like
// exp(sqrt(sigma F . t / EI) s) there and the condition balances a decaying against a growing one),
// so the solution is started at the end in tension and the condition is read at the compressed one:
// from the tip when the clamp is compressed (F_x < 0), else from the clamp. u and EI u' are
// integrated as a linear system together with the elastica EI theta' = m, m' = F_x sin(theta) - F_y
// cos(theta), written for the tangent (cos theta, sin theta) so that the whole system is
// polynomial, by Taylor series of order 24 whose coefficients come from the products' recurrences
// (automatic differentiation), each step as long as the last two terms allow for 1e-16 relative
// (about ten steps along the beam; the margin agrees with an eighth-order Runge-Kutta integration
// at rtol 1e-10 within 4e-13 on the n = 2 sweep); the Jacobi solution is rescaled when large, and
// the Pruefer angle is unwrapped on points of each step's polynomial at most 1 / max(1, sqrt(sigma
// |F| / EI)) apart (on the scaled beam), over which it turns by less than one radian. The elastica
// starts from the clamp with the solution's root moment (ShootingResult::reaction) or from the tip
// with its tip angle and moment; the far end must meet the solution (within 1e-8), else the verdict
// declines. It also declines (nullopt: the caller uses the general verdict) where the first
// integration sees no compression, where sigma_1 would exceed 1e4 (margins above 0.9999: a short
// compressed stretch next to long tensioned ones, where the Jacobi solutions grow fastest), and
// where Newton's method does not settle in 60 integrations.
//
// Covers the chains tension_verdict_applies() accepts: one uniform flexible segment, free end,
// dead tip force and moment, no intermediate or distributed loads; anything else returns nullopt.
// tests/solver/compressed_cantilever_stability_test.cpp checks it against the general verdict
// (equilibrium_stability on the shooting shape) on seeded random loads and against the closed
// forms of the straight column.
#include <optional>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

// The verdict of `result` (a converged shooting solution of `chain` at its full loads) from the
// Jacobi equation, or nullopt when `chain` is not a uniform free cantilever under dead tip loads
// or the re-integration does not reproduce the solution's tip. `options`: critical_tolerance
// (validated like equilibrium_stability() does). `margin_guess`: a prediction of the margin (a
// sweep's, from its neighbours' margins): Newton's method starts there and the index pass is left
// out where the margin found is above -critical_tolerance (see above); the verdict is the same.
std::optional<Stability> compressed_cantilever_stability(
    const SegmentChain& chain,
    const ShootingResult& result,
    const StabilityOptions& options = {},
    std::optional<double> margin_guess = std::nullopt);

}  // namespace flexure
