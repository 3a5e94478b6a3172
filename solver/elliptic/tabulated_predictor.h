#pragma once
// The tabulated predictor of the forward solve with an end moment (docs/theory-elliptic.md,
// "Tabulated predictor"): on the goal domain of issue 14 (n in [-5, 10], |alpha2| <= 20,
// |mu| <= 2 pi) the proportional-loading equilibrium is looked up in a table made by the
// continuation (load_continuation.h) and settled by a guarded Newton iteration, instead of
// following the path from the unloaded beam every time.
//
// The grid. Loads are taken after mirroring (Fy > 0): n = -Fx/Fy, alpha2 = Fy. Mirroring turns a
// load with alpha2 < 0 and ratio n into one with -n, so the goal domain becomes n in [-10, 10],
// alpha2 in (0, 20], |mu| <= 2 pi, which the table covers. The point (alpha2/20, mu/(2 pi)) of the
// box [0, 1] x [-1, 1] is written as rho times a point of the box's boundary: rho, its L-infinity
// norm, is the load factor, and sigma in [0, 4] the direction (0: the corner alpha2 = 0,
// mu = -2 pi; 1: alpha2 = 20, mu = -2 pi; 2: alpha2 = 20, mu = 0; 3: alpha2 = 20, mu = 2 pi;
// 4: alpha2 = 0, mu = 2 pi; linear along each side). Proportional loading of a load
// is then the segment from rho = 0 at fixed (n, sigma): a grid line. The table has one row per node
// of a uniform grid in (n, sigma, rho); each row holds the proportional-loading solution at the
// node (its tip state in all three chart coordinates of tip_chart.h and the folds passed on the
// way) and the verdict on the cell of which the node is the lowest corner.
//
// The verdict is made when the table is generated (solver/elliptic/tools/make_predictor_table.cpp,
// run by the build): a cell is handed to the continuation if the path to any corner or to any of
// 27 interior loads passes a fold or fails, or if at those 27 loads the guarded Newton below,
// started from the trilinear interpolation of the corners in one chart, does not return the
// continuation's equilibrium on every one. Otherwise the cell gets that chart and a trust radius:
// twice the largest distance of those 27 interpolated guesses from the continuation's solutions,
// plus 1e-3 (at most 1).
//
// The guard at run time (guarded_newton): the root is accepted only if the iteration converges
// within kMaxNewtonSteps steps, each at most half the previous one, every iterate stays within the
// cell's trust radius of the interpolated guess, and the slope keeps the orientation the path has
// at an equilibrium reached without a fold (chart orientation times dg/dx > 0: consecutive simple
// roots of g alternate in that sign, so the neighbouring roots are excluded). Anything else, and
// every load outside the goal domain, goes to the continuation, unchanged.
#include <cstdint>
#include <numbers>
#include <span>

#include "flexure/solver/elliptic/elastica_closed_form.h"
#include "flexure/solver/elliptic/tip_chart.h"

namespace flexure::elliptic {

struct PredictorGrid {
  // The goal domain (after mirroring, Fy > 0).
  static constexpr double kMinN = -10.0;
  static constexpr double kMaxN = 10.0;
  static constexpr double kMaxAlpha2 = 20.0;
  static constexpr double kMaxMu = 2.0 * std::numbers::pi;
  // Nodes per axis (uniform): n, sigma, rho.
  static constexpr int kNodesN = 41;
  static constexpr int kNodesSigma = 41;
  static constexpr int kNodesRho = 21;
  static constexpr int kNodes = kNodesN * kNodesSigma * kNodesRho;

  // Row of node (i, j, k): rho fastest, then sigma, then n.
  static constexpr int index(int i, int j, int k) { return (i * kNodesSigma + j) * kNodesRho + k; }
  // Coordinates at fractional node indices.
  static double n_at(double i) { return kMinN + (kMaxN - kMinN) * i / (kNodesN - 1); }
  static double sigma_at(double j) { return 4.0 * j / (kNodesSigma - 1); }
  static double rho_at(double k) { return k / (kNodesRho - 1); }

  // The load (n, alpha2 >= 0, mu) at fractional node indices.
  struct Load {
    double n = 0.0;
    double alpha2 = 0.0;
    double mu = 0.0;
  };
  static Load load_at(double i, double j, double k);
};

// A load's place in the grid: the cell (i, j, k) (its lowest corner) and the position in it.
struct GridPoint {
  int i = 0, j = 0, k = 0;
  double ti = 0.0, tj = 0.0, tk = 0.0;  // in [0, 1]
};
// False outside the goal domain: Fy <= 0, n = -Fx/Fy outside [-5, 10], Fy > 20, |mu| > 2 pi or
// mu = 0 (all of these are left to the other paths of the solver).
bool locate_in_grid(double Fx, double Fy, double mu, GridPoint& at);

// One row of the table.
struct PredictorRow {
  float n = 0.0f, sigma = 0.0f, rho = 0.0f;  // the node (checked against the grid)
  float t = 0.0f;                            // theta0 - psi: the angle chart's coordinate
  float x_saddle = 0.0f;         // the saddle chart's, asinh(tau/eps); NaN where undefined (F = 0)
  float x_separatrix = 0.0f;     // the separatrix chart's, asinh(w/eps_s); NaN where undefined
  float cell_radius = 0.0f;      // the cell's trust radius, in its chart's coordinate
  std::int8_t winding = 0;       // t = 2 pi winding + tau
  std::int8_t side = 1;          // sign of tau (+1 for tau = 0)
  std::int8_t limit_points = 0;  // folds passed on the path to the node; kNodeFailed if unsolved
  std::int8_t cell_chart = -1;   // kCellContinuation, or the TipChart::Kind of the cell's Newton
};
inline constexpr std::int8_t kCellContinuation = -1;
inline constexpr std::int8_t kNodeFailed = 127;

// The table compiled into the library (generated by the build from make_predictor_table's CSV).
std::span<const PredictorRow> predictor_table();

// The node's solution in `chart`; NaN where it is not in that chart (another winding or side of
// the separatrix) or the chart is undefined there.
double node_coordinate(const PredictorRow& row, const TipChart& chart);

// The cell's chart (from its lowest corner's row: kind, and that corner's winding and side).
TipChart cell_chart_of(const PredictorRow& row);

// Trilinear interpolation in `chart` of the cell's eight corners; NaN if a corner is not in it.
double interpolate_in_chart(std::span<const PredictorRow> table,
                            const GridPoint& at,
                            const TipChart& chart);

inline constexpr int kMaxNewtonSteps = 8;

struct GuardedNewton {
  bool accepted = false;
  double x = 0.0;                 // root, in the chart
  TipState tip;                   // its tip state
  ElasticaParameters parameters;  // the closed form through it (integrate_from_tip)
  double residual = 0.0;          // |g| at the root (the full-precision residual)
  double slope = 0.0;             // dg/dx there (secant)
  int evaluations = 0;            // residual evaluations
};

// Newton's method on the full-load residual g(x) = chi(0) - chi0 in `chart`, from x0: a first step
// with a forward-difference slope, then secant steps, on the residual by the addition theorem until
// a step is below 1e-9 max(1, |x|), then Newton steps on the full-precision residual until the
// correction is below x_tolerance (relative), as the continuation polishes its last point.
// Accepted only under the guard above; `radius` is the trust radius around x0.
GuardedNewton guarded_newton(const PendulumProblem& problem,
                             const TipChart& chart,
                             double x0,
                             double radius,
                             double x_tolerance);

// The whole fast path for a mirrored load (Fy > 0) and its pendulum problem: locate it, read its
// cell's verdict, interpolate, and run the guarded Newton. `accepted` is false when the
// continuation must answer (outside the domain, a cell left to it, or a root the guard refuses).
GuardedNewton solve_with_predictor(std::span<const PredictorRow> table,
                                   double Fx,
                                   double Fy,
                                   double mu,
                                   const PendulumProblem& problem,
                                   double x_tolerance);

}  // namespace flexure::elliptic
