#pragma once
// Stability of a segment chain's equilibrium from the continuous Jacobi equation: the independent
// second method behind segment_chain.h (docs/stability.md, "Method 2"). It shares no
// discretisation with the discrete second variation; the tests compare the two.
//
// The second variation Q[eta] = int EI eta'^2 + (N . t) eta^2 ds (eta(0) = 0) and the count of its
// constrained eigenvalues relative to B[eta] = int EI eta'^2 ds below lambda < 1 is the number of
// negative eigenvalues of Q_sigma = B + sigma W, sigma = 1 / (1 - lambda) (second_variation.h).
//   * Unconstrained count (Sturm oscillation, by a Pruefer angle): the solution of the Jacobi
//     equation (EI u')' = sigma (N . t) u, u(0) = 0, (EI u')(0) = 1, written u = r sin(phi),
//     EI u' = r cos(phi), phi' = cos^2(phi) / EI - sigma (N . t) sin^2(phi) (phi(0) = 0, never
//     decreasing through a multiple of pi): the count is floor((phi(L) + pi/2) / pi) with a free
//     tip angle (eigenfunctions end at EI u'(L) = 0: phi(L) = pi/2 mod pi) and floor(phi(L) / pi)
//     with a prescribed one (u(L) = 0). On a rigid link EI is infinite: u is constant.
//   * Constraints int g_a eta ds = 0 (g = sin(theta) for x, cos(theta) for y prescribed): the
//     continuous form of the bordered-matrix formula (Maddocks 1987, Theorem 1), count = count_0 -
//     neg(S) - zero(S) with S_ab = int g_a u_b ds and u_b = Q_sigma^{-1} g_b, the solution of the
//     inhomogeneous Jacobi equation (EI u')' = sigma (N . t) u - g_b with the same end conditions
//     (a particular solution from u = EI u' = 0 at the clamp plus a multiple of the homogeneous
//     one that meets the tip condition).
//   * The eigenvalues: bisection in lambda on that count.
// The equilibrium's theta(s) comes from integrating the elastica from the clamp with the root
// loads (N(0), m(0) = minus the clamp's reaction, e.g. ShootingResult::reaction), or from a
// function of the caller's (e.g. the elliptic closed form); either way not from the samples the
// discrete method is given. All of it is integrated by GSL's Prince-Dormand 8(7) (rtol 1e-12).
//
// Limits: as an initial-value method it loses digits like single shooting under large loads: the
// constraint correction subtracts solutions that grow like exp(int sqrt(sigma max(0, N . t) / EI)
// ds) (growth_exponent()), which is large under heavy tension and, since sigma = 1 / (1 - lambda),
// for eigenvalues close to 1. Meant for |N| L^2 / EI up to about 100 and margins whose growth
// exponent is below about 12. Eigenvalues above 1 - 1 / max_sigma are reported as 1. A test
// reference, about a millisecond per count.
#include <array>
#include <functional>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct JacobiStabilityOptions {
  double rtol = 1e-12;                  // integrator relative tolerance
  double atol = 1e-14;                  // absolute (the problem is scaled to length 1, EI_min 1)
  double eigenvalue_tolerance = 1e-11;  // bisection width, times max(1, |lambda|)
  double critical_tolerance = kCriticalMarginTolerance;
  double max_sigma = 1e6;  // largest load multiplier searched (see Limits)

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

// theta of segment `segment` (0-based) at local arc length s in [0, its length].
using SegmentAngle = std::function<double(int segment, double s_local)>;

class JacobiSecondVariation {
 public:
  // theta from the elastica integrated from the clamp: N(0) = -(root_reaction.Fx, .Fy),
  // m(0) = -root_reaction.M (the loads the clamp exerts on the chain, segment_chain.h).
  JacobiSecondVariation(const SegmentChain& chain,
                        const Reaction& root_reaction,
                        JacobiStabilityOptions options = {});
  // theta given; N from the root reaction as above (its moment is not used).
  JacobiSecondVariation(const SegmentChain& chain,
                        const Reaction& root_reaction,
                        SegmentAngle theta,
                        JacobiStabilityOptions options = {});

  // Constrained eigenvalues below lambda < 1, and the same without the x, y constraints (the tip
  // angle's condition kept).
  int count(double lambda) const;
  int unconstrained_count(double lambda) const;
  // The k-th (k >= 1) constrained eigenvalue below 1 by bisection, or 1 when there are fewer.
  double eigenvalue(int k) const;
  // Index at -critical_tolerance, margin = eigenvalue(1), classified as in status.h.
  Stability verdict() const;
  // int sqrt(sigma max(0, N . t) / EI) ds at lambda: the Jacobi solutions grow like its
  // exponential in tension, and the constraint correction, a difference of such solutions, loses
  // that many digits (e^G times the integrator's tolerance): trust counts and margins where it is
  // below about 12, which excludes margins close to 1 of chains largely in tension.
  double growth_exponent(double lambda) const;
  // Number of independent linearised tip constraints in x, y (0 to 2).
  int constraint_count() const { return static_cast<int>(combinations_.size()); }

 private:
  struct CountResult {
    int unconstrained = 0;
    int constrained = 0;
    double growth = 0.0;
  };
  void prepare();
  CountResult evaluate(double lambda, bool constraints) const;

  SegmentChain chain_;
  JacobiStabilityOptions options_;
  SegmentAngle theta_;  // empty: integrate the elastica
  double length_scale_ = 1.0, stiffness_scale_ = 1.0;
  double Nx0_ = 0.0, Ny0_ = 0.0, m0_ = 0.0;          // scaled root loads
  double compression_bound_ = 0.0;                   // lambda_1 >= 1 - this
  std::vector<std::array<double, 2>> combinations_;  // independent combinations of sin, cos rows
  bool follower_ = false, flexible_ = false;
};

}  // namespace flexure
