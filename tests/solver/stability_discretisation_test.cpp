// The discrete second variation's linear algebra and convergence (docs/stability.md):
//  * the bordered-matrix inertia formula (Haynsworth; Maddocks 1987), count = neg(A) - neg(S) -
//    zero(S), against the dense projection Z^T A Z onto a basis Z of the constraints' null space
//    (Eigen), on random shapes and loads for every end condition, also where A itself is singular;
//    and the Newton eigenvalues against the dense generalized eigenvalues of (Z^T Q Z, Z^T B Z);
//  * the convergence rate of the margin: O(h^2) on one grid (error ratio 4 per halving), O(h^4)
//    after Richardson's step (16), O(h^6) after Romberg's (64); against the closed form of a
//    guided column (1 - P / pi^2) and against the Jacobi method (jacobi_stability.h) on a bent
//    clamped-clamped equilibrium;
//  * the vocabulary's stable names (the JSON contract of the key `stability`).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

#include "flexure/solver/chain_model/jacobi_stability.h"
#include "flexure/solver/chain_model/second_variation.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/shooting_problem.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;

// A smooth random shape of a chain (positions from a random theta(s); no equilibrium needed for
// the algebra) at n equal elements per flexible segment.
std::vector<ShapePoint> random_shape(const SegmentChain& chain, int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double a = 1.5 * unit(rng), b = 2.0 * unit(rng), c = 0.7 * unit(rng);
  auto theta = [&](double s) { return a * s + b * s * s + c * std::sin(5.0 * s); };
  std::vector<ShapePoint> shape{ShapePoint{0.0, 0.0, 0.0, 0.0}};
  double s = 0.0, x = 0.0, y = 0.0, kink = 0.0;
  for (const Segment& segment : chain.segments) {
    if (const auto* f = std::get_if<FlexibleSegment>(&segment)) {
      for (int i = 1; i <= n; ++i) {
        // Midpoint-rule positions are exact enough: only the chords' directions matter here.
        const double h = f->length / n, mid = s + (i - 0.5) * h;
        x += h * std::cos(theta(mid) + kink);
        y += h * std::sin(theta(mid) + kink);
        shape.push_back(ShapePoint{s + i * h, x, y, theta(s + i * h) + kink});
      }
      s += f->length;
    } else {
      const auto& r = std::get<RigidSegment>(segment);
      kink += r.angle_offset;
      if (r.length > 0.0) {
        x += r.length * std::cos(theta(s) + kink);
        y += r.length * std::sin(theta(s) + kink);
        s += r.length;
        shape.push_back(ShapePoint{s, x, y, theta(s) + kink});
      }
    }
  }
  return shape;
}

struct Dense {
  Eigen::MatrixXd Q, B, Z;  // Q = B + W, Z orthonormal basis of ker C
};

Dense dense(const DiscreteSecondVariation& q) {
  const int n = q.size();
  Dense d;
  d.B = Eigen::MatrixXd::Zero(n, n);
  d.Q = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    d.B(i, i) = q.bending_diag[static_cast<std::size_t>(i)];
    if (i + 1 < n) d.B(i, i + 1) = d.B(i + 1, i) = q.bending_off[static_cast<std::size_t>(i)];
  }
  d.Q = d.B;
  for (int i = 0; i < n; ++i) d.Q(i, i) += q.axial[static_cast<std::size_t>(i)];
  const int m = static_cast<int>(q.constraints.size());
  if (m == 0) {
    d.Z = Eigen::MatrixXd::Identity(n, n);
  } else {
    Eigen::MatrixXd Ct(n, m);
    for (int a = 0; a < m; ++a) {
      for (int i = 0; i < n; ++i) Ct(i, a) = q.constraints[a][static_cast<std::size_t>(i)];
    }
    // The last n - m columns of the full Q factor of C^T span ker C.
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Ct);
    const Eigen::MatrixXd full = qr.householderQ() * Eigen::MatrixXd::Identity(n, n);
    d.Z = full.rightCols(n - m);
  }
  return d;
}

// Negative eigenvalues of Z^T (Q - lambda B) Z.
int dense_count(const Dense& d, double lambda) {
  const Eigen::MatrixXd A = d.Z.transpose() * (d.Q - lambda * d.B) * d.Z;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A, Eigen::EigenvaluesOnly);
  return static_cast<int>((eig.eigenvalues().array() < 0.0).count());
}

SegmentChain random_chain(EndCondition end, bool mixed, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  SegmentChain chain;
  if (mixed) {
    FlexibleSegment a;
    a.length = 0.5;
    a.EI_profile = {2.0, 1.0, 1.5};
    RigidSegment link;
    link.length = 0.4;
    link.angle_offset = 0.3;
    FlexibleSegment b;
    b.length = 0.6;
    b.EI = 0.7;
    chain.segments = {a, link, b};
    chain.node_loads.push_back(NodeLoad{1, 5.0 * unit(rng), 5.0 * unit(rng), 0.0});
  } else {
    chain = uniform_cantilever(EndLoad{});
  }
  chain.end = end;
  const PrescribedMask mask = prescribed_mask(end);
  if (!mask.x) chain.tip_load.Fx = 30.0 * unit(rng);
  if (!mask.y) chain.tip_load.Fy = 30.0 * unit(rng);
  return chain;
}

Reaction random_support(EndCondition end, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const PrescribedMask mask = prescribed_mask(end);
  return Reaction{mask.x ? 30.0 * unit(rng) : 0.0, mask.y ? 30.0 * unit(rng) : 0.0, 0.0};
}

TEST(StabilityInertia, BorderedFormulaEqualsDenseProjection) {
  std::mt19937_64 rng(2701u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0, constrained = 0, nonzero = 0;
  for (const EndCondition end : {EndCondition::kFree,
                                 EndCondition::kGuided,
                                 EndCondition::kPinned,
                                 EndCondition::kSlider,
                                 EndCondition::kFixed}) {
    for (const bool mixed : {false, true}) {
      for (int trial = 0; trial < 6; ++trial) {
        const SegmentChain chain = random_chain(end, mixed, rng);
        const Reaction support = random_support(end, rng);
        const std::vector<ShapePoint> shape = random_shape(chain, 12 + trial * 7, rng);
        const DiscreteSecondVariation q = discrete_second_variation(chain, support, shape);
        const Dense d = dense(q);
        constrained += q.constraints.empty() ? 0 : 1;
        for (int k = 0; k < 8; ++k) {
          const double lambda = 1.0 - std::pow(10.0, 3.0 * unit(rng) - 2.0);  // 1 - [0.01, 10]
          const int count = constrained_inertia(q, lambda).count;
          EXPECT_EQ(count, dense_count(d, lambda)) << to_string(end) << (mixed ? " mixed" : "")
                                                   << " trial " << trial << " lambda " << lambda;
          nonzero += count > 0 ? 1 : 0;
          ++checked;
        }
        // Where A(sigma) itself is singular (an unconstrained eigenvalue) the count still holds.
        const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> unconstrained(d.Q, d.B);
        const double at = unconstrained.eigenvalues()(0);
        if (at < 0.999) {
          const int expected = dense_count(d, at);
          const int count = constrained_inertia(q, at).count;
          // A constrained eigenvalue exactly there would make the expectation itself ambiguous.
          if (dense_count(d, at - 1e-9) == expected && dense_count(d, at + 1e-9) == expected) {
            EXPECT_EQ(count, expected) << to_string(end) << " at the unconstrained eigenvalue";
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 400);
  EXPECT_GT(constrained, 30);
  EXPECT_GT(nonzero, 100);
}

TEST(StabilityInertia, NewtonEigenvaluesEqualDenseEigenvalues) {
  std::mt19937_64 rng(2702u);
  int checked = 0;
  for (const EndCondition end :
       {EndCondition::kFree, EndCondition::kPinned, EndCondition::kFixed}) {
    for (int trial = 0; trial < 5; ++trial) {
      const SegmentChain chain = random_chain(end, trial % 2 == 1, rng);
      const Reaction support = random_support(end, rng);
      const DiscreteSecondVariation q =
          discrete_second_variation(chain, support, random_shape(chain, 24, rng));
      const Dense d = dense(q);
      const Eigen::MatrixXd Qz = d.Z.transpose() * d.Q * d.Z, Bz = d.Z.transpose() * d.B * d.Z;
      const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(Qz, Bz);
      for (int k = 1; k <= 3; ++k) {
        const double expected = eig.eigenvalues()(k - 1);
        const PencilEigenvalue e = constrained_eigenvalue(q, k, 1e-13);
        if (expected >= 1.0) {
          EXPECT_FALSE(e.exists);
          continue;
        }
        ASSERT_TRUE(e.exists);
        EXPECT_NEAR(e.value, expected, 1e-10 * std::max(1.0, std::fabs(expected)))
            << to_string(end) << " trial " << trial << " k " << k;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 25);
}

// Single-grid eigenvalues at n, 2n, 4n, ... elements and their Richardson and Romberg tables.
struct Table {
  std::vector<double> plain, richardson, romberg;
};
Table table(const std::vector<double>& plain) {
  Table t{plain, {}, {}};
  for (std::size_t i = 0; i + 1 < plain.size(); ++i) {
    t.richardson.push_back((4.0 * plain[i + 1] - plain[i]) / 3.0);
  }
  for (std::size_t i = 0; i + 1 < t.richardson.size(); ++i) {
    t.romberg.push_back((16.0 * t.richardson[i + 1] - t.richardson[i]) / 15.0);
  }
  return t;
}

// log2 of successive error ratios.
std::vector<double> orders(const std::vector<double>& values, double exact) {
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < values.size(); ++i) {
    out.push_back(std::log2(std::fabs(values[i] - exact) / std::fabs(values[i + 1] - exact)));
  }
  return out;
}

void print_orders(const char* what, const Table& t, double exact) {
  std::cout << what << ": observed orders (log2 of error ratios per halving of h)";
  for (const auto* row : {&t.plain, &t.richardson, &t.romberg}) {
    std::cout << "\n  ";
    for (double p : orders(*row, exact)) std::cout << p << " ";
    std::cout << "(last error " << row->back() - exact << ")";
  }
  std::cout << "\n";
}

TEST(StabilityConvergence, MarginOrdersOnAGuidedColumn) {
  // Guided column, P = 0.6 pi^2: margin exactly 0.4.
  SegmentChain chain = uniform_cantilever(EndLoad{-0.6 * kPi * kPi, 0.0, 0.0});
  chain.end = EndCondition::kGuided;
  std::vector<double> plain;
  for (int n = 8; n <= 128; n *= 2) {
    std::vector<ShapePoint> shape;
    for (int i = 0; i <= n; ++i) shape.push_back(ShapePoint{1.0 * i / n, 1.0 * i / n, 0.0, 0.0});
    const PencilEigenvalue e =
        constrained_eigenvalue(discrete_second_variation(chain, Reaction{}, shape), 1, 1e-15);
    plain.push_back(e.value);
  }
  const Table t = table(plain);
  print_orders("guided column", t, 0.4);
  for (double p : orders(t.plain, 0.4)) EXPECT_NEAR(p, 2.0, 0.05);
  for (double p : orders(t.richardson, 0.4)) EXPECT_NEAR(p, 4.0, 0.1);
  // Romberg's errors reach rounding (1e-13) at the finest grids: the first two ratios only.
  const std::vector<double> romberg = orders(t.romberg, 0.4);
  EXPECT_NEAR(romberg[0], 6.0, 0.3);
  EXPECT_NEAR(romberg[1], 6.0, 0.5);
}

TEST(StabilityConvergence, MarginOrdersOnABentClampedClampedBeam) {
  // The first-mode clamped-clamped equilibrium (tip at (0.9, 0.001), angle 0.01): the
  // reference margin from the Jacobi method (about 1e-10).
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = EndCondition::kFixed;
  chain.prescribed.x = 0.9;
  chain.prescribed.y = 0.001;
  chain.prescribed.theta = 0.01;
  const ShootingSolver::Options o;
  const ShootingResult r = ShootingSolver(o).solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  const double exact = JacobiSecondVariation(chain, r.reaction).eigenvalue(1);
  const ShootingProblem problem(chain, o.multiple_shooting);
  ElasticaIntegrator integrator(o.integrator_options());
  const Eigen::VectorXd z = Eigen::Map<const Eigen::VectorXd>(r.unknowns.data(), r.unknowns.size());
  const Reaction support = tip_support_reaction(chain, r.tip_load);
  std::vector<double> plain;
  for (int n = 16; n <= 256; n *= 2) {
    std::vector<double> s;
    for (int i = 0; i <= n; ++i) s.push_back(1.0 * i / n);
    TipState tip;
    std::string error;
    std::vector<ShapePoint> shape;
    ASSERT_TRUE(problem.integrate_solution(z, 1.0, integrator, tip, error, &s, &shape)) << error;
    plain.push_back(
        constrained_eigenvalue(discrete_second_variation(chain, support, shape), 1, 1e-15).value);
  }
  const Table t = table(plain);
  print_orders("bent clamped-clamped beam", t, exact);
  for (double p : orders(t.plain, exact)) EXPECT_NEAR(p, 2.0, 0.1);
  const std::vector<double> richardson = orders(t.richardson, exact);
  EXPECT_NEAR(richardson[0], 4.0, 0.3);
  EXPECT_NEAR(richardson[1], 4.0, 0.3);
  EXPECT_NEAR(orders(t.romberg, exact)[0], 6.0, 0.3);
  EXPECT_NEAR(t.romberg.back(), exact, 1e-10);
}

TEST(StabilityVocabulary, NamesAreTheContract) {
  EXPECT_EQ(stability_name(StabilityKind::kStable), "stable");
  EXPECT_EQ(stability_name(StabilityKind::kUnstable), "unstable");
  EXPECT_EQ(stability_name(StabilityKind::kCritical), "critical");
  EXPECT_EQ(stability_name(StabilityKind::kNotConservative), "not_conservative");
  EXPECT_EQ(stability_name(StabilityKind::kNotChecked), "not_checked");
  for (const StabilityKind kind : {StabilityKind::kStable,
                                   StabilityKind::kUnstable,
                                   StabilityKind::kCritical,
                                   StabilityKind::kNotConservative,
                                   StabilityKind::kNotChecked}) {
    EXPECT_EQ(stability_kind_from_name(stability_name(kind)), kind);
  }
  EXPECT_THROW(stability_kind_from_name("buckled"), InvalidInput);
  EXPECT_EQ(classify_stability(2, -0.5).kind, StabilityKind::kUnstable);
  EXPECT_EQ(classify_stability(0, 5e-7).kind, StabilityKind::kCritical);
  EXPECT_EQ(classify_stability(0, -5e-7).kind, StabilityKind::kCritical);
  EXPECT_EQ(classify_stability(0, 2e-6).kind, StabilityKind::kStable);
}

TEST(StabilityInput, FollowerForceAndBadInputs) {
  SegmentChain chain = uniform_cantilever(EndLoad{0.0, 1.0, 0.0});
  chain.tip_load.follower = 2.0;
  std::vector<ShapePoint> shape;
  for (int i = 0; i <= 32; ++i) shape.push_back(ShapePoint{i / 32.0, i / 32.0, 0.0, 0.0});
  const Stability v = equilibrium_stability(chain, Reaction{}, shape);
  EXPECT_EQ(v.kind, StabilityKind::kNotConservative);
  EXPECT_FALSE(v.judged());
  EXPECT_NE(v.message.find("follower"), std::string::npos) << v.message;
  chain.tip_load.follower = 0.0;
  // A reaction component conjugate to a free coordinate, a missing node, a shape not of the chain.
  EXPECT_THROW(equilibrium_stability(chain, Reaction{1.0, 0.0, 0.0}, shape), InvalidInput);
  std::vector<ShapePoint> short_shape(shape.begin(), shape.end() - 1);
  EXPECT_THROW(equilibrium_stability(chain, Reaction{}, short_shape), InvalidInput);
  std::vector<ShapePoint> stretched = shape;
  for (ShapePoint& p : stretched) p.x *= 1.5;
  EXPECT_THROW(equilibrium_stability(chain, Reaction{}, stretched), InvalidInput);
  StabilityOptions bad;
  bad.critical_tolerance = -1.0;
  EXPECT_THROW(equilibrium_stability(chain, Reaction{}, shape, bad), InvalidInput);
  // A chain of rigid links only cannot deflect.
  SegmentChain rigid;
  rigid.segments = {RigidSegment{1.0, 0.0}};
  EXPECT_EQ(equilibrium_stability(rigid, Reaction{}, shape).kind, StabilityKind::kNotChecked);
}

}  // namespace
}  // namespace flexure
