// The stability verdict of extensible and shear-flexible (Reissner) chains and of chains under dead
// distributed loads (docs/extensible.md, "Stability"; segment_chain.h), against values
// that share nothing with the verdict's condensed second variation and its compliant constraints:
//
//  * Straight columns (L = 1, EI = 1) under an axial compression P, from the linearised
//    equilibrium equations of docs/extensible.md (m' = -V (1 + N_a delta), y' = (1 + eps) sin
//    theta + gamma cos theta, delta = 1/EA - 1/GAs): EI theta'' + P (1 - P delta) theta = -R
//    (1 - P delta), R the transverse reaction. With k^2 = P (1 - P delta) / EI:
//      cantilever (free tip):      k L = pi/2, i.e. P (1 - P delta) = pi^2/4: for EA alone the
//                                  extensible column's P_cr = EA (1 - sqrt(1 - pi^2 / EA)) / 2,
//                                  for GAs alone Haringx's P_cr = GAs (sqrt(1 + pi^2/GAs) - 1) / 2
//                                  (Reissner's beam gives Haringx's formula, not Engesser's
//                                  P_E / (1 + P_E/GAs); they differ at O((P/GAs)^2));
//                                  margin 1 - P (1 - P delta) / (pi^2/4);
//      clamped-clamped, symmetric mode: P (1 - P delta) = 4 pi^2;
//      clamped-pinned (x, y held): (1 - P delta) (tan(kL)/(kL) - 1) + P L/GAs = 0 (the tip's
//                                  y = int ((1 - P delta) theta + R/GAs) ds = 0), which involves
//                                  the compliance of the held coordinate.
//    The verdict must flip from stable to unstable (index 1) across each P_cr within 1e-6.
//  * Greenhill's column under its own weight q along its axis: critical q L^3/EI = (9/4) z^2, z
//    the first zero of J_{-1/3} (Timoshenko & Gere, Theory of Elastic Stability, 2nd ed., sec.
//    2.13: 7.837), computed here from the Bessel functions.
//  * Deflected equilibria of the shooting solver: the Hessian of the discrete Reissner energy in
//    (u, theta) at midpoints with the held tip coordinates removed as unknowns (a dense matrix
//    written here, condensed on theta by Eigen), its lowest eigenvalue against the bending
//    stiffness as the margin: no condensation formula, no compliance, no bordered inertia.
//  * EA = GAs = 1e12 against the inextensible verdict (margins to 1e-7, same kind and index).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/scalar_root.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<ShapePoint> straight(const std::vector<double>& s) {
  std::vector<ShapePoint> shape;
  for (double si : s) shape.push_back(ShapePoint{si, si, 0.0, 0.0});
  return shape;
}

SegmentChain column_chain(double EA, double GAs, EndCondition end) {
  SegmentChain chain;
  FlexibleSegment f(1.0, 1.0);
  f.EA = EA;
  f.GAs = GAs;
  chain.segments.push_back(f);
  chain.end = end;
  return chain;
}

// The verdict of the straight column compressed by P (the tip load for a free end, the support's
// reaction where x is held). Positions along x do not matter to Reissner's terms (the angles do).
Stability straight_verdict(double EA, double GAs, EndCondition end, double P) {
  SegmentChain chain = column_chain(EA, GAs, end);
  Reaction support;
  if (prescribed_mask(end).x) {
    support.Fx = -P;
  } else {
    chain.tip_load.Fx = -P;
  }
  return equilibrium_stability(chain, support, straight(stability_stations(chain, support)));
}

double delta_of(double EA, double GAs) { return 1.0 / EA - 1.0 / GAs; }

// The critical load from P (1 - P delta) = P_E (the smaller root), for delta of either sign.
double critical_from_PE(double PE, double delta) {
  if (delta == 0.0) return PE;
  return (1.0 - std::sqrt(1.0 - 4.0 * delta * PE)) / (2.0 * delta);
}

// At P_cr the verdict is critical with a margin within 1e-8 of zero (the verdict's accuracy);
// 1e-5 below and above (outside the critical band of 1e-6) stable and unstable with index 1.
void expect_flip(double EA, double GAs, EndCondition end, double P_cr, const char* what) {
  const Stability at = straight_verdict(EA, GAs, end, P_cr);
  EXPECT_EQ(at.kind, StabilityKind::kCritical) << what << ": " << at.message;
  EXPECT_NEAR(at.margin, 0.0, 1e-8) << what;
  const Stability below = straight_verdict(EA, GAs, end, P_cr * (1.0 - 1e-5));
  const Stability above = straight_verdict(EA, GAs, end, P_cr * (1.0 + 1e-5));
  EXPECT_EQ(below.kind, StabilityKind::kStable) << what << ": " << below.message;
  EXPECT_EQ(above.kind, StabilityKind::kUnstable) << what << ": " << above.message;
  EXPECT_EQ(above.index, 1) << what;
}

TEST(StabilityExtensible, CantileverColumnCriticalLoads) {
  const double inf = std::numeric_limits<double>::infinity();
  const double PE = kPi * kPi / 4.0;
  struct Case {
    double EA, GAs;
  };
  for (const Case c : {Case{20.0, inf},
                       Case{100.0, inf},
                       Case{inf, 5.0},
                       Case{inf, 50.0},
                       Case{30.0, 8.0},
                       Case{1e4, 2.6e3}}) {
    const double delta = delta_of(c.EA, c.GAs);
    const double P_cr = critical_from_PE(PE, delta);
    // The closed forms of the two special cases, written out.
    if (c.GAs == inf) {
      EXPECT_NEAR(P_cr, c.EA * (1.0 - std::sqrt(1.0 - kPi * kPi / c.EA)) / 2.0, 1e-12);
    }
    if (c.EA == inf) {
      EXPECT_NEAR(P_cr, c.GAs * (std::sqrt(1.0 + kPi * kPi / c.GAs) - 1.0) / 2.0, 1e-12);
    }
    expect_flip(c.EA, c.GAs, EndCondition::kFree, P_cr, "cantilever");
    // The margin 1 - P (1 - P delta) / P_E at a few loads, and the index past the second load.
    for (double P : {0.3 * P_cr, 0.8 * P_cr, 1.5 * P_cr}) {
      const Stability v = straight_verdict(c.EA, c.GAs, EndCondition::kFree, P);
      EXPECT_NEAR(v.margin, 1.0 - P * (1.0 - P * delta) / PE, 1e-8)
          << "EA " << c.EA << " GAs " << c.GAs << " P " << P;
    }
  }
}

// A second, independent location of the critical load: the shooting solver's continuation of the
// straight column finds the bifurcation where its Jacobian changes sign (continuation.h); there
// the verdict must be critical, and that load is the closed form's.
TEST(StabilityExtensible, ShootingBifurcationIsWhereTheVerdictIsCritical) {
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    double EA, GAs;
  };
  for (const Case c : {Case{500.0, 200.0}, Case{50.0, inf}, Case{inf, 10.0}}) {
    SegmentChain chain = column_chain(c.EA, c.GAs, EndCondition::kFree);
    chain.tip_load.Fx = -3.0;
    const ShootingResult r = ShootingSolver().solve(chain);
    ASSERT_TRUE(r.converged()) << r.message;
    const SpecialPoint* bifurcation = nullptr;
    for (const SpecialPoint& sp : r.special_points) {
      if (sp.kind == SpecialPointKind::kBifurcation && sp.located) bifurcation = &sp;
    }
    ASSERT_NE(bifurcation, nullptr) << r.message;
    const double P = 3.0 * bifurcation->lambda;
    EXPECT_NEAR(P, critical_from_PE(kPi * kPi / 4.0, delta_of(c.EA, c.GAs)), 1e-8);
    const Stability v = straight_verdict(c.EA, c.GAs, EndCondition::kFree, P);
    EXPECT_EQ(v.kind, StabilityKind::kCritical) << v.message;
  }
}

TEST(StabilityExtensible, ClampedClampedSymmetricMode) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double EA : {200.0, 1000.0}) {
    const double P_cr = critical_from_PE(4.0 * kPi * kPi, delta_of(EA, inf));
    expect_flip(EA, inf, EndCondition::kFixed, P_cr, "clamped-clamped");
  }
}

TEST(StabilityExtensible, ClampedPinnedWithShearCompliance) {
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    double EA, GAs;
  };
  for (const Case c : {Case{inf, 20.0}, Case{inf, 100.0}, Case{300.0, 40.0}, Case{150.0, inf}}) {
    const double delta = delta_of(c.EA, c.GAs);
    // (1 - P delta) (tan(kL)/(kL) - 1) + P/GAs = 0, k = sqrt(P (1 - P delta)), between k = pi
    // and the inextensible root 4.4934 (shear lowers it).
    auto condition = [&](double P) {
      const double k = std::sqrt(P * (1.0 - P * delta));
      return (1.0 - P * delta) * (std::tan(k) / k - 1.0) + P / c.GAs;
    };
    // Bracket in P between k = pi + 1e-6 (tan k / k - 1 < 0 just above pi ... negative) and
    // k = 4.6 (past the inextensible root 4.4934, tan k / k - 1 > 0).
    auto P_of_k = [&](double k) { return critical_from_PE(k * k, delta); };
    const double a = P_of_k(kPi + 1e-6), b = P_of_k(4.6);
    const ScalarRootResult root = brent_root(condition, a, b, condition(a), condition(b));
    ASSERT_TRUE(root.converged()) << "f(" << a << ") = " << condition(a) << ", f(" << b
                                  << ") = " << condition(b);
    expect_flip(c.EA, c.GAs, EndCondition::kPinned, root.x, "clamped-pinned");
  }
}

// J_{-1/3}(x) = cos(pi/3) J_{1/3}(x) - sin(pi/3) Y_{1/3}(x).
double bessel_j_minus_third(double x) {
  return std::cos(kPi / 3.0) * std::cyl_bessel_j(1.0 / 3.0, x) -
         std::sin(kPi / 3.0) * std::cyl_neumann(1.0 / 3.0, x);
}

TEST(StabilityExtensible, GreenhillColumnUnderItsOwnWeight) {
  const ScalarRootResult z = brent_root(
      bessel_j_minus_third, 1.0, 2.5, bessel_j_minus_third(1.0), bessel_j_minus_third(2.5));
  ASSERT_TRUE(z.converged());
  const double q_cr = 2.25 * z.x * z.x;
  EXPECT_NEAR(q_cr, 7.837, 5e-4);  // Timoshenko & Gere's value
  auto verdict = [](double q) {
    SegmentChain chain = column_chain(std::numeric_limits<double>::infinity(),
                                      std::numeric_limits<double>::infinity(),
                                      EndCondition::kFree);
    std::get<FlexibleSegment>(chain.segments[0]).qx = -q;  // weight toward the clamp
    return equilibrium_stability(chain, Reaction{}, straight(stability_stations(chain, {})));
  };
  EXPECT_EQ(verdict(q_cr * (1.0 - 1e-5)).kind, StabilityKind::kStable);
  EXPECT_EQ(verdict(q_cr * (1.0 + 1e-5)).kind, StabilityKind::kUnstable);
  EXPECT_EQ(verdict(q_cr * (1.0 + 1e-5)).index, 1);
  EXPECT_NEAR(verdict(q_cr).margin, 0.0, 1e-8);
  EXPECT_EQ(verdict(0.5 * q_cr).kind, StabilityKind::kStable);
}

// ---- The independent discrete Hessian ------------------------------------------------------

// The lowest eigenvalue of the Hessian of the discrete Reissner energy (n equal elements, midpoint
// rule for the stretch and shear energies, the bending energy exact) relative to the bending
// stiffness, condensed on eta, with the tip's held coordinates removed, at the shooting
// solution's angles and internal forces. The unknowns (u_x, u_y, eta) at nodes 1..n.
double hessian_margin(const SegmentChain& chain, const ShootingResult& r, int n) {
  const auto& f = std::get<FlexibleSegment>(chain.segments[0]);
  const double L = f.length, h = L / n;
  std::vector<double> mids;
  for (int e = 0; e < n; ++e) mids.push_back((e + 0.5) * h);
  const std::vector<ShapePoint> shape = shooting_shape_at(chain, r, mids);
  // N(s) = the total tip load (given + reaction) plus the dead load beyond s.
  const PrescribedMask mask = prescribed_mask(chain.end);
  const int dofs = 3 * n;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(dofs, dofs), B = Eigen::MatrixXd::Zero(dofs, dofs);
  auto ux = [](int node) { return 3 * (node - 1); };
  for (int e = 0; e < n; ++e) {
    const double th = shape[e].theta;
    const double tx = std::cos(th), ty = std::sin(th);
    const double Nx = r.tip_load.Fx + f.qx * (L - mids[e]);
    const double Ny = r.tip_load.Fy + f.qy * (L - mids[e]);
    const double Na = Nx * tx + Ny * ty, V = -Nx * ty + Ny * tx;
    const double eps = Na / f.EA, gam = V / f.GAs;
    // Element unknowns z = (ux_a, uy_a, eta_a, ux_b, uy_b, eta_b); u' = (u_b - u_a)/h, eta-bar =
    // (eta_a + eta_b)/2, eta' = (eta_b - eta_a)/h. The integrand as a quadratic form in
    // (u'_x, u'_y, eta-bar): EA (u'.t + gam eb)^2 + GAs (u'.n - (1 + eps) eb)^2
    // + Na (2 (u'.n) eb - (1 + eps) eb^2) + V (-2 (u'.t) eb - gam eb^2).
    Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
    const Eigen::Vector3d a_t(tx, ty, gam), a_n(-ty, tx, -(1.0 + eps));
    if (std::isfinite(f.EA)) K += f.EA * a_t * a_t.transpose();
    if (std::isfinite(f.GAs)) K += f.GAs * a_n * a_n.transpose();
    K(0, 2) += -Na * ty - V * tx;
    K(1, 2) += Na * tx - V * ty;
    K(2, 0) = K(0, 2);
    K(2, 1) = K(1, 2);
    K(2, 2) += -Na * (1.0 + eps) - V * gam;
    // (u'_x, u'_y, eb) = T z.
    Eigen::Matrix<double, 3, 6> T = Eigen::Matrix<double, 3, 6>::Zero();
    T(0, 0) = -1.0 / h;
    T(0, 3) = 1.0 / h;
    T(1, 1) = -1.0 / h;
    T(1, 4) = 1.0 / h;
    T(2, 2) = 0.5;
    T(2, 5) = 0.5;
    Eigen::Matrix<double, 6, 6> Ke = h * T.transpose() * K * T;
    Eigen::Matrix<double, 6, 6> Be = Eigen::Matrix<double, 6, 6>::Zero();
    Be(2, 2) = Be(5, 5) = f.EI / h;
    Be(2, 5) = Be(5, 2) = -f.EI / h;
    Ke += Be;
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        const int node_i = e + i / 3, node_j = e + j / 3;
        if (node_i == 0 || node_j == 0) continue;
        H(ux(node_i) + i % 3, ux(node_j) + j % 3) += Ke(i, j);
        B(ux(node_i) + i % 3, ux(node_j) + j % 3) += Be(i, j);
      }
    }
  }
  // Keep the unknowns that are free: drop the tip's held x, y, eta.
  std::vector<int> u_keep, eta_keep;
  for (int node = 1; node <= n; ++node) {
    const bool tip = node == n;
    if (!(tip && mask.x)) u_keep.push_back(ux(node));
    if (!(tip && mask.y)) u_keep.push_back(ux(node) + 1);
    if (!(tip && mask.theta)) eta_keep.push_back(ux(node) + 2);
  }
  auto pick =
      [](const Eigen::MatrixXd& M, const std::vector<int>& rows, const std::vector<int>& cols) {
        Eigen::MatrixXd out(rows.size(), cols.size());
        for (std::size_t i = 0; i < rows.size(); ++i) {
          for (std::size_t j = 0; j < cols.size(); ++j) out(i, j) = M(rows[i], cols[j]);
        }
        return out;
      };
  const Eigen::MatrixXd Huu = pick(H, u_keep, u_keep), Hue = pick(H, u_keep, eta_keep);
  const Eigen::MatrixXd S = pick(H, eta_keep, eta_keep) - Hue.transpose() * Huu.ldlt().solve(Hue);
  const Eigen::MatrixXd Bee = pick(B, eta_keep, eta_keep);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(S, Bee, Eigen::EigenvaluesOnly);
  return std::min(1.0, solver.eigenvalues()(0));
}

struct Deflected {
  EndCondition end;
  double EA, GAs, Fx, Fy, M, qx, qy;
  double tip_x = std::numeric_limits<double>::quiet_NaN();  // prescribed tip x (NaN: L)
};

TEST(StabilityExtensible, DeflectedEquilibriaAgainstTheDiscreteHessian) {
  // Compressed and bent, stable and unstable, every held coordinate: free, guided, pinned, fixed.
  // (Guided, pinned and fixed ends take their loads as the prescribed tip's stress-free value:
  // the beam is bent by the given loads conjugate to the free coordinates and by distributed
  // loads.)
  const std::vector<Deflected> cases = {
      {EndCondition::kFree, 50.0, 20.0, -3.0, 0.6, 0.0, 0.0, 0.0},
      {EndCondition::kFree, 400.0, 1e4, -1.5, 0.2, 0.3, 0.0, 0.0},
      {EndCondition::kFree, 5e3, 30.0, 0.0, 2.0, 0.0, -1.0, 0.0},
      {EndCondition::kFree, 80.0, 30.0, -6.0, 0.3, 0.0, 0.0, 0.0},
      {EndCondition::kGuided, 100.0, 40.0, -2.0, 3.0, 0.0, 0.0, 0.0},
      {EndCondition::kSlider, 60.0, 25.0, -4.0, 0.0, 0.5, 0.0, 0.0},
      {EndCondition::kPinned, 100.0, 40.0, 0.0, 0.0, 0.0, 0.0, 6.0},
      {EndCondition::kFixed, 120.0, 50.0, 0.0, 0.0, 0.0, 0.0, 20.0},
      // Pushed in: compressed and bent (the held x's compliance D enters).
      {EndCondition::kPinned, 200.0, 80.0, 0.0, 0.0, 1.0, 0.0, 2.0, 0.97},
      {EndCondition::kFixed, 300.0, 100.0, 0.0, 0.0, 0.0, 0.0, 10.0, 0.99},
  };
  for (const Deflected& c : cases) {
    SegmentChain chain = column_chain(c.EA, c.GAs, c.end);
    const PrescribedMask mask = prescribed_mask(c.end);
    chain.tip_load = TipLoad{mask.x ? 0.0 : c.Fx, mask.y ? 0.0 : c.Fy, mask.theta ? 0.0 : c.M, 0.0};
    auto& f = std::get<FlexibleSegment>(chain.segments[0]);
    f.qx = c.qx;
    f.qy = c.qy;
    if (!std::isnan(c.tip_x)) chain.prescribed.x = c.tip_x;
    const ShootingSolver solver;
    const ShootingResult r = solver.solve(chain);
    ASSERT_TRUE(r.converged()) << r.message;
    const Reaction support = tip_support_reaction(chain, r.tip_load);
    const Stability v = equilibrium_stability(chain, support, [&](const std::vector<double>& s) {
      return shooting_shape_at(chain, r, s, solver.options());
    });
    ASSERT_TRUE(v.judged()) << v.message;
    // The Hessian's margin at n = 200 and 400 elements, Richardson-extrapolated (O(h^2)).
    const double m200 = hessian_margin(chain, r, 200), m400 = hessian_margin(chain, r, 400);
    const double reference = (4.0 * m400 - m200) / 3.0;
    EXPECT_NEAR(v.margin, reference, 2e-5 + 0.1 * std::fabs(m400 - m200))
        << to_string(c.end) << " EA " << c.EA << " GAs " << c.GAs << " Fx " << c.Fx;
    EXPECT_EQ(v.stable(), reference > 1e-4) << to_string(c.end) << " " << v.message;
  }
}

// The same beam cut into two segments (0.4 + 0.6, each with the EA, GAs and distributed load) is
// the same equilibrium: the verdict's node between segments, its per-segment forces and the
// distributed loads beyond a segment must give the same margin (to its accuracy).
TEST(StabilityExtensible, ASegmentCutInTwoGivesTheSameVerdict) {
  const std::vector<Deflected> cases = {
      {EndCondition::kFree, 50.0, 20.0, -3.0, 0.6, 0.0, 0.0, 0.0},
      {EndCondition::kFree, 5e3, 30.0, 0.0, 2.0, 0.0, -1.0, 0.0},
      {EndCondition::kGuided, 100.0, 40.0, -2.0, 3.0, 0.0, 0.0, 0.0},
      {EndCondition::kPinned, 200.0, 80.0, 0.0, 0.0, 1.0, 0.0, 2.0, 0.97},
  };
  for (const Deflected& c : cases) {
    SegmentChain one = column_chain(c.EA, c.GAs, c.end);
    const PrescribedMask mask = prescribed_mask(c.end);
    one.tip_load = TipLoad{mask.x ? 0.0 : c.Fx, mask.y ? 0.0 : c.Fy, mask.theta ? 0.0 : c.M, 0.0};
    auto& f = std::get<FlexibleSegment>(one.segments[0]);
    f.qx = c.qx;
    f.qy = c.qy;
    if (!std::isnan(c.tip_x)) one.prescribed.x = c.tip_x;
    SegmentChain two = one;
    FlexibleSegment a = f, b = f;
    a.length = 0.4;
    b.length = 0.6;
    two.segments = {a, b};
    const ShootingSolver solver;
    auto verdict = [&](const SegmentChain& chain) {
      const ShootingResult r = solver.solve(chain);
      EXPECT_TRUE(r.converged()) << r.message;
      const Reaction support = tip_support_reaction(chain, r.tip_load);
      return equilibrium_stability(chain, support, [&](const std::vector<double>& s) {
        return shooting_shape_at(chain, r, s, solver.options());
      });
    };
    const Stability v1 = verdict(one), v2 = verdict(two);
    EXPECT_EQ(v1.kind, v2.kind) << to_string(c.end);
    EXPECT_NEAR(v1.margin, v2.margin, 1e-8) << to_string(c.end);
  }
}

TEST(StabilityExtensible, StiffLimitRecoversTheInextensibleVerdict) {
  const std::vector<Deflected> cases = {
      {EndCondition::kFree, 1e12, 1e12, -3.0, 0.6, 0.0, 0.0, 0.0},
      {EndCondition::kFree, 1e12, 1e12, -12.0, 0.05, 0.0, 0.0, 0.0},
      {EndCondition::kGuided, 1e12, 1e12, -2.0, 3.0, 0.0, 0.0, 0.0},
      {EndCondition::kPinned, 1e12, 1e12, 0.0, 0.0, 1.0, 0.0, 0.0},
      {EndCondition::kFixed, 1e12, 1e12, 0.0, 0.0, 0.0, 0.0, 0.0},
  };
  for (const Deflected& c : cases) {
    SegmentChain rigid = column_chain(
        std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), c.end);
    const PrescribedMask mask = prescribed_mask(c.end);
    rigid.tip_load = TipLoad{mask.x ? 0.0 : c.Fx, mask.y ? 0.0 : c.Fy, mask.theta ? 0.0 : c.M, 0.0};
    // The clamped-clamped beam with its tip moved across (an S shape); the pinned one with its
    // tip moved in (compressed and bent by the end moment).
    if (c.end == EndCondition::kFixed) {
      rigid.prescribed.x = 0.95;
      rigid.prescribed.y = 0.2;
    }
    if (c.end == EndCondition::kPinned) rigid.prescribed.x = 0.8;
    SegmentChain stretchy = rigid;
    auto& f = std::get<FlexibleSegment>(stretchy.segments[0]);
    f.EA = c.EA;
    f.GAs = c.GAs;
    const ShootingSolver solver;
    auto verdict = [&](const SegmentChain& chain) {
      const ShootingResult r = solver.solve(chain);
      EXPECT_TRUE(r.converged()) << r.message;
      const Reaction support = tip_support_reaction(chain, r.tip_load);
      return equilibrium_stability(chain, support, [&](const std::vector<double>& s) {
        return shooting_shape_at(chain, r, s, solver.options());
      });
    };
    const Stability a = verdict(rigid), b = verdict(stretchy);
    EXPECT_EQ(a.kind, b.kind) << to_string(c.end) << ": " << a.message << " / " << b.message;
    EXPECT_EQ(a.index, b.index) << to_string(c.end);
    EXPECT_NEAR(a.margin, b.margin, 1e-7) << to_string(c.end);
  }
}

TEST(StabilityExtensible, FollowerPressureIsNotConservative) {
  SegmentChain chain = column_chain(100.0, 50.0, EndCondition::kFree);
  std::get<FlexibleSegment>(chain.segments[0]).q_follower = 1.0;
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  const Stability v = equilibrium_stability(chain, Reaction{}, [&](const std::vector<double>& s) {
    return shooting_shape_at(chain, r, s);
  });
  EXPECT_EQ(v.kind, StabilityKind::kNotConservative);
}

}  // namespace
}  // namespace flexure
