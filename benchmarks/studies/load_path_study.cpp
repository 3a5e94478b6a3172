#include "flexure/benchmarks/studies/load_path_study.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "flexure/beam/physical_beam.h"
#include "flexure/benchmarks/studies/shapes_group.h"
#include "flexure/elements/cbcm_path.h"
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/path_point_stability.h"

namespace flexure {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Shape values stored at most (points x shape points), so that a file stays within a few GB.
constexpr double kMaxShapeValues = 5e7;

void require_in_range(int value, const char* what, int lo, int hi) {
  if (value < lo || value > hi) {
    throw InvalidInput(
        fmt::format("{} = {} is outside the allowed range [{}, {}]", what, value, lo, hi));
  }
}

// The state a special point and a force point share, in the table's units: the tip, the clamp's
// reaction, the tip load, and where on the path the point lies.
template <class Point, class Row>
void scale_point_state(const Point& p, const PathUnits& u, Row& out) {
  out.tip_x = p.tip.x * u.length;
  out.tip_y = p.tip.y * u.length;
  out.tip_theta = p.tip.theta;
  out.reaction_Fx = p.reaction.Fx * u.force;
  out.reaction_Fy = p.reaction.Fy * u.force;
  out.reaction_M = p.reaction.M * u.moment;
  out.tip_Fx = p.tip_load.Fx * u.force;
  out.tip_Fy = p.tip_load.Fy * u.force;
  out.tip_M = p.tip_load.M * u.moment;
  out.stage = p.stage;
  out.branch = p.branch;
  out.located = p.located;
}

// One path point appended to the table's columns in its units (shooting and CBCM points
// carry the same state under the same names).
template <class Point>
void append_path_row(const Point& p, const PathUnits& u, PathTable& t) {
  t.load_factor.push_back(p.lambda);
  t.tip_x.push_back(p.tip.x * u.length);
  t.tip_y.push_back(p.tip.y * u.length);
  t.tip_theta.push_back(p.tip.theta);
  t.reaction_Fx.push_back(p.reaction.Fx * u.force);
  t.reaction_Fy.push_back(p.reaction.Fy * u.force);
  t.reaction_M.push_back(p.reaction.M * u.moment);
  t.tip_Fx.push_back(p.tip_load.Fx * u.force);
  t.tip_Fy.push_back(p.tip_load.Fy * u.force);
  t.tip_M.push_back(p.tip_load.M * u.moment);
  t.status.push_back(static_cast<int>(p.status));
  t.stage.push_back(p.stage);
  t.branch.push_back(p.branch);
}

// The continuation's counts and message, the same members in the shooting and CBCM paths.
template <class Path>
void copy_path_counts(const Path& path, PathTable& t) {
  t.switched_branch = path.switched_branch;
  t.steps = path.steps;
  t.rejected_steps = path.rejected_steps;
  t.newton_iterations = path.newton_iterations;
  t.location_corrections = path.location_corrections;
  t.message = path.message;
}

PathSpecialPoint to_table(const SpecialPoint& sp, const PathUnits& u) {
  PathSpecialPoint out;
  out.kind = sp.kind;
  out.load_factor = sp.lambda;
  out.index = sp.index;
  out.index_after = sp.index_after;
  scale_point_state(sp, u, out);
  out.switched = sp.switched;
  return out;
}

PathForcePoint to_table(const ForcePoint& f, const PathUnits& u, TipCoordinate coordinate) {
  const bool angle = coordinate == TipCoordinate::kTheta;
  PathForcePoint out;
  out.kind = f.kind;
  out.load_factor = f.lambda;
  out.coordinate = f.coordinate * (angle ? 1.0 : u.length);
  out.force = f.force * (angle ? u.moment : u.force);
  out.slope = f.slope * (angle ? u.moment : u.force / u.length);
  out.index_before = f.index_before;
  scale_point_state(f, u, out);
  return out;
}

// What a bifurcation passed means for the state on the path. Under dead loads the unloaded chain
// is stable and each simple bifurcation crossed changes the number of unstable directions of the
// state on the path (negative eigenvalues of the second variation) by one, as det(dg/dz) changes
// sign there (Jacobi's conjugate points); so after the first special point on a proportional path
// from zero the state is certainly unstable. Further on, only the change is known.
std::string bifurcation_warning(const PathSpecialPoint& b,
                                int number,
                                bool first_special,
                                bool follower,
                                bool displacement_control) {
  const std::string where =
      fmt::format("the path passed a bifurcation at load factor {:.10g} (path point {})",
                  b.load_factor,
                  b.index >= 0 ? b.index : b.index_after);
  const std::string follow = fmt::format("--branch {} follows it", number);
  if (follower) {
    return fmt::format(
        "{}: another branch exists ({}); stability under the follower load cannot be judged by "
        "the energy",
        where,
        follow);
  }
  if (first_special && b.stage == 1 && b.branch == 0 && !displacement_control) {
    return fmt::format(
        "{}: beyond it the proportional-loading state is unstable; another branch exists ({})",
        where,
        follow);
  }
  return fmt::format(
      "{}: another branch exists ({}); the state on the path gains or loses one unstable "
      "direction there",
      where,
      follow);
}

// N . t and N . n at the shape points of a path whose chain carries distributed or joint loads:
// the statics of the part before each point from the clamp's reaction (shape_internal_forces).
// The loads of a point are those of the chain at its load factor, or at full load in a later
// stage (displacement control moves the tip with the loads applied); whichever carries the force
// integrated from the clamp's reaction to the tip's own total load (to 1e-9 of the loads) is
// taken. Where neither does (a point without a reaction), nothing is stored. (The force is exact
// for dead loads linear along a segment and for follower pressures; the moment of a dead load by
// the midpoint rule is not, so the solver's moment stays the stored one.)
void store_loaded_internal_forces(const PathRequest& r, const LoadPath& path, PathTable& t) {
  std::vector<double> axial, shear;
  for (const PathPoint& p : path.points) {
    if (static_cast<int>(p.shape.size()) != r.shape_points || p.moment.size() != p.shape.size()) {
      return;
    }
    const ShapePoint& end = p.shape.back();
    const double tip_axial =
        p.tip_load.Fx * std::cos(end.theta) + p.tip_load.Fy * std::sin(end.theta);
    const double tip_shear =
        -p.tip_load.Fx * std::sin(end.theta) + p.tip_load.Fy * std::cos(end.theta);
    const double size = 1e-300 + std::fabs(p.reaction.Fx) + std::fabs(p.reaction.Fy) +
                        std::fabs(p.tip_load.Fx) + std::fabs(p.tip_load.Fy);
    bool matched = false;
    for (double lambda : {p.lambda, 1.0}) {
      const ShapeInternalForces f =
          shape_internal_forces(r.chain.at_load_factor(lambda), p.shape, p.reaction);
      // The force integrated from the clamp arrives at the tip as the tip's own load.
      const bool same = std::fabs(f.axial.back() - tip_axial) <= 1e-9 * size &&
                        std::fabs(f.shear.back() - tip_shear) <= 1e-9 * size;
      if (!same) continue;
      for (std::size_t k = 0; k < f.axial.size(); ++k) {
        axial.push_back(f.axial[k] * r.units.force);
        shear.push_back(f.shear[k] * r.units.force);
      }
      matched = true;
      break;
    }
    if (!matched) return;
  }
  t.shape_axial = std::move(axial);
  t.shape_shear = std::move(shear);
}

PathTable shooting_table(const PathRequest& r) {
  ShootingSolver::Options options;
  ContinuationOptions& c = options.continuation;
  if (r.max_step > 0.0) {
    c.max_step = r.max_step;
    c.initial_step = std::min(c.initial_step, r.max_step);
  }
  if (r.min_points >= 2) c.max_load_step = 1.0 / (r.min_points - 1);
  c.switch_at_bifurcation = r.branch;
  c.branch_side = r.branch_side;
  c.shape_points = r.shape_points;
  const LoadPath path = r.control ? trace_controlled_path(r.chain, *r.control, options)
                                  : trace_load_path(r.chain, options);
  const PathUnits& u = r.units;
  PathTable t;
  t.shape_points = r.shape_points;
  for (const PathPoint& p : path.points) {
    append_path_row(p, u, t);
    if (r.shape_points > 0) {
      const bool have = static_cast<int>(p.shape.size()) == r.shape_points;
      for (int k = 0; k < r.shape_points; ++k) {
        t.shape_x.push_back(have ? p.shape[k].x * u.length : kNaN);
        t.shape_y.push_back(have ? p.shape[k].y * u.length : kNaN);
        t.shape_theta.push_back(have ? p.shape[k].theta : kNaN);
        t.shape_moment.push_back(have ? p.moment[k] * u.moment : kNaN);
      }
      if (!have) {
        throw std::runtime_error(
            fmt::format("the shape of path point {} (load factor {:.6g}) could not be integrated",
                        t.size() - 1,
                        p.lambda));
      }
    }
  }
  if (r.shape_points > 0) {
    const double total = r.chain.total_length();
    for (int k = 0; k < r.shape_points; ++k) {
      t.shape_s.push_back(total * k / (r.shape_points - 1) * u.length);
    }
    if (!r.chain.has_distributed_loads() && r.chain.node_loads.empty()) {
      // Tip loads only: N(s) is the total tip load at every s (statics of the part beyond s).
      for (std::size_t i = 0; i < path.points.size(); ++i) {
        const PathPoint& p = path.points[i];
        for (int k = 0; k < r.shape_points; ++k) {
          const double Nx = p.tip_load.Fx, Ny = p.tip_load.Fy;
          const double theta = t.shape_theta[i * r.shape_points + k];
          t.shape_axial.push_back((Nx * std::cos(theta) + Ny * std::sin(theta)) * u.force);
          t.shape_shear.push_back((-Nx * std::sin(theta) + Ny * std::cos(theta)) * u.force);
        }
      }
    } else {
      store_loaded_internal_forces(r, path, t);
    }
    if (!t.shape_axial.empty() &&
        static_cast<int>(r.shape_section_modulus.size()) == r.shape_points &&
        r.shape_area.size() == r.shape_section_modulus.size()) {
      // N/A -+ m c/I: a positive moment compresses the +n fibre (docs/units.md).
      for (std::size_t i = 0; i < t.shape_axial.size(); ++i) {
        const std::size_t k = i % static_cast<std::size_t>(r.shape_points);
        const double axial = t.shape_axial[i] / r.shape_area[k];
        const double bending = t.shape_moment[i] / r.shape_section_modulus[k];
        t.shape_stress_pos.push_back(axial - bending);
        t.shape_stress_neg.push_back(axial + bending);
      }
    }
  }
  // The verdict of every point under the path's control there (path_point_stability.h).
  for (const PathPoint& p : path.points) {
    t.stability.push_back(
        r.judge_stability
            ? path_point_stability(r.chain, p, p.held, options, r.stability)
            : not_checked_stability("the verdict was switched off (--stability off)"));
  }
  for (const SpecialPoint& sp : path.special_points) t.special_points.push_back(to_table(sp, u));
  if (r.control) {
    for (const ForcePoint& f : path.force_points) {
      t.force_points.push_back(to_table(f, u, r.control->coordinate));
    }
  }
  t.completed = path.converged();
  t.lambda_reached = path.lambda_reached;
  t.limit_points = path.limit_points;
  t.bifurcation_points = path.bifurcation_points;
  if (path.limit_points > 0) t.first_limit_load_factor = path.first_limit_load_factor;
  copy_path_counts(path, t);
  int number = 0;
  for (std::size_t i = 0; i < t.special_points.size(); ++i) {
    const PathSpecialPoint& b = t.special_points[i];
    if (b.kind != SpecialPointKind::kBifurcation) continue;
    ++number;
    if (b.switched) continue;
    t.warnings.push_back(bifurcation_warning(
        b, number, i == 0, r.chain.tip_load.follower != 0.0, r.control.has_value()));
  }
  return t;
}

// The ladder's BCM and CBCM under displacement control (cbcm_path.h).
PathTable cbcm_table(const PathRequest& r) {
  CbcmPathOptions options;
  options.elements = r.method == PathMethod::kBcm ? 1 : r.elements;
  if (r.min_points >= 2) options.max_load_step = 1.0 / (r.min_points - 1);
  options.branch = r.branch;
  options.branch_side = r.branch_side;
  const CbcmPathResult path = trace_cbcm_controlled_path(r.chain, *r.control, options);
  const PathUnits& u = r.units;
  PathTable t;
  struct Scaled {
    ChainPose tip;
    Reaction reaction, tip_load;
    int stage = 1, branch = 0;
    bool located = true;
  };
  const auto scaled = [](const CbcmPathPoint& p, bool located) {
    return Scaled{p.tip, p.reaction, p.tip_load, p.stage, p.branch, located};
  };
  for (const CbcmPathPoint& p : path.points) append_path_row(p, u, t);
  t.stability.assign(t.size(),
                     not_checked_stability("the BCM and CBCM paths are not judged (their "
                                           "discrete energy is not assembled); --method shooting "
                                           "judges every point"));
  for (const CbcmSpecialPoint& sp : path.special_points) {
    PathSpecialPoint out;
    out.kind = sp.kind;
    out.load_factor = sp.point.lambda;
    out.index = sp.index;
    out.index_after = sp.index_after;
    scale_point_state(scaled(sp.point, sp.located), u, out);
    out.switched = sp.switched;
    t.special_points.push_back(out);
  }
  const bool angle = r.control->coordinate == TipCoordinate::kTheta;
  for (const CbcmForcePoint& f : path.force_points) {
    PathForcePoint out;
    out.kind = f.kind;
    out.load_factor = f.point.lambda;
    out.coordinate = f.coordinate * (angle ? 1.0 : u.length);
    out.force = f.force * (angle ? u.moment : u.force);
    out.slope = f.slope * (angle ? u.moment : u.force / u.length);
    out.index_before = f.index_before;
    scale_point_state(scaled(f.point, f.located), u, out);
    t.force_points.push_back(out);
  }
  t.completed = path.converged();
  t.left_domain = path.left_domain;
  t.elements = path.elements;
  t.lambda_reached = path.lambda_reached;
  t.limit_points = path.limit_points;
  t.bifurcation_points = path.bifurcation_points;
  if (path.limit_points > 0) {
    for (const CbcmSpecialPoint& sp : path.special_points) {
      if (sp.kind == SpecialPointKind::kLimitPoint) {
        t.first_limit_load_factor = sp.point.lambda;
        break;
      }
    }
  }
  copy_path_counts(path, t);
  for (const Warning& w : path.warnings) t.warnings.push_back(w.text);
  int number = 0;
  for (const PathSpecialPoint& b : t.special_points) {
    if (b.kind != SpecialPointKind::kBifurcation) continue;
    ++number;
    if (b.switched) continue;
    t.warnings.push_back(bifurcation_warning(b, number, false, false, true));
  }
  return t;
}

PathTable chain_table(const PathRequest& r) {
  ChainAlgorithmSolver::Options options;
  options.elements = r.elements;
  options.increments = r.increments;
  options.record_load_path = true;
  const ChainResult result = solve_chain(r.chain, options);
  const PathUnits& u = r.units;
  PathTable t;
  const ChainPose start = r.chain.unloaded_tip();
  auto add = [&](double lambda, const ChainPose& tip, int status) {
    t.load_factor.push_back(lambda);
    t.tip_x.push_back(tip.x * u.length);
    t.tip_y.push_back(tip.y * u.length);
    t.tip_theta.push_back(tip.theta);
    t.status.push_back(status);
    t.stage.push_back(1);
    t.branch.push_back(0);
  };
  add(0.0, start, 0);
  for (const ChainLoadPathPoint& p : result.load_path) {
    add(p.load_factor, p.tip, p.load_factor >= 1.0 ? 3 : 1);
  }
  // The chain algorithm records tip poses per increment; reactions only at the end.
  for (auto* column :
       {&t.reaction_Fx, &t.reaction_Fy, &t.reaction_M, &t.tip_Fx, &t.tip_Fy, &t.tip_M}) {
    column->assign(t.size(), kNaN);
  }
  t.reaction_Fx.back() = result.root_reaction.Fx * u.force;
  t.reaction_Fy.back() = result.root_reaction.Fy * u.force;
  t.reaction_M.back() = result.root_reaction.M * u.moment;
  // The increments record tips only (no shape to judge); the answer carries the chain
  // algorithm's own verdict (chain_algorithm_solver.h).
  t.stability.assign(t.size(),
                     not_checked_stability("the chain algorithm's path records the tip only; "
                                           "--method shooting judges every point"));
  if (r.judge_stability && result.stability.kind != StabilityKind::kNotChecked) {
    t.stability.back() = result.stability;
  }
  t.completed = result.converged();
  t.lambda_reached = result.load_factor;
  t.steps = result.increments;
  t.message = result.message;
  return t;
}

}  // namespace

const char* to_string(PathMethod method) {
  switch (method) {
    case PathMethod::kChain:
      return "chain";
    case PathMethod::kBcm:
      return "bcm";
    case PathMethod::kCbcm:
      return "cbcm";
    case PathMethod::kShooting:
      break;
  }
  return "shooting";
}

// (Built whole: assigning short literals to the members trips GCC 12's -Wrestrict.)
PathUnits PathUnits::si(double length_m, double EI_Nm2) {
  // F = (F l^2/EI) EI / l^2, M = (M l/EI) EI / l.
  return PathUnits{std::string("SI"),
                   length_m,
                   EI_Nm2 / (length_m * length_m),
                   EI_Nm2 / length_m,
                   std::string("m"),
                   std::string("N"),
                   std::string("N m")};
}

PathUnits PathUnits::chain_file(bool physical) {
  // A physical file's values are SI already (io/toml_files.h): factors 1, units m, N, N m.
  if (physical) return si(1.0, 1.0);
  return PathUnits{std::string("chain file"),
                   1.0,
                   1.0,
                   1.0,
                   std::string("length unit of the chain file"),
                   std::string("force unit of the chain file"),
                   std::string("force unit * length unit of the chain file")};
}

void PathRequest::validate() const {
  chain.validate();
  if (judge_stability) stability.validate();
  if (method == PathMethod::kChain) {
    require_in_range(elements, "--elements (chain algorithm elements N)", 1, 1'000'000);
    require_in_range(increments, "--increments (load increments)", 1, 1'000'000);
    const char* shooting_only = max_step > 0.0     ? "--max-step"
                                : min_points > 0   ? "--min-points"
                                : branch > 0       ? "--branch"
                                : control          ? "--control"
                                : shape_points > 0 ? "--shapes"
                                                   : nullptr;
    if (shooting_only != nullptr) {
      throw InvalidInput(fmt::format(
          "{} belongs to the continuation of --method shooting; the chain algorithm takes load "
          "increments (--increments) and records the tip only",
          shooting_only));
    }
    return;
  }
  if (method == PathMethod::kBcm || method == PathMethod::kCbcm) {
    const char* name = to_string(method);
    if (!control) {
      throw InvalidInput(fmt::format(
          "the {} path is a displacement-controlled one (the problem the beam-constraint models "
          "were made for): give --control tip-x|tip-y|tip-angle with its target; --method "
          "shooting follows proportional loading",
          name));
    }
    if (method == PathMethod::kCbcm) {
      require_in_range(elements, "--elements (CBCM elements N)", 1, 2000);
    }
    const char* shooting_only = max_step > 0.0     ? "--max-step"
                                : shape_points > 0 ? "--shapes"
                                                   : nullptr;
    if (shooting_only != nullptr) {
      throw InvalidInput(fmt::format(
          "{} belongs to the shooting method's continuation; the {} path takes --min-points, "
          "--branch, --branch-side and (cbcm) --elements",
          shooting_only,
          name));
    }
    if (branch < 0) {
      throw InvalidInput(
          fmt::format("--branch counts the bifurcations along the path from 1 (got {})", branch));
    }
    if (min_points != 0) {
      require_in_range(min_points, "--min-points (points from zero to full load)", 2, 1'000'000);
    }
    return;
  }
  if (max_step != 0.0 && !(std::isfinite(max_step) && max_step >= 1e-6 && max_step <= 10.0)) {
    throw InvalidInput(fmt::format(
        "--max-step (largest arclength step, scaled so that 1 is about a unit of load factor at "
        "the start) must be in [1e-6, 10] (got {})",
        max_step));
  }
  if (min_points != 0) {
    require_in_range(min_points, "--min-points (points from zero to full load)", 2, 1'000'000);
  }
  if (branch < 0) {
    throw InvalidInput(
        fmt::format("--branch counts the bifurcations along the path from 1 (got {})", branch));
  }
  if (branch_side != 1 && branch_side != -1) {
    throw InvalidInput("the branch side is +1 (tip to +y) or -1 (tip to -y)");
  }
  if (shape_points != 0) {
    require_in_range(shape_points, "--shapes (shape points per path point)", 2, 1'000'000);
  }
}

std::vector<const PathSpecialPoint*> PathTable::of_kind(SpecialPointKind kind) const {
  std::vector<const PathSpecialPoint*> out;
  for (const PathSpecialPoint& sp : special_points) {
    if (sp.kind == kind) out.push_back(&sp);
  }
  return out;
}

std::vector<StabilityStretch> PathTable::stability_stretches() const {
  std::vector<StabilityStretch> out;
  for (std::size_t i = 0; i < stability.size() && i < size(); ++i) {
    const Stability& s = stability[i];
    const int index = s.judged() ? s.index : 0;
    if (out.empty() || out.back().kind != s.kind || out.back().index != index) {
      StabilityStretch next;
      next.kind = s.kind;
      next.index = index;
      next.first = static_cast<int>(i);
      next.first_load_factor = load_factor[i];
      out.push_back(next);
    }
    out.back().last = static_cast<int>(i);
    out.back().last_load_factor = load_factor[i];
  }
  return out;
}

std::string describe(const StabilityStretch& s) {
  const std::string kind = s.kind == StabilityKind::kUnstable
                               ? fmt::format("unstable (index {})", s.index)
                               : std::string(stability_name(s.kind));
  if (s.first == s.last) {
    return fmt::format("{} at point {} (load factor {:.10g})", kind, s.first, s.first_load_factor);
  }
  return fmt::format("{} at points {}-{} (load factor {:.10g} to {:.10g})",
                     kind,
                     s.first,
                     s.last,
                     s.first_load_factor,
                     s.last_load_factor);
}

PathTable run_load_path(const PathRequest& request) {
  request.validate();
  PathTable t = request.method == PathMethod::kChain      ? chain_table(request)
                : request.method == PathMethod::kShooting ? shooting_table(request)
                                                          : cbcm_table(request);
  t.method = request.method;
  t.units = request.units;
  t.boundary = to_string(request.chain.end);
  if (request.control) {
    t.control = to_string(request.control->coordinate);
    t.control_target = request.control->coordinate == TipCoordinate::kTheta
                           ? request.control->target
                           : request.control->target * request.units.length;
  }
  if (request.shape_points > 0 &&
      static_cast<double>(t.size()) * request.shape_points > kMaxShapeValues) {
    throw InvalidInput(fmt::format(
        "--shapes {}: {} path points x {} shape points exceeds the {:g} values a path file holds; "
        "ask for fewer shape points",
        request.shape_points,
        t.size(),
        request.shape_points,
        kMaxShapeValues));
  }
  return t;
}

const std::vector<io::CodeMeaning>& path_code_meanings() {
  static const std::vector<io::CodeMeaning> codes = {
      {"status", 0, "start: the unloaded beam (load factor 0)"},
      {"status", 1, "an accepted continuation step or load increment"},
      {"status",
       2,
       "a limit point (fold) of the load factor, located: this row is the fold itself (not "
       "located: the first point after it)"},
      {"status", 3, "end: the full load (load factor 1)"},
      {"status",
       4,
       "a bifurcation point, located: dg/dz singular while the load factor keeps its direction "
       "(another branch crosses here)"},
      {"located", 0, "not refined: the load factor is that of the nearer path point"},
      {"located", 1, "located on the path to about 1e-10 in the load factor"},
      {"switched", 0, "the path went on through this point"},
      {"switched", 1, "the path left here onto the other branch (--branch)"},
      {"stability",
       0,
       "stable: the second variation of the energy is positive definite under the path's control "
       "(docs/stability.md)"},
      {"stability", 1, "unstable: the energy decreases in stability_index directions"},
      {"stability",
       2,
       "critical: the lowest eigenvalue is zero within 1e-6 (a located limit or bifurcation "
       "point)"},
      {"stability", 3, "not_conservative: a follower force; the energy cannot judge"},
      {"stability",
       4,
       "not_checked: not computed (the chain algorithm's increments, --stability off, or the "
       "shape could not be integrated; index -1, margin NaN)"}};
  return codes;
}

namespace {

// /force_points of a displacement-controlled path (docs/hdf5-schema.md "flexure path").
// The columns a special point and a force point share (the fields of the same names): where the
// tip is, what holds it, and on which stage and branch of the path it lies.
template <class Point>
void write_point_state(io::Hdf5Group& g,
                       const std::vector<Point>& points,
                       const PathUnits& u,
                       const std::string& scaled) {
  const auto column = [&points](auto field) {
    std::vector<std::decay_t<decltype(Point{}.*field)>> values;
    values.reserve(points.size());
    for (const Point& p : points) values.push_back(p.*field);
    return values;
  };
  g.write_dataset("tip_x", column(&Point::tip_x), u.length_unit, "tip x at the point" + scaled);
  g.write_dataset("tip_y", column(&Point::tip_y), u.length_unit, "tip y at the point" + scaled);
  g.write_dataset("tip_theta", column(&Point::tip_theta), "rad", "tip angle at the point");
  g.write_dataset("reaction_Fx",
                  column(&Point::reaction_Fx),
                  u.force_unit,
                  "x force the clamp exerts" + scaled);
  g.write_dataset("reaction_Fy",
                  column(&Point::reaction_Fy),
                  u.force_unit,
                  "y force the clamp exerts" + scaled);
  g.write_dataset(
      "reaction_M", column(&Point::reaction_M), u.moment_unit, "moment the clamp exerts" + scaled);
  g.write_dataset(
      "tip_Fx", column(&Point::tip_Fx), u.force_unit, "total x force on the tip" + scaled);
  g.write_dataset(
      "tip_Fy", column(&Point::tip_Fy), u.force_unit, "total y force on the tip" + scaled);
  g.write_dataset(
      "tip_M", column(&Point::tip_M), u.moment_unit, "total moment on the tip" + scaled);
  g.write_dataset("stage", column(&Point::stage), "1", "stage of the path (dataset /stage)");
  g.write_dataset(
      "branch", column(&Point::branch), "1", "branch on which it lies (dataset /branch)");
}

void write_force_points(io::Hdf5Group& root, const PathTable& t) {
  const PathUnits& u = t.units;
  const bool angle = t.control == "tip-angle";
  const std::string scaled = u.system == "nondimensional" ? " (nondimensional: l = 1, EI = 1)" : "";
  const std::string coordinate_unit = angle ? "rad" : u.length_unit;
  const std::string force_unit = angle ? u.moment_unit : u.force_unit;
  io::Hdf5Group g = root.create_group("force_points");
  std::vector<std::string> kind;
  std::vector<double> lambda, c, f, slope;
  std::vector<int> index, located;
  for (const PathForcePoint& p : t.force_points) {
    kind.push_back(to_string(p.kind));
    lambda.push_back(p.load_factor);
    c.push_back(p.coordinate);
    f.push_back(p.force);
    slope.push_back(p.slope);
    index.push_back(p.index_before);
    located.push_back(p.located ? 1 : 0);
  }
  g.write_dataset("kind",
                  kind,
                  "text",
                  "force_zero (the support's load on the moved coordinate crosses zero: an "
                  "equilibrium with that coordinate free), force_maximum or force_minimum (a "
                  "local extremum along the path: a limit point under force control)");
  g.write_dataset("load_factor", lambda, "1", "path parameter (fraction of the travel moved)");
  g.write_dataset("coordinate", c, coordinate_unit, "the moved coordinate (" + t.control + ")");
  g.write_dataset(
      "force", f, force_unit, "the support's load on the moved coordinate (0 at a zero)" + scaled);
  g.write_dataset("slope",
                  slope,
                  force_unit + " / " + coordinate_unit,
                  "at a zero: d force / d coordinate along the path (> 0 with a stable "
                  "displacement-controlled state: a stable equilibrium with the coordinate "
                  "free); 0 at an extremum; NaN not computed");
  write_point_state(g, t.force_points, u, scaled);
  g.write_dataset("index_before", index, "1", "row of the path datasets before the point");
  g.write_dataset("located",
                  located,
                  "1",
                  "1 located on the path (or a sampled corner at a bifurcation), 0 the refinement "
                  "failed: the nearest path point");
}

}  // namespace

ShapesView path_shapes_view(const PathTable& t) {
  ShapesView v;
  v.rows = static_cast<long>(t.size());
  v.shape_points = t.shape_points;
  v.s = t.shape_s;
  v.x = t.shape_x;
  v.y = t.shape_y;
  v.theta = t.shape_theta;
  v.moment = t.shape_moment;
  v.axial = t.shape_axial;
  v.shear = t.shape_shear;
  v.stress_pos = t.shape_stress_pos;
  v.stress_neg = t.shape_stress_neg;
  v.row_name = "path point";
  v.length_unit = t.units.length_unit;
  v.force_unit = t.units.force_unit;
  v.moment_unit = t.units.moment_unit;
  v.scaled = t.units.system == "nondimensional" ? " (nondimensional: l = 1, EI = 1)" : "";
  return v;
}

void write_path_file(io::Hdf5Group& root, const PathTable& t) {
  const PathUnits& u = t.units;
  const bool nondimensional = u.system == "nondimensional";
  const std::string scaled = nondimensional ? " (nondimensional: l = 1, EI = 1)" : "";
  const std::string chain_only = t.method == PathMethod::kChain ? "; chain: NaN except at the last "
                                                                  "point"
                                                                : "";
  root.write_dataset(
      "load_factor",
      t.load_factor,
      "1",
      t.control == "load"
          ? "load factor lambda: 0 unloaded, 1 full load; may fall and rise at limit points"
          : "path parameter lambda: in the last stage the fraction of the controlled tip "
            "coordinate's travel (root attribute control)");
  root.write_dataset("tip_x", t.tip_x, u.length_unit, "tip x along the clamp's axis" + scaled);
  root.write_dataset(
      "tip_y", t.tip_y, u.length_unit, "tip y perpendicular to the clamp's axis" + scaled);
  root.write_dataset("tip_theta", t.tip_theta, "rad", "tip angle");
  root.write_dataset(
      "reaction_Fx", t.reaction_Fx, u.force_unit, "x force the clamp exerts" + scaled + chain_only);
  root.write_dataset(
      "reaction_Fy", t.reaction_Fy, u.force_unit, "y force the clamp exerts" + scaled + chain_only);
  root.write_dataset(
      "reaction_M", t.reaction_M, u.moment_unit, "moment the clamp exerts" + scaled + chain_only);
  const std::string tip_note =
      t.method == PathMethod::kChain
          ? "; chain: NaN (not recorded)"
          : "; a prescribed coordinate's component is the support's reaction";
  root.write_dataset(
      "tip_Fx", t.tip_Fx, u.force_unit, "total x force on the tip" + scaled + tip_note);
  root.write_dataset(
      "tip_Fy", t.tip_Fy, u.force_unit, "total y force on the tip" + scaled + tip_note);
  root.write_dataset(
      "tip_M", t.tip_M, u.moment_unit, "total moment on the tip" + scaled + tip_note);
  root.write_dataset("status", t.status, "1", "kind of point (root status_meanings)");
  root.write_dataset("stage",
                     t.stage,
                     "1",
                     "stage of a staged path: 1, then 2 (3) for the second stage of a pinned or "
                     "fixed straight beam and for the moving stage of --control");
  root.write_dataset("branch",
                     t.branch,
                     "1",
                     "0 on the path from zero load; k after switching at the k-th bifurcation");
  std::vector<int> stability, stability_index;
  std::vector<double> stability_margin;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Stability s = i < t.stability.size() ? t.stability[i] : Stability{};
    stability.push_back(static_cast<int>(s.kind));
    stability_index.push_back(s.judged() ? s.index : -1);
    stability_margin.push_back(s.judged() ? s.margin : kNaN);
  }
  const std::string under = t.control == "load"
                                ? "under load control (proportional loading)"
                                : "under displacement control of " + t.control +
                                      " in the moving stage (the loads applied first under load "
                                      "control)";
  root.write_dataset("stability",
                     stability,
                     "1",
                     "stability verdict of the point's equilibrium " + under +
                         ": 0 stable, 1 unstable, 2 critical, 3 not_conservative, 4 not_checked "
                         "(root status_meanings; docs/stability.md)");
  root.write_dataset("stability_index",
                     stability_index,
                     "1",
                     "independent directions in which the potential energy decreases (0 "
                     "stable); -1 where stability is 3 or 4");
  root.write_dataset("stability_margin",
                     stability_margin,
                     "1",
                     "lowest eigenvalue of the second variation relative to the unloaded bending "
                     "stiffness (1 - P/P_cr for a straight column); NaN where stability is 3 or 4");

  // The special points, exactly (the rows `index` of the path datasets hold them too).
  io::Hdf5Group sp = root.create_group("special_points");
  std::vector<std::string> kind;
  std::vector<double> lambda;
  std::vector<int> index, after, located, switched;
  for (const PathSpecialPoint& p : t.special_points) {
    kind.push_back(to_string(p.kind));
    lambda.push_back(p.load_factor);
    index.push_back(p.index);
    after.push_back(p.index_after);
    located.push_back(p.located ? 1 : 0);
    switched.push_back(p.switched ? 1 : 0);
  }
  sp.write_dataset("kind",
                   kind,
                   "text",
                   "limit_point (a fold of the load factor) or bifurcation (dg/dz singular while "
                   "the load factor keeps its direction)");
  sp.write_dataset("load_factor", lambda, "1", "load factor at the point (located to ~1e-10)");
  sp.write_dataset(
      "index", index, "1", "row of the path datasets holding the point (-1: not stored)");
  sp.write_dataset("index_after",
                   after,
                   "1",
                   "first row of the path datasets after the point (-1: the path stopped there)");
  write_point_state(sp, t.special_points, u, scaled);
  sp.write_dataset("located", located, "1", "1 located, 0 not refined (root status_meanings)");
  sp.write_dataset(
      "switched", switched, "1", "1 where the path left onto the other branch (--branch)");

  if (t.control != "load") write_force_points(root, t);

  if (t.shape_points > 0) write_shapes_group(root, path_shapes_view(t));

  root.set_attribute("method", to_string(t.method));
  if (t.method == PathMethod::kBcm || t.method == PathMethod::kCbcm) {
    root.set_attribute("elements", static_cast<std::int64_t>(t.elements));
    root.set_attribute("left_domain", static_cast<std::int64_t>(t.left_domain ? 1 : 0));
  }
  root.set_attribute("boundary", t.boundary);
  root.set_attribute("units", t.units.system);
  root.set_attribute("control", t.control);
  if (t.control != "load") root.set_attribute("control_target", t.control_target);
  root.set_attribute("completed", static_cast<std::int64_t>(t.completed ? 1 : 0));
  root.set_attribute("load_factor_reached", t.lambda_reached);
  root.set_attribute("limit_points", static_cast<std::int64_t>(t.limit_points));
  if (t.first_limit_load_factor) {
    root.set_attribute("first_limit_load_factor", *t.first_limit_load_factor);
  }
  root.set_attribute("bifurcation_points", static_cast<std::int64_t>(t.bifurcation_points));
  root.set_attribute("switched_branch", static_cast<std::int64_t>(t.switched_branch ? 1 : 0));
  root.set_attribute("shape_points", static_cast<std::int64_t>(t.shape_points));
  root.set_attribute("message", t.message);
  io::write_provenance(root, path_code_meanings());
}

PathFile::PathFile(const std::string& path, const std::string& shown_as) : path_(path) {
  try {
    file_ = std::make_unique<io::AtomicHdf5File>(path);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("{}: {}", shown_as, e.what()));
  }
}

PathFile::~PathFile() = default;
PathFile::PathFile(PathFile&&) noexcept = default;
PathFile& PathFile::operator=(PathFile&&) noexcept = default;

void PathFile::write(const PathTable& table) {
  if (!file_ || file_->committed()) {
    throw std::logic_error(path_ + ": a PathFile is written once only");
  }
  write_path_file(file_->root(), table);
  file_->commit();
}

}  // namespace flexure
