// Generates the table of the elliptic solver's tabulated predictor (tabulated_predictor.h) and its
// compiled form. Run by the build (solver/CMakeLists.txt):
//
//   flexure_make_predictor_table --csv FILE.csv --cpp FILE.cpp [--threads N]
//
// 1. Every node of the grid is solved by the continuation the solver itself uses
//    (solve_by_continuation, tolerance 1e-14 as EllipticSolver's default): its tip state in the
//    three chart coordinates, and the folds passed on the way. Nodes without force (rho = 0, or
//    alpha2 = 0 on the sides sigma = 0 and 4) are the unloaded beam and the circular arc, theta0 =
//    mu.
// 2. Every cell is verified: if a corner's path passes a fold or failed, the cell goes to the
//    continuation. Otherwise 27 interior loads (at 1/6, 1/2, 5/6 of each side) are solved by the
//    continuation; if any passes a fold the cell goes to the continuation. Then each candidate
//    chart (the corners' own charts, preferred_chart from the angle chart, then the angle chart) is
//    tried: the trilinear interpolation of the corners (as stored, in float) gives each of the 27 a
//    guess, the trust radius is twice the largest distance of a guess from the continuation's
//    solution plus 1e-3 (at most kMaxRadius), and guarded_newton, exactly as the solver runs it,
//    must accept a root equal to the continuation's on all 27 (1e-8 in the chart coordinate, 1e-11
//    in the tip angle). The first chart that passes is the cell's; if none does, the cell goes to
//    the continuation.
// 3. The CSV (named columns, provenance in its comments) and a C++ source holding the same rows as
//    an array of PredictorRow are written; tests/solver/elliptic_predictor_test.cpp checks that the
//    two agree.
// Cells are independent, and each is done by one thread into its own row, so the output does not
// depend on the number of threads.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "flexure/solver/common/end_load.h"
#include "flexure/solver/elliptic/load_continuation.h"
#include "flexure/solver/elliptic/tabulated_predictor.h"
#include "flexure/version.h"

namespace {

using namespace flexure;
using namespace flexure::elliptic;
using G = PredictorGrid;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kTolerance = 1e-14;  // EllipticSolver::Options::tolerance's default
constexpr double kRadiusFloor = 1e-3;
constexpr double kMaxRadius = 1.0;
constexpr double kSamePoint = 1e-8;      // chart coordinate, times max(1, |x|)
constexpr double kSameTipAngle = 1e-11;  // rad
constexpr double kSamples[3] = {1.0 / 6.0, 0.5, 5.0 / 6.0};

// A load as the solver sees it after mirroring (Fy >= 0), and its pendulum problem.
struct Problem {
  double Fx = 0.0, Fy = 0.0, mu = 0.0;
  double force = 0.0, psi = 0.0;
  PendulumProblem pendulum;
};
Problem problem_at(double i, double j, double k) {
  const G::Load l = G::load_at(i, j, k);
  const EndLoad load = EndLoad::howell(l.n, l.alpha2, l.mu);
  Problem p;
  p.Fx = load.Fx;
  p.Fy = load.Fy;
  p.mu = load.mu;
  p.force = std::hypot(load.Fx, load.Fy);
  // The force angle of a load with Fy > 0; for Fy = 0 (no force) the one of the grid line's n.
  p.psi = load.Fy > 0.0 ? std::atan2(load.Fy, load.Fx) : std::atan2(1.0, -l.n);
  p.pendulum = make_pendulum_problem(p.force, p.psi, p.mu);
  return p;
}

struct Solved {
  bool ok = false;
  int limit_points = 0;
  TipState tip;
};
Solved continuation(const Problem& p) {
  ContinuationOptions options;
  options.x_tolerance = kTolerance;
  const ContinuationSolution c = solve_by_continuation(p.force, p.psi, p.mu, options);
  return {c.converged(), c.limit_points, c.tip};
}

// The coordinate of a tip state in a chart; NaN where it is not in it.
double chart_coordinate(const Problem& p, const TipState& tip, const TipChart& chart) {
  const int side = tip.tau >= 0.0 ? 1 : -1;
  switch (chart.kind) {
    case TipChart::Kind::kAngle:
      return tip.t();
    case TipChart::Kind::kSaddle:
      return tip.winding == chart.winding ? std::asinh(tip.tau / separatrix_scale(p.force)) : kNaN;
    case TipChart::Kind::kSeparatrix:
      return tip.winding == chart.winding && side == chart.side
                 ? std::asinh(tip.h_minus / p.force / separatrix_chart_scale(p.pendulum))
                 : kNaN;
  }
  return kNaN;
}

struct Node {
  bool loaded = false;  // F > 0 (else the tip state below is not used for charts)
  TipState tip;
  Problem problem;
};

void solve_node(int i, int j, int k, PredictorRow& row, Node& node) {
  const Problem p = problem_at(i, j, k);
  row.n = static_cast<float>(G::n_at(i));
  row.sigma = static_cast<float>(G::sigma_at(j));
  row.rho = static_cast<float>(G::rho_at(k));
  row.cell_chart = kCellContinuation;
  row.cell_radius = 0.0f;
  node.problem = p;
  double t = 0.0;
  if (p.force == 0.0) {
    // The unloaded beam (rho = 0) or a pure end moment: the circular arc, theta0 = mu.
    t = p.mu - p.psi;
    row.x_saddle = row.x_separatrix = static_cast<float>(kNaN);
  } else {
    const Solved s = continuation(p);
    if (!s.ok) {
      row.limit_points = kNodeFailed;
      row.t = row.x_saddle = row.x_separatrix = static_cast<float>(kNaN);
      return;
    }
    node.loaded = true;
    node.tip = s.tip;
    row.limit_points = static_cast<std::int8_t>(std::min(s.limit_points, 100));
    t = s.tip.t();
    TipChart saddle, separatrix;
    saddle.kind = TipChart::Kind::kSaddle;
    saddle.winding = s.tip.winding;
    separatrix.kind = TipChart::Kind::kSeparatrix;
    separatrix.winding = s.tip.winding;
    separatrix.side = s.tip.tau >= 0.0 ? 1 : -1;
    row.x_saddle = static_cast<float>(chart_coordinate(p, s.tip, saddle));
    row.x_separatrix = static_cast<float>(chart_coordinate(p, s.tip, separatrix));
  }
  const TipState tip = tip_state_from_angle(p.pendulum, t);
  row.t = static_cast<float>(t);
  row.winding = static_cast<std::int8_t>(node.loaded ? node.tip.winding : tip.winding);
  row.side = static_cast<std::int8_t>((node.loaded ? node.tip.tau : tip.tau) >= 0.0 ? 1 : -1);
}

enum class Verdict { kAngle, kSaddle, kSeparatrix, kFoldCorner, kFoldInside, kNoChart };

struct Sample {
  Problem problem;
  GridPoint at;
  TipState tip;  // the continuation's solution
};

bool same_chart(const TipChart& a, const TipChart& b) {
  return a.kind == b.kind && a.winding == b.winding && a.side == b.side;
}

// Tries `chart` on the cell's samples; on success writes the verdict into `row`.
bool verify_chart(const std::vector<PredictorRow>& rows,
                  const std::vector<Sample>& samples,
                  const TipChart& chart,
                  PredictorRow& row) {
  std::vector<double> guess(samples.size()), truth(samples.size());
  double worst = 0.0;
  for (std::size_t s = 0; s < samples.size(); ++s) {
    guess[s] = interpolate_in_chart(rows, samples[s].at, chart);
    truth[s] = chart_coordinate(samples[s].problem, samples[s].tip, chart);
    if (!std::isfinite(guess[s]) || !std::isfinite(truth[s])) return false;
    worst = std::max(worst, std::fabs(guess[s] - truth[s]));
  }
  // Rounded up to the float that is stored.
  const float radius = std::nextafter(static_cast<float>(2.0 * worst + kRadiusFloor), HUGE_VALF);
  if (!(radius <= kMaxRadius)) return false;
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const GuardedNewton fast =
        guarded_newton(samples[s].problem.pendulum, chart, guess[s], radius, kTolerance);
    if (!fast.accepted ||
        !(std::fabs(fast.x - truth[s]) <= kSamePoint * std::max(1.0, std::fabs(truth[s]))) ||
        !(std::fabs(fast.tip.t() - samples[s].tip.t()) <= kSameTipAngle)) {
      return false;
    }
  }
  row.cell_chart = static_cast<std::int8_t>(chart.kind);
  row.cell_radius = radius;
  return true;
}

Verdict verify_cell(
    int i, int j, int k, std::vector<PredictorRow>& rows, const std::vector<Node>& nodes) {
  std::vector<TipChart> candidates;
  for (int corner = 0; corner < 8; ++corner) {
    const int index = G::index(i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1));
    const PredictorRow& r = rows[static_cast<std::size_t>(index)];
    if (r.limit_points != 0) return Verdict::kFoldCorner;
    const Node& n = nodes[static_cast<std::size_t>(index)];
    if (!n.loaded) continue;
    const TipChart preferred = preferred_chart(n.problem.pendulum, TipChart{}, n.tip).chart;
    if (preferred.kind == TipChart::Kind::kAngle) continue;
    if (std::none_of(candidates.begin(), candidates.end(), [&](const TipChart& c) {
          return same_chart(c, preferred);
        })) {
      candidates.push_back(preferred);
    }
  }
  candidates.push_back(TipChart{});
  std::vector<Sample> samples;
  for (double a : kSamples) {
    for (double b : kSamples) {
      for (double c : kSamples) {
        Sample s;
        s.problem = problem_at(i + a, j + b, k + c);
        if (!locate_in_grid(s.problem.Fx, s.problem.Fy, s.problem.mu, s.at) || s.at.i != i ||
            s.at.j != j || s.at.k != k) {
          return Verdict::kNoChart;  // not expected: the samples lie inside the cell
        }
        const Solved solved = continuation(s.problem);
        if (!solved.ok || solved.limit_points != 0) return Verdict::kFoldInside;
        s.tip = solved.tip;
        samples.push_back(s);
      }
    }
  }
  PredictorRow& row = rows[static_cast<std::size_t>(G::index(i, j, k))];
  for (const TipChart& chart : candidates) {
    // The stored chart of a cell has its lowest corner's winding and side (cell_chart_of), so a
    // chart of another winding (or, for the separatrix chart, side) cannot be the cell's; it
    // would not hold that corner anyway.
    TipChart c = chart;
    c.winding = row.winding;
    c.side = row.side;
    const bool holds_lowest_corner =
        c.kind == TipChart::Kind::kAngle ||
        (c.winding == chart.winding && (c.kind == TipChart::Kind::kSaddle || c.side == chart.side));
    if (holds_lowest_corner) {
      if (verify_chart(rows, samples, c, row)) {
        return c.kind == TipChart::Kind::kAngle    ? Verdict::kAngle
               : c.kind == TipChart::Kind::kSaddle ? Verdict::kSaddle
                                                   : Verdict::kSeparatrix;
      }
    }
  }
  return Verdict::kNoChart;
}

// Runs f(0 .. count - 1) on `threads` threads.
template <class F>
void parallel_for(int count, int threads, F f) {
  std::atomic<int> next{0};
  auto work = [&] {
    for (int item = next++; item < count; item = next++) f(item);
  };
  std::vector<std::thread> helpers;
  for (int t = 1; t < threads; ++t) helpers.emplace_back(work);
  work();
  for (std::thread& h : helpers) h.join();
}

std::string cell(double v) {
  if (!std::isfinite(v)) return "-";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", v);
  return buffer;
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv_path, cpp_path;
  int threads = 2;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--csv" && a + 1 < argc) {
      csv_path = argv[++a];
    } else if (arg == "--cpp" && a + 1 < argc) {
      cpp_path = argv[++a];
    } else if (arg == "--threads" && a + 1 < argc) {
      threads = std::max(1, std::atoi(argv[++a]));
    } else {
      std::fprintf(stderr, "usage: %s --csv FILE.csv --cpp FILE.cpp [--threads N]\n", argv[0]);
      return 2;
    }
  }
  if (csv_path.empty() || cpp_path.empty()) {
    std::fprintf(stderr, "usage: %s --csv FILE.csv --cpp FILE.cpp [--threads N]\n", argv[0]);
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<PredictorRow> rows(G::kNodes);
  std::vector<Node> nodes(G::kNodes);
  parallel_for(G::kNodes, threads, [&](int index) {
    const int k = index % G::kNodesRho;
    const int j = (index / G::kNodesRho) % G::kNodesSigma;
    const int i = index / (G::kNodesRho * G::kNodesSigma);
    solve_node(
        i, j, k, rows[static_cast<std::size_t>(index)], nodes[static_cast<std::size_t>(index)]);
  });
  const int cells = (G::kNodesN - 1) * (G::kNodesSigma - 1) * (G::kNodesRho - 1);
  std::vector<Verdict> verdicts(static_cast<std::size_t>(cells));
  parallel_for(cells, threads, [&](int c) {
    const int k = c % (G::kNodesRho - 1);
    const int j = (c / (G::kNodesRho - 1)) % (G::kNodesSigma - 1);
    const int i = c / ((G::kNodesRho - 1) * (G::kNodesSigma - 1));
    verdicts[static_cast<std::size_t>(c)] = verify_cell(i, j, k, rows, nodes);
  });
  int count[6] = {0, 0, 0, 0, 0, 0};
  for (Verdict v : verdicts) ++count[static_cast<int>(v)];
  int failed_nodes = 0;
  for (const PredictorRow& r : rows) failed_nodes += r.limit_points == kNodeFailed ? 1 : 0;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::FILE* csv = std::fopen(csv_path.c_str(), "w");
  if (csv == nullptr) {
    std::perror(csv_path.c_str());
    return 1;
  }
  std::fprintf(
      csv,
      "# Tabulated predictor of the elliptic solver with an end moment "
      "(solver/elliptic/tabulated_predictor.h, docs/theory-elliptic.md).\n"
      "# Generated at build time by flexure_make_predictor_table "
      "(solver/elliptic/tools/make_predictor_table.cpp), flexure %s, commit %s:\n"
      "# every node solved by the continuation of solver/elliptic/load_continuation.cpp "
      "(tolerance 1e-14), every cell verified against it at 27 interior loads.\n"
      "# Grid (uniform): n in [%g, %g], %d nodes; sigma in [0, 4], %d nodes; rho in [0, "
      "1], %d nodes;\n"
      "#   alpha2 = %g rho a(sigma), mu = 2 pi rho m(sigma), (a, m) = (sigma, -1), (1, "
      "sigma - 2), (4 - sigma, 1) on [0, 1], [1, 3], [3, 4].\n"
      "# Cells: %d; Newton in the angle chart %d, saddle chart %d, separatrix chart %d; "
      "continuation: a fold at a corner %d, inside %d, no chart verified %d.\n"
      "# Nodes whose continuation failed: %d.\n"
      "# One row per node, rho fastest, then sigma, then n. Columns (dimensionless, angles "
      "in rad):\n"
      "#   n, sigma, rho   the node\n"
      "#   limit_points    folds on the proportional-loading path to the node (127: the "
      "continuation failed)\n"
      "#   winding, side   t = 2 pi winding + tau, |tau| <= pi; side = sign of tau (+1 "
      "for 0)\n"
      "#   t               theta0 - psi, psi = atan2(1, -n) the force angle\n"
      "#   x_saddle        asinh(tau/eps), eps = exp(-sqrt F)/2 (- without force)\n"
      "#   x_separatrix    asinh(w/eps_s), w = (F - H)/(2F), eps_s = eps d/(1 + d), d = "
      "|mu|/sqrt(F) (- without force)\n"
      "#   cell_chart      the cell with this node as its lowest corner: -1 "
      "continuation, 0 angle, 1 saddle, 2 separatrix chart\n"
      "#   cell_radius     its trust radius in that chart's coordinate (- for -1)\n"
      "n,sigma,rho,limit_points,winding,side,t,x_saddle,x_separatrix,cell_chart,cell_"
      "radius\n",
      kVersion,
      kGitCommit,
      G::kMinN,
      G::kMaxN,
      G::kNodesN,
      G::kNodesSigma,
      G::kNodesRho,
      G::kMaxAlpha2,
      cells,
      count[0],
      count[1],
      count[2],
      count[3],
      count[4],
      count[5],
      failed_nodes);
  for (const PredictorRow& r : rows) {
    std::fprintf(csv,
                 "%s,%s,%s,%d,%d,%d,%s,%s,%s,%d,%s\n",
                 cell(r.n).c_str(),
                 cell(r.sigma).c_str(),
                 cell(r.rho).c_str(),
                 r.limit_points,
                 r.winding,
                 r.side,
                 cell(r.t).c_str(),
                 cell(r.x_saddle).c_str(),
                 cell(r.x_separatrix).c_str(),
                 r.cell_chart,
                 r.cell_chart == kCellContinuation ? "-" : cell(r.cell_radius).c_str());
  }
  if (std::fclose(csv) != 0) {
    std::perror(csv_path.c_str());
    return 1;
  }

  std::FILE* cpp = std::fopen(cpp_path.c_str(), "w");
  if (cpp == nullptr) {
    std::perror(cpp_path.c_str());
    return 1;
  }
  std::fprintf(cpp,
               "// Generated by flexure_make_predictor_table "
               "(solver/elliptic/tools/make_predictor_table.cpp)\n"
               "// with the same rows as %s; edit the generator, not this file.\n"
               "#include <limits>\n\n"
               "#include \"flexure/solver/elliptic/tabulated_predictor.h\"\n\n"
               "namespace flexure::elliptic {\n"
               "namespace {\n\n"
               "constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();\n\n"
               "// n, sigma, rho, t, x_saddle, x_separatrix, cell_radius, winding, side, "
               "limit_points, cell_chart\n"
               "constexpr PredictorRow kRows[] = {\n",
               csv_path.c_str());
  auto literal = [](double v) { return std::isfinite(v) ? cell(v) : std::string("kNaN"); };
  for (const PredictorRow& r : rows) {
    std::fprintf(cpp,
                 "    {%s, %s, %s, %s, %s, %s, %s, %d, %d, %d, %d},\n",
                 literal(r.n).c_str(),
                 literal(r.sigma).c_str(),
                 literal(r.rho).c_str(),
                 literal(r.t).c_str(),
                 literal(r.x_saddle).c_str(),
                 literal(r.x_separatrix).c_str(),
                 literal(r.cell_radius).c_str(),
                 r.winding,
                 r.side,
                 r.limit_points,
                 r.cell_chart);
  }
  std::fprintf(cpp,
               "};\n\n"
               "}  // namespace\n\n"
               "std::span<const PredictorRow> predictor_table() { return kRows; }\n\n"
               "}  // namespace flexure::elliptic\n");
  if (std::fclose(cpp) != 0) {
    std::perror(cpp_path.c_str());
    return 1;
  }
  std::printf(
      "predictor table: %d nodes (%d failed), %d cells: angle %d, saddle %d, separatrix %d; "
      "continuation: fold at a corner %d, inside %d, no chart %d; %.1f s on %d threads\n",
      G::kNodes,
      failed_nodes,
      cells,
      count[0],
      count[1],
      count[2],
      count[3],
      count[4],
      count[5],
      seconds,
      threads);
  return 0;
}
