#pragma once
// The stability verdict of a uniform cantilever under a dead tip load from the continuous Jacobi
// (accessory) equation of its second variation, integrated along the equilibrium from the clamp:
// the fast verdict of compressed cantilevers (docs/stability.md, "A compressed cantilever: the
// Jacobi equation along the solve").
//
// The second variation Q[eta] = int EI eta'^2 + (F . t) eta^2 ds (eta(0) = 0, free tip angle;
// equilibrium_stability.h) has, relative to B[eta] = int EI eta'^2 ds, eigenvalues lambda below 1
// where B + sigma W is singular, sigma = 1 / (1 - lambda), W[eta] = int (F . t) eta^2 ds: where
// the Jacobi equation (EI u')' = sigma (F . t) u, u(0) = 0, EI u'(0) = 1 has EI u'(L) = 0 (the
// natural condition of the free tip). With the Pruefer angle phi = atan2(u, EI u') (continuous,
// phi(0) = 0) the number of eigenvalues below lambda is floor((phi(L; sigma) + pi/2) / pi) (Sturm
// oscillation; the count of Method 2 in docs/stability.md, there integrated as an angle ODE):
//   * the index (the count at lambda = -critical_tolerance) is one integration;
//   * the margin lambda_1 solves phi(L; sigma) = pi/2, the first sigma where the count reaches 1:
//     Newton's method in sqrt(sigma) with the exact derivative dphi/dsigma = (EI u' du/dsigma -
//     u d(EI u')/dsigma) / (u^2 + (EI u')^2) from the sensitivities integrated alongside, kept
//     inside the bracket the signs of phi(L) - pi/2 give (bisection otherwise), started from the
//     straight column's sqrt(sigma) int sqrt(max(0, -F . t) / EI) ds = pi/2. 3-6 integrations.
// u and EI u' are integrated as a linear system (one sine and cosine of theta per evaluation); the
// angle is unwrapped between steps, and steps are limited so that it turns by less than one radian
// in one (h <= 1 / max(1, sqrt(sigma |F| / EI)) on the scaled beam), so no turn is missed.
// theta(s) comes from the elastica EI theta' = m, m' = F_x sin(theta) - F_y cos(theta) integrated
// from the clamp with the solution's root moment (ShootingResult::reaction), GSL's Prince-Dormand
// 8(7) at rtol 1e-12; the integration must end at the solution's tip angle within 1e-8, else the
// verdict declines (nullopt) and the caller uses the general one. Eigenvalues above 1 - 1e-10 are
// reported as 1 (the general verdict's accuracy near 1 is 1e-9).
//
// Covers the chains tension_verdict_applies() accepts: one uniform flexible segment, free end,
// dead tip force and moment, no intermediate or distributed loads; anything else returns nullopt.
// tests/solver/compressed_cantilever_stability_test.cpp checks it against the general verdict
// (equilibrium_stability on the shooting shape) on seeded random loads and against the closed
// forms of the straight column.
#include <optional>

#include "flexure/solver/chain_model/equilibrium_stability.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/stability.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

// The verdict of `result` (a converged shooting solution of `chain` at its full loads) from the
// Jacobi equation, or nullopt when `chain` is not a uniform free cantilever under dead tip loads
// or the re-integration does not reproduce the solution's tip. `options`: critical_tolerance
// (validated like equilibrium_stability() does).
std::optional<Stability> compressed_cantilever_stability(const SegmentChain& chain,
                                                         const ShootingResult& result,
                                                         const StabilityOptions& options = {});

}  // namespace flexure
