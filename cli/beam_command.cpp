// `flexure beam`: one cantilever with an end load, solved for a given alpha2, theta0 or b/l.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>

#include "cli/beam_methods.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "solver/common/errors.h"

namespace flexure::cli {
namespace {

struct BeamArgs {
  double load_ratio_n = 0.0;
  double mu = 0.0;
  double alpha2 = 0.0;
  double theta0 = 0.0;
  double b_over_l = 0.0;
  std::string method = "auto";
  int shape_points = 0;
  bool json = false;
  CLI::Option* alpha2_option = nullptr;
  CLI::Option* theta0_option = nullptr;
  CLI::Option* b_over_l_option = nullptr;
  CLI::Option* shape_option = nullptr;
};

constexpr int kMaxShapePoints = 1'000'000;

BeamProblem make_problem(const BeamArgs& args) {
  BeamProblem problem;
  require_finite_input(args.load_ratio_n, "--n (load ratio n)");
  require_finite_input(args.mu, "--mu (end moment M l/EI)");
  problem.load_ratio_n = args.load_ratio_n;
  problem.mu = args.mu;
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
  fmt::print("Cantilever with end load, method {} (n = {:g}, mu = {:g})\n",
             solution.method,
             problem.load_ratio_n,
             problem.mu);
  fmt::print("  alpha2 = P l^2/EI = {:.10g}\n", solution.alpha2);
  fmt::print("  a/l    = {:.10g}\n", solution.tip.a_over_l);
  fmt::print("  b/l    = {:.10g}\n", solution.tip.b_over_l);
  fmt::print(
      "  theta0 = {:.10g} rad ({:.6g} deg)\n", solution.tip.theta0, solution.tip.theta0 * degrees);
  fmt::print("  root moment M(0) l/EI = {:.10g}\n", solution.root_moment);
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

Json to_json(const BeamProblem& problem, const BeamSolution& solution) {
  Json out;
  out["method"] = solution.method;
  out["n"] = problem.load_ratio_n;
  out["alpha2"] = solution.alpha2;
  out["mu"] = problem.mu;
  out["a_over_l"] = solution.tip.a_over_l;
  out["b_over_l"] = solution.tip.b_over_l;
  out["theta0"] = solution.tip.theta0;
  out["iterations"] = solution.iterations;
  out["converged"] = solution.converged;
  out["branch"] = solution.branch;
  out["inflection_points"] = solution.inflection_points;
  out["root_moment"] = solution.root_moment;
  out["family"] = solution.family;
  out["message"] = solution.message;
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
  const BeamSolution solution = solve_beam(args.method, problem);
  if (!solution.converged) {
    throw NoConvergence(
        fmt::format("method '{}' found no converged solution after {} iterations: {}. {}",
                    solution.method,
                    solution.iterations,
                    solution.message.empty() ? "no message" : solution.message,
                    other_methods_hint(solution.method)));
  }
  require_finite_result(solution.alpha2, "alpha2");
  require_finite_result(solution.tip.a_over_l, "a/l");
  require_finite_result(solution.tip.b_over_l, "b/l");
  require_finite_result(solution.tip.theta0, "theta0");
  if (problem.shape_points > 0 && static_cast<int>(solution.shape.size()) != problem.shape_points) {
    throw NoConvergence(fmt::format("method '{}' returned {} shape points instead of {}",
                                    solution.method,
                                    solution.shape.size(),
                                    problem.shape_points));
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
  given->require_option(1);
  add_method_option(*beam, args->method);
  args->shape_option = beam->add_option(
      "--shape", args->shape_points, "Also output the deflected shape at K points (K >= 2)");
  beam->add_flag("--json", args->json, "Print one JSON object on stdout");
  beam->callback([args] { run_beam(*args); });
}

}  // namespace flexure::cli
