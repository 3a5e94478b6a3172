// `flexure mechanism list | analyze NAME|FILE.toml | validate`: dimensional constant-force slider
// mechanisms computed with the PRBM and with the exact model (docs/mechanisms.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "io/hdf5_file.h"
#include "mechanisms/mechanism.h"
#include "mechanisms/mechanism_analysis.h"
#include "mechanisms/mechanism_exact.h"
#include "mechanisms/mechanism_method.h"
#include "mechanisms/mechanism_toml.h"
#include "solver/common/errors.h"

namespace flexure::cli {
namespace {

using namespace flexure::mechanism;

const char* pivot_letter(PivotType t) {
  return t == PivotType::kPin ? "p" : t == PivotType::kSmall ? "s" : "l";
}

MechanismDesign resolve(const std::string& what) {
  const bool is_file = what.size() > 5 && what.substr(what.size() - 5) == ".toml";
  return is_file ? load_mechanism_toml(what) : find_builtin_mechanism(what);
}

Json or_null(bool present, double value) { return present ? Json(value) : Json(nullptr); }

Json pivot_array(const MechanismDesign& d, const std::array<double, 3>& v, bool present = true) {
  Json a = Json::array();
  for (int i = 0; i < 3; ++i) {
    a.push_back(present && d.joints[i].type != PivotType::kPin ? Json(v[i]) : Json(nullptr));
  }
  return a;
}

Json design_json(const MechanismDesign& d) {
  Json joints = Json::array();
  for (const auto& j : d.joints) {
    joints.push_back(j.type == PivotType::kPin ? Json{{"type", "p"}}
                                               : Json{{"type", pivot_letter(j.type)},
                                                      {"length", j.length},
                                                      {"thickness", j.thickness},
                                                      {"width", j.width}});
  }
  return Json{{"name", d.name},
              {"config", d.config},
              {"class", d.configuration().class_name},
              {"r2", d.r2},
              {"r3", d.r3},
              {"E", d.E},
              {"yield_strength", d.yield_strength},
              {"stroke", d.stroke},
              {"toggle_stroke", d.toggle_stroke()},
              {"joints", joints},
              {"note", d.note}};
}

Json analysis_json(const MechanismAnalysis& a) {
  const bool exact = a.has_exact && a.exact.converged;
  Json j;
  j["design"] = design_json(a.design);
  j["units"] = "SI: m, N, Pa";
  j["displacement"] = a.prbm.displacement;
  j["force_prbm"] = a.prbm.force;
  j["force_exact"] = exact ? Json(a.force_exact) : Json(nullptr);
  j["exact_model"] = a.has_exact;
  j["exact_note"] = a.exact_note;
  j["percent_constant_force_prbm"] = a.prbm.percent_constant_force;
  j["percent_constant_force_exact"] = or_null(exact, a.percent_constant_force_exact);
  j["mean_force_prbm"] = a.prbm.mean_force;
  j["mean_force_exact"] = or_null(exact, a.mean_force_exact);
  j["max_force_error"] = or_null(exact, a.max_force_error);
  j["max_force_error_at"] = or_null(exact, a.max_force_error_at);
  j["prbm_validity_limit"] = a.prbm_validity_limit ? Json(*a.prbm_validity_limit) : Json(nullptr);
  j["prbm_validity_reason"] = a.prbm_validity_reason;
  j["max_stress"] = a.max_stress_all;
  j["max_stress_per_pivot"] = pivot_array(a.design, a.max_stress);
  j["max_stress_prbm"] = pivot_array(a.design, a.prbm.max_stress);
  j["max_stress_exact"] = pivot_array(a.design, a.max_stress_exact, exact);
  j["safety_factor"] = a.safety_factor;
  j["yielding_pivots"] = a.yielding_pivots;
  return j;
}

void write_hdf5(const std::string& path, const MechanismAnalysis& a, io::AtomicHdf5File& file) {
  auto& root = file.root();
  root.set_attribute("mechanism", a.design.name);
  root.set_attribute("config", a.design.config);
  root.set_attribute("units", "SI: m, N, Pa");
  root.set_attribute("percent_constant_force_prbm", a.prbm.percent_constant_force);
  root.set_attribute("safety_factor", a.safety_factor);
  root.write_dataset("displacement", std::span<const double>(a.prbm.displacement));
  root.write_dataset("force_prbm", std::span<const double>(a.prbm.force));
  if (a.has_exact && a.exact.converged) {
    root.write_dataset("force_exact", std::span<const double>(a.force_exact));
    root.set_attribute("percent_constant_force_exact", a.percent_constant_force_exact);
    root.set_attribute("max_force_error", a.max_force_error);
  }
  for (int p = 0; p < 3; ++p) {
    if (!a.prbm.stress[p].empty()) {
      root.write_dataset(fmt::format("stress_prbm_pivot{}", p + 1),
                         std::span<const double>(a.prbm.stress[p]));
    }
  }
  file.commit();
  (void)path;
}

std::string percent(double v) { return fmt::format("{:.2f}", 100.0 * v); }

// Elements per chain of the chain-algorithm check in `mechanism validate` (corrected variant:
// O(N^-3), 1e-9-1e-5 r2 on the built-in designs at N = 100; under 1 ms per check,
// BM_ChainCheck100).
constexpr int kChainCheckElements = 100;

void print_validation(int points, std::optional<double> toggle_fraction, bool markdown, bool json) {
  Json rows = Json::array();
  std::string table =
      "| Mechanism | Exact model | Xi' PRBM % | Xi' exact % | Xi' error (points) | max force "
      "error % | at Delta x / stroke % | PRBM validity limit (Delta x / stroke %) | SF | chain "
      "check tip error / r2 |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  for (MechanismDesign d : builtin_mechanisms()) {
    if (toggle_fraction) d.stroke = *toggle_fraction * d.toggle_stroke();
    AnalysisOptions o;
    o.points = points;
    o.exact_stress = false;
    const MechanismAnalysis a = analyze_mechanism(d, o);
    const bool exact = a.has_exact && a.exact.converged;
    // Second opinion on the last stroke point: Howell's chain algorithm (corrected variant,
    // kChainCheckElements elements per chain) on the exact model's solution.
    std::optional<ChainCheck> check;
    if (exact && !a.exact.points.empty()) {
      check = chain_algorithm_check(a.exact.points.back(), kChainCheckElements);
    }
    const std::string limit = a.prbm_validity_limit
                                  ? fmt::format("{:.0f}", 100.0 * *a.prbm_validity_limit / d.stroke)
                                  : std::string("never (s pivots only, or within Table 5.1)");
    table += fmt::format(
        "| {} | {} | {:.2f} | {} | {} | {} | {} | {} | {:.2f} | {} |\n",
        d.name,
        a.has_exact ? (exact ? "yes" : "did not converge") : "PRBM only",
        a.prbm.percent_constant_force,
        exact ? fmt::format("{:.2f}", a.percent_constant_force_exact) : "-",
        exact
            ? fmt::format("{:+.2f}", a.prbm.percent_constant_force - a.percent_constant_force_exact)
            : "-",
        exact ? percent(a.max_force_error) : "-",
        exact ? fmt::format("{:.0f}", 100.0 * a.max_force_error_at / d.stroke) : "-",
        limit,
        a.safety_factor,
        check ? (check->converged ? fmt::format("{:.1e}", check->tip_error / d.r2)
                                  : std::string("did not converge"))
              : std::string("-"));
    Json r = analysis_json(a);
    if (check) {
      r["chain_check_converged"] = check->converged;
      r["chain_check_tip_error"] = check->converged ? Json(check->tip_error) : Json(nullptr);
      r["chain_check_closure_error"] =
          check->converged ? Json(check->closure_error) : Json(nullptr);
      r["chain_check_elements"] = kChainCheckElements;
      r["chain_check_at"] = a.exact.points.back().displacement;
    }
    r.erase("displacement");
    r.erase("force_prbm");
    r.erase("force_exact");
    rows.push_back(r);
  }
  if (json) {
    print_json(Json{{"points", points}, {"mechanisms", rows}});
  } else if (markdown) {
    std::cout << table;
  } else {
    std::cout << table;
  }
}

}  // namespace

void register_mechanism_command(CLI::App& app) {
  CLI::App& mech = get_or_add_subcommand(
      app, "mechanism", "Constant-force slider mechanisms: PRBM and exact model of one design");
  mech.require_subcommand(1);

  auto list_json = std::make_shared<bool>(false);
  CLI::App* list = mech.add_subcommand("list", "List the built-in mechanism designs");
  list->add_flag("--json", *list_json, "Print one JSON object");
  list->callback([list_json] {
    Json all = Json::array();
    for (const auto& d : builtin_mechanisms()) {
      if (*list_json) {
        Json j = design_json(d);
        j["exact_model"] = exact_support(d) != ExactSupport::kPrbmOnly;
        all.push_back(j);
      } else {
        std::cout << fmt::format("{:8} r2 = {:.4g} m, r3 = {:.4g} m, stroke {:.4g} m{}  -- {}\n",
                                 d.name,
                                 d.r2,
                                 d.r3,
                                 d.stroke,
                                 exact_support(d) == ExactSupport::kPrbmOnly ? " (PRBM only)" : "",
                                 d.note);
      }
    }
    if (*list_json) print_json(Json{{"mechanisms", all}});
  });

  struct AnalyzeArgs {
    std::string what;
    int points = 50;
    std::string out;
    bool json = false;
    bool no_exact = false;
    std::string method = "auto";
    double tol = 1e-6;
  };
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* analyze = mech.add_subcommand(
      "analyze", "Force-deflection over the stroke, PRBM and exact, with stresses");
  analyze->add_option("mechanism", args->what, "Built-in name (1A-lpp, 3A-sss, ...) or FILE.toml")
      ->required();
  analyze->add_option("--points", args->points, "Stroke points (2..100000)");
  analyze->add_option("--out", args->out, "Write the curves to this HDF5 file (atomic)");
  analyze->add_flag("--json", args->json, "Print one JSON object");
  analyze->add_flag("--prbm-only", args->no_exact, "Skip the exact model (= --method prbm)");
  analyze
      ->add_option("--method",
                   args->method,
                   "auto (PRBM alone when its measured force error x1.5 is within --tol), prbm, "
                   "exact (PRBM and exact)")
      ->default_str("auto")
      ->check(CLI::IsMember({"auto", "prbm", "exact"}));
  analyze->add_option("--tol", args->tol, "Relative force error allowed by --method auto")
      ->default_str("1e-6");
  analyze->callback([args] {
    require_in_range(args->points, "--points", 2, 100000);
    const MechanismDesign d = resolve(args->what);
    std::optional<io::AtomicHdf5File> file;
    if (!args->out.empty()) {
      try {
        file.emplace(args->out);
      } catch (const io::Hdf5Error& e) {
        throw InvalidInput(fmt::format("--out: {}", e.what()));
      }
    }
    const MechanismMethodChoice choice =
        choose_mechanism_method(d, args->no_exact ? "prbm" : args->method, args->tol);
    AnalysisOptions o;
    o.points = args->points;
    o.exact = choice.exact;
    const MechanismAnalysis a = analyze_mechanism(d, o);
    if (a.has_exact && o.exact && !a.exact.converged) {
      throw NoConvergence(fmt::format("{}: {}", d.name, a.exact.message));
    }
    for (int p : a.yielding_pivots) {
      std::cerr << fmt::format(
          "flexure: warning: pivot {} of {} yields: max stress {:.4g} Pa >= yield strength "
          "{:.4g} Pa\n",
          p,
          d.name,
          a.max_stress[p - 1],
          d.yield_strength);
    }
    if (file) write_hdf5(args->out, a, *file);
    if (args->json) {
      Json j = analysis_json(a);
      j["method"] = choice.method;
      j["method_reason"] = choice.reason;
      print_json(j);
      return;
    }
    std::cout << fmt::format("{} ({}): {}\n", d.name, d.config, d.note);
    std::cout << fmt::format("  method: {} ({})\n", choice.method, choice.reason);
    std::cout << fmt::format("  percent constant force: PRBM {:.2f} %{}\n",
                             a.prbm.percent_constant_force,
                             a.has_exact && o.exact
                                 ? fmt::format(", exact {:.2f} %", a.percent_constant_force_exact)
                                 : std::string(" (") + a.exact_note + ")");
    std::cout << fmt::format(
        "  mean force: PRBM {:.5g} N{}\n",
        a.prbm.mean_force,
        a.has_exact && o.exact ? fmt::format(", exact {:.5g} N", a.mean_force_exact) : "");
    if (a.has_exact && o.exact) {
      std::cout << fmt::format("  max PRBM force error: {:.3f} % at Delta x = {:.5g} m\n",
                               100.0 * a.max_force_error,
                               a.max_force_error_at);
    }
    std::cout << fmt::format("  max stress {:.5g} Pa, safety factor {:.3f}{}\n",
                             a.max_stress_all,
                             a.safety_factor,
                             a.yielding_pivots.empty() ? "" : " (YIELDS)");
  });

  struct ValidateArgs {
    std::optional<double> toggle_fraction;
    int points = 50;
    bool markdown = false;
    bool json = false;
  };
  auto vargs = std::make_shared<ValidateArgs>();
  CLI::App* validate = mech.add_subcommand(
      "validate", "PRBM vs exact model for every built-in mechanism (docs/validation.md table)");
  validate->add_option("--points", vargs->points, "Stroke points (2..100000)");
  validate->add_option("--toggle-fraction",
                       vargs->toggle_fraction,
                       "Stroke of every design = this fraction of its toggle stroke, in (0, 1]");
  validate->add_flag("--markdown", vargs->markdown, "Print the Markdown table");
  validate->add_flag("--json", vargs->json, "Print one JSON object");
  validate->callback([vargs] {
    require_in_range(vargs->points, "--points", 2, 100000);
    if (vargs->toggle_fraction) {
      require_in_range(*vargs->toggle_fraction, "--toggle-fraction", 1e-6, 1.0);
    }
    print_validation(vargs->points, vargs->toggle_fraction, vargs->markdown, vargs->json);
  });
}

}  // namespace flexure::cli
