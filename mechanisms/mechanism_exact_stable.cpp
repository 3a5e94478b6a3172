// The stable stroke of a serial chain (ExactMechanismSolver::Options::stable_start,
// `mechanism analyze --stable`): docs/stability.md "Mechanisms".
//
// The stroke from the PRBM start follows the linkage mode the PRBM describes. Where a thin
// flexure has a lower buckling mode of its own (3A-lssm, 3A-lslm: the middle strip sways between
// its two long links at P1 = 10.10 N and 10.55 N, below the linkage's 20.95 N) that branch is
// unstable with the slider held. The stable stroke starts instead on the branch of the straight
// chain's lowest buckling mode (exact_lowest_mode_point) and marches along it on a fixed grid of
// stations, kStations equal steps over the stroke plus the requested displacements, so that what
// it meets (3A-lslm's pitchfork, where the symmetric sway turns unstable and two mirror-image
// asymmetric branches take over) is resolved the same way at any point count. A station whose
// shooting Jacobian has the sign of its predecessor's lies on the same smooth stretch of branch
// (the sign changes at every fold and bifurcation) and keeps its stability; otherwise it is
// judged, and an unstable one is replaced by the stable neighbour (exact_stable_neighbour).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"

namespace flexure::mechanism {
namespace {

// Equal steps of the march over the stroke: 3A-lslm's pitchfork (13 % into its stroke) then lies
// within a step of 0.8 % of the stroke from a station, close enough for the stable neighbour's
// Newton starts; about 1 s of solves on either design.
constexpr int kStations = 128;

bool held_stable(const MechanismDesign& design, const ExactPoint& p) {
  try {
    return exact_point_stability(design, p).displacement_control.kind == StabilityKind::kStable;
  } catch (const std::exception&) {
    return false;
  }
}

bool comparable(const ExactPoint& a, const ExactPoint& b) {
  return a.jacobian_sign != 0 && b.jacobian_sign != 0 && a.unknowns.size() == b.unknowns.size();
}

// Secant prediction of the unknowns at x from the last two points (same size), else `b`.
ExactPoint predicted(const ExactPoint* a, const ExactPoint& b, double x) {
  ExactPoint p = b;
  if (a == nullptr || a->unknowns.size() != b.unknowns.size() ||
      a->displacement == b.displacement) {
    return p;
  }
  const double w = (x - b.displacement) / (b.displacement - a->displacement);
  for (std::size_t i = 0; i < p.unknowns.size(); ++i) {
    p.unknowns[i] = b.unknowns[i] + w * (b.unknowns[i] - a->unknowns[i]);
  }
  return p;
}

}  // namespace

ExactStrokeResult exact_stable_stroke(const MechanismDesign& design,
                                      const std::vector<double>& displacements,
                                      const ExactMechanismSolver::Options& options_in,
                                      const StrokeProgress& progress) {
  ExactStrokeResult result;
  if (displacements.empty()) {
    result.set_converged(true);
    return result;
  }
  ExactMechanismSolver::Options options = options_in;
  options.work_spent = std::make_shared<long>(0);
  options.work_limit = exact_work_limit(options_in, displacements.size() + kStations);
  const ExactMechanismSolver solver(design, options);
  // Newton from the prediction converges in at most 7 iterations on a smooth stretch (as in
  // exact_stroke's first try); a slower one means the step is too long for it, which substeps fix
  // for less than the remaining iterations cost.
  ExactMechanismSolver::Options first_options = options;
  first_options.shooting.newton.max_iterations =
      std::min(first_options.shooting.newton.max_iterations, 10);
  const ExactMechanismSolver first_try(design, first_options);
  const double end = displacements.back();
  // The stations: the grid and the requested displacements (requested ones marked).
  std::vector<std::pair<double, int>> stations;  // (displacement, index requested or -1)
  for (int i = 1; i <= kStations; ++i) stations.emplace_back(end * i / kStations, -1);
  for (std::size_t k = 0; k < displacements.size(); ++k) {
    stations.emplace_back(displacements[k], static_cast<int>(k));
  }
  std::stable_sort(stations.begin(), stations.end(), [](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && a.second > b.second);
  });
  // A grid station within 1e-9 of the stroke of a requested one is the requested one.
  std::vector<std::pair<double, int>> unique;
  for (const auto& s : stations) {
    if (!unique.empty() && std::abs(s.first - unique.back().first) <= 1e-9 * std::abs(end)) {
      if (unique.back().second < 0) unique.back().second = s.second;
      continue;
    }
    unique.push_back(s);
  }
  result.points.resize(displacements.size());
  auto fail = [&](double x, const std::string& why) {
    result.set_converged(false);
    result.message = fmt::format("stable branch stopped at Delta x = {:.6g} m: {}{}",
                                 x,
                                 solver.out_of_time() ? solver.budget_message() + "; " : "",
                                 why);
    result.integrator_steps = *options.work_spent;
    result.points.clear();
    return result;
  };

  // The first station: from the PRBM start when that equilibrium is stable, else on the lowest
  // buckling mode's branch.
  const double x0 = unique.front().first;
  ExactPoint current = solver.solve(x0);
  if (!current.converged() || !held_stable(design, current)) {
    ExactPoint lowest = exact_lowest_mode_point(design, x0, options);
    if (!lowest.converged()) return fail(x0, "lowest buckling mode: " + lowest.message);
    if (!held_stable(design, lowest)) {
      return fail(x0, "the lowest buckling mode's branch is not stable with the slider held there");
    }
    result.lowest_mode_start = true;
    current = std::move(lowest);
  }
  int neighbours = 0, judged = 1;
  std::size_t done = 0;
  auto keep = [&](int requested, const ExactPoint& p) {
    if (requested < 0) return;
    result.points[requested] = p;
    result.iterations += p.iterations;
    ++done;
    if (progress) progress(done, displacements.size());
  };
  keep(unique.front().second, current);
  ExactPoint before;
  bool have_before = false;
  for (std::size_t i = 1; i < unique.size(); ++i) {
    const double x = unique[i].first;
    const ExactPoint guess = predicted(have_before ? &before : nullptr, current, x);
    ExactPoint q = first_try.solve(x, &guess, false);
    bool same = q.converged() && comparable(q, current) && q.jacobian_sign == current.jacobian_sign;
    for (const int m : {4, 16}) {
      if (same) break;
      // Substeps from the last station, each Newton from the one before: they keep to the
      // stretch of branch where the prediction's Newton did not converge or landed across a
      // singular point (3A-lslm's pitchfork: the symmetric saddle), and stay with a stable
      // branch leaving a pitchfork (same sign of the Jacobian).
      ExactPoint at = current;
      bool ok = true;
      for (int j = 1; j <= m && ok; ++j) {
        ExactPoint r =
            solver.solve(current.displacement + (x - current.displacement) * j / m, &at, false);
        ok = r.converged();
        if (ok) at = std::move(r);
      }
      if (!ok) continue;
      if (comparable(at, current) && at.jacobian_sign == current.jacobian_sign) {
        q = std::move(at);
        same = true;
      } else if (!q.converged()) {
        q = std::move(at);
      }
    }
    if (!q.converged()) {
      // Steps adapted to the branch (which hop to a stable neighbour where the Jacobian changes
      // sign).
      ExactPoint walked =
          exact_adaptive_walk(design, current, x, 0.25 * (x - current.displacement), options);
      q = std::move(walked);
    }
    same = q.converged() && comparable(q, current) && q.jacobian_sign == current.jacobian_sign;
    if (q.converged() && !same) {
      ++judged;
      if (!held_stable(design, q)) {
        // Past a pitchfork the unstable equilibrium's own null-most direction points to the
        // stable pair (amplitude growing as the root of the distance past it); from the last
        // station's, next to the pitchfork, the stable ones may lie beyond the amplitudes tried.
        ExactPoint near = exact_stable_neighbour(design, q, x, options);
        if (!near.converged()) near = exact_stable_neighbour(design, current, x, options);
        if (!near.converged()) {
          return fail(x,
                      "the branch turned unstable with the slider held and no stable "
                      "equilibrium was found next to it: " +
                          near.message);
        }
        ++neighbours;
        q = std::move(near);
      }
    }
    if (!q.converged()) return fail(x, q.message);
    // After a hop to another branch (a stable neighbour) the secant would mix the two.
    have_before = same;
    before = std::move(current);
    current = std::move(q);
    keep(unique[i].second, current);
  }
  result.set_converged(true);
  result.integrator_steps = *options.work_spent;
  result.message = fmt::format("{} points converged", displacements.size());
  result.stable_search = fmt::format(
      "{} and marched in {} stations ({} equal steps over the stroke and the requested points), "
      "every one on a stretch of branch judged stable with the slider held ({} verdicts where the "
      "shooting Jacobian's sign changed{})",
      result.lowest_mode_start
          ? "the stroke from the PRBM start is unstable with the slider held: started on the "
            "branch of the straight chain's lowest buckling mode"
          : "started from the PRBM start (stable with the slider held)",
      unique.size(),
      kStations,
      judged,
      neighbours > 0 ? fmt::format(", {} stable neighbour(s) taken where the branch lost its "
                                   "stability: a pitchfork",
                                   neighbours)
                     : std::string());
  return result;
}

}  // namespace flexure::mechanism
