// `flexure path`: the equilibrium path from zero load (proportional loading or a moved tip
// coordinate), by pseudo-arclength continuation (shooting; folds and bifurcations located) or the
// chain algorithm's load increments, written to HDF5. The work is in
// benchmarks/studies/load_path_study.h; this file parses, calls and prints.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "cli/beam_methods.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/physical_flags.h"
#include "flexure/beam/beam_problem.h"
#include "flexure/benchmarks/studies/load_path_study.h"
#include "flexure/benchmarks/studies/path_shapes_xdmf.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/toml_files.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure::cli {
namespace {

struct PathArgs {
  double load_ratio_n = 0.0;
  double alpha2 = 0.0;
  double mu = 0.0;
  double follower = 0.0;
  std::string boundary = "free";
  std::string tip_x, tip_y, tip_angle;
  CLI::Option* tip_x_option = nullptr;
  CLI::Option* tip_y_option = nullptr;
  CLI::Option* tip_angle_option = nullptr;
  CLI::Option* n_option = nullptr;
  CLI::Option* alpha2_option = nullptr;
  CLI::Option* mu_option = nullptr;
  CLI::Option* follower_option = nullptr;
  std::string method = "shooting";
  int elements = 100;
  CLI::Option* elements_option = nullptr;
  int increments = 10;
  std::string chain_file;
  CLI::Option* chain_option = nullptr;
  PhysicalFlags physical;
  // Continuation (shooting only).
  double max_step = 0.0;
  CLI::Option* max_step_option = nullptr;
  int min_points = 0;
  CLI::Option* min_points_option = nullptr;
  int branch = 0;
  std::string branch_side = "positive";
  std::string control = "load";
  bool one_way = false;  // --one-way: go on past a fold of the moved coordinate
  int shapes = 0;
  CLI::Option* shapes_option = nullptr;
  std::string stability = "on";  // --stability on|off: the verdict of every point
  std::string out;
  std::string csv;
  bool json = false;
};

// A nondimensional tip coordinate (x/l, y/l): a plain number; a unit needs a physical beam.
double plain_length(const std::string& text, const char* what) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0') {
    throw InvalidInput(fmt::format(
        "{} = '{}': a tip coordinate of Howell's nondimensional beam is a plain number (x/l, "
        "y/l); a length with a unit needs a physical beam (--length, --E, the section)",
        what,
        text));
  }
  require_finite_input(value, what);
  return value;
}

TipCoordinate control_coordinate(const std::string& name) {
  if (name == "tip-x") return TipCoordinate::kX;
  if (name == "tip-y") return TipCoordinate::kY;
  return TipCoordinate::kTheta;
}

// The request `flexure path` describes: the chain (nondimensional, physical or from a file), its
// units, the method and the continuation settings.
PathRequest make_request(const PathArgs& args) {
  PathRequest request;
  const bool physical = args.physical.given();
  const bool from_file = bool(*args.chain_option);
  const bool howell =
      *args.n_option || *args.alpha2_option || *args.mu_option || *args.follower_option;
  if (physical && (howell || from_file)) {
    throw InvalidInput(
        "a physical beam (--length, --E, the section, --Fx, --Fy, --M) is loaded in newtons; do "
        "not combine it with the nondimensional --n, --alpha2, --mu, --follower or with --chain");
  }
  // The file first: its own errors (a missing file, bad TOML) are named before the combination.
  std::optional<SegmentChain> file_chain;
  bool file_physical = false;  // units = "SI" (or a value with a unit): results in m, N, N m
  if (from_file) {
    const io::ChainFile file = io::read_chain_file(args.chain_file);
    if (!file.contacts.empty()) {
      throw InvalidInput(
          "path --chain: a [[contact]] is solved by `flexure beam --chain FILE` only (its load "
          "continuation reports landing and lift-off; docs/contact.md)");
    }
    for (std::size_t k = 0; k < file.segments.size(); ++k) {
      if (file.segments[k] && file.segments[k]->plate == PlateRule::kAuto) {
        // As --plate auto below: one solved curvature decides, a path passes through many.
        throw InvalidInput(
            fmt::format("{}: segment {} has plate = \"auto\", which is decided by a solved beam's "
                        "curvature; a path passes through many: give plate = \"on\" or \"off\"",
                        args.chain_file,
                        k + 1));
      }
    }
    file_chain = file.chain;
    file_physical = file.physical;
  }
  if (from_file && (howell || args.boundary != "free")) {
    throw InvalidInput(
        "--chain FILE.toml describes the whole problem (segments, loads, boundary); do not "
        "combine it with --n, --alpha2, --mu, --follower or --boundary");
  }
  const EndCondition end = from_file ? file_chain->end : end_condition_from_string(args.boundary);
  const bool controlled = args.control != "load";
  const TipCoordinate coordinate = control_coordinate(args.control);

  // The tip targets: metres for a physical beam, x/l and y/l otherwise; angles in rad or with a
  // unit. A coordinate may be given only when the end condition or --control prescribes it.
  const PrescribedMask mask = prescribed_mask(end);
  auto allowed = [&](bool by_end, TipCoordinate c, const char* flag) {
    if (controlled && coordinate == c) return;
    if (from_file) {
      throw InvalidInput(fmt::format(
          "{}: with --chain the file prescribes the tip (its end condition and values); the tip "
          "flags only give the target of --control",
          flag));
    }
    if (by_end) return;
    throw InvalidInput(fmt::format(
        "{} is not prescribed by --boundary {} (it prescribes {}); --control {} moves that "
        "coordinate as the path parameter",
        flag,
        args.boundary,
        mask.x || mask.y || mask.theta ? fmt::format("{}{}{}",
                                                     mask.x ? "tip x " : "",
                                                     mask.y ? "tip y " : "",
                                                     mask.theta ? "tip angle" : "")
                                       : std::string("nothing"),
        flag + 2));
  };
  TipPrescription tip;
  auto length_value = [&](const std::string& text, const char* flag) {
    // A chain file in SI units takes metres too (plain, or with a unit: 5mm).
    return physical || file_physical ? io::parse_quantity(text, io::Dimension::kLength, flag).si
                                     : plain_length(text, flag);
  };
  if (*args.tip_x_option) {
    allowed(mask.x, TipCoordinate::kX, "--tip-x");
    tip.x = length_value(args.tip_x, "--tip-x");
  }
  if (*args.tip_y_option) {
    allowed(mask.y, TipCoordinate::kY, "--tip-y");
    tip.y = length_value(args.tip_y, "--tip-y");
  }
  if (*args.tip_angle_option) {
    allowed(mask.theta, TipCoordinate::kTheta, "--tip-angle");
    const io::Quantity angle =
        io::parse_quantity(args.tip_angle, io::Dimension::kAngle, "--tip-angle");
    warn(io::angle_warning(angle, "--tip-angle"));
    tip.theta = angle.si;
  }
  // --control: the target is the coordinate's own flag; the end condition keeps only what it
  // prescribes (a coordinate it leaves free is added by the control).
  std::optional<double> target;
  if (controlled) {
    const std::optional<double>& given = coordinate == TipCoordinate::kX   ? tip.x
                                         : coordinate == TipCoordinate::kY ? tip.y
                                                                           : tip.theta;
    if (!given) {
      throw InvalidInput(fmt::format(
          "--control {} moves the tip to the value of --{}; give it (the target of the path)",
          args.control,
          args.control));
    }
    target = *given;
    const bool by_end = coordinate == TipCoordinate::kX   ? mask.x
                        : coordinate == TipCoordinate::kY ? mask.y
                                                          : mask.theta;
    if (!by_end) {
      (coordinate == TipCoordinate::kX   ? tip.x
       : coordinate == TipCoordinate::kY ? tip.y
                                         : tip.theta)
          .reset();
    }
  }

  if (physical) {
    const PhysicalCantilever beam = args.physical.parse();
    if (beam.plate == PlateRule::kAuto) {
      // auto is decided at one solved curvature; a path passes through many (plate-modulus.md).
      throw InvalidInput(
          "--plate auto is decided by a solved beam's curvature; a path passes "
          "through many: choose --plate on or off");
    }
    request.chain = beam.to_chain(end, tip);
    request.units = PathUnits::si(beam.length, beam.flexural_rigidity());
    // The section at each shape point: the fibre stresses of /shapes.
    if (args.shapes >= 2 && args.shapes <= 1'000'000) {  // else refused below
      beam.fibre_sections(args.shapes, request.shape_section_modulus, request.shape_area);
    }
  } else if (from_file) {
    request.chain = *file_chain;
    request.units = PathUnits::chain_file(file_physical);
  } else {
    require_finite_input(args.load_ratio_n, "--n (load ratio n)");
    require_finite_input(args.alpha2, "--alpha2 (P l^2/EI)");
    require_finite_input(args.mu, "--mu (end moment M l/EI)");
    require_finite_input(args.follower, "--follower (follower force F l^2/EI)");
    BeamProblem problem;
    problem.load_ratio_n = args.load_ratio_n;
    problem.mu = args.mu;
    problem.follower = args.follower;
    problem.boundary = end;
    problem.prescribed = tip;
    request.chain = problem.to_chain(args.alpha2);
    request.units = PathUnits::nondimensional();
  }
  if (controlled) {
    const double scale =
        coordinate == TipCoordinate::kTheta || !physical ? 1.0 : 1.0 / request.units.length;
    request.control = DisplacementControl{coordinate, *target * scale};
    request.control->one_way = args.one_way;
  } else if (args.one_way) {
    throw InvalidInput(
        "--one-way moves a tip coordinate one way (displacement control): give --control "
        "tip-x|tip-y|tip-angle");
  }

  request.method = args.method == "chain"  ? PathMethod::kChain
                   : args.method == "bcm"  ? PathMethod::kBcm
                   : args.method == "cbcm" ? PathMethod::kCbcm
                                           : PathMethod::kShooting;
  if (request.method == PathMethod::kBcm && *args.elements_option) {
    throw InvalidInput("--method bcm is one BCM element; --elements N belongs to --method cbcm");
  }
  require_in_range(args.elements, "--elements (chain algorithm elements N)", 1, 1'000'000);
  require_in_range(args.increments, "--increments (load increments)", 1, 1'000'000);
  request.elements = args.elements;
  // The CBCM's default: 20 elements (docs/models.md: tip error about 1e-4 L on the reference
  // inclined beam), not the chain algorithm's 100.
  if (request.method == PathMethod::kCbcm && !*args.elements_option) request.elements = 20;
  request.increments = args.increments;
  if (*args.max_step_option) {
    require_in_range(args.max_step, "--max-step (largest arclength step)", 1e-6, 10.0);
    request.max_step = args.max_step;
  }
  if (*args.min_points_option) {
    require_in_range(args.min_points, "--min-points (points from zero to full load)", 2, 1e6);
    request.min_points = args.min_points;
  }
  request.judge_stability = same_name(args.stability, "on");
  request.branch = args.branch;
  request.branch_side = args.branch_side == "negative" ? -1 : 1;
  if (*args.shapes_option) {
    require_in_range(args.shapes, "--shapes (shape points per path point)", 2, 1e6);
    request.shape_points = args.shapes;
  }
  return request;
}

Json maybe_index(int index) { return index >= 0 ? Json(index) : Json(nullptr); }

// The keys a special point and a force point share (the fields of the same names), in the order
// both objects list them.
template <class Point>
Json point_state_json(const Point& p) {
  return Json{{"tip_x", p.tip_x},
              {"tip_y", p.tip_y},
              {"tip_theta", p.tip_theta},
              {"reaction_Fx", p.reaction_Fx},
              {"reaction_Fy", p.reaction_Fy},
              {"reaction_M", p.reaction_M},
              {"tip_Fx", p.tip_Fx},
              {"tip_Fy", p.tip_Fy},
              {"tip_M", p.tip_M},
              {"stage", p.stage},
              {"branch", p.branch},
              {"located", p.located}};
}

Json special_point_json(const PathSpecialPoint& p) {
  Json j{{"kind", to_string(p.kind)},
         {"load_factor", p.load_factor},
         {"index", maybe_index(p.index)},
         {"index_after", maybe_index(p.index_after)}};
  j.update(point_state_json(p));
  j["switched"] = p.switched;
  return j;
}

Json force_point_json(const PathForcePoint& p) {
  Json j{{"kind", to_string(p.kind)},
         {"load_factor", p.load_factor},
         {"coordinate", p.coordinate},
         {"force", p.force},
         {"slope", std::isfinite(p.slope) ? Json(p.slope) : Json(nullptr)},
         {"index_before", maybe_index(p.index_before)}};
  j.update(point_state_json(p));
  return j;
}

// The verdict of every point as columns (null where not judged) and its stretches.
void add_stability_json(Json& out, const PathTable& t) {
  Json kind = Json::array(), index = Json::array(), margin = Json::array();
  for (const Stability& s : t.stability) {
    kind.push_back(std::string(stability_name(s.kind)));
    index.push_back(s.judged() ? Json(s.index) : Json(nullptr));
    margin.push_back(s.judged() && std::isfinite(s.margin) ? Json(s.margin) : Json(nullptr));
  }
  out["stability"] = std::move(kind);
  out["stability_index"] = std::move(index);
  out["stability_margin"] = std::move(margin);
  Json stretches = Json::array();
  for (const StabilityStretch& s : t.stability_stretches()) {
    const bool judged = s.kind == StabilityKind::kStable || s.kind == StabilityKind::kUnstable ||
                        s.kind == StabilityKind::kCritical;
    stretches.push_back(Json{{"stability", std::string(stability_name(s.kind))},
                             {"stability_index", judged ? Json(s.index) : Json(nullptr)},
                             {"first_index", s.first},
                             {"last_index", s.last},
                             {"first_load_factor", s.first_load_factor},
                             {"last_load_factor", s.last_load_factor}});
  }
  out["stability_stretches"] = std::move(stretches);
}

// "under load control" / "under displacement control of tip-y" (the text output).
std::string stability_control_words(const PathTable& t) {
  return t.control == "load"
             ? "under load control"
             : fmt::format("under displacement control of {} in the moving stage", t.control);
}

Json special_points_json(const PathTable& t, SpecialPointKind kind) {
  Json list = Json::array();
  for (const PathSpecialPoint* p : t.of_kind(kind)) list.push_back(special_point_json(*p));
  return list;
}

void print_text(const PathTable& t, const PathArgs& args, const std::string& written) {
  fmt::print("{} load path: {} points, load factor reached {:.6g}, {} limit point(s){}; {}\n",
             args.method,
             t.size(),
             t.lambda_reached,
             t.limit_points,
             t.bifurcation_points > 0
                 ? fmt::format(", {} bifurcation point(s)", t.bifurcation_points)
                 : std::string(),
             t.message);
  const PathUnits& u = t.units;
  const bool si = u.system == "SI";
  const char* m = si ? " m" : "";
  const char* N = si ? " N" : "";
  const char* Nm = si ? " N m" : "";
  for (const PathSpecialPoint& p : t.special_points) {
    // (+ 0.0 prints a negative zero as 0.)
    fmt::print(
        "  {} at load factor {:.10g}{} (path point {}): tip x = {:.8g}{}, y = {:.8g}{}, angle = "
        "{:.8g} rad; clamp reaction Fx = {:.8g}{}, Fy = {:.8g}{}, M = {:.8g}{}{}\n",
        p.kind == SpecialPointKind::kLimitPoint ? "limit point" : "bifurcation",
        p.load_factor,
        p.located ? "" : " (not located)",
        p.index >= 0 ? p.index : p.index_after,
        p.tip_x + 0.0,
        m,
        p.tip_y + 0.0,
        m,
        p.tip_theta + 0.0,
        p.reaction_Fx + 0.0,
        N,
        p.reaction_Fy + 0.0,
        N,
        p.reaction_M + 0.0,
        Nm,
        p.switched ? "; the path left here onto the other branch" : "");
  }
  const bool angle = t.control == "tip-angle";
  for (const PathForcePoint& p : t.force_points) {
    const char* cu = angle ? " rad" : m;
    const char* fu = angle ? Nm : N;
    fmt::print("  {} of the {} load at {} = {:.10g}{} (load factor {:.10g}{}): {} = {:.8g}{}{}\n",
               p.kind == ForcePointKind::kZero      ? "zero crossing"
               : p.kind == ForcePointKind::kMaximum ? "maximum"
                                                    : "minimum",
               angle ? "tip-angle" : t.control,
               t.control,
               p.coordinate + 0.0,
               cu,
               p.load_factor,
               p.located ? "" : ", not located",
               angle ? "tip M" : (t.control == "tip-x" ? "tip Fx" : "tip Fy"),
               p.force + 0.0,
               fu,
               p.kind == ForcePointKind::kZero && std::isfinite(p.slope)
                   ? fmt::format(", slope {:.6g}", p.slope)
                   : std::string());
  }
  const std::vector<StabilityStretch> stretches = t.stability_stretches();
  if (!stretches.empty()) {
    fmt::print("  stability {}:\n", stability_control_words(t));
    for (const StabilityStretch& s : stretches) fmt::print("    {}\n", describe(s));
  }
  fmt::print("written to {}\n", written);
}

void run_path(const PathArgs& args) {
  const PathRequest request = make_request(args);
  request.validate();
  // Check and open the output first: an unwritable path fails before any solving (exit 2).
  require_out_or_csv(args.out, args.csv);
  if (!args.out.empty()) io::check_output_path(args.out);
  const CsvOutput csv(args.out, args.csv);
  PathFile output(csv.hdf5_path(), fmt::format("--out {}", csv.written_path()));
  const auto start = std::chrono::steady_clock::now();
  const PathTable t = run_load_path(request);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  output.write(t);
  csv.write({"load_factor"}, {"special_points", "force_points", "shapes"});
  // With --shapes, the XDMF sidecar that ParaView opens (io/shapes_xdmf.h); not for a hidden
  // temporary HDF5 file (--out FILE.csv, or --csv alone), which is removed.
  const std::string xdmf =
      csv.hdf5_path() == args.out ? write_path_shapes_xdmf(args.out, t) : std::string();
  for (const std::string& w : t.warnings) warn(w);
  if (args.json) {
    Json out{{"out", csv.out_json()},
             {"csv", csv.csv_json()},
             {"xdmf", xdmf.empty() ? Json(nullptr) : Json(xdmf)},
             {"method", args.method},
             {"points", static_cast<long>(t.size())},
             {"completed", t.completed},
             {"load_factor_reached", t.lambda_reached},
             {"limit_points", t.limit_points},
             {"message", t.message},
             {"seconds", seconds}};
    out["units"] = t.units.system;
    out["boundary"] = t.boundary;
    out["control"] = t.control;
    out["control_target"] = t.control == "load" ? Json(nullptr) : Json(t.control_target);
    out["first_limit_load_factor"] =
        t.first_limit_load_factor ? Json(*t.first_limit_load_factor) : Json(nullptr);
    out["bifurcation_points"] = t.bifurcation_points;
    out["bifurcations"] = special_points_json(t, SpecialPointKind::kBifurcation);
    out["limit_point_list"] = special_points_json(t, SpecialPointKind::kLimitPoint);
    // Displacement control: the force-displacement curve's zeros and extrema (null under load
    // control).
    if (t.control == "load") {
      out["force_points"] = nullptr;
      out["force_zero_crossings"] = nullptr;
    } else {
      Json list = Json::array();
      int zeros = 0;
      for (const PathForcePoint& p : t.force_points) {
        list.push_back(force_point_json(p));
        zeros += p.kind == ForcePointKind::kZero ? 1 : 0;
      }
      out["force_points"] = std::move(list);
      out["force_zero_crossings"] = zeros;
    }
    out["branch"] = args.branch;
    out["switched_branch"] = t.switched_branch;
    out["steps"] = t.steps;
    out["rejected_steps"] = t.rejected_steps;
    out["location_corrections"] = t.location_corrections;
    out["shape_points"] = t.shape_points;
    if (t.method == PathMethod::kBcm || t.method == PathMethod::kCbcm) {
      out["elements"] = t.elements;
      out["left_domain"] = t.left_domain;
    }
    add_stability_json(out, t);
    print_json(out);
  } else {
    print_text(t, args, csv.written_path());
  }
  if (t.left_domain) {
    // The BCM answers within its range only: the path up to there is written, exit code 2.
    throw OutsideMethodDomain(
        fmt::format("the bcm load path stopped at load factor {:.6g}: {} (the "
                    "path up to there is in {})",
                    t.lambda_reached,
                    t.message,
                    csv.written_path()));
  }
  if (!t.completed) {
    throw NoConvergence(fmt::format(
        "the {} load path stopped at load factor {:.6g}: {} (the path up to there is in {})",
        args.method,
        t.lambda_reached,
        t.message,
        csv.written_path()));
  }
  if (args.branch > 0 && !t.switched_branch) {
    throw NoConvergence(fmt::format(
        "--branch {}: the path met {} bifurcation(s) on the way to full load, so there was no "
        "branch to follow; the path from zero load is in {}",
        args.branch,
        t.bifurcation_points,
        csv.written_path()));
  }
}

}  // namespace

void register_path_command(CLI::App& app) {
  auto args = std::make_shared<PathArgs>();
  CLI::App* path = app.add_subcommand(
      "path",
      "Equilibrium path from zero load (continuation: limit points and bifurcations located, "
      "branch switching, displacement control), written to HDF5");
  args->n_option = path->add_option("--n",
                                    args->load_ratio_n,
                                    "Load ratio n: horizontal load nP, n > 0 "
                                    "compressive")
                       ->default_str("0");
  args->alpha2_option =
      path->add_option("--alpha2", args->alpha2, "Full load alpha2 = P l^2/EI")->default_str("0");
  args->mu_option = path->add_option("--mu", args->mu, "End moment mu = M l/EI")->default_str("0");
  args->follower_option =
      path->add_option("--follower", args->follower, "Follower tip force F l^2/EI")
          ->default_str("0");
  path->add_option("--boundary", args->boundary, "free | guided | pinned | slider | fixed")
      ->default_str("free")
      ->transform(CLI::IsMember({"free", "guided", "pinned", "slider", "fixed"}, CLI::ignore_case));
  args->tip_x_option = path->add_option(
      "--tip-x", args->tip_x, "Prescribed tip x (x/l; metres or with a unit for a physical beam)");
  args->tip_y_option = path->add_option(
      "--tip-y", args->tip_y, "Prescribed tip y (y/l; metres or with a unit for a physical beam)");
  args->tip_angle_option =
      path->add_option("--tip-angle", args->tip_angle, "Prescribed tip angle (rad, or 30deg)");
  path->add_option("--method",
                   args->method,
                   "shooting (arc-length continuation) | chain | bcm | cbcm (the beam-constraint "
                   "models under --control; docs/models.md)")
      ->default_str("shooting")
      ->transform(CLI::IsMember({"shooting", "chain", "bcm", "cbcm"}, CLI::ignore_case));
  args->elements_option = path->add_option("--elements",
                                           args->elements,
                                           "Chain algorithm (default 100) or CBCM "
                                           "(default 20): elements N");
  path->add_option("--increments", args->increments, "Chain algorithm: load increments")
      ->default_str("10");
  args->chain_option =
      path->add_option("--chain", args->chain_file, "Segment chain from a TOML file");
  args->max_step_option = path->add_option(
      "--max-step",
      args->max_step,
      "Largest arclength step of the continuation (scaled: about one unit of load factor at the "
      "start; default 0.5)");
  args->min_points_option = path->add_option(
      "--min-points",
      args->min_points,
      "At least N points from zero to full load (the load factor changes by at most 1/(N-1) per "
      "step)");
  path->add_option("--branch",
                   args->branch,
                   "Leave the path at its N-th bifurcation onto the other branch and follow it "
                   "to full load")
      ->default_str("0");
  path->add_option("--branch-side",
                   args->branch_side,
                   "positive: the half-branch on which the tip moves to +y (+angle when y "
                   "cannot move); negative: the other")
      ->default_str("positive")
      ->transform(CLI::IsMember({"positive", "negative"}, CLI::ignore_case));
  path->add_option("--control",
                   args->control,
                   "load (proportional loading) | tip-x | tip-y | tip-angle: move that tip "
                   "coordinate to its --tip-... value as the path parameter (displacement "
                   "control), the loads applied first")
      ->default_str("load")
      ->transform(CLI::IsMember({"load", "tip-x", "tip-y", "tip-angle"}, CLI::ignore_case));
  path->add_flag("--one-way",
                 args->one_way,
                 "With --control: move the coordinate one way, as an experiment does: where the "
                 "path folds back at a point where another equilibrium goes on (a buckled branch "
                 "rejoining the unbuckled one), go on along that one to the target");
  args->shapes_option =
      path->add_option("--shapes",
                       args->shapes,
                       "Store the shape (x, y, angle, moment) at K points of every path "
                       "point");
  path->add_option("--stability",
                   args->stability,
                   "The stability verdict of every point under the path's control: on (default; "
                   "shooting) or off")
      ->default_str("on")
      ->transform(CLI::IsMember({"on", "off"}, CLI::ignore_case));
  args->physical.add_to(*path, false);
  path->add_option("--out",
                   args->out,
                   "Output HDF5 file (written atomically), or FILE.csv for the table as CSV only; "
                   "--out, --csv or both");
  add_csv_option(path, args->csv);
  path->add_flag("--json", args->json, "Print one JSON summary object on stdout");
  path->callback([args] { run_path(*args); });
}

}  // namespace flexure::cli
