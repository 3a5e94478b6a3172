#include "flexure/beam/beam_sweep_solver.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace flexure {

namespace {

// The load on the same ray from zero as the neighbour's, as a multiple c of it (NaN when not on
// the ray): all three components of the tip load scale together.
double ray_multiple(double Fx, double Fy, double M, double qFx, double qFy, double qM) {
  const double qq = qFx * qFx + qFy * qFy + qM * qM;
  if (!(qq > 0.0)) return std::nan("");
  const double c = (Fx * qFx + Fy * qFy + M * qM) / qq;
  const double off =
      std::max({std::fabs(Fx - c * qFx), std::fabs(Fy - c * qFy), std::fabs(M - c * qM)});
  const double size = std::max({std::fabs(Fx), std::fabs(Fy), std::fabs(M)});
  return off <= 1e-12 * size ? c : std::nan("");
}

}  // namespace

BeamSweepSolver::BeamSweepSolver(BeamSweepGrid grid, BeamMethod method, long max_gap)
    : grid_(std::move(grid)), method_(method), max_gap_(max_gap) {}

BeamSweepSolver::Counts BeamSweepSolver::counts() const {
  return Counts{from_neighbour_.load(), from_zero_.load(), refused_.load()};
}

BeamSweepSolver::Memory& BeamSweepSolver::memory() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  // References to the elements of an unordered_map survive its rehashing.
  return memories_[std::this_thread::get_id()];
}

bool BeamSweepSolver::warm_candidate() const {
  const BeamProblem& b = grid_.base;
  // Forward shooting problems of the free cantilever with dead loads: the ones whose load path
  // is known from the loads alone (the sweep's own problems).
  // (A physical sweep's points may be chains, e.g. an axial load alone: each from zero.) With
  // shapes (`--shapes`) the warm-started solve integrates them too (ShootingSolver::Options::
  // shape_points), as the solve from zero does.
  return method_ == BeamMethod::kShooting && !grid_.physical && !grid_.chain &&
         b.given == BeamProblem::Given::kAlpha2 && !b.chain && b.boundary == EndCondition::kFree &&
         b.follower == 0.0;
}

void BeamSweepSolver::remember(Memory& m,
                               long index,
                               const SegmentChain& chain,
                               const ShootingResult& r,
                               const BeamSolution& solution) const {
  if (!r.converged() || r.jacobian_sign == 0) {
    m.last.clear();
    return;
  }
  Solved s;
  s.index = index;
  s.coordinates = grid_.coordinates(index);
  s.Fx = chain.tip_load.Fx;
  s.Fy = chain.tip_load.Fy;
  s.M = chain.tip_load.M;
  s.result = r;
  s.margin = solution.stability.judged() ? solution.stability.margin : std::nan("");
  if (m.last.size() == 4) m.last.erase(m.last.begin());
  m.last.push_back(std::move(s));
}

BeamSolution BeamSweepSolver::solve(long index) const {
  BeamProblem problem = grid_.at(index);
  if (!warm_candidate()) {
    ++from_zero_;
    return solve_beam(method_, problem);
  }
  return solve_shooting_point(index, problem);
}

BeamSolution BeamSweepSolver::solve_shooting_point(long index, const BeamProblem& problem) const {
  Memory& m = memory();
  const SegmentChain chain = problem.to_chain(problem.value);
  const ShootingSolver solver(beam_shooting_options(problem, problem.shape_points));
  const std::vector<double> here = grid_.coordinates(index);
  const std::size_t last_axis = here.size() - 1;
  // A neighbour on the same line of the grid (every coordinate but the fastest axis's equal),
  // at most max_gap points away.
  const auto on_line = [&](const Solved& s) {
    const long gap = std::labs(s.index - index);
    if (gap == 0 || gap > max_gap_) return false;
    for (std::size_t k = 0; k < last_axis; ++k) {
      if (s.coordinates[k] != here[k]) return false;
    }
    return true;
  };
  // The margin predicted along the line: the Lagrange polynomial through the last (up to four)
  // consecutive judged points on it; a guess only (compressed_cantilever_stability.h).
  const auto margin_guess = [&]() -> std::optional<double> {
    std::vector<const Solved*> basis;
    for (auto it = m.last.rbegin(); it != m.last.rend(); ++it) {
      if (!on_line(*it) || !std::isfinite(it->margin)) break;
      basis.push_back(&*it);
    }
    if (basis.empty()) return std::nullopt;
    const double x = here[last_axis];
    double guess = 0.0;
    for (std::size_t a = 0; a < basis.size(); ++a) {
      double weight = 1.0;
      for (std::size_t b = 0; b < basis.size(); ++b) {
        const double xa = basis[a]->coordinates[last_axis];
        const double xb = basis[b]->coordinates[last_axis];
        if (a == b) continue;
        if (xa == xb) return basis.front()->margin;
        weight *= (x - xb) / (xa - xb);
      }
      guess += weight * basis[a]->margin;
    }
    return guess;
  };
  const auto finish = [&](const ShootingResult& r, std::string branch) {
    BeamSolution s = beam_solution_from_shooting(
        problem, problem.value, r, problem.shape_points, margin_guess());
    if (!branch.empty())
      s.branch = std::move(branch) + limit_points_note(s.limit_points, s.first_limit_load_factor);
    s.method_reason = resolve_beam_method(method_, problem).reason;
    s.load_ratio_n = problem.load_ratio_n;
    s.mu = problem.mu;
    return s;
  };

  const auto describe = [&](const std::vector<double>& c) {
    std::string text;
    for (std::size_t k = 0; k < c.size(); ++k) {
      text +=
          fmt::format("{}{} = {:.9g}", k ? ", " : "", dataset_name(grid_.axes[k].parameter), c[k]);
    }
    return text;
  };
  const Solved* q = !m.last.empty() && on_line(m.last.back()) ? &m.last.back() : nullptr;
  if (q != nullptr) {
    const bool unique = unique_equilibrium_bound(chain) < 1.0;
    const double c =
        ray_multiple(chain.tip_load.Fx, chain.tip_load.Fy, chain.tip_load.M, q->Fx, q->Fy, q->M);
    const bool outward = c >= 1.0;  // false for NaN (off the ray)
    // A dead tip force alone, on the same side of the beam as the neighbour's.
    const bool dead_force =
        chain.tip_load.M == 0.0 && q->M == 0.0 &&
        (chain.tip_load.Fy > 0.0 ? q->Fy > 0.0 : chain.tip_load.Fy < 0.0 && q->Fy < 0.0) &&
        q->result.limit_points == 0 && q->result.inflection_points == 0;
    if (unique || outward || dead_force) {
      ShootingNeighbour neighbour;
      neighbour.unknowns = q->result.unknowns;
      neighbour.jacobian_sign = q->result.jacobian_sign;
      neighbour.tip = q->result.tip;
      // Prediction along the line: the Lagrange polynomial through the last two or three
      // solutions on it (quadratic: an error of O(h^3), so that one Newton step usually reaches
      // the tolerance).
      std::vector<const Solved*> basis;
      for (auto it = m.last.rbegin(); it != m.last.rend() && basis.size() < 3; ++it) {
        if (!on_line(*it) || it->result.unknowns.size() != q->result.unknowns.size()) break;
        basis.push_back(&*it);
      }
      if (basis.size() >= 2) {
        const double x = here[last_axis];
        std::vector<double> weight(basis.size(), 1.0);
        bool distinct = true;
        for (std::size_t a = 0; a < basis.size(); ++a) {
          for (std::size_t b = 0; b < basis.size(); ++b) {
            if (a == b) continue;
            const double xa = basis[a]->coordinates[last_axis];
            const double xb = basis[b]->coordinates[last_axis];
            if (xa == xb) distinct = false;
            weight[a] *= distinct ? (x - xb) / (xa - xb) : 0.0;
          }
        }
        if (distinct) {
          neighbour.predicted.assign(q->result.unknowns.size(), 0.0);
          for (std::size_t a = 0; a < basis.size(); ++a) {
            for (std::size_t i = 0; i < neighbour.predicted.size(); ++i) {
              neighbour.predicted[i] += weight[a] * basis[a]->result.unknowns[i];
            }
          }
        }
      }
      ShootingResult r = solver.solve_near(chain, neighbour);
      // The answer of a dead tip force has no inflection point (tested with the neighbour).
      if (r.converged() && !unique && !outward && r.inflection_points != 0) {
        r.set_converged(false);
      }
      if (r.converged()) {
        std::string branch;
        const std::string from = describe(q->coordinates);
        if (unique) {
          branch = fmt::format(
              "unique equilibrium (Newton from the neighbouring point {}; contraction bound below "
              "1)",
              from);
        } else if (!outward) {
          branch = fmt::format(
              "proportional loading (a dead tip force alone, whose load paths pass no limit point: "
              "Newton from the neighbouring point {} on the same branch)",
              from);
        } else {
          // On the neighbour's load path, farther out: its limit points are this one's, at load
          // factors 1/c of theirs.
          r.limit_points = q->result.limit_points;
          r.first_limit_load_factor = q->result.first_limit_load_factor / c;
          branch = fmt::format(
              "proportional loading (continued along the load path from the neighbouring point "
              "{})",
              from);
        }
        ++from_neighbour_;
        BeamSolution solution = finish(r, branch);
        remember(m, index, chain, r, solution);
        return solution;
      }
      ++refused_;
    }
  }
  ++from_zero_;
  const ShootingResult r = solver.solve(chain);
  BeamSolution solution = finish(r, {});
  remember(m, index, chain, r, solution);
  return solution;
}

}  // namespace flexure
