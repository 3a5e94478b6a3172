#pragma once
// Shared by the cross-checks of the fast cantilever verdicts against the general one
// (tests/solver/tension_stability_test.cpp, tests/solver/compressed_cantilever_stability_test.cpp):
// seeded families of dead tip loads on the uniform cantilever, with and without limit points on
// their proportional path, and the other equilibria of some of them.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure::test {

// The shooting settings of both cross-checks: inflections counted, which records
// ShootingResult::largest_curvature, as solve_beam does.
inline ShootingSolver::Options fast_verdict_solve_options() {
  ShootingSolver::Options o;
  o.count_inflections = true;
  return o;
}

// A load in full precision, for failure messages.
inline std::string describe(const EndLoad& load) {
  std::ostringstream out;
  out.precision(17);
  out << "Fx = " << load.Fx << ", Fy = " << load.Fy << ", mu = " << load.mu;
  return out.str();
}

// The general verdict of a free cantilever's shooting solution (no support reaction).
inline Stability general_verdict(const SegmentChain& chain, const ShootingResult& r) {
  return equilibrium_stability(chain, Reaction{}, [&](const std::vector<double>& s) {
    return shooting_shape_at(chain, r, s);
  });
}

// How many loads of each family, and the range of Howell's n (Fx = -n alpha2, Fy = alpha2).
struct CantileverLoadFamilies {
  int any_direction = 120;  // |F| up to 40 (past the second Euler load, 22.2), any direction
  int howell = 120;         // n in [n_min, n_max], alpha2 in [0.1, 20.1], an end moment in some
  double howell_n_min = -5.0, howell_n_max = 10.0;
  double howell_without_moment = 0.3;  // the fraction of Howell's loads with mu = 0
  int near_straight = 30;          // columns up to P = 70 (past the Euler loads 2.47, 22.2, 61.7)
  int straight = 15;               // exactly straight columns up to P = 70
  int folding = 8;                 // loads whose proportional path passes limit points
  int with_other_equilibria = 25;  // loads whose other equilibria are sought
};

// Calls `proportional(load)` for every load of the families and `other(load, m0)` for the Newton
// starts m0 = -12, -9, ..., 12 (root moments) of the loads whose other equilibria are sought.
// Expects the requested number of folding loads to be found.
inline void for_each_cantilever_load(std::mt19937_64& rng,
                                     const CantileverLoadFamilies& f,
                                     const std::function<void(const EndLoad&)>& proportional,
                                     const std::function<void(const EndLoad&, double m0)>& other) {
  constexpr double kPi = std::numbers::pi;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < f.any_direction; ++i) {
    const double P = 40.0 * unit(rng), psi = 2.0 * kPi * unit(rng);
    const double mu = unit(rng) < 0.5 ? 0.0 : 6.0 * (unit(rng) - 0.5);
    proportional(EndLoad{P * std::cos(psi), P * std::sin(psi), mu});
  }
  for (int i = 0; i < f.howell; ++i) {
    const double n = f.howell_n_min + (f.howell_n_max - f.howell_n_min) * unit(rng);
    const double alpha2 = 0.1 + 20.0 * unit(rng);
    const double mu = unit(rng) < f.howell_without_moment ? 0.0 : -8.0 + 16.0 * unit(rng);
    proportional(EndLoad{-n * alpha2, alpha2, mu});
  }
  for (int i = 0; i < f.near_straight; ++i) {
    const double P = 70.0 * unit(rng);
    proportional(EndLoad{-P, 1e-3 * P * (unit(rng) - 0.5), 0.0});
  }
  for (int i = 0; i < f.straight; ++i) proportional(EndLoad{-70.0 * unit(rng), 0.0, 0.0});
  // About 1 in 200 loads of this region folds; the elliptic solver's count picks them.
  int folding = 0;
  for (int attempt = 0; attempt < 20000 && folding < f.folding; ++attempt) {
    const EndLoad load = EndLoad::howell(
        -8.0 + 23.0 * unit(rng), 60.0 * unit(rng), (2.0 * unit(rng) - 1.0) * 2.0 * kPi);
    if (EllipticSolver().solve(load).limit_points < 1) continue;
    ++folding;
    proportional(load);
  }
  EXPECT_EQ(folding, f.folding);
  for (int i = 0; i < f.with_other_equilibria; ++i) {
    const EndLoad load = EndLoad::howell(-4.0 + 12.0 * unit(rng),
                                         2.0 + 18.0 * unit(rng),
                                         unit(rng) < 0.5 ? 0.0 : 4.0 * unit(rng) - 2.0);
    for (int k = -4; k <= 4; ++k) other(load, 3.0 * k);
  }
}

}  // namespace flexure::test
