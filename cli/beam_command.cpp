// `flexure beam`: one cantilever with an end load, solved for a given alpha2, theta0 or b/l.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>

#include "cli/beam_methods.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "flexure/io/chain_toml.h"
#include "flexure/solver/common/errors.h"
#include "flexure/solver/common/names.h"

namespace flexure::cli {
namespace {

struct BeamArgs {
  double load_ratio_n = 0.0;
  double mu = 0.0;
  double alpha2 = 0.0;
  double theta0 = 0.0;
  double b_over_l = 0.0;
  std::string method = "auto";
  double tol = 1e-6;  // --method auto: relative error allowed
  int shape_points = 0;
  bool json = false;
  CLI::Option* alpha2_option = nullptr;
  CLI::Option* tol_option = nullptr;
  CLI::Option* theta0_option = nullptr;
  CLI::Option* b_over_l_option = nullptr;
  CLI::Option* shape_option = nullptr;
  // End conditions and the numerical methods (docs/cli.md).
  std::string boundary = "free";
  double tip_x = 0.0;
  double tip_y = 0.0;
  double tip_angle = 0.0;
  double follower = 0.0;
  int elements = 100;
  int increments = 10;
  std::string chain_variant = "corrected";
  std::string integrator = "cvodes";
  CLI::Option* integrator_option = nullptr;
  std::string chain_file;
  CLI::Option* tip_x_option = nullptr;
  CLI::Option* tip_y_option = nullptr;
  CLI::Option* tip_angle_option = nullptr;
  CLI::Option* chain_option = nullptr;
};

constexpr int kMaxShapePoints = 1'000'000;

BeamProblem make_problem(const BeamArgs& args) {
  refuse_tol_with_named_method(args.tol_option, args.method);
  BeamProblem problem;
  require_finite_input(args.load_ratio_n, "--n (load ratio n)");
  require_finite_input(args.mu, "--mu (end moment M l/EI)");
  problem.load_ratio_n = args.load_ratio_n;
  problem.mu = args.mu;
  problem.tolerance = args.tol;
  problem.boundary = end_condition_from_string(args.boundary);
  const PrescribedMask mask = prescribed_mask(problem.boundary);
  auto prescribe = [&](CLI::Option* option, double value, bool allowed, const char* name) {
    if (!*option) return std::optional<double>();
    require_finite_input(value, name);
    if (!allowed) {
      throw InvalidInput(
          fmt::format("{} is not prescribed by --boundary {} (it prescribes{}{}{})",
                      name,
                      args.boundary,
                      mask.x ? " tip x" : "",
                      mask.y ? " tip y" : "",
                      mask.theta ? " tip angle" : (mask.x || mask.y ? "" : " nothing")));
    }
    return std::optional<double>(value);
  };
  problem.prescribed.x = prescribe(args.tip_x_option, args.tip_x, mask.x, "--tip-x");
  problem.prescribed.y = prescribe(args.tip_y_option, args.tip_y, mask.y, "--tip-y");
  problem.prescribed.theta =
      prescribe(args.tip_angle_option, args.tip_angle, mask.theta, "--tip-angle");
  require_finite_input(args.follower, "--follower (follower force F l^2/EI)");
  problem.follower = args.follower;
  require_in_range(args.elements, "--elements (chain algorithm elements N)", 1, 1'000'000);
  require_in_range(args.increments, "--increments (load increments)", 1, 1'000'000);
  problem.elements = args.elements;
  problem.increments = args.increments;
  problem.chain_variant = chain_variant_from_string(args.chain_variant);
  if (*args.integrator_option && !same_name(args.method, "shooting") &&
      !same_name(args.method, "auto")) {
    throw InvalidInput(fmt::format(
        "--integrator chooses the shooting method's integrator; --method {} does not use one",
        args.method));
  }
  problem.integrator = args.integrator == "dormand-prince"
                           ? ElasticaIntegrator::Backend::kDormandPrince
                           : ElasticaIntegrator::Backend::kCvodes;
  const bool any_given = *args.alpha2_option || *args.theta0_option || *args.b_over_l_option;
  if (*args.chain_option) {
    if (any_given || args.load_ratio_n != 0.0 || args.mu != 0.0 || args.follower != 0.0 ||
        args.boundary != "free") {
      throw InvalidInput(
          "--chain FILE.toml describes the whole problem (segments, loads, boundary); do not "
          "combine it with --alpha2, --theta0, --b-over-l, --n, --mu, --follower or --boundary");
    }
    problem.chain = io::read_chain_toml(args.chain_file);
    problem.boundary = problem.chain->end;
    if (*args.shape_option) {
      require_in_range(args.shape_points, "--shape (number of shape points)", 2, kMaxShapePoints);
      problem.shape_points = args.shape_points;
    }
    return problem;
  }
  if (!any_given) {
    throw InvalidInput("one of --alpha2, --theta0 or --b-over-l is required (or --chain FILE)");
  }
  if (*args.alpha2_option) {
    require_finite_input(args.alpha2, "--alpha2 (P l^2/EI)");
    problem.given = BeamProblem::Given::kAlpha2;
    problem.value = args.alpha2;
  } else if (*args.theta0_option) {
    require_finite_input(args.theta0, "--theta0 (tip angle, rad)");
    problem.given = BeamProblem::Given::kTheta0;
    problem.value = args.theta0;
  } else {
    require_in_range(args.b_over_l, "--b-over-l (tip deflection b/l)", -1.0, 1.0);
    problem.given = BeamProblem::Given::kBOverL;
    problem.value = args.b_over_l;
  }
  if (*args.shape_option) {
    require_in_range(args.shape_points, "--shape (number of shape points)", 2, kMaxShapePoints);
    problem.shape_points = args.shape_points;
  }
  return problem;
}

void print_report(const BeamProblem& problem, const BeamSolution& solution) {
  const double degrees = 180.0 / std::numbers::pi;
  const bool howell = std::isfinite(solution.alpha2);  // false: a chain without a single alpha2
  if (problem.chain) {
    const Reaction& tip = solution.chain_tip_load;
    fmt::print(
        "Segment chain ({} segments), method {}, {} end; tip load Fx = {:g}, Fy = {:g}, M = "
        "{:g} (the file's units)\n",
        problem.chain->segment_count(),
        to_string(solution.method),
        to_string(problem.chain->end),
        tip.Fx,
        tip.Fy,
        tip.M);
  } else {
    fmt::print("Cantilever with end load, method {} (n = {:g}, mu = {:g}, {} end)\n",
               to_string(solution.method),
               problem.load_ratio_n,
               problem.mu,
               to_string(problem.boundary));
  }
  if (howell) {
    fmt::print("  alpha2 = P l^2/EI = {:.10g}\n", solution.alpha2);
  } else {
    fmt::print("  alpha2: none (the chain is not one uniform straight beam)\n");
  }
  fmt::print("  a/l    = {:.10g}\n", solution.tip.a_over_l);
  fmt::print("  b/l    = {:.10g}\n", solution.tip.b_over_l);
  fmt::print(
      "  theta0 = {:.10g} rad ({:.6g} deg)\n", solution.tip.theta0, solution.tip.theta0 * degrees);
  if (howell) {
    fmt::print("  root moment M(0) l/EI = {:.10g}\n", solution.root_moment);
    fmt::print(
        "  reactions at the clamp (nondimensional): Fx = {:.10g}, Fy = {:.10g}, M = {:.10g}\n",
        solution.reactions.Fx,
        solution.reactions.Fy,
        solution.reactions.M);
  }
  if (problem.chain) {
    fmt::print(
        "  root moment M(0) = {:.10g}; reactions at the clamp: Fx = {:.10g}, Fy = {:.10g}, "
        "M = {:.10g} (the file's units)\n",
        solution.chain_root_moment,
        solution.chain_reactions.Fx,
        solution.chain_reactions.Fy,
        solution.chain_reactions.M);
  }
  fmt::print("  {} elastica, {} inflection point(s), branch: {}\n",
             solution.family,
             solution.inflection_points,
             solution.branch);
  fmt::print("  converged in {} iterations: {}\n", solution.iterations, solution.message);
  if (!solution.shape.empty()) {
    fmt::print("  shape ({} points):\n  {:>12} {:>14} {:>14} {:>14}\n",
               solution.shape.size(),
               "s",
               "x/l",
               "y/l",
               "theta");
    for (const ShapePoint& p : solution.shape) {
      fmt::print("  {:12.6f} {:14.8f} {:14.8f} {:14.8f}\n", p.s, p.x, p.y, p.theta);
    }
  }
}

// NaN (a quantity the problem does not have) as null.
Json number_or_null(double value) {
  return std::isfinite(value) ? Json(value + 0.0) : Json(nullptr);
}

Json reaction_json(const Reaction& r) {
  return Json{
      {"Fx", number_or_null(r.Fx)}, {"Fy", number_or_null(r.Fy)}, {"M", number_or_null(r.M)}};
}

Json to_json(const BeamProblem& problem, const BeamSolution& solution) {
  Json out;
  out["method"] = to_string(solution.method);
  out["method_reason"] = solution.method_reason;
  // Howell's parameters; null for a chain that has none (not one uniform straight beam).
  out["n"] = number_or_null(solution.load_ratio_n);
  out["alpha2"] = number_or_null(solution.alpha2);
  out["mu"] = number_or_null(solution.mu);
  out["a_over_l"] = solution.tip.a_over_l;
  out["b_over_l"] = solution.tip.b_over_l;
  out["theta0"] = solution.tip.theta0;
  out["iterations"] = solution.iterations;
  out["converged"] = solution.converged();
  out["branch"] = solution.branch;
  out["inflection_points"] = solution.inflection_points;
  out["root_moment"] = number_or_null(solution.root_moment);
  out["limit_points"] = solution.limit_points;
  out["target_residual"] =
      std::isfinite(solution.target_residual) ? Json(solution.target_residual) : Json(nullptr);
  out["first_limit_load_factor"] =
      solution.limit_points > 0 ? Json(solution.first_limit_load_factor) : Json(nullptr);
  out["family"] = solution.family;
  out["message"] = solution.message;
  out["termination"] = termination_name(solution.termination);
  out["boundary"] = to_string(problem.boundary);
  out["reactions"] = reaction_json(solution.reactions);
  if (problem.chain) {
    // The chain's loads in the file's own units, whether or not it has Howell's parameters.
    out["tip_load_chain_units"] = reaction_json(solution.chain_tip_load);
    out["root_moment_chain_units"] = solution.chain_root_moment;
    out["reactions_chain_units"] = reaction_json(solution.chain_reactions);
  }
  if (solution.method == BeamMethod::kPrbm) {
    // PRBM validity as a result, not a phrase: the PRB angle, the limit and the verdict.
    out["within_validity"] = solution.prbm_inside_validity;
    out["Theta"] = solution.prbm_Theta;
    out["theta_max"] = solution.prbm_theta_max;
    out["validity_source"] = solution.prbm_limits_source;
  }
  if (solution.method == BeamMethod::kChain) {
    out["elements"] = solution.elements;
    out["increments"] = solution.increments;
  }
  if (problem.shape_points > 0) {
    Json shape = Json::array();
    for (const ShapePoint& p : solution.shape) {
      shape.push_back(Json{{"s", p.s}, {"x", p.x}, {"y", p.y}, {"theta", p.theta}});
    }
    out["shape"] = std::move(shape);
  }
  return out;
}

void run_beam(const BeamArgs& args) {
  const BeamProblem problem = make_problem(args);
  const BeamSolution solution = solve_beam(beam_method_from_string(args.method), problem);
  if (!solution.converged()) {
    // What was reached, for the JSON error object (null where it is not a number).
    Json reached;
    reached["method"] = to_string(solution.method);
    reached["method_reason"] = solution.method_reason;
    reached["termination"] = termination_name(solution.termination);
    reached["iterations"] = solution.iterations;
    reached["load_factor"] = solution.load_factor;
    reached["alpha2"] = solution.alpha2;
    if (std::isfinite(solution.target_residual)) {
      reached["target_residual"] = solution.target_residual;
    }
    for (auto& [key, value] : reached.items()) {
      if (value.is_number_float() && !std::isfinite(value.get<double>())) value = nullptr;
    }
    throw NoConvergenceReport(
        fmt::format("method '{}' found no converged solution after {} iterations: {}. {}",
                    to_string(solution.method),
                    solution.iterations,
                    solution.message.empty() ? "no message" : solution.message,
                    other_methods_hint(solution.method)),
        std::move(reached));
  }
  if (!problem.chain) require_finite_result(solution.alpha2, "alpha2");
  require_finite_result(solution.tip.a_over_l, "a/l");
  require_finite_result(solution.tip.b_over_l, "b/l");
  require_finite_result(solution.tip.theta0, "theta0");
  if (problem.shape_points > 0 && static_cast<int>(solution.shape.size()) != problem.shape_points) {
    throw NoConvergence(fmt::format("method '{}' returned {} shape points instead of {}",
                                    to_string(solution.method),
                                    solution.shape.size(),
                                    problem.shape_points));
  }
  if (solution.method == BeamMethod::kPrbm && !solution.prbm_inside_validity) {
    std::cerr << fmt::format(
        "flexure: warning: the PRB angle Theta = {:.1f} deg is outside the validity limit {:.1f} "
        "deg ({}); the PRBM tip and force are not trusted here (--method elliptic or shooting "
        "is exact)\n",
        std::fabs(solution.prbm_Theta) * 180.0 / std::numbers::pi,
        solution.prbm_theta_max * 180.0 / std::numbers::pi,
        solution.prbm_limits_source);
  }
  if (args.json) {
    print_json(to_json(problem, solution));  // refuses NaN/Inf anywhere, e.g. in the shape
  } else {
    for (const ShapePoint& p : solution.shape) {
      require_finite_result(p.x, "shape x");
      require_finite_result(p.y, "shape y");
      require_finite_result(p.theta, "shape theta");
    }
    print_report(problem, solution);
  }
}

}  // namespace

void register_beam_command(CLI::App& app) {
  auto args = std::make_shared<BeamArgs>();
  CLI::App* beam = app.add_subcommand(
      "beam", "Initially straight cantilever with an end load (Howell sec. 2.9.2)");
  beam->add_option("--n", args->load_ratio_n, "Load ratio n: horizontal load nP, n > 0 compressive")
      ->default_str("0");
  beam->add_option("--mu", args->mu, "End moment mu = M l/EI (counter-clockwise positive)")
      ->default_str("0");
  CLI::Option_group* given =
      beam->add_option_group("given", "Exactly one of --alpha2, --theta0, --b-over-l");
  args->alpha2_option = given->add_option("--alpha2", args->alpha2, "Load alpha2 = P l^2/EI");
  args->theta0_option = given->add_option("--theta0", args->theta0, "Tip angle theta0 (rad)");
  args->b_over_l_option =
      given->add_option("--b-over-l", args->b_over_l, "Tip deflection b/l (-1..1)");
  given->require_option(0, 1);
  add_method_option(*beam, args->method);
  args->tol_option = add_tolerance_option(*beam, args->tol);
  beam->add_option("--boundary",
                   args->boundary,
                   "Far end: free (loads given), guided (tip angle prescribed), pinned (tip x, y "
                   "prescribed), slider (tip y prescribed), fixed (all prescribed)")
      ->default_str("free")
      ->transform(CLI::IsMember({"free", "guided", "pinned", "slider", "fixed"}, CLI::ignore_case));
  args->tip_x_option = beam->add_option(
      "--tip-x", args->tip_x, "Prescribed tip x/l (pinned, fixed; default: unloaded tip)");
  args->tip_y_option = beam->add_option(
      "--tip-y", args->tip_y, "Prescribed tip y/l (pinned, slider, fixed; default 0)");
  args->tip_angle_option = beam->add_option(
      "--tip-angle", args->tip_angle, "Prescribed tip angle, rad (guided, fixed; default 0)");
  beam->add_option("--follower", args->follower, "Follower tip force F l^2/EI, normal to the tip")
      ->default_str("0");
  beam->add_option("--elements", args->elements, "Chain algorithm: number of elements N")
      ->default_str("100");
  beam->add_option("--increments", args->increments, "Chain algorithm: load increments")
      ->default_str("10");
  args->integrator_option =
      beam->add_option("--integrator",
                       args->integrator,
                       "Shooting method: cvodes (default, the reference: adaptive Adams with "
                       "sensitivities, rtol 1e-12) or dormand-prince (explicit Runge-Kutta 5(4), "
                       "about ten times faster at equal accuracy)")
          ->default_str("cvodes")
          ->transform(CLI::IsMember({"cvodes", "dormand-prince"}, CLI::ignore_case));
  beam->add_option("--chain-variant", args->chain_variant, "Chain algorithm: howell | corrected")
      ->default_str("corrected")
      ->transform(CLI::IsMember({"howell", "corrected"}, CLI::ignore_case));
  args->chain_option = beam->add_option(
      "--chain", args->chain_file, "Segment chain from a TOML file (docs/chain-toml.md)");
  args->shape_option = beam->add_option(
      "--shape", args->shape_points, "Also output the deflected shape at K points (K >= 2)");
  beam->add_flag("--json", args->json, "Print one JSON object on stdout");
  beam->callback([args] { run_beam(*args); });
}

}  // namespace flexure::cli
