// What is checked against what (issue 29 item 3; docs/contact.md):
//   * wrap around a circle tangent at the clamp, small loads: landing at F L = EI/R and the free
//     span a = L - s_c = EI/(F R) of linear theory;
//   * the curvature condition m(s_c) = sigma EI/R evaluated by the statics of the returned free
//     span (tip load and tip position), not by the solver's own residual, to 1e-9;
//   * force balance (clamp reaction + applied load + contact force = 0) to 1e-10 and moment
//     balance about the clamp (pressure, point force, tip load, clamp moment) to 1e-10;
//   * tip contact with a straight stop: a propped cantilever under a uniform load at small loads
//     (R = 3qL/8 - 3EI d/L^3, landing at q = 8 EI d / L^4); under a tip force normal to the stop
//     the reaction grows exactly as lambda F - F_landing (large deflection);
//   * lift-off along a continuation from a load pressing on the stop to one pulling away, located
//     at the load that holds the tip on the stop with zero reaction;
//   * convergence under refinement of the continuation: 3 and 48 steps give the same events and
//     the same final state;
//   * an independent second method: a Hencky chain of N rigid links (midpoint rule, O(h^2)) with a
//     stiff one-sided penalty foundation on its nodes, minimised by Newton's method under load
//     stepping, written here; it converges to the contact solution as N and the stiffness grow;
//   * a seeded random cross-check of both surfaces against the penalty chain and the balances;
//   * several surfaces: one touched gives that surface's own solution; two met are named, never
//     answered;
//   * unsupported combinations are refused with the reason.
#include "flexure/solver/shooting/rigid_contact.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

SegmentChain cantilever(double L, double EI, double Fx, double Fy, double M = 0.0) {
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment(L, EI));
  chain.tip_load.Fx = Fx;
  chain.tip_load.Fy = Fy;
  chain.tip_load.M = M;
  return chain;
}

RigidSurface circle(double cy, double R) {
  RigidSurface s;
  s.type = ContactSurfaceType::kCircle;
  s.center = {0.0, cy};
  s.radius = R;
  return s;
}

RigidSurface line(double px, double py, double nx, double ny) {
  RigidSurface s;
  s.type = ContactSurfaceType::kLine;
  s.point = {px, py};
  s.normal = {nx, ny};
  return s;
}

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Moment about the clamp of every load on the beam, for a wrap: clamp moment, tip load, point
// force at s_c, and the pressure (r x e = c x e on the circle, so its moment is c x resultant).
double wrap_moment_balance(const ContactResult& r, const RigidSurface& s) {
  const ChainPose& pc = r.separation_points.at(0);
  const double px = r.contact_force[0] - r.point_force[0];
  const double py = r.contact_force[1] - r.point_force[1];
  return r.reaction.M + r.tip_load.M + cross(r.tip.x, r.tip.y, r.tip_load.Fx, r.tip_load.Fy) +
         cross(pc.x, pc.y, r.point_force[0], r.point_force[1]) +
         cross(s.center[0], s.center[1], px, py);
}

// m(s_c+) from the statics of the free span: M + (r_tip - r_c) x F.
double separation_moment_by_statics(const ContactResult& r) {
  const ChainPose& pc = r.separation_points.at(0);
  return r.tip_load.M + cross(r.tip.x - pc.x, r.tip.y - pc.y, r.tip_load.Fx, r.tip_load.Fy);
}

// ---- The independent second method: a Hencky chain on a one-sided penalty foundation ----------
// N rigid links of length h = L/N at absolute angles phi_i; bending springs EI/h between links
// and 2 EI/h at the clamp (link 0 represents theta(h/2): the midpoint rule, error O(h^2)); a
// foundation of stiffness k per unit length on the nodes (weight h, h/2 at the tip) acting only
// where the gap is negative; a dead tip force and moment. Energy minimised by Newton's method
// (Hessian by central differences of the analytic gradient) with a backtracking line search,
// the load applied in `load_steps` increments.
struct PenaltyChain {
  int N = 200;
  double L = 1.0, EI = 1.0, k = 1e7;
  double Fx = 0.0, Fy = 0.0, M = 0.0;
  double qx = 0.0, qy = 0.0;  // dead load per unit length, lumped on the nodes (weights h, h/2)
  RigidSurface surface;

  double gap(double x, double y, double& gx, double& gy) const {
    if (surface.type == ContactSurfaceType::kCircle) {
      const double dx = x - surface.center[0], dy = y - surface.center[1];
      const double d = std::hypot(dx, dy);
      gx = dx / d;
      gy = dy / d;
      return d - surface.radius;
    }
    const double n = std::hypot(surface.normal[0], surface.normal[1]);
    gx = surface.normal[0] / n;
    gy = surface.normal[1] / n;
    return gx * (x - surface.point[0]) + gy * (y - surface.point[1]);
  }
  double weight(int node) const { return node == N ? 0.5 * L / N : L / N; }

  // Energy and gradient at load factor lam; contact force (sum of foundation forces) on request.
  double energy(const Eigen::VectorXd& phi,
                double lam,
                Eigen::VectorXd* grad,
                double* cfx = nullptr,
                double* cfy = nullptr) const {
    const double h = L / N;
    std::vector<double> x(N + 1, 0.0), y(N + 1, 0.0);
    for (int i = 0; i < N; ++i) {
      x[i + 1] = x[i] + h * std::cos(phi[i]);
      y[i + 1] = y[i] + h * std::sin(phi[i]);
    }
    double E = EI / h * phi[0] * phi[0];
    for (int i = 1; i < N; ++i) E += 0.5 * EI / h * std::pow(phi[i] - phi[i - 1], 2);
    E -= lam * (Fx * x[N] + Fy * y[N] + M * phi[N - 1]);
    // Node forces G_j (external, including the foundation's push).
    std::vector<double> Gx(N + 1, 0.0), Gy(N + 1, 0.0);
    Gx[N] = lam * Fx;
    Gy[N] = lam * Fy;
    for (int j = 1; j <= N; ++j) {
      E -= lam * weight(j) * (qx * x[j] + qy * y[j]);
      Gx[j] += lam * weight(j) * qx;
      Gy[j] += lam * weight(j) * qy;
    }
    double sx = 0.0, sy = 0.0;
    for (int j = 1; j <= N; ++j) {
      double gx = 0.0, gy = 0.0;
      const double g = gap(x[j], y[j], gx, gy);
      if (g < 0.0) {
        E += 0.5 * k * weight(j) * g * g;
        const double f = -k * weight(j) * g;  // push along the gap gradient
        Gx[j] += f * gx;
        Gy[j] += f * gy;
        sx += f * gx;
        sy += f * gy;
      }
    }
    if (cfx) *cfx = sx;
    if (cfy) *cfy = sy;
    if (grad) {
      grad->setZero(N);
      (*grad)[0] += 2.0 * EI / h * phi[0];
      for (int i = 1; i < N; ++i) {
        const double d = EI / h * (phi[i] - phi[i - 1]);
        (*grad)[i] += d;
        (*grad)[i - 1] -= d;
      }
      (*grad)[N - 1] -= lam * M;
      double sumx = 0.0, sumy = 0.0;  // sum of G_j for j > i
      for (int i = N - 1; i >= 0; --i) {
        sumx += Gx[i + 1];
        sumy += Gy[i + 1];
        (*grad)[i] -= h * (-std::sin(phi[i]) * sumx + std::cos(phi[i]) * sumy);
      }
    }
    return E;
  }

  Eigen::VectorXd solve(int load_steps = 40) const {
    Eigen::VectorXd phi = Eigen::VectorXd::Zero(N);
    Eigen::VectorXd g(N), gp(N), gm(N);
    for (int step = 1; step <= load_steps; ++step) {
      const double lam = static_cast<double>(step) / load_steps;
      for (int it = 0; it < 60; ++it) {
        double E = energy(phi, lam, &g);
        if (g.norm() <
            1e-11 * (1.0 + std::abs(Fx) + std::abs(Fy) + std::abs(M) + std::abs(qx) + std::abs(qy)))
          break;
        Eigen::MatrixXd H(N, N);
        const double eps = 1e-7;
        for (int c = 0; c < N; ++c) {
          Eigen::VectorXd p = phi;
          p[c] += eps;
          energy(p, lam, &gp);
          p[c] -= 2 * eps;
          energy(p, lam, &gm);
          H.col(c) = (gp - gm) / (2 * eps);
        }
        H = 0.5 * (H + H.transpose());
        Eigen::VectorXd d = -H.ldlt().solve(g);
        if (!d.allFinite() || g.dot(d) >= 0.0) d = -g;
        double t = 1.0;
        for (int ls = 0; ls < 40; ++ls, t *= 0.5) {
          if (energy(phi + t * d, lam, nullptr) <= E + 1e-4 * t * g.dot(d)) break;
        }
        phi += t * d;
      }
    }
    return phi;
  }

  void tip(const Eigen::VectorXd& phi, double& x, double& y) const {
    x = y = 0.0;
    for (int i = 0; i < N; ++i) {
      x += L / N * std::cos(phi[i]);
      y += L / N * std::sin(phi[i]);
    }
  }
};

RigidContactSolver::Options options(int steps = 20) {
  RigidContactSolver::Options o;
  o.steps = steps;
  return o;
}

// ---- Circle ------------------------------------------------------------------------------------

TEST(RigidContactCircle, SmallLoadsMatchLinearTheory) {
  // R = 100 L: rotations stay below 0.01 rad, linear theory holds to ~1e-5.
  const double L = 1.0, EI = 1.0, R = 100.0, F = 0.03;
  const ContactResult r =
      RigidContactSolver(options()).solve(cantilever(L, EI, 0.0, F), circle(R, R));
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_TRUE(r.in_contact);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_EQ(r.events[0].kind, ContactEventKind::kLanding);
  EXPECT_NEAR(r.events[0].load_factor, EI / (R * F * L), 1e-4);  // F L = EI/R
  const double free_span = L - r.separation_s.at(0);
  EXPECT_NEAR(free_span, EI / (F * R), 1e-4 * free_span);  // F a = EI/R
  EXPECT_DOUBLE_EQ(r.s_start, 0.0);
  EXPECT_DOUBLE_EQ(r.s_end, r.separation_s[0]);
}

TEST(RigidContactCircle, BelowLandingTheBeamIsFree) {
  const ContactResult r =
      RigidContactSolver(options()).solve(cantilever(1.0, 1.0, 0.0, 0.5), circle(-4.0, 4.0));
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_FALSE(r.in_contact);  // the load bends away from the circle
  EXPECT_TRUE(r.events.empty());
  EXPECT_GT(r.min_gap, 0.0);
}

void expect_wrap_balances(const ContactResult& r, const RigidSurface& s, double EI) {
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_TRUE(r.in_contact);
  const int sigma = s.center[1] > 0 ? 1 : -1;
  const double scale = std::hypot(r.tip_load.Fx, r.tip_load.Fy) + std::abs(r.tip_load.M);
  // Curvature condition by the free span's statics (independent of the solver's residual).
  EXPECT_NEAR(separation_moment_by_statics(r), sigma * EI / s.radius, 1e-9 * EI / s.radius);
  EXPECT_NEAR(r.curvature_condition, 0.0, 1e-9 * EI / s.radius);
  EXPECT_NEAR(r.reaction.Fx + r.tip_load.Fx + r.contact_force[0], 0.0, 1e-10 * scale);
  EXPECT_NEAR(r.reaction.Fy + r.tip_load.Fy + r.contact_force[1], 0.0, 1e-10 * scale);
  EXPECT_NEAR(wrap_moment_balance(r, s), 0.0, 1e-10 * scale);
  EXPECT_GE(r.point_force_normal, 0.0);
  EXPECT_GE(r.line_pressure, 0.0);
  EXPECT_GE(r.min_gap, -1e-9);
  // The separation point lies on the circle with the circle's tangent.
  const ChainPose& pc = r.separation_points.at(0);
  EXPECT_NEAR(std::hypot(pc.x - s.center[0], pc.y - s.center[1]), s.radius, 1e-12 * s.radius);
  EXPECT_NEAR(pc.theta, sigma * r.separation_s[0] / s.radius, 1e-14);
}

TEST(RigidContactCircle, LargeWrapBalancesAndCurvatureCondition) {
  const RigidSurface s = circle(0.5, 0.5);
  const ContactResult r = RigidContactSolver(options()).solve(cantilever(1.0, 1.0, 1.0, 8.0), s);
  expect_wrap_balances(r, s, 1.0);
  ASSERT_EQ(r.separation_s.size(), 1u);
  EXPECT_GT(r.separation_s[0] / s.radius, 0.5);  // wrapped by more than half a radian
}

TEST(RigidContactCircle, ConvergesUnderRefinementOfTheContinuation) {
  const RigidSurface s = circle(-0.8, 0.8);
  const SegmentChain c = cantilever(1.0, 1.0, 1.0, -6.0, -0.5);
  const ContactResult coarse = RigidContactSolver(options(3)).solve(c, s);
  const ContactResult fine = RigidContactSolver(options(48)).solve(c, s);
  ASSERT_TRUE(coarse.converged() && fine.converged());
  ASSERT_EQ(coarse.events.size(), 1u);
  ASSERT_EQ(fine.events.size(), 1u);
  EXPECT_NEAR(coarse.events[0].load_factor, fine.events[0].load_factor, 1e-10);
  EXPECT_NEAR(coarse.separation_s[0], fine.separation_s[0], 1e-11);
  EXPECT_NEAR(coarse.tip.x, fine.tip.x, 1e-11);
  EXPECT_NEAR(coarse.tip.y, fine.tip.y, 1e-11);
  expect_wrap_balances(fine, s, 1.0);
}

TEST(RigidContactCircle, PenaltyChainConvergesToTheWrap) {
  // Measured: the penalty chain's tip agrees to 3e-6 at N = 200, k = 1e9 EI/L^4. Its clamp carries
  // a small transverse force that the exact wrap does not (N(0) = T t(0)): the foundation's
  // boundary layer at the clamp, of length (EI/k)^(1/4), so that force falls like k^(-1/4)
  // (measured 0.29 at k = 1e7, 0.086 at 1e9 of the load 8).
  const RigidSurface s = circle(0.5, 0.5);
  const ContactResult r = RigidContactSolver(options()).solve(cantilever(1.0, 1.0, 1.0, 8.0), s);
  ASSERT_TRUE(r.converged()) << r.message;
  double shear[2] = {0.0, 0.0};
  int i = 0;
  for (double k : {1e7, 1e9}) {
    PenaltyChain p;
    p.N = 200;
    p.Fx = 1.0;
    p.Fy = 8.0;
    p.k = k;
    p.surface = s;
    const Eigen::VectorXd phi = p.solve(20);
    double x = 0, y = 0, cfx = 0, cfy = 0;
    p.tip(phi, x, y);
    p.energy(phi, 1.0, nullptr, &cfx, &cfy);
    shear[i++] = std::abs(cfy - r.contact_force[1]);
    if (k == 1e9) {
      EXPECT_NEAR(x, r.tip.x, 2e-5);
      EXPECT_NEAR(y, r.tip.y, 2e-5);
      EXPECT_NEAR(cfx, r.contact_force[0], 1e-3 * std::abs(cfx));
    }
  }
  EXPECT_GT(shear[0] / shear[1], 2.5);  // k^(-1/4): 100^(1/4) = 3.16
  EXPECT_LT(shear[1], 0.02 * std::abs(r.contact_force[1]));
}

// ---- Line --------------------------------------------------------------------------------------

TEST(RigidContactLine, ProppedCantileverUnderUniformLoad) {
  // Stop a gap d below the tip, uniform load q toward it: R = 3 q L/8 - 3 EI d / L^3 (linear
  // superposition of q L^4/(8 EI) and R L^3/(3 EI)), landing at q = 8 EI d / L^4.
  // q <= 72 EI d / L^4 keeps the tip the lowest point (R <= q L/3: the tip slope stays
  // downward); past it the span sags onto the stop (refused below).
  const double d = 1e-3, q = 0.05;
  SegmentChain c = cantilever(1.0, 1.0, 0.0, 0.0);
  std::get<FlexibleSegment>(c.segments[0]).qy = -q;
  const ContactResult r = RigidContactSolver(options()).solve(c, line(0.0, -d, 0.0, 1.0));
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_TRUE(r.in_contact);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_NEAR(r.events[0].load_factor, 8.0 * d / q, 1e-3 * 8.0 * d / q);
  EXPECT_NEAR(r.point_force_normal, 3.0 * q / 8.0 - 3.0 * d, 1e-3 * (3.0 * q / 8.0 - 3.0 * d));
  EXPECT_NEAR(r.tip.y, -d, 1e-12);
  // Force balance: clamp reaction + load q L + contact force = 0.
  EXPECT_NEAR(r.reaction.Fy - q + r.contact_force[1], 0.0, 1e-10 * q);
  EXPECT_EQ(r.kind, ContactKind::kTip);
}

// ---- Line contact: the beam lying on the stop ------------------------------------------------

// A cantilever under q lying on a stop d below its clamp, by linear theory (EI w'''' = q): the
// free span [0, a] is a cantilever under q and an upward force R at a with w(a) = d, w'(a) = 0
// and m(a) = 0 (the lying part is straight and unbent); the part (a, L] rests on the stop, which
// carries q there. w'(a) = q a^3/(6 EI) - R a^2/(2 EI) = 0 gives R = q a/3, and
// w(a) = q a^4/(8 EI) - R a^3/(3 EI) = q a^4/(72 EI) = d gives a = (72 EI d/q)^(1/4): the line
// contact begins at q = 72 EI d/L^4, where the propped cantilever's tip slope
// q L^3/(6 EI) - R L^2/(2 EI) with R = 3qL/8 - 3 EI d/L^3 turns to zero. Clamp: 2 q a/3 and the
// moment q a^2/6.
TEST(RigidContactLine, LineContactSmallLoadsMatchTheClosedForm) {
  const double d = 1e-5;
  for (double ratio : {100.0, 200.0, 1000.0}) {  // q / (EI d / L^4)
    const double q = ratio * d;
    SegmentChain c = cantilever(1.0, 1.0, 0.0, 0.0);
    std::get<FlexibleSegment>(c.segments[0]).qy = -q;
    const ContactResult r = RigidContactSolver(options()).solve(c, line(0.0, -d, 0.0, 1.0));
    ASSERT_TRUE(r.converged()) << r.message;
    ASSERT_EQ(r.kind, ContactKind::kLine);
    ASSERT_EQ(r.events.size(), 2u);
    EXPECT_EQ(r.events[0].kind, ContactEventKind::kLanding);
    EXPECT_EQ(r.events[1].kind, ContactEventKind::kLineContact);
    // Measured: 3e-10 relative everywhere (the geometric terms are O(d^2)).
    EXPECT_NEAR(r.events[0].load_factor, 8.0 / ratio, 1e-8 * 8.0 / ratio);
    EXPECT_NEAR(r.events[1].load_factor, 72.0 / ratio, 1e-8 * 72.0 / ratio);
    const double a = std::pow(72.0 * d / q, 0.25);
    EXPECT_NEAR(r.s_start, a, 1e-8 * a);
    EXPECT_NEAR(r.s_end, 1.0, 1e-15);
    EXPECT_NEAR(r.point_force_normal, q * a / 3.0, 1e-8 * q);
    EXPECT_NEAR(r.line_pressure, q, 1e-12 * q);
    EXPECT_NEAR(r.tip_reaction_normal, 0.0, 1e-15);
    EXPECT_NEAR(r.reaction.Fy, 2.0 * q * a / 3.0, 1e-8 * q);
    EXPECT_NEAR(r.reaction.M, q * a * a / 6.0, 1e-8 * q);
    EXPECT_NEAR(r.contact_force[1], q * a / 3.0 + q * (1.0 - a), 1e-8 * q);
    EXPECT_NEAR(r.separation_points.at(0).y, -d, 1e-13);  // the Newton tolerance, in lengths
    EXPECT_NEAR(r.tip.y, -d, 1e-13);
    EXPECT_EQ(r.stability.kind, StabilityKind::kNotChecked);
    EXPECT_NE(r.stability.message.find("line contact"), std::string::npos);
  }
}

TEST(RigidContactLine, ReactionGrowsLinearlyAfterLandingUnderANormalTipForce) {
  // The tip held on y = -d by a frictionless stop under a vertical force: the net vertical tip
  // force is the landing force whatever the load, so R_n = F - F_landing exactly.
  const double F = 5.0, d = 0.3;
  for (int steps : {4, 40}) {
    const ContactResult r = RigidContactSolver(options(steps))
                                .solve(cantilever(1.0, 1.0, 0.0, -F), line(0.0, -d, 0.0, 1.0));
    ASSERT_TRUE(r.converged()) << r.message;
    ASSERT_EQ(r.events.size(), 1u);
    const double landing = r.events[0].load_factor * F;
    EXPECT_NEAR(r.point_force_normal, F - landing, 1e-9 * F);
    for (const ContactPathPoint& p : r.path) {
      if (p.in_contact) EXPECT_NEAR(p.normal_force, p.load_factor * F - landing, 1e-9 * F);
    }
    EXPECT_NEAR(r.tip.y, -d, 1e-12);
    // Moment balance about the clamp: depends on the solved shape.
    const double Mb = r.reaction.M + r.tip_load.M +
                      cross(r.tip.x,
                            r.tip.y,
                            r.tip_load.Fx + r.contact_force[0],
                            r.tip_load.Fy + r.contact_force[1]);
    EXPECT_NEAR(Mb, 0.0, 1e-10 * F);
  }
}

TEST(RigidContactLine, LiftOffAlongTheContinuation) {
  // Start pressed on the stop (Fy = -5), end pulled away (Fy = +1): lift-off where the tip force
  // equals the landing force of the same stop, found separately.
  const double d = 0.3;
  const ContactResult landing =
      RigidContactSolver(options(10))
          .solve(cantilever(1.0, 1.0, 0.0, -5.0), line(0.0, -d, 0.0, 1.0));
  ASSERT_TRUE(landing.converged());
  const double F_land = 5.0 * landing.events.at(0).load_factor;
  TipLoad start;
  start.Fy = -5.0;
  for (int steps : {3, 30}) {
    const ContactResult r =
        RigidContactSolver(options(steps))
            .solve(cantilever(1.0, 1.0, 0.0, 1.0), line(0.0, -d, 0.0, 1.0), start);
    ASSERT_TRUE(r.converged()) << r.message;
    ASSERT_EQ(r.events.size(), 1u);
    EXPECT_EQ(r.events[0].kind, ContactEventKind::kLiftOff);
    EXPECT_NEAR(-5.0 + 6.0 * r.events[0].load_factor, -F_land, 1e-9);
    EXPECT_FALSE(r.in_contact);
    EXPECT_TRUE(r.path.front().in_contact);
    EXPECT_GT(r.tip_gap, 0.0);
  }
}

TEST(RigidContactLine, PenaltyChainConvergesToTheTipContact) {
  // An inclined stop and a tip force with a component along it.
  const RigidSurface s = line(0.0, -0.4, 0.3, 1.0);
  const ContactResult r = RigidContactSolver(options()).solve(cantilever(1.0, 1.0, 1.5, -6.0), s);
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_TRUE(r.in_contact);
  PenaltyChain p;
  p.N = 100;
  p.Fx = 1.5;
  p.Fy = -6.0;
  p.k = 1e9;
  p.surface = s;
  const Eigen::VectorXd phi = p.solve(20);
  double x = 0, y = 0, cfx = 0, cfy = 0;
  p.tip(phi, x, y);
  p.energy(phi, 1.0, nullptr, &cfx, &cfy);
  EXPECT_NEAR(x, r.tip.x, 1e-4);
  EXPECT_NEAR(y, r.tip.y, 1e-4);
  EXPECT_NEAR(std::hypot(cfx, cfy), r.point_force_normal, 2e-3 * r.point_force_normal);
}

// The large-deflection line contact against its own free span solved alone with the loads the
// solution reports (the end force at a: the point force R_a nu and the lying part's axial force
// along tau): each is an equilibrium of the other. Also the statics of the lying part (axial
// force q . tau (L - a), pressure -q . nu), force balance, and moment balance about the clamp by
// quadrature of the returned shape (trapezoid, 4001 points, O(h^2)). Level and inclined stops, a
// load with a component along the stop.
TEST(RigidContactLine, LargeDeflectionLineContactIsAnEquilibriumOfItsFreeSpan) {
  struct Case {
    double nx, ny, qx, qy;
  };
  for (const Case& k :
       {Case{0.0, 1.0, 0.0, -100.0}, Case{0.25, 1.0, 0.0, -100.0}, Case{0.0, 1.0, 20.0, -100.0}}) {
    SegmentChain c = cantilever(1.0, 1.0, 0.0, 0.0);
    std::get<FlexibleSegment>(c.segments[0]).qx = k.qx;
    std::get<FlexibleSegment>(c.segments[0]).qy = k.qy;
    const RigidSurface s = line(0.0, -0.3, k.nx, k.ny);
    RigidContactSolver::Options o = options(20);
    o.shape_points = 4001;
    const ContactResult r = RigidContactSolver(o).solve(c, s);
    ASSERT_TRUE(r.converged()) << r.message;
    ASSERT_EQ(r.kind, ContactKind::kLine);
    const double nn = std::hypot(k.nx, k.ny);
    const double nux = k.nx / nn, nuy = k.ny / nn;
    const double tx = nuy, ty = -nux;  // the stop's direction, the beam running along +x
    const double a = r.s_start;
    const ChainPose& pa = r.separation_points.at(0);
    EXPECT_GT(a, 0.3);
    EXPECT_LT(a, 0.95);
    // The free span alone.
    SegmentChain span = cantilever(a,
                                   1.0,
                                   r.point_force[0] + r.lying_axial_force * tx,
                                   r.point_force[1] + r.lying_axial_force * ty);
    std::get<FlexibleSegment>(span.segments[0]).qx = k.qx;
    std::get<FlexibleSegment>(span.segments[0]).qy = k.qy;
    const ShootingResult fs = ShootingSolver().solve(span);
    ASSERT_TRUE(fs.converged()) << fs.message;
    EXPECT_NEAR(fs.tip.x, pa.x, 1e-10);
    EXPECT_NEAR(fs.tip.y, pa.y, 1e-10);
    EXPECT_NEAR(nux * fs.tip.x + nuy * (fs.tip.y + 0.3), 0.0, 1e-10);  // on the stop
    EXPECT_NEAR(fs.tip.theta, std::atan2(ty, tx), 1e-10);              // tangent to it
    EXPECT_NEAR(fs.reaction.Fx, r.reaction.Fx, 1e-9 * 100.0);
    EXPECT_NEAR(fs.reaction.Fy, r.reaction.Fy, 1e-9 * 100.0);
    EXPECT_NEAR(fs.reaction.M, r.reaction.M, 1e-9 * 100.0);
    // The lying part: axial force, pressure, the stop's reactions along its normal.
    EXPECT_NEAR(r.lying_axial_force, (k.qx * tx + k.qy * ty) * (1.0 - a), 1e-12 * 100.0);
    EXPECT_NEAR(r.line_pressure, -(k.qx * nux + k.qy * nuy), 1e-12 * 100.0);
    EXPECT_GT(r.point_force_normal, 0.0);
    EXPECT_NEAR(r.point_force[0] * nuy - r.point_force[1] * nux, 0.0, 1e-12);
    EXPECT_NEAR(r.tip.x, pa.x + (1.0 - a) * tx, 1e-12);
    EXPECT_NEAR(r.tip.y, pa.y + (1.0 - a) * ty, 1e-12);
    // The first integral of the loaded elastica (N' = -q, m' = -N . n with n the left normal):
    // d/ds [m^2/(2 EI) + N . t + q . r] = 0 on the free span. At the clamp theta = 0, r = 0 and
    // N(0) = -(clamp force); at a- m = 0 and N . tau is the lying part's axial force:
    //   M^2/(2 EI) - reaction.Fx = N_t + q . r(a).
    // For a level stop d below and a load along -y alone: M = sqrt(2 EI q d), exactly.
    EXPECT_NEAR(0.5 * r.reaction.M * r.reaction.M - r.reaction.Fx,
                r.lying_axial_force + k.qx * pa.x + k.qy * pa.y,
                1e-9 * 100.0);
    if (k.nx == 0.0 && k.qx == 0.0) {
      EXPECT_NEAR(r.reaction.M, std::sqrt(2.0 * 100.0 * 0.3), 1e-9);
    }
    // Force balance: clamp reaction + q L + contact force = 0.
    EXPECT_NEAR(r.reaction.Fx + k.qx + r.contact_force[0], 0.0, 1e-9 * 100.0);
    EXPECT_NEAR(r.reaction.Fy + k.qy + r.contact_force[1], 0.0, 1e-9 * 100.0);
    // Moment balance about the clamp: the dead load over the returned shape, the point force at
    // a, the pressure p nu on (a, L] (r = r_a + (s - a) tau there) and the tip reaction.
    double Mq = 0.0;
    for (std::size_t i = 1; i < r.shape.size(); ++i) {
      const ShapePoint& p0 = r.shape[i - 1];
      const ShapePoint& p1 = r.shape[i];
      Mq += 0.5 * (p1.s - p0.s) * (cross(p0.x, p0.y, k.qx, k.qy) + cross(p1.x, p1.y, k.qx, k.qy));
    }
    const double la = 1.0 - a, p = r.line_pressure;
    const double Mp =
        p * (cross(pa.x, pa.y, nux, nuy) * la + cross(tx, ty, nux, nuy) * 0.5 * la * la);
    const double M =
        r.reaction.M + Mq + cross(pa.x, pa.y, r.point_force[0], r.point_force[1]) + Mp +
        cross(r.tip.x, r.tip.y, r.tip_reaction_normal * nux, r.tip_reaction_normal * nuy);
    EXPECT_NEAR(M, 0.0, 1e-6 * 100.0);  // measured 2e-14 .. 1.6e-8 (quadrature)
  }
}

TEST(RigidContactLine, LineContactConvergesUnderRefinementOfTheContinuation) {
  SegmentChain c = cantilever(1.0, 1.0, 0.0, 0.0);
  std::get<FlexibleSegment>(c.segments[0]).qy = -100.0;
  const RigidSurface s = line(0.0, -0.3, 0.0, 1.0);
  const ContactResult ref = RigidContactSolver(options(80)).solve(c, s);
  ASSERT_TRUE(ref.converged()) << ref.message;
  ASSERT_EQ(ref.events.size(), 2u);
  for (int steps : {3, 10}) {
    const ContactResult r = RigidContactSolver(options(steps)).solve(c, s);
    ASSERT_TRUE(r.converged()) << r.message;
    ASSERT_EQ(r.events.size(), 2u);
    for (int e = 0; e < 2; ++e) {
      EXPECT_EQ(r.events[e].kind, ref.events[e].kind);
      EXPECT_NEAR(r.events[e].load_factor, ref.events[e].load_factor, 1e-10);
    }
    EXPECT_NEAR(r.s_start, ref.s_start, 1e-10);
    EXPECT_NEAR(r.point_force_normal, ref.point_force_normal, 1e-9);
    EXPECT_NEAR(r.reaction.M, ref.reaction.M, 1e-9);
  }
  // Along the continuation: tip contact between the events, lying after the second, the
  // separation point moving toward the clamp as the load grows.
  double last_a = 1.0;
  for (const ContactPathPoint& p : ref.path) {
    if (p.load_factor > ref.events[1].load_factor) {
      EXPECT_LT(p.separation_s, last_a);
      last_a = p.separation_s;
    } else if (p.load_factor > ref.events[0].load_factor) {
      EXPECT_EQ(p.separation_s, 1.0);
    }
  }
}

TEST(RigidContactLine, PenaltyChainConvergesToTheLineContact) {
  // The penalty chain knows nothing of separation points: it lies on its foundation where the
  // load presses it there. Tip within O(h^2), the contact force within 2e-4, the first node in
  // contact within 0.02 L of a (a boundary layer (EI/k)^(1/4) = 6e-3 and a spacing h).
  SegmentChain c = cantilever(1.0, 1.0, 0.0, 0.0);
  std::get<FlexibleSegment>(c.segments[0]).qy = -100.0;
  const RigidSurface s = line(0.0, -0.3, 0.0, 1.0);
  const ContactResult r = RigidContactSolver(options()).solve(c, s);
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.kind, ContactKind::kLine);
  PenaltyChain p;
  p.N = 200;
  p.qy = -100.0;
  p.k = 1e9;
  p.surface = s;
  const Eigen::VectorXd phi = p.solve(40);
  double x = 0, y = 0, cfx = 0, cfy = 0;
  p.tip(phi, x, y);
  p.energy(phi, 1.0, nullptr, &cfx, &cfy);
  // Measured: tip x 1.2e-6, contact force 2.9e-5 relative; first node in contact 0.715 (a 0.719).
  EXPECT_NEAR(x, r.tip.x, 1e-5);
  EXPECT_NEAR(y, r.tip.y, 1e-6);
  EXPECT_NEAR(cfy, r.contact_force[1], 2e-4 * r.contact_force[1]);
  double yy = 0.0;
  int first = -1;
  for (int i = 0; i < p.N && first < 0; ++i) {
    yy += std::sin(phi[i]) / p.N;
    if (yy < -0.3) first = i + 1;
  }
  ASSERT_GT(first, 0);
  EXPECT_NEAR(static_cast<double>(first) / p.N, r.s_start, 0.02);
}

// ---- Point contact at an interior point ---------------------------------------------------------

double point_moment_balance(const ContactResult& r) {
  const ChainPose& p = r.separation_points.at(0);
  return r.reaction.M + r.tip_load.M + cross(r.tip.x, r.tip.y, r.tip_load.Fx, r.tip_load.Fy) +
         cross(p.x, p.y, r.point_force[0], r.point_force[1]);
}

TEST(RigidContactPoint, BeamPressedOverAPinAgainstThePenaltyChain) {
  // A pin (circle of radius 0.1 L) under the middle of the beam; the tip force bends the beam
  // over it: one interior contact point, tangent, with a force along the pin's radius.
  const RigidSurface pin = circle(-0.15, 0.1);
  RigidSurface s = pin;
  s.center = {0.5, -0.15};
  const ContactResult r = RigidContactSolver(options()).solve(cantilever(1.0, 1.0, 0.5, -3.0), s);
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_TRUE(r.in_contact);
  ASSERT_EQ(r.events.size(), 1u);
  ASSERT_EQ(r.separation_points.size(), 1u);
  const ChainPose& p = r.separation_points[0];
  const double dx = p.x - 0.5, dy = p.y + 0.15;
  EXPECT_NEAR(std::hypot(dx, dy), 0.1, 1e-12);                               // on the pin
  EXPECT_NEAR(std::cos(p.theta) * dx + std::sin(p.theta) * dy, 0.0, 1e-11);  // tangent
  // The force acts along the pin's radius, outward.
  EXPECT_NEAR(cross(dx, dy, r.point_force[0], r.point_force[1]), 0.0, 1e-10);
  EXPECT_GT(r.point_force_normal, 0.0);
  EXPECT_NEAR(r.reaction.Fx + r.tip_load.Fx + r.contact_force[0], 0.0, 1e-10);
  EXPECT_NEAR(r.reaction.Fy + r.tip_load.Fy + r.contact_force[1], 0.0, 1e-10);
  EXPECT_NEAR(point_moment_balance(r), 0.0, 1e-10);
  EXPECT_GE(r.min_gap, -1e-9);
  PenaltyChain pc;
  pc.N = 200;
  pc.Fx = 0.5;
  pc.Fy = -3.0;
  pc.k = 1e9;
  pc.surface = s;
  const Eigen::VectorXd phi = pc.solve(20);
  double x = 0, y = 0, cfx = 0, cfy = 0;
  pc.tip(phi, x, y);
  pc.energy(phi, 1.0, nullptr, &cfx, &cfy);
  EXPECT_NEAR(x, r.tip.x, 1e-4);
  EXPECT_NEAR(y, r.tip.y, 1e-4);
  EXPECT_NEAR(std::hypot(cfx, cfy), r.point_force_normal, 5e-3 * r.point_force_normal);
  // Refinement of the continuation.
  const ContactResult coarse =
      RigidContactSolver(options(3)).solve(cantilever(1.0, 1.0, 0.5, -3.0), s);
  ASSERT_TRUE(coarse.converged()) << coarse.message;
  EXPECT_NEAR(coarse.events.at(0).load_factor, r.events[0].load_factor, 1e-9);
  EXPECT_NEAR(coarse.separation_s.at(0), r.separation_s[0], 1e-9);
  EXPECT_NEAR(coarse.point_force_normal, r.point_force_normal, 1e-8);
}

TEST(RigidContactPoint, SmallLoadsMatchAPointSupportOfLinearTheory) {
  // A tiny pin (R = 1e-3 L) a gap d below x = a: linear theory with a point support there,
  // P = 3 [F a^2 (3L - a)/6 - EI d] / a^3; the tangency shifts the point by O(R slope).
  const double a = 0.6, d = 1e-4, F = 1e-3, R = 1e-3;
  RigidSurface s = circle(0.0, R);
  s.center = {a, -d - R};
  const ContactResult r = RigidContactSolver(options()).solve(cantilever(1.0, 1.0, 0.0, -F), s);
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_TRUE(r.in_contact);
  const double P = 3.0 * (F * a * a * (3.0 - a) / 6.0 - d) / (a * a * a);
  EXPECT_NEAR(r.point_force_normal, P, 2e-3 * P);
  EXPECT_NEAR(r.separation_s.at(0), a, 2e-3);
  // Landing: the free deflection at a reaches d.
  EXPECT_NEAR(r.events.at(0).load_factor * F, 6.0 * d / (a * a * (3.0 - a)), 2e-3 * F);
}

// ---- Seeded random cross-check -----------------------------------------------------------------

TEST(RigidContactRandom, BothSurfacesAgainstThePenaltyChainAndTheBalances) {
  std::mt19937 rng(29003);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int wraps = 0, tips = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const bool use_circle = trial % 2 == 0;
    const double sigma = u(rng) < 0.5 ? 1.0 : -1.0;
    RigidSurface s;
    double Fx = 0, Fy = 0;
    if (use_circle) {
      const double R = 0.4 + 1.6 * u(rng);
      s = circle(sigma * R, R);
      Fx = 2.0 * u(rng);  // a compressed wrap (Fx < 0) lifts off: outside the model
      Fy = sigma * (3.0 + 7.0 * u(rng));
    } else {
      s = line(0.0, -sigma * (0.1 + 0.4 * u(rng)), -0.4 + 0.8 * u(rng), sigma);
      Fx = -1.0 + 3.0 * u(rng);
      Fy = -sigma * (2.0 + 6.0 * u(rng));
    }
    const ContactResult r = RigidContactSolver(options()).solve(cantilever(1.0, 1.0, Fx, Fy), s);
    ASSERT_TRUE(r.converged()) << "trial " << trial << ": " << r.message;
    if (use_circle && r.in_contact) {
      expect_wrap_balances(r, s, 1.0);
      ++wraps;
    }
    if (!use_circle && r.in_contact) ++tips;
    PenaltyChain p;
    p.N = 100;
    p.Fx = Fx;
    p.Fy = Fy;
    p.k = 1e9;
    p.surface = s;
    const Eigen::VectorXd phi = p.solve(20);
    double x = 0, y = 0;
    p.tip(phi, x, y);
    EXPECT_NEAR(x, r.tip.x, 1e-4) << "trial " << trial;
    EXPECT_NEAR(y, r.tip.y, 1e-4) << "trial " << trial;
  }
  EXPECT_GE(wraps, 2);
  EXPECT_GE(tips, 2);
}

// ---- Several surfaces -------------------------------------------------------------------------

TEST(RigidContactSeveral, OneOfTwoSurfacesTouchedIsThatSurfacesSolution) {
  // A pin above the beam that it never reaches and a stop below that its tip lands on: the
  // two-surface solve is the stop's own solve (the same numbers), whichever order they are given.
  const SegmentChain c = cantilever(1.0, 1.0, 0.0, -5.0);
  RigidSurface pin = circle(0.3, 0.1);
  pin.center = {0.5, 0.3};
  const RigidSurface stop = line(0.0, -0.3, 0.0, 1.0);
  const ContactResult alone = RigidContactSolver(options()).solve(c, stop);
  ASSERT_TRUE(alone.converged()) << alone.message;
  for (int order = 0; order < 2; ++order) {
    const std::vector<RigidSurface> both =
        order == 0 ? std::vector<RigidSurface>{pin, stop} : std::vector<RigidSurface>{stop, pin};
    const ContactResult r = RigidContactSolver(options()).solve(c, both);
    ASSERT_TRUE(r.converged()) << r.message;
    EXPECT_EQ(r.surface_index, order == 0 ? 1 : 0);
    EXPECT_EQ(r.kind, ContactKind::kTip);
    EXPECT_EQ(r.tip.x, alone.tip.x);
    EXPECT_EQ(r.point_force_normal, alone.point_force_normal);
    EXPECT_EQ(r.reaction.M, alone.reaction.M);
    ASSERT_EQ(r.events.size(), 1u);
    EXPECT_EQ(r.events[0].load_factor, alone.events[0].load_factor);
  }
  // Neither touched: the free beam.
  const ContactResult none =
      RigidContactSolver(options()).solve(cantilever(1.0, 1.0, 0.0, -0.5), {pin, stop});
  ASSERT_TRUE(none.converged()) << none.message;
  EXPECT_FALSE(none.in_contact);
}

TEST(RigidContactSeveral, TwoSurfacesMetAreNamedNotAnswered) {
  // A pin under the span and a stop under the tip: the beam lands on the pin, slides off it and
  // meets the stop (or, followed on the stop, crosses the pin): not an answer, both named.
  const SegmentChain c = cantilever(1.0, 1.0, 0.0, -8.0);
  RigidSurface pin = circle(0.3, 0.1);
  pin.center = {0.6, -0.22};
  const ContactResult r = RigidContactSolver(options()).solve(c, {line(0.0, -0.3, 0.0, 1.0), pin});
  EXPECT_FALSE(r.converged());
  EXPECT_NE(r.message.find("contact 1"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("contact 2"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("several contacts at once"), std::string::npos) << r.message;
  EXPECT_THROW(RigidContactSolver(options()).solve(c, std::vector<RigidSurface>{}), InvalidInput);
  // A bad surface among several is refused like a bad one alone.
  EXPECT_THROW(RigidContactSolver(options()).solve(c, {line(0.0, 0.1, 0.0, 1.0), pin}),
               InvalidInput);
}

// ---- Refusals ----------------------------------------------------------------------------------

TEST(RigidContactRefusals, UnsupportedCombinationsSayWhy) {
  RigidContactSolver solver(options());
  const SegmentChain c = cantilever(1.0, 1.0, 0.0, 1.0);
  EXPECT_THROW(solver.solve(c, circle(0.3, 0.5)), InvalidInput);   // not tangent at the clamp
  EXPECT_THROW(solver.solve(c, circle(0.5, -0.5)), InvalidInput);  // negative radius
  SegmentChain guided = c;
  guided.tip_load = TipLoad{};
  guided.end = EndCondition::kGuided;
  EXPECT_THROW(solver.solve(guided, circle(1.0, 1.0)), InvalidInput);
  SegmentChain curved = c;
  std::get<FlexibleSegment>(curved.segments[0]).kappa0 = 0.1;
  EXPECT_THROW(solver.solve(curved, circle(1.0, 1.0)), InvalidInput);
  EXPECT_THROW(solver.solve(c, line(0.0, 0.1, 0.0, 1.0)), InvalidInput);  // clamp behind it
  try {
    solver.solve(c, circle(0.3, 0.5));
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("tangent"), std::string::npos) << e.what();
  }
}

TEST(RigidContactRefusals, AnEndMomentThatWrapsTheWholeSegmentIsNotAnAnswer) {
  // A pure moment 2 EI/R bends the beam tighter than the circle everywhere: no separation point.
  const ContactResult r =
      RigidContactSolver(options(4)).solve(cantilever(1.0, 1.0, 0.0, 0.0, 4.0), circle(0.5, 0.5));
  EXPECT_FALSE(r.converged());
  EXPECT_NE(r.message.find("separation point"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace flexure
