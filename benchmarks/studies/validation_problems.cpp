#include "flexure/benchmarks/studies/validation_problems.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace flexure {
namespace {

// The tabulated values (Howell §2.9.2 worked example, n = 0 table) carry 8 significant digits (n =
// 0 table, Howell example alpha2): half a unit in the last digit is at most 5e-8 relative for
// values >= 0.1, so 1e-7 can only fail on a real error.
constexpr double kEightDigits = 1e-7;
// The theta0 = 0.6 rad rows give 7 decimals; for b/l = 0.3767408 half a unit is 1.3e-7 relative.
constexpr double kSevenDecimals = 2e-7;
// Closed forms (end moment) need only the solver's own accuracy (tolerance 1e-14) plus rounding.
constexpr double kClosedForm = 1e-10;
// Inverse by deflection from the 7-digit b/l = 0.6103718: half a unit (5e-8) moves theta0 by
// d(theta0)/d(b/l) * 5e-8 ~ 1e-7 near theta0 = 1 (slope ~1.9 from the n = 0 table), so 5e-7.
constexpr double kFromSevenDigitDeflection = 5e-7;
// Small-load limit b/l = alpha2/3, theta0 = alpha2/2: the first nonlinear correction is relative
// O(alpha2^2) = 1e-8 at alpha2 = 1e-4 (elastica series), so 1e-7 leaves a margin of ten.
constexpr double kSmallLoad = 1e-7;

BeamProblem inverse_theta0(double n, double theta0) {
  BeamProblem p;
  p.given = BeamProblem::Given::kTheta0;
  p.value = theta0;
  p.load_ratio_n = n;
  return p;
}

BeamProblem forward_alpha2(double n, double alpha2, double mu = 0.0) {
  BeamProblem p;
  p.given = BeamProblem::Given::kAlpha2;
  p.value = alpha2;
  p.load_ratio_n = n;
  p.mu = mu;
  return p;
}

}  // namespace

std::vector<ReferenceProblem> reference_problems() {
  std::vector<ReferenceProblem> problems;
  const std::string howell = "Howell eqs. 2.90-2.98 by quadrature";

  // Howell §2.9.2 worked example, values recomputed to 8 digits.
  problems.push_back({"howell-example theta0=1 inverse",
                      howell + ", §2.9.2 worked example",
                      inverse_theta0(0.0, 1.0),
                      {{"alpha", 1.7569869, kEightDigits},
                       {"a_over_l", 0.7383564, kEightDigits},
                       {"b_over_l", 0.6103718, kEightDigits}}});
  problems.push_back({"howell-example alpha2=3.0870030 forward",
                      howell + ", §2.9.2 worked example",
                      forward_alpha2(0.0, 3.0870030),
                      {{"theta0", 1.0, kEightDigits},
                       {"a_over_l", 0.7383564, kEightDigits},
                       {"b_over_l", 0.6103718, kEightDigits}}});

  BeamProblem by_deflection;
  by_deflection.given = BeamProblem::Given::kBOverL;
  by_deflection.value = 0.6103718;
  problems.push_back({"howell-example b/l=0.6103718 inverse",
                      howell + ", §2.9.2 worked example",
                      by_deflection,
                      {{"theta0", 1.0, kFromSevenDigitDeflection},
                       {"alpha", 1.7569869, kFromSevenDigitDeflection},
                       {"a_over_l", 0.7383564, kFromSevenDigitDeflection}}});

  // n = 0 table (docs/validation.md): theta0, alpha2, a/l, b/l.
  struct Row {
    double theta0, alpha2, a_over_l, b_over_l;
  };
  constexpr Row kTable[] = {{0.25, 0.51169274, 0.98336262, 0.16572770},
                            {0.50, 1.0996750, 0.93377750, 0.32590739},
                            {0.75, 1.8779867, 0.85201234, 0.47544836},
                            {1.00, 3.0870030, 0.73835640, 0.61037180},
                            {1.25, 5.4691778, 0.58909259, 0.72947569},
                            {1.40, 8.8064153, 0.47307789, 0.79655336}};
  for (const Row& row : kTable) {
    problems.push_back({fmt::format("n=0 table theta0={:.2f} inverse", row.theta0),
                        howell + ", n = 0 table",
                        inverse_theta0(0.0, row.theta0),
                        {{"alpha2", row.alpha2, kEightDigits},
                         {"a_over_l", row.a_over_l, kEightDigits},
                         {"b_over_l", row.b_over_l, kEightDigits}}});
    problems.push_back({fmt::format("n=0 table alpha2={} forward", row.alpha2),
                        howell + ", n = 0 table",
                        forward_alpha2(0.0, row.alpha2),
                        {{"theta0", row.theta0, kEightDigits},
                         {"a_over_l", row.a_over_l, kEightDigits},
                         {"b_over_l", row.b_over_l, kEightDigits}}});
  }

  // theta0 = 0.6 rad with horizontal load components (Howell eqs. 2.90-2.98, n != 0).
  struct LoadRatioRow {
    double n, alpha, a_over_l, b_over_l;
  };
  constexpr LoadRatioRow kLoadRatios[] = {{1.0, 0.9439966, 0.9071300, 0.3809919},
                                          {-1.0, 1.7993680, 0.8975785, 0.4067666},
                                          {2.5, 0.7647424, 0.9086205, 0.3767408}};
  for (const LoadRatioRow& row : kLoadRatios) {
    problems.push_back({fmt::format("n={:g} theta0=0.6 inverse", row.n),
                        "Howell eqs. 2.90-2.98 by quadrature, theta0 = 0.6 rad rows",
                        inverse_theta0(row.n, 0.6),
                        {{"alpha", row.alpha, kSevenDecimals},
                         {"a_over_l", row.a_over_l, kSevenDecimals},
                         {"b_over_l", row.b_over_l, kSevenDecimals}}});
  }

  // Pure end moment: a circular arc, theta0 = mu (eq. 2.53), b/l = (1 - cos mu)/mu (eq. 2.59),
  // a/l = sin(mu)/mu (eq. 2.64). At mu = pi and 2 pi some lengths vanish (mu = 2 pi closes the
  // circle: the tip is back at the origin), so lengths are compared in units of l.
  const std::pair<const char*, double> kMoments[] = {
      {"1", 1.0}, {"pi", std::numbers::pi}, {"2pi", 2.0 * std::numbers::pi}};
  for (const auto& [label, mu] : kMoments) {
    problems.push_back({fmt::format("end-moment mu={} forward", label),
                        "Howell eqs. 2.53, 2.59, 2.64 (closed form)",
                        forward_alpha2(0.0, 0.0, mu),
                        {{"theta0", mu, kClosedForm},
                         {"a_over_l", std::sin(mu) / mu, kClosedForm, 1.0},
                         {"b_over_l", (1.0 - std::cos(mu)) / mu, kClosedForm, 1.0}}});
  }

  // Proportional-loading path under strong compression with an opposing end moment:
  // the elliptic solver once returned another equilibrium here (theta0 -2.57561, -2.27684,
  // -2.43979, -2.52651). The reference tip angles come from an independent continuation (SciPy
  // DOP853 at rtol 1e-12, 4000 proportional load steps from zero with Newton and fold detection;
  // docs/theory-elliptic.md, "Which equilibrium"), quoted to 5 decimals: half a unit, 5e-6, is at
  // most 1.8e-6 relative for |theta0| >= 2.7, so 2e-6.
  constexpr double kFiveDecimals = 2e-6;
  struct PathRow {
    double n, alpha2, mu, theta0;
  };
  constexpr PathRow kPathRows[] = {
      {14.735472838536637, 5.097255650846384, -4.885525980498873, -3.77864},
      {14.345999117253545, 2.939314167801687, -1.704399054643246, 2.79731},
      {15.0, 3.448426183511485, -3.5841092436926187, -3.70478},
      {10.058119179379627, 8.549908987101713, -6.283185307179586, -3.92930}};
  for (const PathRow& row : kPathRows) {
    ReferenceProblem problem{
        fmt::format("path n={:.4g} alpha2={:.3g} mu={:.3g} forward", row.n, row.alpha2, row.mu),
        "independent continuation (docs/theory-elliptic.md)",
        forward_alpha2(row.n, row.alpha2, row.mu),
        {{"theta0", row.theta0, kFiveDecimals}}};
    problem.exact_methods_only = true;
    problems.push_back(std::move(problem));
  }

  // Small-load limit: linear cantilever b = P l^3/(3 EI), theta0 = P l^2/(2 EI) (linear beam
  // theory).
  constexpr double kSmallAlpha2 = 1e-4;
  problems.push_back(
      {"small-load alpha2=1e-4 forward",
       "linear beam theory",
       forward_alpha2(0.0, kSmallAlpha2),
       {{"b_over_l", kSmallAlpha2 / 3.0, kSmallLoad}, {"theta0", kSmallAlpha2 / 2.0, kSmallLoad}}});
  return problems;
}

namespace {

// The reference checks compare tips, and the table's time per solve is the solver's: the
// stability verdict (tested on its own: docs/stability.md, "Validation") is left out.
BeamSolution solve_tips(BeamMethod method, BeamProblem problem) {
  problem.judge_stability = false;
  return solve_beam(method, problem);
}

}  // namespace

std::vector<ValidationMethod> validation_methods() {
  std::vector<ValidationMethod> methods;
  methods.push_back(
      {"elliptic",
       [](const ReferenceProblem&) { return true; },
       [](const BeamProblem& problem) { return solve_tips(BeamMethod::kElliptic, problem); },
       0.0,
       "exact"});
  // CVODES at rtol 1e-12: agrees with the elliptic solution to 1e-9 over a 175-case grid
  // (tests/solver/shooting_elliptic_grid_test.cpp).
  methods.push_back(
      {"shooting",
       [](const ReferenceProblem&) { return true; },
       [](const BeamProblem& problem) { return solve_tips(BeamMethod::kShooting, problem); },
       1e-8,
       "shooting vs elliptic grid test, 1e-9"});
  // Chain algorithm, corrected variant, N = 100: third-order discretisation error, 8.5e-7 at
  // alpha2 = 10 (docs/theory-chain.md); 1e-5 relative covers every reference load here.
  methods.push_back(
      {"chain",
       [](const ReferenceProblem& p) { return !p.exact_methods_only; },
       [](const BeamProblem& problem) { return solve_tips(BeamMethod::kChain, problem); },
       1e-5,
       "docs/theory-chain.md convergence table, N = 100"});
  return methods;
}

double quantity_value(const BeamSolution& solution, const std::string& quantity) {
  if (quantity == "alpha") return std::sqrt(solution.alpha2);
  if (quantity == "alpha2") return solution.alpha2;
  if (quantity == "a_over_l") return solution.tip.a_over_l;
  if (quantity == "b_over_l") return solution.tip.b_over_l;
  if (quantity == "theta0") return solution.tip.theta0;
  throw std::logic_error("unknown validation quantity " + quantity);
}

}  // namespace flexure
