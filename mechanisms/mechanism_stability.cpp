#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <deque>

#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/mechanisms/mechanism_second_variation.h"
#include "flexure/mechanisms/prbm_virtual_work.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_problem.h"

namespace flexure::mechanism {

const char* to_string(SliderControl control) {
  return control == SliderControl::kDisplacement ? "displacement control" : "force control";
}

// ---- PRBM -------------------------------------------------------------------------------------

PointStability prbm_point_stability(const MechanismDesign& design,
                                    double displacement,
                                    double critical_tolerance) {
  PointStability out;
  // Slider held: the loop closure fixes the linkage (one degree of freedom, taken by the slider).
  out.displacement_control = classify_stability(0, 1.0, critical_tolerance, "the mechanism");
  out.displacement_control.message =
      "stable: with the slider held the pseudo-rigid-body linkage has no degree of freedom left "
      "(its loop closure fixes both link angles), so nothing can move; margin 1 by convention "
      "(no direction in which to lose stiffness)";
  // Dead load on the slider: Pi'' = V'' = dF/dDelta x against the springs' unloaded stiffness
  // (the original's springs and links: an inversion has the same relative motion and energy).
  const VirtualWorkState s = virtual_work_state(
      design.r2,
      design.r3,
      {design.spring_constant(1), design.spring_constant(2), design.spring_constant(3)},
      displacement);
  if (!(s.unloaded_stiffness > 0.0) || !std::isfinite(s.stiffness)) {
    out.force_control = not_checked_stability(fmt::format(
        "the PRBM's springs give the slider no stiffness at Delta x = {:.6g} m", displacement));
    return out;
  }
  const double margin = s.stiffness / s.unloaded_stiffness;
  const int index = margin < -critical_tolerance ? 1 : 0;
  out.force_control = classify_stability(index, margin, critical_tolerance, "the mechanism");
  out.force_control.message += fmt::format(
      "; under a dead slider load dF/dDelta x = {:.6g} N/m against the springs' unloaded {:.6g} "
      "N/m{}",
      s.stiffness,
      s.unloaded_stiffness,
      index > 0 ? " (the force falls with the stroke: snap-through under force control)" : "");
  return out;
}

// ---- Exact ------------------------------------------------------------------------------------

namespace {

ShootingSolver::Options shooting_options() { return ExactMechanismSolver::Options{}.shooting; }

// The solved chain's equilibrium at arc lengths s, integrated from its unknowns (all of them when
// they fit the problem's layout, else the root unknowns completed by one integration from the
// clamp, as shooting_shape_at does).
std::vector<ShapePoint> integrate_shape(const SegmentChain& chain,
                                        const std::vector<double>& unknowns,
                                        const std::vector<double>& s) {
  const ShootingSolver::Options o = shooting_options();
  const ShootingProblem problem(chain, o.multiple_shooting);
  ElasticaIntegrator integrator(o.integrator_options());
  std::string error;
  Eigen::VectorXd z;
  if (static_cast<int>(unknowns.size()) == problem.size()) {
    z = Eigen::Map<const Eigen::VectorXd>(unknowns.data(), problem.size());
  } else {
    const int n = problem.root_unknown_count();
    if (static_cast<int>(unknowns.size()) < n) {
      throw NoConvergence("the exact point has fewer unknowns than its chain's root loads");
    }
    Eigen::VectorXd root(n);
    for (int i = 0; i < n; ++i) root[i] = unknowns[static_cast<std::size_t>(i)];
    if (!problem.complete_guess(root, 1.0, integrator, z, error)) {
      throw NoConvergence("integrating the exact point for its shape failed: " + error);
    }
  }
  TipState tip;
  std::vector<ShapePoint> shape;
  if (!problem.integrate_solution(z, 1.0, integrator, tip, error, &s, &shape) ||
      shape.size() != s.size()) {
    throw NoConvergence("integrating the exact point for its shape failed: " + error);
  }
  return shape;
}

// The shapes integrated so far for one point: both controls sample the same chains at the same
// stations (which depend on the force only), so each shape is integrated once.
class ShapeMemo {
 public:
  const std::vector<ShapePoint>& at(const SegmentChain& chain,
                                    const std::vector<double>& unknowns,
                                    const std::vector<double>& s) {
    for (const Entry& e : entries_) {
      if (e.chain == &chain && e.s == s) return e.shape;
    }
    entries_.push_back({&chain, s, integrate_shape(chain, unknowns, s)});
    return entries_.back().shape;
  }

 private:
  struct Entry {
    const SegmentChain* chain;
    std::vector<double> s;
    std::vector<ShapePoint> shape;
  };
  std::deque<Entry> entries_;  // references stay valid as it grows
};

// The stations of a chain carrying the dead tip force (Nx, Ny) (its own frame).
std::vector<double> stations_of(const SegmentChain& chain,
                                double Nx,
                                double Ny,
                                const StabilityOptions& options) {
  SegmentChain c = chain;
  c.end = EndCondition::kFree;
  c.prescribed = TipPrescription{};
  c.tip_load = TipLoad{Nx, Ny, 0.0, 0.0};
  c.node_loads.clear();
  return stability_stations(c, Reaction{}, options);
}

double segment_length(const Segment& segment) {
  return std::visit([](const auto& seg) { return seg.length; }, segment);
}

// One chain of the point, placed on the path.
struct Part {
  const SegmentChain* chain = nullptr;
  const std::vector<double>* unknowns = nullptr;
  double Nx = 0.0, Ny = 0.0;  // force on its tip, its own frame (for the stations)
  bool turned = false;        // the coupler's frame: global = (xs - x, -y)
  bool reversed = false;      // walked from its tip to its root
  bool hinge_first = false;   // a pin before its first piece in path order
};

// The pieces of a part in path order, the frame of the path; `tip` gets the global position of
// the chain's tip (its last station).
std::vector<PathPiece> part_pieces(const Part& part,
                                   double xs,
                                   const StabilityOptions& options,
                                   ShapeMemo& memo,
                                   std::array<double, 2>& tip) {
  const SegmentChain& chain = *part.chain;
  const std::vector<double> s = stations_of(chain, part.Nx, part.Ny, options);
  const std::vector<ShapePoint>& shape = memo.at(chain, *part.unknowns, s);
  auto global = [&](const ShapePoint& p) {
    return part.turned ? std::array<double, 2>{xs - p.x, -p.y} : std::array<double, 2>{p.x, p.y};
  };
  const double tol = 1e-9 * chain.total_length();
  auto station = [&](double at) {
    const auto it = std::lower_bound(s.begin(), s.end(), at - tol);
    if (it == s.end() || std::fabs(*it - at) > tol) {
      throw InvalidInput(fmt::format("no station at the node s = {:.9g}", at));
    }
    return static_cast<std::size_t>(it - s.begin());
  };
  std::vector<PathPiece> pieces;
  double start = 0.0;
  for (const Segment& seg : chain.segments) {
    const double length = segment_length(seg);
    if (length > 0.0) {
      const std::size_t a = station(start), b = station(start + length);
      PathPiece p;
      p.length = length;
      if (const auto* f = std::get_if<FlexibleSegment>(&seg)) {
        p.EI = f->EI;
        for (std::size_t i = a; i <= b; ++i) p.points.push_back(global(shape[i]));
      } else {
        p.points = {global(shape[a]), global(shape[b])};
      }
      pieces.push_back(std::move(p));
    }
    start += length;
  }
  tip = global(shape.back());
  if (part.reversed) {
    std::reverse(pieces.begin(), pieces.end());
    for (PathPiece& p : pieces) std::reverse(p.points.begin(), p.points.end());
  }
  if (!pieces.empty()) pieces.front().hinge = part.hinge_first;
  return pieces;
}

void check_closure(double miss, double scale, const char* what) {
  if (!(miss <= 1e-7 * scale)) {
    throw NoConvergence(
        fmt::format("the exact point integrated again misses {} by {:.3g} (relative {:.3g}): not a "
                    "solution of this mechanism",
                    what,
                    miss,
                    miss / scale));
  }
}

}  // namespace

namespace {

MechanismPath build_path(const MechanismDesign& design,
                         const ExactPoint& point,
                         SliderControl control,
                         const StabilityOptions& options,
                         ShapeMemo& memo) {
  if (!point.converged()) throw InvalidInput("exact_mechanism_path needs a converged point");
  const ExactSupport support = exact_support(design);
  const double L = point.length_scale;
  const double force_scale = point.EI_scale / (L * L);
  // Nondimensional, as the point's chains.
  const double xs = (L - point.displacement) / L;
  MechanismPath path;
  path.Nx = point.Nx / force_scale;
  path.Ny = point.Ny / force_scale;
  path.hold_x = control == SliderControl::kDisplacement;
  path.hold_y = true;
  std::array<double, 2> tip{};
  auto append = [&](std::vector<PathPiece> more) {
    for (PathPiece& p : more) path.pieces.push_back(std::move(p));
  };
  switch (support) {
    case ExactSupport::kDirectChain:
    case ExactSupport::kPinnedEnds: {
      // One chain from the ground to the slider joint (pinned ends: from the ground pin, whose
      // root kink carries the crank angle).
      Part crank{&point.chain, &point.unknowns, path.Nx, path.Ny};
      crank.hinge_first = support == ExactSupport::kPinnedEnds;
      append(part_pieces(crank, xs, options, memo, tip));
      check_closure(std::hypot(tip[0] - xs, tip[1]), xs, "the slider joint");
      path.hold_theta = point.chain.end == EndCondition::kFixed;
      break;
    }
    case ExactSupport::kTwoForceCoupler: {
      // The crank, then the rigid coupler between pivot 2 and the slider pin.
      Part crank{&point.chain, &point.unknowns, path.Nx, path.Ny};
      append(part_pieces(crank, xs, options, memo, tip));
      const double r3 = design.r3 / L;
      check_closure(std::fabs(std::hypot(xs - tip[0], tip[1]) - r3), xs, "the coupler's length");
      PathPiece coupler;
      coupler.length = r3;
      coupler.points = {tip, {xs, 0.0}};
      coupler.hinge = true;
      path.pieces.push_back(std::move(coupler));
      break;
    }
    case ExactSupport::kPinnedMiddle: {
      // The crank to pivot 2, the pin, then the coupler chain walked from pivot 2 to its clamp in
      // the slider (its frame turned by pi about the slider). The force across every section is
      // the pin force P in the path's frame; in the coupler's own frame its tip load reads +P.
      Part crank{&point.chain, &point.unknowns, path.Nx, path.Ny};
      append(part_pieces(crank, xs, options, memo, tip));
      Part coupler{&point.coupler_chain, &point.coupler_unknowns, path.Nx, path.Ny};
      coupler.turned = true;
      coupler.reversed = true;
      coupler.hinge_first = true;
      std::array<double, 2> coupler_tip{};
      append(part_pieces(coupler, xs, options, memo, coupler_tip));
      check_closure(std::hypot(tip[0] - coupler_tip[0], tip[1] - coupler_tip[1]), xs, "pivot 2");
      path.hold_theta = true;  // the coupler's flexure is clamped into the slider
      break;
    }
    case ExactSupport::kPrbmOnly:
      throw InvalidInput(fmt::format("design {} has no exact model", design.name));
  }
  return path;
}

}  // namespace

MechanismPath exact_mechanism_path(const MechanismDesign& design,
                                   const ExactPoint& point,
                                   SliderControl control,
                                   const StabilityOptions& options) {
  ShapeMemo memo;
  return build_path(design, point, control, options, memo);
}

namespace {

int path_elements(const MechanismPath& path) {
  int n = 0;
  for (const PathPiece& p : path.pieces) n += static_cast<int>(p.points.size()) - 1;
  return n;
}

// The path's verdict, the stations doubled until the margin's estimated error is below
// margin_accuracy (as equilibrium_stability's ShapeAtStations form).
Stability judge_path(const MechanismDesign& design,
                     const ExactPoint& point,
                     SliderControl control,
                     const StabilityOptions& options,
                     ShapeMemo& memo) {
  StabilityOptions o = options;
  for (;;) {
    const MechanismPath path = build_path(design, point, control, o, memo);
    const PathVerdict v = path_stability(path, o, "the mechanism");
    const bool refinable = 2 * path_elements(path) <= o.max_elements;
    if (!v.stability.judged() || !refinable ||
        v.margin_error <= o.margin_accuracy * std::max(1.0, std::fabs(v.stability.margin))) {
      return v.stability;
    }
    o.element_resolution *= 0.5;
    o.min_elements = std::min(2 * o.min_elements, o.max_elements);
  }
}

// A serial chain judged by the chain's own verdict: displacement control with its end as solved
// (pinned or fixed at the slider); force control of a pinned slider end as a `slider` end carrying
// the slider force as a dead load.
Stability judge_chain(const ExactPoint& point,
                      SliderControl control,
                      const StabilityOptions& options,
                      ShapeMemo& memo) {
  const double L = point.length_scale;
  const double force_scale = point.EI_scale / (L * L);
  const double Nx = point.Nx / force_scale, Ny = point.Ny / force_scale;
  SegmentChain chain = point.chain;
  Reaction support = tip_support_reaction(chain, Reaction{Nx, Ny, 0.0});
  if (control == SliderControl::kForce) {
    chain.end = EndCondition::kSlider;
    chain.prescribed.x.reset();
    chain.prescribed.theta.reset();
    chain.tip_load.Fx = Nx;
    support = Reaction{0.0, Ny, 0.0};
  }
  const double xs = *point.chain.prescribed.x;
  return equilibrium_stability(
      chain,
      support,
      [&](const std::vector<double>& s) {
        std::vector<ShapePoint> shape = memo.at(point.chain, point.unknowns, s);
        if (!shape.empty() && s.back() >= point.chain.total_length() * (1.0 - 1e-12)) {
          check_closure(std::hypot(shape.back().x - xs, shape.back().y), xs, "the slider joint");
        }
        return shape;
      },
      options);
}

Stability with_control(Stability s, SliderControl control) {
  s.message = fmt::format("{}: {}", to_string(control), s.message);
  return s;
}

}  // namespace

PointStability exact_point_stability(const MechanismDesign& design,
                                     const ExactPoint& point,
                                     const StabilityOptions& options) {
  options.validate();
  PointStability out;
  if (!point.converged()) {
    out.displacement_control = out.force_control =
        not_checked_stability("the exact model did not converge at this stroke point");
    return out;
  }
  const ExactSupport support = exact_support(design);
  ShapeMemo memo;
  if (support == ExactSupport::kDirectChain) {
    out.displacement_control = judge_chain(point, SliderControl::kDisplacement, options, memo);
    // A pin at the slider: the chain's slider end; a flexure clamped into it (y and the angle
    // held, x free) is none of the chain's ends: the path.
    out.force_control = point.chain.end == EndCondition::kPinned
                            ? judge_chain(point, SliderControl::kForce, options, memo)
                            : judge_path(design, point, SliderControl::kForce, options, memo);
  } else {
    out.displacement_control =
        judge_path(design, point, SliderControl::kDisplacement, options, memo);
    out.force_control = judge_path(design, point, SliderControl::kForce, options, memo);
  }
  out.displacement_control =
      with_control(std::move(out.displacement_control), SliderControl::kDisplacement);
  out.force_control = with_control(std::move(out.force_control), SliderControl::kForce);
  return out;
}

// ---- Summaries --------------------------------------------------------------------------------

std::vector<StabilityStretch> stability_stretches(const std::vector<double>& displacement,
                                                  const std::vector<Stability>& verdicts) {
  if (displacement.size() != verdicts.size()) {
    throw InvalidInput(
        fmt::format("{} displacements for {} verdicts", displacement.size(), verdicts.size()));
  }
  std::vector<StabilityStretch> out;
  for (std::size_t i = 0; i < verdicts.size(); ++i) {
    const Stability& v = verdicts[i];
    const int index = v.kind == StabilityKind::kUnstable ? v.index : 0;
    if (out.empty() || out.back().kind != v.kind || out.back().index != index) {
      StabilityStretch s;
      s.kind = v.kind;
      s.index = index;
      s.first = i;
      s.from = displacement[i];
      s.least_margin = v.margin;
      out.push_back(s);
    }
    StabilityStretch& s = out.back();
    s.last = i;
    s.to = displacement[i];
    s.least_margin = std::min(s.least_margin, v.margin);
  }
  return out;
}

StrokeStability summarise_stroke_stability(std::vector<Stability> points,
                                           const std::vector<double>& displacement,
                                           const char* model,
                                           SliderControl control,
                                           const std::vector<Stability>* held) {
  StrokeStability out;
  out.points = std::move(points);
  bool any_judged = false;
  double least_at = 0.0;
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const Stability& v = out.points[i];
    out.unstable_points += v.kind == StabilityKind::kUnstable ? 1 : 0;
    out.critical_points += v.kind == StabilityKind::kCritical ? 1 : 0;
    out.not_checked_points += v.judged() ? 0 : 1;
    if (!v.judged()) continue;
    if (!any_judged || v.margin < out.least_margin) {
      out.least_margin = v.margin;
      least_at = displacement[i];
    }
    out.largest_margin = any_judged ? std::max(out.largest_margin, v.margin) : v.margin;
    any_judged = true;
  }
  const std::vector<StabilityStretch> stretches = stability_stretches(displacement, out.points);
  auto mm = [](double x) { return fmt::format("{:.4g}", 1e3 * x); };
  std::string text = fmt::format("{} ({}): ", to_string(control), model);
  for (std::size_t k = 0; k < stretches.size(); ++k) {
    const StabilityStretch& s = stretches[k];
    if (k > 0) text += "; ";
    std::string what(stability_name(s.kind));
    if (s.kind == StabilityKind::kUnstable) what += fmt::format(" (index {})", s.index);
    text += stretches.size() == 1 ? fmt::format("{} at all {} points", what, s.last - s.first + 1)
            : s.first == s.last
                ? fmt::format("{} at Delta x = {} mm", what, mm(s.from))
                : fmt::format("{} for Delta x in [{}, {}] mm", what, mm(s.from), mm(s.to));
    if (s.kind == StabilityKind::kUnstable && control == SliderControl::kForce) {
      // One negative direction more than with the slider held: the slider's own, where dF/dx < 0.
      const int held_index = held != nullptr && s.first < held->size() &&
                                     (*held)[s.first].kind == StabilityKind::kUnstable
                                 ? (*held)[s.first].index
                                 : 0;
      text += s.index > held_index ? " (the force falls: snap-through under a dead load)"
                                   : " (unstable with the slider held as well)";
    }
  }
  const bool rigid_linkage =
      std::string_view(model) == "PRBM" && control == SliderControl::kDisplacement &&
      out.unstable_points + out.critical_points + out.not_checked_points == 0;
  if (rigid_linkage) {
    text +=
        " (held at its slider the pseudo-rigid-body linkage has no degree of freedom; margin 1 by "
        "convention)";
  } else if (any_judged) {
    text += fmt::format("; least margin {:.3g} at Delta x = {} mm", out.least_margin, mm(least_at));
    if (control == SliderControl::kForce &&
        std::max(std::fabs(out.least_margin), std::fabs(out.largest_margin)) <=
            kNearCriticalMargin) {
      text += fmt::format(
          "; margins within +-{:g} over the whole stroke: near-critical by design (a "
          "constant-force mechanism holds a dead load with almost no stiffness of its own)",
          kNearCriticalMargin);
    }
  } else {
    text += " (not judged)";
  }
  out.summary = std::move(text);
  return out;
}

}  // namespace flexure::mechanism
