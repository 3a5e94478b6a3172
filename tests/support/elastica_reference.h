#pragma once
// Independent reference for the tests: the elastica initial-value problem integrated numerically
// (classical RK4 with Richardson extrapolation), sharing no code with the closed-form solvers.
//   x' = cos theta, y' = sin theta, theta' = kappa0 + m, m' = Fx sin theta - Fy cos theta
// (moment balance of the segment [s, 1] under a dead tip force (Fx, Fy); l = 1, EI = 1; kappa0 the
// stress-free curvature of an initially curved beam, m the bending moment).
#include <array>
#include <cmath>

namespace flexure::testing {

struct ElasticaState {
  double x = 0.0, y = 0.0, theta = 0.0, m = 0.0;
};

inline ElasticaState integrate_elastica(
    double Fx, double Fy, double root_moment, int steps, double kappa0 = 0.0) {
  using V = std::array<double, 4>;
  auto rhs = [&](const V& v) {
    return V{
        std::cos(v[2]), std::sin(v[2]), kappa0 + v[3], Fx * std::sin(v[2]) - Fy * std::cos(v[2])};
  };
  V v{0.0, 0.0, 0.0, root_moment};
  const double h = 1.0 / steps;
  for (int i = 0; i < steps; ++i) {
    const V k1 = rhs(v);
    V t;
    for (int j = 0; j < 4; ++j) t[j] = v[j] + 0.5 * h * k1[j];
    const V k2 = rhs(t);
    for (int j = 0; j < 4; ++j) t[j] = v[j] + 0.5 * h * k2[j];
    const V k3 = rhs(t);
    for (int j = 0; j < 4; ++j) t[j] = v[j] + h * k3[j];
    const V k4 = rhs(t);
    for (int j = 0; j < 4; ++j) v[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
  }
  return {v[0], v[1], v[2], v[3]};
}

// Richardson extrapolation of two RK4 runs (error O(h^4) -> O(h^6)).
inline ElasticaState integrate_elastica_accurate(double Fx, double Fy, double root_moment) {
  constexpr int kSteps = 4000;
  const ElasticaState a = integrate_elastica(Fx, Fy, root_moment, kSteps);
  const ElasticaState b = integrate_elastica(Fx, Fy, root_moment, 2 * kSteps);
  auto r = [](double coarse, double fine) { return (16.0 * fine - coarse) / 15.0; };
  return {r(a.x, b.x), r(a.y, b.y), r(a.theta, b.theta), r(a.m, b.m)};
}

}  // namespace flexure::testing
