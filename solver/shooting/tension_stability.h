#pragma once
// The stability verdict of a uniform cantilever under a dead tip load that is nowhere compressed,
// without an eigenproblem (docs/stability.md, "A cantilever in tension").
//
// The second variation Q[eta] = int EI eta'^2 + int (N . t) eta^2 (segment_chain.h) has
// margin 1 + min over eta of int (N . t) eta^2 / int EI eta'^2: exactly 1 (no eigenvalue below 1;
// index 0, stable) when N . t >= 0 along the whole beam, and below 1 as soon as any stretch is
// compressed. For one uniform flexible segment (no EI profile, kappa0 = 0, no distributed or
// intermediate loads) with a free end under a dead tip force F and moment M_L, N = F everywhere and
// the elastica EI theta' = m, m' = F_x sin(theta) - F_y cos(theta) has the first integral
//     m(s)^2 / (2 EI) + F . t(s) = C = M_L^2 / (2 EI) + F . t(L)
// (the pendulum's energy; its derivative is theta' (m' + t x F) = 0). So F . t = C - m^2/(2 EI),
// and F . t is stationary in the interior only where m = 0 (where it equals C, its maximum) or
// where t is parallel to F (F . t = +-|F|). Its minimum is therefore at an end or at a point
// where t is antiparallel to F, and there m^2 = 2 EI (C + |F|), the largest m^2 the first
// integral allows. Hence the beam is nowhere compressed when
//     F . t(0) = F_x >= 0,   F . t(L) >= 0,   max_s m(s)^2 < 2 EI (C + |F|)   (F != 0),
// and the verdict is then that of the general method (which finds no eigenvalue below 1 on such a
// shape, since every chord's N . t is an average of a nonnegative function): stable, index 0,
// margin exactly 1. max |m| comes from the shooting integration itself
// (ShootingResult::largest_curvature: the step ends and the interior extrema of the moment's
// interpolant), so the verdict costs nothing beyond the solve. The last inequality is required
// with a relative slack of 1e-6, far beyond the integration's error; it fails only close to a
// point with t antiparallel to F, which is compressed.
//
// Howell's cantilever under a transverse force (n = 0, the sweep of issue 27) and every load with
// n <= 0 and mu = 0 on the same side qualify. Other chains, end conditions, follower loads and
// compressed beams return nullopt: the caller uses equilibrium_stability() (the discrete second
// variation). tests/solver/tension_stability_test.cpp checks the verdict against it on seeded
// random loads.
#include <optional>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

// The verdict of `result` (a converged shooting solution of `chain` at its full loads, with
// ShootingResult::largest_curvature recorded, e.g. by Options::count_inflections and an explicit
// backend) when the first integral proves `chain` nowhere compressed; nullopt otherwise (the
// general verdict applies). `options`: only critical_tolerance is used (validated like
// equilibrium_stability() does).
std::optional<Stability> tensioned_cantilever_stability(const SegmentChain& chain,
                                                        const ShootingResult& result,
                                                        const StabilityOptions& options = {});

// The same verdict for a solution known by its tip angle whose tangent angle is monotone along the
// beam (no inflection point: the curvature EI theta' = m keeps its sign), e.g. the elliptic
// solution (EllipticResult::inflection_points, tip.theta0). Its tangent then takes exactly the
// angles between 0 and tip_angle, on which F . t = |F| cos(theta - theta_F) is smallest at an end
// or at the antiparallel angle theta_F + pi: the beam is nowhere compressed when F . t >= 0 at both
// ends and theta_F + pi (+ 2 pi k) lies outside that range. Then: stable, index 0, margin 1, as
// above; otherwise (or with inflection points) nullopt. tests/solver/tension_stability_test.cpp
// checks it against equilibrium_stability() on the elliptic shape on seeded random loads.
std::optional<Stability> tensioned_cantilever_stability(const SegmentChain& chain,
                                                        double tip_angle,
                                                        int inflection_points,
                                                        const StabilityOptions& options = {});

// The part of the test that needs no solution: whether `chain` is a uniform one-segment
// cantilever with a free end under dead tip loads only (the chains the first integral covers).
bool tension_verdict_applies(const SegmentChain& chain);

}  // namespace flexure
