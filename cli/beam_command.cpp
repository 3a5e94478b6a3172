// `flexure beam`: one cantilever with an end load, solved for a given alpha2, theta0 or b/l.
#include "cli/beam_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>

#include "cli/beam_contact_command.h"
#include "cli/beam_methods.h"
#include "cli/cli_common.h"
#include "cli/command_runner.h"
#include "cli/commands.h"
#include "cli/fatigue_flags.h"
#include "cli/modulus_output.h"
#include "cli/physical_flags.h"
#include "cli/warning_output.h"
#include "flexure/beam/beam_keys.h"
#include "flexure/beam/beam_problem.h"
#include "flexure/beam/physical_beam.h"
#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/load_cycle_fatigue.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

struct BeamArgs {
  double load_ratio_n = 0.0;
  double mu = 0.0;
  double alpha2 = 0.0;
  std::string theta0;  // an angle, radians or with a unit (30deg)
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
  // x/l, y/l; a physical beam's in metres, or with a unit (45mm).
  std::string tip_x;
  std::string tip_y;
  std::string tip_angle;  // an angle, radians or with a unit
  double follower = 0.0;
  int elements = 100;
  CLI::Option* elements_option = nullptr;
  std::string constants = "su";  // --method prbm3r: the PR-3R constants
  CLI::Option* constants_option = nullptr;
  double slenderness = 0.0;  // --method bcm, cbcm: L/t (0: inextensible)
  CLI::Option* slenderness_option = nullptr;
  int increments = 1;
  std::string chain_variant = "corrected";
  std::string integrator = "rk8pd";
  CLI::Option* integrator_option = nullptr;
  std::string chain_file;
  bool stable = false;           // --stable: a stable equilibrium instead of an unstable one
  std::string stability = "on";  // --stability on|off: the verdict (docs/stability.md)
  CLI::Option* tip_x_option = nullptr;
  CLI::Option* tip_y_option = nullptr;
  CLI::Option* tip_angle_option = nullptr;
  CLI::Option* chain_option = nullptr;
  // A physical cantilever (SI, or values with units: 50mm, 200GPa, 5N; solver/common/section.h).
  PhysicalFlags physical;
  // Fatigue of a load cycle of the physical beam (load_cycle_fatigue.h; docs/fatigue.md).
  std::string cycle;
  FatigueFlags fatigue;
  std::string out;  // --out: the HDF5 file of a contact solution (docs/contact.md)
};

// A prescribed tip coordinate: x/l or y/l, a plain number; a physical beam's in metres (plain, or
// with a unit: 45mm).
double tip_length(const std::string& text, const char* flag, bool physical) {
  if (physical) return io::parse_quantity(text, io::Dimension::kLength, flag).si;
  double value = 0.0;
  if (!parse_double(text, value)) {
    throw InvalidInput(fmt::format(
        "{} = '{}': a tip coordinate of Howell's nondimensional beam is a plain number (x/l, "
        "y/l); a length with a unit needs a physical beam (--length, --E, the section)",
        flag,
        text));
  }
  return value;
}

// The request the flags make (beam/beam_request.h): a value is given when its flag is, so the
// library tells a default from a value the user gave.
BeamRequest request_of(const BeamArgs& args) {
  const auto given = [](const CLI::Option* option) { return option->count() > 0; };
  BeamRequest r;
  if (given(args.alpha2_option)) r.alpha2 = args.alpha2;
  if (given(args.theta0_option)) r.theta0 = args.theta0;
  if (given(args.b_over_l_option)) r.b_over_l = args.b_over_l;
  r.load_ratio_n = args.load_ratio_n;
  r.mu = args.mu;
  r.boundary = args.boundary;
  r.physical = args.physical.given();
  if (given(args.tip_x_option)) r.tip_x = tip_length(args.tip_x, "--tip-x", r.physical);
  if (given(args.tip_y_option)) r.tip_y = tip_length(args.tip_y, "--tip-y", r.physical);
  if (given(args.tip_angle_option)) r.tip_angle = args.tip_angle;
  r.follower = args.follower;
  r.method = args.method;
  if (given(args.tol_option)) r.tolerance = args.tol;
  if (given(args.elements_option)) r.elements = args.elements;
  r.increments = args.increments;
  r.chain_variant = args.chain_variant;
  if (given(args.integrator_option)) r.integrator = args.integrator;
  if (given(args.shape_option)) r.shape_points = args.shape_points;
  if (given(args.constants_option)) r.constants = args.constants;
  if (given(args.slenderness_option)) r.slenderness = args.slenderness;
  r.stable = args.stable;
  r.judge_stability = same_name(args.stability, "on");
  r.chain = given(args.chain_option);
  return r;
}

// What `flexure beam` solves: the library's checks of the request with the flags' names, then the
// beam given whole (a physical cantilever or a chain file), read only once the combination passed.
BeamInput make_input(const BeamArgs& args, const BeamRequest& request) {
  BeamInput input = make_beam_input(request, BeamRequestNames::command_line());
  warn(input.warnings);
  if (request.physical) {
    add_physical_beam(input, args.physical.parse());
  } else if (request.chain) {
    io::ChainFile file = io::read_chain_file(args.chain_file);
    if (!file.contacts.empty()) {
      throw InvalidInput("a [[contact]] is solved by `flexure beam --chain FILE` alone");
    }
    warn(file.warnings);
    const bool in_si = file.physical;
    add_chain(input, std::move(file), in_si);
  }
  return input;
}

// The physical results in words: tip, moments, stress and safety factor (docs/units.md).
void print_physical(const PhysicalResults& r) {
  fmt::print("  in SI units:\n");
  fmt::print("    tip x = {:.10g} m, tip y = {:.10g} m, theta0 = {:.10g} rad ({:.6g} deg)\n",
             r.tip_x,
             r.tip_y,
             r.theta0,
             r.theta0 * 180.0 / std::numbers::pi);
  fmt::print(
      "    bending moment at the clamp = {:.10g} N m; largest |moment| = {:.10g} N m at s = "
      "{:.6g} m{}\n",
      r.root_moment,
      r.max_moment,
      r.max_moment_at,
      std::string_view(r.max_from) == "ends" ? " (PRBM: the larger end moment)" : "");
  print_modulus(r.modulus);
  if (r.max_axial_strain) {
    fmt::print("    largest axial force |N| = {:.10g} N; axial strain N/EA up to {:.6g}\n",
               r.max_axial_force,
               *r.max_axial_strain);
  }
  if (r.max_stress) {
    fmt::print("    largest {} = {:.6g} MPa at s = {:.6g} m\n",
               r.max_axial_strain ? "stress |N|/A + |M| c/I" : "bending stress M c/I",
               *r.max_stress * 1e-6,
               *r.max_stress_at);
  } else {
    fmt::print("    bending stress: not computed (the section's thickness is not given)\n");
  }
  if (r.yield_strength) {
    if (r.safety_factor) {
      fmt::print("    safety factor against yield (S_y = {:.6g} MPa): {:.4g}{}\n",
                 *r.yield_strength * 1e-6,
                 *r.safety_factor,
                 *r.safety_factor < 1.0 ? "  -- YIELDS" : "");
    } else {
      fmt::print("    safety factor: none (no bending stress)\n");
    }
  }
}

std::string special_points_words(const BeamSolution& solution);

// "unstable, index 1, stability margin -0.215854 (the message)" (index and margin only when the
// energy judged the equilibrium).
std::string stability_line(const Stability& s) {
  if (!s.judged()) return fmt::format("{} ({})", stability_name(s.kind), s.message);
  return fmt::format("{}, index {}, stability margin {:.6g} ({})",
                     stability_name(s.kind),
                     s.index,
                     s.margin,
                     s.message);
}

void print_report(const BeamInput& input,
                  const BeamProblem& problem,
                  const BeamSolution& solution,
                  const std::optional<PhysicalResults>& physical) {
  const double degrees = 180.0 / std::numbers::pi;
  const bool howell = std::isfinite(solution.alpha2);  // false: a chain without a single alpha2
  if (input.physical) {
    const PhysicalCantilever& b = *input.physical;
    fmt::print(
        "Cantilever in SI units, method {}: L = {:g} m, E = {:g} Pa, I = {:g} m^4 (EI = {:g} N "
        "m^2); tip load Fx = {:g} N, Fy = {:g} N, M = {:g} N m\n",
        to_string(solution.method),
        b.length,
        b.material.E,
        b.second_moment(),
        // The rigidity solved with (E I, or E I/(1 - nu^2) with the plate modulus).
        physical && !physical->modulus.empty()
            ? physical->modulus.front().effective_E * b.second_moment()
            : b.flexural_rigidity(),
        b.Fx,
        b.Fy,
        b.M);
    if (b.shaped() || b.end != EndCondition::kFree) {
      fmt::print(
          "  {} end{}{}{}\n",
          to_string(b.end),
          b.curvature != 0.0 ? fmt::format("; stress-free curvature {:g} 1/m", b.curvature)
                             : std::string(),
          b.width_tip ? fmt::format("; width {:g} m at the tip", *b.width_tip) : std::string(),
          b.thickness_tip
              ? fmt::format("; thickness {:g} m at the tip (EI and I above: at the clamp)",
                            *b.thickness_tip)
              : std::string());
    }
  } else if (problem.chain) {
    const Reaction& tip = solution.chain_tip_load;
    fmt::print(
        "Segment chain ({} segments), method {}, {} end; tip load Fx = {:g}, Fy = {:g}, M = "
        "{:g} {}\n",
        problem.chain->segment_count(),
        to_string(solution.method),
        to_string(problem.chain->end),
        tip.Fx,
        tip.Fy,
        tip.M,
        input.is_physical() ? "(N, N m)" : "(the file's units)");
  } else {
    fmt::print("Cantilever with end load, method {} (n = {:g}, mu = {:g}, {} end)\n",
               to_string(solution.method),
               problem.load_ratio_n,
               problem.mu,
               to_string(problem.boundary));
  }
  if (howell) {
    fmt::print("  alpha2 = P l^2/EI = {:.10g}\n", solution.alpha2);
    if (input.physical) {
      fmt::print("  n      = {}, mu = M l/EI = {:.10g}\n",
                 std::isfinite(solution.load_ratio_n)
                     ? fmt::format("{:.10g}", solution.load_ratio_n)
                     : std::string("none (axial load only)"),
                 solution.mu);
    }
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
  if (input.chain) {
    fmt::print(
        "  root moment M(0) = {:.10g}; reactions at the clamp: Fx = {:.10g}, Fy = {:.10g}, "
        "M = {:.10g} {}\n",
        solution.chain_root_moment,
        solution.chain_reactions.Fx,
        solution.chain_reactions.Fy,
        solution.chain_reactions.M,
        input.is_physical() ? "(N m; N, N, N m)" : "(the file's units)");
  }
  if (physical) print_physical(*physical);
  fmt::print("  {} elastica, {} inflection point(s), branch: {}\n",
             solution.family,
             solution.inflection_points,
             solution.branch);
  fmt::print("  converged in {} iterations: {}\n", solution.iterations, solution.message);
  if (!solution.special_points.empty()) {
    fmt::print("  passed on the path: {}\n", special_points_words(solution));
  }
  fmt::print("  stability: {}\n", stability_line(solution.stability));
  if (!solution.stable_search.empty()) {
    fmt::print("  stable equilibrium search: {}\n", solution.stable_search);
  }
  if (physical && !physical->shape.empty()) {
    fmt::print("  shape ({} points, SI):\n  {:>12} {:>14} {:>14} {:>14} {:>14} {:>14}\n",
               physical->shape.size(),
               "s [m]",
               "x [m]",
               "y [m]",
               "theta [rad]",
               "M [N m]",
               "stress [Pa]");
    for (const PhysicalShapePoint& p : physical->shape) {
      fmt::print("  {:12.6g} {:14.8g} {:14.8g} {:14.8f} {:14.8g} {:>14}\n",
                 p.s,
                 p.x,
                 p.y,
                 p.theta,
                 p.moment,
                 p.stress ? fmt::format("{:.8g}", *p.stress) : std::string("-"));
    }
  } else if (!solution.shape.empty()) {
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

// The special points in words, for the text output ("" when none).
std::string special_points_words(const BeamSolution& solution) {
  std::string text;
  for (const SpecialPoint& sp : solution.special_points) {
    text += fmt::format("{}{} at load factor {:.10g}{}{}",
                        text.empty() ? "" : "; ",
                        sp.kind == SpecialPointKind::kLimitPoint ? "limit point" : "bifurcation",
                        sp.lambda,
                        sp.stage > 1 ? fmt::format(" (stage {})", sp.stage) : std::string(),
                        sp.located ? "" : " (not located)");
  }
  return text;
}

}  // namespace

std::vector<std::string> beam_warnings(const BeamProblem& problem, const BeamSolution& solution) {
  std::vector<std::string> out;
  for (Warning& w : beam_answer_warnings(problem, solution, BeamRequestNames::command_line())) {
    out.push_back(std::move(w.text));
  }
  return out;
}

namespace {

Json to_json(const BeamInput& input,
             const BeamSolution& solution,
             const std::optional<PhysicalResults>& physical) {
  return beam_keys::answer<Json>(
      input, solution, physical ? &*physical : nullptr, BeamRequestNames::command_line());
}

// The fatigue of `--cycle`: the critical fibre's cycle at the beam's largest stress.
struct BeamFatigue {
  FatigueMaterial material;
  FatigueOptions options;
  PartFatigueStrength strength;
  FatigueCheck check;
  LoadCycle cycle = LoadCycle::kReversed;
};

BeamFatigue beam_fatigue(const BeamArgs& args, const BeamInput& input, const PhysicalResults& r) {
  BeamFatigue f;
  f.cycle = parse_load_cycle(args.cycle);
  f.options = args.fatigue.options();
  f.material = args.fatigue.fatigue_material_of(args.physical.material, r.yield_strength);
  const PhysicalCantilever& b = *input.physical;
  f.strength = part_fatigue_strength(
      f.material, f.options, equivalent_diameter_rectangle(b.section.width, b.section.thickness));
  f.check = check_load_cycle(r.max_stress.value_or(0.0), f.cycle, f.material, f.strength);
  return f;
}

Json number_or_null_value(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

void add_fatigue_json(Json& out, const BeamFatigue& f) {
  out["fatigue_safety_factor"] = number_or_null_value(f.check.safety_factor);
  out["alternating_stress"] = f.check.alternating_stress;
  out["mean_stress"] = f.check.mean_stress;
  out["endurance_limit"] = f.check.endurance_limit;
  out["fatigue"] = Json{{"cycle", load_cycle_name(f.cycle)},
                        {"criterion", "modified Goodman (Howell eq. 3.110)"},
                        {"infinite_life", f.check.infinite_life && !f.material.fatigue_cycles},
                        {"cycles_to_failure", number_or_null_value(f.check.cycles_to_failure)},
                        {"ultimate_strength", f.material.ultimate_strength},
                        {"uncorrected_endurance_limit", f.material.uncorrected_strength},
                        {"endurance_limit_source", f.material.source},
                        {"surface_finish", surface_finish_name(f.options.finish)},
                        {"reliability", f.options.reliability},
                        {"K_f", f.options.K_f},
                        {"c_surf", f.strength.factors.surface},
                        {"c_size", f.strength.factors.size},
                        {"c_load", f.strength.factors.load},
                        {"c_reliab", f.strength.factors.reliability},
                        {"c_misc", f.strength.factors.misc}};
}

// A chain file with a [[contact]] (docs/contact.md): the flags that have a meaning there, and
// the first given one that has none.
BeamContactArgs contact_args(const BeamArgs& args) {
  BeamContactArgs c;
  c.chain_file = args.chain_file;
  c.method = args.method;
  if (args.integrator_option->count() > 0) c.integrator = args.integrator;
  c.shape_points = args.shape_points;
  c.json = args.json;
  c.out = args.out;
  if (args.stable) c.refused_flag = "--stable";
  if (!args.cycle.empty()) c.refused_flag = "--cycle";
  if (args.follower != 0.0) c.refused_flag = "--follower (give the follower force in the file)";
  if (!same_name(args.boundary, "free")) c.refused_flag = "--boundary (contact needs a free end)";
  if (args.tip_x_option->count() + args.tip_y_option->count() + args.tip_angle_option->count() >
      0) {
    c.refused_flag = "a prescribed tip (--tip-x, --tip-y, --tip-angle)";
  }
  return c;
}

void run_beam(const BeamArgs& args, const BeamRequest& request) {
  if (request.chain || !args.out.empty()) {
    if (!request.chain) {
      throw InvalidInput(
          "--out writes the HDF5 file of a contact solution: give --chain FILE with a [[contact]] "
          "(docs/contact.md)");
    }
    // The library's checks of the flags first (e.g. --alpha2 with --chain), then contact.
    (void)make_beam_input(request, BeamRequestNames::command_line());
    if (run_beam_contact(contact_args(args))) return;
  }
  const BeamInput input = make_input(args, request);
  if (!args.cycle.empty()) {
    if (!input.physical || !input.physical->rectangle()) {
      throw InvalidInput(
          "--cycle checks a physical cantilever with a rectangular section: give --length, --E "
          "(or --material), --width and --thickness");
    }
    args.fatigue.options();  // a bad --reliability, --Kf or --surface-finish before solving
  }
  const BeamProblem& problem = input.problem;
  const BeamMethod method = input.method;
  BeamSolution solution;
  std::optional<PhysicalResults> physical;
  try {
    if (input.is_physical()) {
      PhysicalBeamSolution solved = input.physical
                                        ? solve_physical_beam(method, *input.physical, problem)
                                        : solve_physical_chain(method, problem, *input.chain);
      solution = std::move(solved.solution);
      if (solution.converged()) physical = std::move(solved.physical);
    } else {
      solution = solve_beam(method, problem);
    }
  } catch (const bench::ToleranceBelowReach& e) {
    refuse_tolerance_below_reach(e, problem.tolerance);
  }
  if (!solution.converged()) throw_beam_failure(problem, solution);
  require_complete_answer(problem, solution, physical ? &*physical : nullptr);
  warn(beam_warnings(problem, solution));
  std::optional<BeamFatigue> fatigue;
  if (!args.cycle.empty() && physical) fatigue = beam_fatigue(args, input, *physical);
  if (fatigue) warn(load_cycle_warnings(fatigue->cycle, fatigue->check));
  if (args.json) {
    Json out = to_json(input, solution, physical);
    if (fatigue) add_fatigue_json(out, *fatigue);
    print_json(out);  // refuses NaN/Inf anywhere
  } else {
    for (const ShapePoint& p : solution.shape) {
      require_finite_result(p.x, "shape x");
      require_finite_result(p.y, "shape y");
      require_finite_result(p.theta, "shape theta");
    }
    print_report(input, problem, solution, physical);
    if (fatigue) {
      fmt::print(
          "    fatigue ({} load cycle): sigma_a = {:.6g} MPa, sigma_m = {:.6g} MPa, S_e = {:.6g} "
          "MPa (S_e' {:.6g} MPa x Marin {:.4f}); fatigue safety factor {:.4g} (modified "
          "Goodman){}\n",
          load_cycle_name(fatigue->cycle),
          fatigue->check.alternating_stress * 1e-6,
          fatigue->check.mean_stress * 1e-6,
          fatigue->check.endurance_limit * 1e-6,
          fatigue->material.uncorrected_strength * 1e-6,
          fatigue->strength.factors.product(),
          fatigue->check.safety_factor,
          fatigue->check.infinite_life ? "" : "  -- FINITE LIFE");
    }
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
  args->theta0_option =
      given->add_option("--theta0", args->theta0, "Tip angle theta0 (rad, or with a unit: 30deg)");
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
      "--tip-x",
      args->tip_x,
      "Prescribed tip x/l (pinned, fixed; default: unloaded tip); metres or with a unit for a "
      "physical beam");
  args->tip_y_option = beam->add_option(
      "--tip-y",
      args->tip_y,
      "Prescribed tip y/l (pinned, slider, fixed; default 0); metres or with a unit for a "
      "physical beam");
  args->tip_angle_option =
      beam->add_option("--tip-angle",
                       args->tip_angle,
                       "Prescribed tip angle, rad or with a unit (guided, fixed; default 0)");
  beam->add_option("--follower", args->follower, "Follower tip force F l^2/EI, normal to the tip")
      ->default_str("0");
  args->elements_option =
      beam->add_option("--elements",
                       args->elements,
                       "Number of elements N: the chain algorithm's (default 100) or the chained "
                       "BCM's (cbcm, default 6)")
          ->default_str("100");
  args->constants_option =
      beam->add_option("--constants",
                       args->constants,
                       "PR-3R model (prbm3r): su (Su 2009's general set, the default), su-moment, "
                       "su-force (Su's sets for one load) or flexure (derived against the exact "
                       "elastica, docs/models.md)")
          ->default_str("su")
          ->transform(CLI::IsMember({"su", "su-moment", "su-force", "flexure"}, CLI::ignore_case));
  args->slenderness_option = beam->add_option(
      "--slenderness",
      args->slenderness,
      "BCM and chained BCM: slenderness L/t of the flexible segment, axial stiffness d = 12 "
      "(L/t)^2 (default: a --chain segment's EA, else inextensible, d -> infinity)");
  beam->add_option("--increments",
                   args->increments,
                   "Chain algorithm: load increments to start with (default 1: the whole load; a "
                   "step whose passes fail is halved, so increments are added only where needed)")
      ->default_str("1");
  args->integrator_option =
      beam->add_option("--integrator",
                       args->integrator,
                       "Shooting method: rk8pd (default: GSL's Prince-Dormand 8(7), the fastest "
                       "at rtol 1e-12 and as accurate as the reference), cvodes (the reference: "
                       "adaptive Adams with sensitivities) or dormand-prince (the built-in "
                       "Runge-Kutta 5(4) it replaced); all at rtol 1e-12")
          ->default_str("rk8pd")
          ->transform(CLI::IsMember({"rk8pd", "cvodes", "dormand-prince"}, CLI::ignore_case));
  beam->add_option("--chain-variant", args->chain_variant, "Chain algorithm: howell | corrected")
      ->default_str("corrected")
      ->transform(CLI::IsMember({"howell", "corrected"}, CLI::ignore_case));
  args->chain_option = beam->add_option(
      "--chain", args->chain_file, "Segment chain from a TOML file (docs/chain-toml.md)");
  args->shape_option = beam->add_option(
      "--shape", args->shape_points, "Also output the deflected shape at K points (K >= 2)");
  // A physical cantilever (docs/units.md): SI numbers or values with units.
  args->physical.add_to(*beam, true);
  beam->add_flag("--stable",
                 args->stable,
                 "Return a stable equilibrium: when the one reached by proportional loading is "
                 "unstable or critical, descend the potential energy from it and return the stable "
                 "equilibrium found (exit 3 when none is); given loads only (docs/stability.md)");
  beam->add_option("--stability",
                   args->stability,
                   "The stability verdict of the answer: on (default) or off (stability "
                   "not_checked; --stable judges anyway)")
      ->default_str("on")
      ->transform(CLI::IsMember({"on", "off"}, CLI::ignore_case));
  beam->add_option("--cycle",
                   args->cycle,
                   "Fatigue of the physical beam over a load cycle: reversed (the load and its "
                   "mirror image) or repeated (unloaded to the load); needs S_ut and S_e' "
                   "(--material, or --ultimate-strength and --endurance-limit)")
      ->transform(CLI::IsMember({"reversed", "repeated"}));
  args->fatigue.add_to(*beam);
  beam->add_flag("--json", args->json, "Print one JSON object on stdout");
  beam->add_option("--out",
                   args->out,
                   "HDF5 file of a contact solution (--chain FILE with a [[contact]]; "
                   "docs/contact.md)");
  beam->callback([args] { run_beam(*args, request_of(*args)); });
}

}  // namespace flexure::cli
