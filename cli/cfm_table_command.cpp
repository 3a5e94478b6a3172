// `flexure cfm --table [--exact]`: every printed row of the thesis and of Howell's Table 10.1
// recomputed with the PRBM model (and with the exact model), beside the printed values
// (docs/cfm.md, docs/validation.md).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cli/cfm_cli_support.h"
#include "cli/slow_progress.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm_comparison.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

using cfm::CfmClassRow;
using cfm::CfmModel;
using cfm::CfmResult;
using cfm::CfmSubclass;

// The printed stroke, and the effective one where the toggle clamp shortened it.
std::string stroke_cell(double printed_percent, const CfmResult& r) {
  return r.stroke_clamped ? fmt::format("{:g} → {:.2f}", printed_percent, r.stroke_percent)
                          : fmt::format("{:g}", printed_percent);
}

std::string cell(const cfm::PrintedComparison& c, int decimals) {
  return fmt::format(
      "{:.{}f} / {:.{}f}{}", c.computed, decimals + 1, c.printed, decimals, c.within() ? "" : " ✗");
}

Json comparison_json(const cfm::PrintedComparison& c) {
  return Json{{"computed", c.computed},
              {"printed", c.printed},
              {"tolerance", c.tolerance},
              {"within", c.within()}};
}

}  // namespace

void run_table(const CfmArgs& args) {
  const cfm::PrintedTablesReport report = cfm::compare_printed_tables();
  Json subclass_rows = Json::array();
  Json class_rows = Json::array();
  if (args.markdown) {
    fmt::print(
        "| Sub-class | d (eff.) | Phi computed / printed | Xi' | beta | lambda | Psi | "
        "d_N max | p | within |\n|---|---|---|---|---|---|---|---|---|---|\n");
  } else if (!args.json) {
    fmt::print("Thesis sub-classes: computed / printed (✗ = outside rounding tolerance)\n");
  }
  for (const cfm::SubclassComparison& c : report.subclasses) {
    const CfmSubclass& row = *c.row;
    const std::string pivot =
        fmt::format("{}/{}{}",
                    c.result.primary_pivot,
                    row.primary_pivot,
                    c.primary_pivot_tie ? " (tie)" : (c.primary_pivot_matches ? "" : " ✗"));
    if (args.json) {
      subclass_rows.push_back(
          {{"name", row.name},
           {"stroke_percent", c.result.stroke_percent},
           {"Phi", comparison_json(c.Phi)},
           {"percent_constant_force", comparison_json(c.percent_constant_force)},
           {"beta", comparison_json(c.beta)},
           {"lambda", comparison_json(c.lambda)},
           {"Psi", comparison_json(c.Psi)},
           {"d_N_max", comparison_json(c.d_N_max)},
           {"primary_pivot", c.result.primary_pivot},
           {"primary_pivot_printed", row.primary_pivot},
           {"primary_pivot_tie", c.primary_pivot_tie},
           {"within", c.all_within()}});
      continue;
    }
    const std::string stroke = stroke_cell(row.stroke_percent, c.result);
    if (args.markdown) {
      fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                 row.name,
                 stroke,
                 cell(c.Phi, 4),
                 cell(c.percent_constant_force, 1),
                 cell(c.beta, 3),
                 cell(c.lambda, 3),
                 cell(c.Psi, 3),
                 cell(c.d_N_max, 2),
                 pivot,
                 c.all_within() ? "yes" : "**no**");
    } else {
      fmt::print(
          "  {:<11} d {:<12} Phi {:<20} Xi' {:<14} beta {:<22} lambda {:<14} Psi {:<14} "
          "dN {:<16} p {}\n",
          row.name,
          stroke,
          cell(c.Phi, 4),
          cell(c.percent_constant_force, 1),
          cell(c.beta, 3),
          cell(c.lambda, 3),
          cell(c.Psi, 3),
          cell(c.d_N_max, 2),
          pivot);
    }
  }
  if (!args.json) {
    fmt::print("{}Largest |computed - printed| / tolerance over the 68 rows:",
               args.markdown ? "\n" : "");
    for (const cfm::WorstDeviation& w : report.worst) {
      fmt::print(" {} {:.2f} ({}){}",
                 w.quantity,
                 w.ratio,
                 w.row,
                 &w == &report.worst.back() ? ".\n" : ";");
    }
  }

  // Thickness and width ratios (Tables 7.7, 7.10, 7.13).
  Json ratio_rows = Json::array();
  std::vector<std::string> ratio_lines;
  for (const cfm::RatioComparison& c : report.ratios) {
    const cfm::CfmThicknessRatios& row = *c.row;
    auto cells = [&](const std::array<std::optional<cfm::PrintedComparison>, 3>& field) {
      std::string text;
      Json values = Json::array();
      for (const std::optional<cfm::PrintedComparison>& v : field) {
        text += text.empty() ? "" : ", ";
        text += v ? cell(*v, row.decimals) : "–";
        values.push_back(v ? comparison_json(*v) : Json(nullptr));
      }
      return std::pair{text, values};
    };
    const auto [C_text, C_json] = cells(c.C);
    const auto [De_text, De_json] = cells(c.D_equal);
    const auto [Dm_text, Dm_json] = cells(c.D_min);
    if (args.json) {
      ratio_rows.push_back({{"name", row.name},
                            {"C", C_json},
                            {"D_equal", De_json},
                            {"D_min", Dm_json},
                            {"within", c.all_within()}});
    } else {
      ratio_lines.push_back(
          fmt::format(fmt::runtime(args.markdown ? "| {} | {} | {} | {} | {} |"
                                                 : "  {:<11} C {}  D_equal {}  D_min {}  {}"),
                      row.name,
                      C_text,
                      De_text,
                      Dm_text,
                      c.all_within() ? "yes" : "**no**"));
    }
  }
  if (!args.json) {
    fmt::print("{}",
               args.markdown ? "\n| Sub-class | C1, C2, C3 | D_equal 1, 2, 3 | D_min 1, 2, 3 | "
                               "within |\n|---|---|---|---|---|\n"
                             : "Thickness and width ratios (Tables 7.7, 7.10, 7.13): computed / "
                               "printed\n");
    for (const std::string& line : ratio_lines) fmt::print("{}\n", line);
  }
  if (args.markdown) {
    fmt::print(
        "\n| Row | class as | d (eff.) | Xi computed / printed | Phi computed / printed | "
        "within |\n|---|---|---|---|---|---|\n");
  } else if (!args.json) {
    fmt::print("Class rows (50 equally spaced points): computed / printed\n");
  }
  for (const cfm::ClassRowReport& report_row : report.class_rows) {
    const cfm::ClassRowComparison& c = report_row.comparison;
    const CfmClassRow& row = *c.row;
    const bool within = report_row.verdict == cfm::RowVerdict::kWithin;
    const std::string verdict = within ? "yes"
                                : report_row.verdict == cfm::RowVerdict::kOutside
                                    ? "**no**"
                                    : "no (printed K2 inconsistent, see text)";
    if (args.json) {
      class_rows.push_back({{"name", row.name},
                            {"stroke_percent", c.result.stroke_percent},
                            {"Xi", comparison_json(c.Xi)},
                            {"Phi", comparison_json(c.Phi)},
                            {"reproducible", row.reproducible},
                            {"within", within}});
      continue;
    }
    const std::string stroke = stroke_cell(row.stroke_percent, c.result);
    if (args.markdown) {
      fmt::print("| {} | {} | {} | {} | {} | {} |\n",
                 row.name,
                 row.config,
                 stroke,
                 cell(c.Xi, 4),
                 cell(c.Phi, 4),
                 verdict);
    } else {
      fmt::print("  {:<16} d {:<12} Xi {:<22} Phi {:<22} {}\n",
                 row.name,
                 stroke,
                 cell(c.Xi, 4),
                 cell(c.Phi, 4),
                 verdict);
    }
  }
  if (args.json) {
    print_json(Json{{"subclasses", subclass_rows},
                    {"class_rows", class_rows},
                    {"all_within", report.all_within}});
  }
  if (!report.all_within) set_exit_code(kExitCheckFailed);
}

// --table --exact: the thesis sub-classes (the nine "a" rows, or all 68) solved with the exact
// model. The thesis optimised the PRBM only, so Phi and Xi' differ; docs/validation.md lists them.
void run_exact_table(const CfmArgs& args) {
  if (args.exact_rows != "a" && args.exact_rows != "all") {
    throw InvalidInput(
        fmt::format("--exact-rows = '{}' is unknown; allowed: a, all", args.exact_rows));
  }
  Json rows = Json::array();
  if (args.markdown) {
    fmt::print(
        "| Sub-class | d (eff.) | Phi printed | Phi PRBM | Phi exact | Xi' printed | Xi' PRBM | "
        "Xi' exact | max force error (at d) |\n|---|---|---|---|---|---|---|---|---|\n");
  } else if (!args.json) {
    fmt::print(
        "Thesis sub-classes, PRBM and exact model on {} equally spaced points (Phi, Xi' in %)\n",
        args.exact_points);
  }
  // Progress by elapsed time on a terminal (slow_progress.h), counted in exact stroke points over
  // all rows; each row is printed as it is finished.
  const auto print_row = [&](const cfm::ExactTableRow& t) {
    const CfmSubclass& row = *t.row;
    const CfmResult& r = t.prbm;
    const cfm::CfmExactResult& e = t.exact;
    const std::string stroke = r.stroke_clamped ? fmt::format("{:.2f}", r.stroke_percent)
                                                : fmt::format("{:g}", r.stroke_percent);
    if (args.json) {
      Json j{{"name", row.name},
             {"stroke_percent", r.stroke_percent},
             {"Phi_printed", row.Phi},
             {"percent_constant_force_printed", row.percent_constant_force},
             {"Phi", r.Phi},
             {"percent_constant_force", r.percent_constant_force},
             {"converged", e.converged()}};
      if (e.converged()) {
        add_exact_json(j, e, false);
      } else {
        j["exact_message"] = e.message;
      }
      rows.push_back(j);
      return;
    }
    const std::string phi_exact = e.converged() ? fmt::format("{:.4f}", e.Phi_exact) : "–";
    const std::string xi_exact =
        e.converged() ? fmt::format("{:.1f}", e.percent_constant_force_exact) : "–";
    const std::string error =
        e.converged()
            ? fmt::format(
                  "{:.2f} % ({:.1f})", 100.0 * e.max_force_error, e.max_force_error_at_percent)
            : "not converged (" + e.message.substr(0, e.message.find("): ") + 1) + ")";
    fmt::print(fmt::runtime(args.markdown
                                ? "| {} | {} | {:.4f} | {:.4f} | {} | {:.1f} | {:.1f} | {} | {} |\n"
                                : "  {:<11} d {:<6} Phi {:.4f} / {:.4f} / {:<8} Xi' {:.1f} / "
                                  "{:.1f} / {:<6} error {}\n"),
               row.name,
               stroke,
               row.Phi,
               e.Phi_prbm_mean,
               phi_exact,
               row.percent_constant_force,
               e.percent_constant_force_prbm,
               xi_exact,
               error);
  };
  const cfm::ExactTableReport report = cfm::compare_exact_table(
      args.exact_rows == "a" ? cfm::ExactTableRows::kSubclassA : cfm::ExactTableRows::kAll,
      make_exact_options(args),
      stoppable_progress("cfm --table --exact: stroke points"),
      print_row);
  if (args.json) print_json(Json{{"points", args.exact_points}, {"subclasses", rows}});
  if (!report.all_converged) set_exit_code(kExitNoConvergence);
}

}  // namespace flexure::cli
