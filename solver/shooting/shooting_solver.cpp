#include "flexure/solver/shooting/shooting_solver.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "flexure/solver/chain_model/tip_reach.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/continuation.h"
#include "flexure/solver/shooting/control_points.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/inflection_count.h"
#include "flexure/solver/shooting/newton.h"
#include "flexure/solver/shooting/shooting_problem.h"

namespace flexure {

// The two stages of a straight chain with both end coordinates prescribed (run_two_stages).
struct ShootingSolver::TwoStageRun {
  bool release_x = true;
  std::optional<ShootingProblem> p1, p2;
  LoadPath s1, s2;
};

void ShootingSolver::Options::validate() const {
  const Options& o = *this;
  if (!(o.rtol > 0.0 && o.rtol < 1e-2)) {
    throw InvalidInput(fmt::format("shooting rtol must be in (0, 1e-2) (got {})", o.rtol));
  }
  if (!(o.atol > 0.0))
    throw InvalidInput(fmt::format("shooting atol must be > 0 (got {})", o.atol));
  if (!(o.newton.trial_cost_factor >= 0.0)) {
    throw InvalidInput(
        fmt::format("Newton trial_cost_factor must be >= 0 (got {})", o.newton.trial_cost_factor));
  }
  if (o.newton.max_iterations < 1) {
    throw InvalidInput(
        fmt::format("max Newton iterations must be >= 1 (got {})", o.newton.max_iterations));
  }
  if (!(o.continuation.min_step > 0.0) ||
      !(o.continuation.initial_step >= o.continuation.min_step)) {
    throw InvalidInput("continuation steps must satisfy 0 < min_step <= initial_step");
  }
  if (shape_points < 0) {
    throw InvalidInput(fmt::format("shape_points must be >= 0 (got {})", shape_points));
  }
  const ContinuationOptions& c = o.continuation;
  if (!(std::isfinite(c.max_step) && c.max_step >= c.min_step)) {
    throw InvalidInput(fmt::format(
        "the largest continuation step must be finite and at least the smallest step {:g} (got "
        "{})",
        c.min_step,
        c.max_step));
  }
  if (!(std::isfinite(c.max_load_step) && c.max_load_step >= 0.0)) {
    throw InvalidInput(
        fmt::format("the largest load-factor step must be finite and >= 0 (0: no cap; got {})",
                    c.max_load_step));
  }
  if (c.switch_at_bifurcation < 0) {
    throw InvalidInput(
        fmt::format("the bifurcation to switch branch at is counted from 1 (0: none; got {})",
                    c.switch_at_bifurcation));
  }
  if (c.branch_side != 1 && c.branch_side != -1) {
    throw InvalidInput(fmt::format("branch_side must be +1 or -1 (got {})", c.branch_side));
  }
  if (!(std::isfinite(c.branch_switch_step) && c.branch_switch_step > 0.0)) {
    throw InvalidInput(
        fmt::format("branch_switch_step must be finite and > 0 (got {})", c.branch_switch_step));
  }
  if (!(c.location_tolerance > 0.0 && c.singular_tolerance > 0.0)) {
    throw InvalidInput("the location and singular-value tolerances must be > 0");
  }
  if (c.shape_points < 0 || c.shape_points == 1) {
    throw InvalidInput(
        fmt::format("path shape points must be 0 (none) or >= 2 (got {})", c.shape_points));
  }
  if (!(max_neighbour_jump > 0.0)) {
    throw InvalidInput(fmt::format("max_neighbour_jump must be > 0 (got {})", max_neighbour_jump));
  }
}

const char* to_string(TipCoordinate coordinate) {
  switch (coordinate) {
    case TipCoordinate::kX:
      return "tip-x";
    case TipCoordinate::kY:
      return "tip-y";
    case TipCoordinate::kTheta:
      return "tip-angle";
  }
  return "unknown";
}

namespace {

// Newton's recorder of the curvature (inflection_count.h) when the inflection points are wanted
// and the backend shows its steps; null otherwise (finish() then counts on an integration of its
// own).
CurvatureRecorder* curvature_recorder(const ShootingSolver::Options& options,
                                      CurvatureRecorder& recorder) {
  const bool explicit_rk = options.backend == ElasticaIntegrator::Backend::kRk8pd ||
                           options.backend == ElasticaIntegrator::Backend::kDormandPrince;
  return options.count_inflections && explicit_rk ? &recorder : nullptr;
}

void take_count(const CurvatureRecorder& recorder, ShootingResult& result) {
  if (recorder.has_accepted()) {
    result.inflection_points = recorder.inflection_points();
    result.largest_curvature = recorder.largest_curvature();
  }
}

}  // namespace

double unique_equilibrium_bound(const SegmentChain& chain) {
  chain.validate();
  if (chain.end != EndCondition::kFree || chain.tip_load.follower != 0.0 ||
      chain.has_follower_pressure() || chain.has_extensible_segments()) {
    return std::numeric_limits<double>::infinity();
  }
  // Largest internal force: partial sums of the dead loads from the tip.
  const int n = chain.segment_count();
  std::vector<double> node_fx(n + 1, 0.0), node_fy(n + 1, 0.0);
  for (const NodeLoad& load : chain.node_loads) {
    node_fx[load.node] += load.Fx;
    node_fy[load.node] += load.Fy;
  }
  double fx = chain.tip_load.Fx, fy = chain.tip_load.Fy, max_force = std::hypot(fx, fy);
  for (int k = n - 1; k >= 1; --k) {
    fx += node_fx[k];
    fy += node_fy[k];
    max_force = std::max(max_force, std::hypot(fx, fy));
  }
  // |delta m(t)| <= max|N| (L - t) max|delta theta|, so the map's constant is
  // max|N| * integral over the flexible arc of (L - t)/EI(t) dt (EI_min of a profile, to be safe).
  const double L = chain.total_length();
  double t0 = 0.0, integral = 0.0, flexible_length = 0.0, EI_min = 0.0;
  int flexible_count = 0;
  bool uniform = true;
  for (const Segment& seg : chain.segments) {
    if (const auto* f = std::get_if<FlexibleSegment>(&seg)) {
      ++flexible_count;
      double EI = f->EI;
      if (!f->EI_profile.empty()) {
        uniform = false;
        for (double v : f->EI_profile) EI = std::min(EI, v);
      }
      EI_min = EI;
      flexible_length += f->length;
      integral += (f->length * (L - t0) - 0.5 * f->length * f->length) / EI;
      t0 += f->length;
    } else {
      uniform = false;
      t0 += std::get<RigidSegment>(seg).length;
    }
  }
  // Dead distributed loads: |delta m(t)| <= (L - t) max|delta theta| times the sum of the load
  // magnitudes beyond t, so the sum of all magnitudes bounds the force factor.
  double q_magnitude = 0.0;
  for (const Segment& seg : chain.segments) {
    const auto* f = std::get_if<FlexibleSegment>(&seg);
    if (f == nullptr || !f->has_dead_load()) continue;
    const int stations = f->q_profile.empty() ? 1 : static_cast<int>(f->q_profile.size());
    double largest = std::hypot(f->qx, f->qy);
    for (int i = 0; i < stations && !f->q_profile.empty(); ++i) {
      largest = std::max(largest, std::hypot(f->q_profile[i][0], f->q_profile[i][1]));
    }
    q_magnitude += largest * f->length;
  }
  if (q_magnitude > 0.0) {
    uniform = false;
    max_force = std::hypot(chain.tip_load.Fx, chain.tip_load.Fy) + q_magnitude;
    for (const NodeLoad& load : chain.node_loads) max_force += std::hypot(load.Fx, load.Fy);
  }
  if (flexible_count == 0 || max_force == 0.0) return 0.0;
  if (uniform && flexible_count == 1 && chain.node_loads.empty()) {
    return 4.0 * max_force * flexible_length * flexible_length /
           (std::numbers::pi * std::numbers::pi * EI_min);
  }
  return max_force * integral;
}

ShootingResult ShootingSolver::finish(const ShootingProblem& problem,
                                      ElasticaIntegrator& integrator,
                                      const Eigen::VectorXd& z,
                                      double lambda,
                                      ShootingResult result,
                                      const TipState* known_tip) const {
  result.load_factor = lambda;
  result.integrator_steps = integrator.steps_taken();
  result.unknown_names = problem.unknown_names();
  result.unknowns.assign(z.data(), z.data() + z.size());
  result.shooting_intervals = problem.interval_count();
  result.reaction = problem.reaction(z, lambda);
  InflectionCount count;
  if (options_.count_inflections && result.converged() && result.inflection_points < 0) {
    std::string error;
    if (!count_inflections(problem, z, lambda, integrator, count, error)) {
      result.set_converged(false);
      result.message += "; final integration failed: " + error;
      return result;
    }
    result.inflection_points = count.inflection_points;
    result.largest_curvature = count.largest_curvature;
    known_tip = &count.tip;
  }
  if (known_tip != nullptr && options_.shape_points <= 1) {
    result.tip = ChainPose{known_tip->x, known_tip->y, known_tip->theta};
    result.tip_load = Reaction{known_tip->N.x(), known_tip->N.y(), known_tip->m};
    return result;
  }
  TipState tip;
  std::string error;
  std::vector<double> s;
  std::vector<double>* s_ptr = nullptr;
  if (options_.shape_points > 1) {
    const double total = problem.chain().total_length();
    for (int i = 0; i < options_.shape_points; ++i) {
      s.push_back(total * i / (options_.shape_points - 1));
    }
    s_ptr = &s;
  }
  if (!problem.integrate_solution(
          z, lambda, integrator, tip, error, s_ptr, s_ptr ? &result.shape : nullptr)) {
    result.set_converged(false);
    result.message += "; final integration failed: " + error;
    return result;
  }
  result.tip = ChainPose{tip.x, tip.y, tip.theta};
  result.tip_load = Reaction{tip.N.x(), tip.N.y(), tip.m};
  return result;
}

ShootingResult ShootingSolver::solve(const SegmentChain& chain) const {
  options_.validate();
  const ShootingProblem problem(chain, options_.multiple_shooting);
  // An unreachable target is bad input, refused before any work (tip_reach.h).
  require_reachable_tip(chain);
  ElasticaIntegrator integrator(options_.integrator_options());
  ShootingResult result;

  const bool direct =
      options_.strategy == ShootingStrategy::kDirect ||
      (options_.strategy == ShootingStrategy::kAuto && unique_equilibrium_bound(chain) < 1.0);
  if (direct) {
    ShootingEvaluation start;
    Eigen::VectorXd z0 = problem.unloaded_unknowns();
    if (problem.evaluate(z0, 0.0, true, true, integrator, start)) {
      // Linear theory: z(1) ~ z(0) + dz/dlambda, the path tangent at zero load.
      Eigen::VectorXd z = z0 + robust_solve(start.jacobian, -start.d_lambda);
      double lambda = 1.0;
      CurvatureRecorder recorder;
      NewtonOutcome nw = newton_solve(problem,
                                      integrator,
                                      options_.newton,
                                      z,
                                      lambda,
                                      nullptr,
                                      curvature_recorder(options_, recorder));
      result.iterations += nw.iterations;
      if (nw.converged()) {
        take_count(recorder, result);
        result.set_converged(true);
        result.method = "direct Newton";
        result.path = ShootingPath::kDirectNewton;
        result.residual = nw.residual;
        result.message = nw.message;
        result.jacobian_sign = jacobian_sign(nw.last);
        return finish(problem, integrator, z, 1.0, result, &nw.last.tip);
      }
    }
  }

  if (options_.strategy == ShootingStrategy::kDirect) {
    result.method = "direct Newton";
    result.path = ShootingPath::kDirectNewton;
    result.set_converged(false);
    result.message = "direct Newton from the linear guess did not converge";
    return finish(problem, integrator, problem.unloaded_unknowns(), 0.0, result);
  }
  ContinuationOptions copt = options_.continuation;
  copt.record_path = false;
  const LoadPath path = continue_load_path(problem, integrator, copt, options_.newton);
  const PrescribedMask mask = prescribed_mask(chain.end);
  if (path.singular_start && mask.x && mask.y) {
    return solve_in_two_stages(chain, integrator, result);
  }
  result.method = "continuation";
  result.path = ShootingPath::kContinuation;
  result.iterations += path.newton_iterations;
  result.continuation_steps = path.steps;
  result.limit_points = path.limit_points;
  result.first_limit_load_factor = path.first_limit_load_factor;
  result.bifurcation_points = path.bifurcation_points;
  result.special_points = path.special_points;
  result.residual = path.residual;
  result.set_converged(path.converged());
  result.message = path.message;
  result.jacobian_sign = path.jacobian_sign;
  if (!path.converged()) {
    // Report the furthest equilibrium that was reached.
    result.message = fmt::format("not converged: {}", path.message);
  }
  return finish(problem, integrator, path.z, path.lambda, result, &path.tip_state);
}

namespace {

// The unknowns of `to` at the solution z (load factor lambda) of `from` on the same chain: shared
// names are copied, a force component that `to` shoots for and `from` does not comes from the
// internal force at the root.
Eigen::VectorXd carry_unknowns(const ShootingProblem& from,
                               const Eigen::VectorXd& z,
                               double lambda,
                               const ShootingProblem& to) {
  Eigen::VectorXd out = to.unloaded_unknowns();
  const ChainForces f = from.forces(z, lambda);
  const auto& names = from.unknown_names();
  for (int i = 0; i < to.size(); ++i) {
    const std::string& name = to.unknown_names()[i];
    const auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end()) {
      out[i] = z[it - names.begin()];
    } else if (name == "Nx0") {
      out[i] = f.N[0].x();
    } else if (name == "Ny0") {
      out[i] = f.N[0].y();
    }
  }
  return out;
}

// The bifurcation a later stage switches at, counted within that stage: none when an earlier
// stage switched already or the count lies in an earlier stage.
int remaining_switch(const ContinuationOptions& options, const LoadPath& earlier) {
  if (options.switch_at_bifurcation == 0 || earlier.switched_branch) return 0;
  const int left = options.switch_at_bifurcation - earlier.bifurcation_points;
  return left > 0 ? left : 0;
}

// Appends the points and special points of a later stage to `joined` (its start point, the end of
// the previous stage, is not repeated) with stage number `stage`, and sums the counts.
void append_stage(LoadPath& joined, const LoadPath& later, int stage) {
  const int offset = static_cast<int>(joined.points.size()) - 1;
  for (PathPoint p : later.points) {
    if (p.status == PathStatus::kStart) continue;
    p.stage = stage;
    joined.points.push_back(std::move(p));
  }
  for (SpecialPoint sp : later.special_points) {
    sp.stage = stage;
    if (sp.index >= 0) sp.index += offset;
    if (sp.index_after >= 0) sp.index_after += offset;
    if (sp.kind == SpecialPointKind::kLimitPoint && joined.limit_points == 0) {
      joined.first_limit_load_factor = sp.lambda;
    }
    joined.special_points.push_back(std::move(sp));
  }
  joined.set_converged(later.converged());
  joined.steps += later.steps;
  joined.rejected_steps += later.rejected_steps;
  joined.newton_iterations += later.newton_iterations;
  joined.location_corrections += later.location_corrections;
  joined.integrator_steps += later.integrator_steps;
  joined.limit_points += later.limit_points;
  joined.bifurcation_points += later.bifurcation_points;
  joined.switched_branch = joined.switched_branch || later.switched_branch;
  joined.z = later.z;
  joined.residual = later.residual;
  joined.tip = later.tip;
  joined.tip_state = later.tip_state;
}

// Throws InvalidInput when the tip pose `target` (its coordinates in `mask`) is out of the chain's
// reach (tip_reach.h): both x and y as for a pinned end, one of them alone within the length.
void require_controlled_reach(const SegmentChain& chain,
                              const PrescribedMask& mask,
                              const ChainPose& target,
                              TipCoordinate coordinate) {
  if (chain.has_extensible_segments()) return;  // a stretching chain reaches any point
  if (mask.x && mask.y) {
    SegmentChain pinned = chain;
    pinned.end = mask.theta ? EndCondition::kFixed : EndCondition::kPinned;
    pinned.prescribed = TipPrescription{target.x, target.y, target.theta};
    pinned.tip_load = TipLoad{};
    pinned.node_loads.clear();
    require_reachable_tip(pinned);
    return;
  }
  if (coordinate == TipCoordinate::kTheta) return;
  const double value = coordinate == TipCoordinate::kX ? target.x : target.y;
  const ChainPose unloaded = chain.unloaded_tip();
  const double start = coordinate == TipCoordinate::kX ? unloaded.x : unloaded.y;
  const double length = chain.total_length();
  if (std::abs(value) >= length && value != start) {
    throw InvalidInput(fmt::format(
        "the controlled {} = {:g} cannot be reached: an inextensible chain of length {:g} reaches "
        "less than its length from the clamp (except straight along its axis)",
        to_string(coordinate),
        value,
        length));
  }
}

}  // namespace

// One-way displacement control (DisplacementControl::one_way; docs/paths.md): where the moving
// stage's path folds back (a located limit point of the path parameter, the largest reached so
// far), an experiment cannot follow it; if an equilibrium lies next to the fold just beyond it
// (the buckled branch rejoining the unbuckled one at a bifurcation, where the fold and the
// bifurcation coincide), the path goes on from there to the target: the part after the fold is
// dropped and a new continuation, from that equilibrium at lambda_f + 1e-6, appended with its
// parameter mapped back onto the travel. Otherwise the path stops at the fold (a snap to an
// equilibrium not connected to it), saying so.
void ShootingSolver::go_on_past_folds(const SegmentChain& chain,
                                      const Homotopy& moving,
                                      const ShootingProblem& problem,
                                      ElasticaIntegrator& integrator,
                                      const ContinuationOptions& copt,
                                      TipCoordinate coordinate,
                                      LoadPath& moved) const {
  constexpr double kBeyond = 1e-6;  // of the travel, past the fold
  const ChainPose start = *moving.tip_start, target = *moving.tip_target;
  auto pose_at = [&](double lambda) {
    return ChainPose{start.x + lambda * (target.x - start.x),
                     start.y + lambda * (target.y - start.y),
                     start.theta + lambda * (target.theta - start.theta)};
  };
  std::optional<ShootingProblem> current;  // the problem of the last part (problem at first)
  double offset = 0.0;                     // the last part's lambda = offset + (1 - offset) lambda'
  for (int restart = 0; restart < 8 && !moved.converged(); ++restart) {
    // The first located fold at the largest lambda reached before it.
    const SpecialPoint* fold = nullptr;
    for (const SpecialPoint& sp : moved.special_points) {
      if (sp.kind != SpecialPointKind::kLimitPoint || !sp.located || sp.index < 0) continue;
      double before = 0.0;
      for (int i = 0; i < sp.index; ++i) before = std::max(before, moved.points[i].lambda);
      if (sp.lambda >= before) {
        fold = &sp;
        break;
      }
    }
    // Or, where the path stopped short of a fold it could not pass (steps shrinking at a
    // pitchfork met from its bifurcated side), its point farthest along.
    struct Turn {
      double lambda = 0.0;
      Eigen::VectorXd z;
      ChainPose tip;
      int index = -1;
    } at;
    if (fold != nullptr) {
      at = Turn{fold->lambda, fold->z, fold->tip, fold->index};
    } else {
      for (int i = 0; i < static_cast<int>(moved.points.size()); ++i) {
        const PathPoint& q = moved.points[i];
        if (q.lambda >= at.lambda && q.z.size() > 0) at = Turn{q.lambda, q.z, q.tip, i};
      }
      if (at.index <= 0) return;
    }
    const ShootingProblem& p = current ? *current : problem;
    // lambda of the part's own problem at the turn; Newton at fixed lambda just beyond it (a
    // little farther when the turn is a stop short of the fold).
    const double own = (at.lambda - offset) / (1.0 - offset);
    Eigen::VectorXd z;
    double lambda1 = own;
    NewtonOutcome nw;
    bool near = false;
    // From the turn itself, or (a located fold is a singular point, where Newton's first step
    // is ill-determined) from the path point before it.
    std::vector<const Eigen::VectorXd*> starts = {&at.z};
    if (at.index > 0 && moved.points[at.index - 1].z.size() == at.z.size()) {
      starts.push_back(&moved.points[at.index - 1].z);
    }
    for (double beyond = kBeyond; beyond <= 1e-3 && !near; beyond *= 10.0) {
      for (const Eigen::VectorXd* from : starts) {
        if (near) break;
        z = *from;
        lambda1 = own + beyond / (1.0 - offset);
        nw = newton_solve(p, integrator, options_.newton, z, lambda1);
        near = nw.converged() &&
               std::hypot(nw.last.tip.x - at.tip.x, nw.last.tip.y - at.tip.y) <=
                   options_.max_neighbour_jump * chain.total_length() &&
               std::fabs(nw.last.tip.theta - at.tip.theta) <= options_.max_neighbour_jump;
      }
    }
    const std::string where = fmt::format("the path {} at {} = {:.9g} (load factor {:.9g})",
                                          fold != nullptr ? "folds back" : "stopped",
                                          to_string(coordinate),
                                          coordinate_value(at.tip, coordinate),
                                          at.lambda);
    if (!near) {
      moved.message = fmt::format(
          "{}; {}: no equilibrium next to it beyond the fold (under displacement control the "
          "structure snaps there to an equilibrium not connected to this path)",
          moved.message,
          where);
      return;
    }
    if (fold == nullptr) {
      // The path stopped short of the rejoining bifurcation and goes on from the equilibrium just
      // beyond it: the bifurcation lies between the stop (lambda at.lambda) and that equilibrium
      // (lambda_new below), within 1e-3 of the travel. Stored as an unlocated bifurcation at the
      // stop (SpecialPoint::located false: lambda is the nearer end), where the path switched.
      SpecialPoint rejoin;
      rejoin.kind = SpecialPointKind::kBifurcation;
      rejoin.lambda = at.lambda;
      rejoin.tip = at.tip;
      rejoin.reaction = moved.points[at.index].reaction;
      rejoin.tip_load = moved.points[at.index].tip_load;
      rejoin.index = at.index;
      rejoin.stage = moved.points[at.index].stage;
      rejoin.branch = moved.points[at.index].branch;
      rejoin.located = false;
      rejoin.z = at.z;
      moved.special_points.push_back(std::move(rejoin));
    }
    // Drop what follows the fold.
    const int keep = at.index + 1;
    moved.points.resize(keep);
    std::vector<SpecialPoint> specials;
    for (SpecialPoint sp : moved.special_points) {
      if (sp.index >= keep || (sp.index < 0 && sp.index_after > keep)) continue;
      if (sp.index_after >= keep) sp.index_after = -1;
      specials.push_back(std::move(sp));
    }
    moved.special_points = std::move(specials);
    std::vector<ForcePoint> forces;
    // An extremum read from the chords at the fold was made with the samples after it (the path
    // going back): only those wholly before the fold's last chord stay.
    for (const ForcePoint& f : moved.force_points) {
      if (f.index_before + 1 < at.index ||
          (f.kind == ForcePointKind::kZero && f.index_before + 1 == at.index)) {
        forces.push_back(f);
      }
    }
    moved.force_points = std::move(forces);
    for (SpecialPoint& sp : moved.special_points) sp.switched = sp.switched || sp.index == at.index;
    // The new part: from the equilibrium beyond the fold to the target.
    const double lambda_new = offset + (1.0 - offset) * lambda1;
    Homotopy next = moving;
    next.tip_start = pose_at(lambda_new);
    const ShootingProblem p2(chain, options_.multiple_shooting, next);
    const Eigen::VectorXd z0 = z.size() == p2.size() ? z : carry_unknowns(p, z, lambda1, p2);
    ContinuationOptions c2 = copt;
    c2.switch_at_bifurcation = 0;
    LoadPath part = continue_load_path(p2, integrator, c2, options_.newton, &z0);
    int corrections = 0;
    std::vector<ForcePoint> part_forces =
        locate_force_points(p2, integrator, options_.newton, part, coordinate, corrections);
    int branch = 0;
    for (const PathPoint& q : moved.points) branch = std::max(branch, q.branch);
    const int stage = moved.points.back().stage;
    const int base = static_cast<int>(moved.points.size());
    auto map = [&](double l) { return lambda_new + (1.0 - lambda_new) * l; };
    for (PathPoint q : part.points) {
      q.lambda = map(q.lambda);
      q.branch = branch + 1;
      q.stage = stage;
      if (q.status == PathStatus::kStart) q.status = PathStatus::kAccepted;
      moved.points.push_back(std::move(q));
    }
    for (SpecialPoint sp : part.special_points) {
      sp.lambda = map(sp.lambda);
      sp.branch = branch + 1;
      sp.stage = stage;
      if (sp.index >= 0) sp.index += base;
      if (sp.index_after >= 0) sp.index_after += base;
      moved.special_points.push_back(std::move(sp));
    }
    for (ForcePoint f : part_forces) {
      f.lambda = map(f.lambda);
      f.branch = branch + 1;
      f.stage = stage;
      if (f.index_before >= 0) f.index_before += base;
      moved.force_points.push_back(std::move(f));
    }
    moved.limit_points = 0;
    moved.bifurcation_points = 0;
    for (const SpecialPoint& sp : moved.special_points) {
      (sp.kind == SpecialPointKind::kLimitPoint ? moved.limit_points : moved.bifurcation_points)++;
    }
    moved.set_converged(part.converged());
    moved.steps += part.steps;
    moved.rejected_steps += part.rejected_steps;
    moved.newton_iterations += part.newton_iterations + nw.iterations;
    moved.location_corrections += part.location_corrections + corrections;
    moved.integrator_steps += part.integrator_steps;
    moved.z = part.z;
    moved.residual = part.residual;
    moved.tip = part.tip;
    moved.tip_state = part.tip_state;
    moved.lambda = map(part.lambda);
    moved.lambda_reached = map(part.lambda_reached);
    moved.message = fmt::format(
        "{}; went on along the equilibrium next to it (one way): {}", where, part.message);
    current.emplace(p2);
    offset = lambda_new;
  }
}

ShootingSolver::TwoStageRun ShootingSolver::run_two_stages(const SegmentChain& chain,
                                                           ElasticaIntegrator& integrator,
                                                           bool record_path) const {
  // Both end coordinates prescribed on a chain whose end-to-end distance cannot change at first
  // order (straight and inextensible): proportional loading starts at a bifurcation. Stage 1
  // releases the coordinate along the unloaded tip tangent and applies the loads and the other
  // prescribed coordinates; stage 2 moves the released coordinate to its target at full load,
  // from a bent chain where the problem is regular.
  TwoStageRun run;
  const ChainPose tangent = chain.unloaded_tip();
  run.release_x = std::abs(std::cos(tangent.theta)) >= std::abs(std::sin(tangent.theta));
  PrescribedMask stage1_mask = prescribed_mask(chain.end);
  (run.release_x ? stage1_mask.x : stage1_mask.y) = false;
  Homotopy stage1;
  stage1.mask = stage1_mask;
  run.p1.emplace(chain, options_.multiple_shooting, stage1);
  ContinuationOptions copt = options_.continuation;
  copt.record_path = record_path;
  run.s1 = continue_load_path(*run.p1, integrator, copt, options_.newton);
  if (!run.s1.converged()) return run;

  ChainPose start = chain.prescribed_tip();
  (run.release_x ? start.x : start.y) = run.release_x ? run.s1.tip_state.x : run.s1.tip_state.y;
  Homotopy stage2;
  stage2.load_offset = 1.0;
  stage2.load_slope = 0.0;
  stage2.tip_start = start;
  run.p2.emplace(chain, options_.multiple_shooting, stage2);
  // Carry the stage-1 solution over; the released force component becomes an unknown.
  const Eigen::VectorXd z0 = carry_unknowns(*run.p1, run.s1.z, 1.0, *run.p2);
  copt.switch_at_bifurcation = remaining_switch(copt, run.s1);
  run.s2 = continue_load_path(*run.p2, integrator, copt, options_.newton, &z0);
  return run;
}

ShootingResult ShootingSolver::solve_in_two_stages(const SegmentChain& chain,
                                                   ElasticaIntegrator& integrator,
                                                   ShootingResult result) const {
  const TwoStageRun run = run_two_stages(chain, integrator, false);
  const char* released = run.release_x ? "x" : "y";
  result.method = "two-stage continuation";
  result.path = ShootingPath::kTwoStageContinuation;
  result.iterations += run.s1.newton_iterations;
  result.continuation_steps = run.s1.steps;
  if (!run.s1.converged()) {
    result.set_converged(false);
    result.message =
        fmt::format("not converged: stage 1 (loads, {} released) {}", released, run.s1.message);
    return finish(*run.p1, integrator, run.s1.z, run.s1.lambda, result, &run.s1.tip_state);
  }
  result.iterations += run.s2.newton_iterations;
  result.continuation_steps += run.s2.steps;
  // The special points of both stages, with their stage (stage 2's lambda is the fraction of the
  // released coordinate's travel); limit_points stays the count of folds of the load factor.
  result.special_points.clear();
  for (const LoadPath* stage : {&run.s1, &run.s2}) {
    for (SpecialPoint sp : stage->special_points) {
      sp.stage = stage == &run.s1 ? 1 : 2;
      result.special_points.push_back(std::move(sp));
    }
  }
  result.bifurcation_points = run.s1.bifurcation_points + run.s2.bifurcation_points;
  result.residual = run.s2.residual;
  result.set_converged(run.s2.converged());
  result.message =
      run.s2.converged()
          ? fmt::format("stage 1 (loads, {} released): {}; stage 2 ({} to target): {}",
                        released,
                        run.s1.message,
                        released,
                        run.s2.message)
          : fmt::format(
                "not converged: full load reached with {} released, but stage 2 (moving {} to "
                "its target) {}",
                released,
                released,
                run.s2.message);
  // Load factor 1 only when the full problem is solved; the stage-2 fraction is in the message.
  ShootingResult out =
      finish(*run.p2, integrator, run.s2.z, run.s2.lambda, result, &run.s2.tip_state);
  out.load_factor = run.s2.converged() ? 1.0 : 0.0;
  return out;
}

ShootingResult ShootingSolver::solve_from(const SegmentChain& chain,
                                          const std::vector<double>& guess) const {
  options_.validate();
  const ShootingProblem problem(chain, options_.multiple_shooting);
  const int count = static_cast<int>(guess.size());
  if (count != problem.size() && count != problem.root_unknown_count()) {
    throw InvalidInput(
        fmt::format("shooting guess must have {} root unknowns or all {} unknowns (got {})",
                    problem.root_unknown_count(),
                    problem.size(),
                    guess.size()));
  }
  for (double g : guess) require_finite(g, "shooting guess");
  ElasticaIntegrator integrator(options_.integrator_options());
  Eigen::VectorXd z = Eigen::Map<const Eigen::VectorXd>(guess.data(), count);
  if (count != problem.size()) {
    Eigen::VectorXd full;
    std::string error;
    if (!problem.complete_guess(z, 1.0, integrator, full, error)) {
      ShootingResult failed;
      failed.message = "integration from the guess failed: " + error;
      failed.method = "Newton from guess";
      failed.path = ShootingPath::kNewtonFromGuess;
      return failed;
    }
    z = full;
  }
  double lambda = 1.0;
  NewtonOutcome nw = newton_solve(problem, integrator, options_.newton, z, lambda, nullptr);
  ShootingResult result;
  result.method = "Newton from guess";
  result.path = ShootingPath::kNewtonFromGuess;
  result.iterations = nw.iterations;
  result.residual = nw.residual;
  result.set_converged(nw.converged());
  result.message = nw.message;
  if (nw.converged()) result.jacobian_sign = jacobian_sign(nw.last);
  return finish(problem, integrator, z, nw.converged() ? 1.0 : 0.0, result);
}

ShootingResult ShootingSolver::solve_near(const SegmentChain& chain,
                                          const ShootingNeighbour& neighbour) const {
  options_.validate();
  const ShootingProblem problem(chain, options_.multiple_shooting);
  ShootingResult result;
  result.method = "Newton from the neighbouring load";
  result.path = ShootingPath::kFromNeighbour;
  const auto refuse = [&](std::string why) {
    result.set_converged(false);
    result.message = "not taken from the neighbouring load: " + std::move(why);
    return result;
  };
  const int nz = problem.size();
  const int root = problem.root_unknown_count();
  const std::vector<double>& start =
      neighbour.predicted.empty() ? neighbour.unknowns : neighbour.predicted;
  if (neighbour.unknowns.size() < static_cast<std::size_t>(root) ||
      (!neighbour.predicted.empty() && neighbour.predicted.size() != neighbour.unknowns.size())) {
    throw InvalidInput(fmt::format(
        "a neighbour needs at least the {} root unknowns, and a prediction as many unknowns as "
        "the neighbour",
        root));
  }
  if (neighbour.jacobian_sign == 0) return refuse("the sign of its Jacobian is not known");
  for (double v : start) require_finite(v, "neighbouring unknowns");
  require_reachable_tip(chain);
  ElasticaIntegrator integrator(options_.integrator_options());
  Eigen::VectorXd z;
  if (static_cast<int>(start.size()) == nz) {
    z = Eigen::Map<const Eigen::VectorXd>(start.data(), nz);
  } else {
    // Other multiple-shooting cuts: the root unknowns carry over, the cut states come from one
    // integration from the root. (The sign of det dg/dz does not depend on the cuts: the
    // continuity rows eliminate to the single-shooting Jacobian, docs/theory-shooting.md.)
    std::string error;
    const Eigen::VectorXd head = Eigen::Map<const Eigen::VectorXd>(start.data(), root);
    if (!problem.complete_guess(head, 1.0, integrator, z, error)) {
      return refuse("integration from its root unknowns failed: " + error);
    }
  }
  double lambda = 1.0;
  CurvatureRecorder recorder;
  const NewtonOutcome nw = newton_solve(problem,
                                        integrator,
                                        options_.newton,
                                        z,
                                        lambda,
                                        nullptr,
                                        curvature_recorder(options_, recorder));
  result.iterations = nw.iterations;
  result.residual = nw.residual;
  result.integrator_steps = integrator.steps_taken();
  // The checks of the header comment, in order; the first that fails is the reason.
  constexpr double kMaxContraction = 0.25;
  if (!nw.converged()) return refuse(nw.message);
  if (nw.damped) return refuse("Newton needed a damped step (a start far from the root)");
  if (nw.contraction > kMaxContraction) {
    return refuse(fmt::format(
        "Newton's steps shrank only by {:.3g} per iteration (a start near the edge of the root's "
        "basin)",
        nw.contraction));
  }
  const int sign = jacobian_sign(nw.last);
  if (sign != neighbour.jacobian_sign) {
    return refuse(
        "the sign of det dg/dz changed (a limit point or bifurcation point lies between)");
  }
  if (!neighbour.predicted.empty() && static_cast<int>(neighbour.predicted.size()) == nz) {
    // The prediction must have made most of the move (at a fold it degrades: the path bends).
    const Eigen::VectorXd predicted = Eigen::Map<const Eigen::VectorXd>(start.data(), nz);
    const Eigen::VectorXd from = Eigen::Map<const Eigen::VectorXd>(neighbour.unknowns.data(), nz);
    const double correction = (z - predicted).lpNorm<Eigen::Infinity>();
    const double move = (predicted - from).lpNorm<Eigen::Infinity>();
    if (correction > 0.5 * move + 1e-8 * (1.0 + z.lpNorm<Eigen::Infinity>())) {
      return refuse(fmt::format(
          "Newton moved {:.3g} from the prediction, more than half the predicted move {:.3g}",
          correction,
          move));
    }
  }
  const TipState& tip = nw.last.tip;
  const double turn = std::fabs(tip.theta - neighbour.tip.theta);
  const double moved =
      std::hypot(tip.x - neighbour.tip.x, tip.y - neighbour.tip.y) / chain.total_length();
  if (!(std::max(turn, moved) <= options_.max_neighbour_jump)) {
    return refuse(
        fmt::format("the tip jumped (turned {:.3g} rad, moved {:.3g} lengths)", turn, moved));
  }
  result.set_converged(true);
  result.jacobian_sign = sign;
  take_count(recorder, result);
  result.message = fmt::format("converged from the neighbouring load: {}", nw.message);
  return finish(problem, integrator, z, 1.0, result, &nw.last.tip);
}

LoadPath ShootingSolver::load_path(const SegmentChain& chain) const {
  options_.validate();
  const ShootingProblem problem(chain, options_.multiple_shooting);
  require_reachable_tip(chain);
  ElasticaIntegrator integrator(options_.integrator_options());
  ContinuationOptions copt = options_.continuation;
  copt.record_path = true;
  LoadPath path = continue_load_path(problem, integrator, copt, options_.newton);
  const PrescribedMask mask = prescribed_mask(chain.end);
  if (!(path.singular_start && mask.x && mask.y)) return path;
  // Straight chain with both end coordinates prescribed: the two stages of solve(), recorded.
  TwoStageRun run = run_two_stages(chain, integrator, true);
  LoadPath joined = std::move(run.s1);
  const char* released = run.release_x ? "x" : "y";
  if (!joined.converged()) {
    joined.message = fmt::format("stage 1 (loads, {} released) {}", released, joined.message);
    return joined;
  }
  append_stage(joined, run.s2, 2);
  joined.lambda = run.s2.converged() ? 1.0 : 0.0;
  joined.lambda_reached = joined.lambda;
  joined.message = fmt::format(
      "two stages: stage 1 (loads, {} released) {}; stage 2 ({} moved to "
      "its target, lambda = fraction moved) {}",
      released,
      joined.message,
      released,
      run.s2.message);
  return joined;
}

LoadPath ShootingSolver::controlled_path(const SegmentChain& chain,
                                         const DisplacementControl& control) const {
  options_.validate();
  chain.validate();
  require_finite(control.target, "the controlled tip coordinate's target");
  const PrescribedMask end_mask = prescribed_mask(chain.end);
  PrescribedMask mask = end_mask;
  const ChainPose unloaded = chain.unloaded_tip();
  ChainPose target = chain.prescribed_tip();
  SegmentChain first = chain;  // stage 1: the loads, the controlled coordinate held or free
  switch (control.coordinate) {
    case TipCoordinate::kX:
      mask.x = true;
      target.x = control.target;
      if (end_mask.x) first.prescribed.x = unloaded.x;
      break;
    case TipCoordinate::kY:
      mask.y = true;
      target.y = control.target;
      if (end_mask.y) first.prescribed.y = unloaded.y;
      break;
    case TipCoordinate::kTheta:
      mask.theta = true;
      target.theta = control.target;
      if (end_mask.theta) first.prescribed.theta = unloaded.theta;
      break;
  }
  require_controlled_reach(chain, mask, target, control.coordinate);
  require_reachable_tip(first);
  // The controlled coordinate's load must be zero: ShootingProblem refuses it, name it here first.
  Homotopy moving;
  moving.load_offset = 1.0;
  moving.load_slope = 0.0;
  moving.tip_target = target;
  moving.mask = mask;
  (void)ShootingProblem(chain, options_.multiple_shooting, moving);

  bool loaded = chain.tip_load.Fx != 0.0 || chain.tip_load.Fy != 0.0 || chain.tip_load.M != 0.0 ||
                chain.tip_load.follower != 0.0 || chain.has_distributed_loads();
  for (const NodeLoad& load : chain.node_loads) {
    loaded = loaded || load.Fx != 0.0 || load.Fy != 0.0 || load.M != 0.0;
  }
  const ChainPose first_target = first.prescribed_tip();
  loaded = loaded || (end_mask.x && first_target.x != unloaded.x) ||
           (end_mask.y && first_target.y != unloaded.y) ||
           (end_mask.theta && first_target.theta != unloaded.theta);

  LoadPath joined;
  ChainPose start = unloaded;
  Eigen::VectorXd z0;
  std::string first_message;
  if (loaded) {
    joined = load_path(first);
    if (!joined.converged()) {
      joined.message = fmt::format("stage 1 (the loads applied before {} moves) {}",
                                   to_string(control.coordinate),
                                   joined.message);
      return joined;
    }
    start = joined.tip;
    first_message = joined.message;
  }
  moving.tip_start = start;
  const ShootingProblem problem(chain, options_.multiple_shooting, moving);
  if (loaded)
    z0 = carry_unknowns(ShootingProblem(first, options_.multiple_shooting), joined.z, 1.0, problem);
  ElasticaIntegrator integrator(options_.integrator_options());
  ContinuationOptions copt = options_.continuation;
  copt.record_path = true;
  copt.switch_at_bifurcation = remaining_switch(copt, joined);
  LoadPath moved =
      continue_load_path(problem, integrator, copt, options_.newton, loaded ? &z0 : nullptr);
  // The zeros and extrema of the support's force on the moved coordinate (control_points.h).
  int corrections = 0;
  moved.force_points = locate_force_points(
      problem, integrator, options_.newton, moved, control.coordinate, corrections);
  moved.location_corrections += corrections;
  if (control.one_way) {
    go_on_past_folds(chain, moving, problem, integrator, copt, control.coordinate, moved);
  }
  const double from = control.coordinate == TipCoordinate::kX   ? start.x
                      : control.coordinate == TipCoordinate::kY ? start.y
                                                                : start.theta;
  const std::string what = fmt::format("{} moved from {:.9g} to {:.9g} (lambda = fraction moved)",
                                       to_string(control.coordinate),
                                       from,
                                       control.target);
  if (!loaded) {
    moved.message = fmt::format("{}: {}", what, moved.message);
    return moved;
  }
  int stage = 1;
  for (const PathPoint& p : joined.points) stage = std::max(stage, p.stage);
  // append_stage drops the moving stage's start (stage 1's last point): indices shift by size - 1.
  const int offset = static_cast<int>(joined.points.size()) - 1;
  append_stage(joined, moved, stage + 1);
  joined.force_points = moved.force_points;
  for (ForcePoint& f : joined.force_points) {
    f.stage = stage + 1;
    if (f.index_before >= 0) f.index_before += offset;
  }
  joined.lambda = moved.lambda;
  joined.lambda_reached = moved.lambda_reached;
  joined.message =
      fmt::format("stage 1 (the loads) {}; then {}: {}", first_message, what, moved.message);
  return joined;
}

ShootingResult solve_shooting(const SegmentChain& chain, const ShootingSolver::Options& options) {
  return ShootingSolver(options).solve(chain);
}

LoadPath trace_load_path(const SegmentChain& chain, const ShootingSolver::Options& options) {
  return ShootingSolver(options).load_path(chain);
}

LoadPath trace_controlled_path(const SegmentChain& chain,
                               const DisplacementControl& control,
                               const ShootingSolver::Options& options) {
  return ShootingSolver(options).controlled_path(chain, control);
}

}  // namespace flexure
