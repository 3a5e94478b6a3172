// `flexure materials`: the rows of data/materials.csv (mechanisms/materials_fatigue.h;
// docs/materials.md), as a table or one JSON object {"materials": [...]}.
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "flexure/mechanisms/materials_fatigue.h"

namespace flexure::cli {
namespace {

Json optional_json(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

Json material_json(const MaterialGrade& g) {
  return Json{
      {"id", g.id},
      {"designation", g.designation},
      {"class", g.family},
      {"E", g.E},
      {"nu", optional_json(g.nu)},
      {"yield_strength", optional_json(g.yield_strength)},
      {"ultimate_strength", optional_json(g.ultimate_strength)},
      {"endurance_limit", optional_json(g.fatigue_strength)},
      {"fatigue_kind",
       !g.fatigue_kind                                           ? Json(nullptr)
       : *g.fatigue_kind == FatigueStrengthKind::kEnduranceLimit ? Json("endurance-limit")
                                                                 : Json("fatigue-strength")},
      {"fatigue_cycles", optional_json(g.fatigue_cycles)},
      {"density", optional_json(g.density)},
      {"ductile", g.ductile},
      {"source", g.source},
      {"fatigue_source", g.fatigue_source},
      {"notes", g.notes},
  };
}

std::string mpa(const std::optional<double>& v) {
  return v ? fmt::format("{:.4g}", *v / 1e6) : std::string("-");
}

}  // namespace

void register_materials_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "materials",
      "The material library (Howell Appendix C): E, nu, strengths, endurance limit, density, "
      "source");
  auto json = std::make_shared<bool>(false);
  auto name = std::make_shared<std::string>();
  cmd->add_option("name", *name, "Show one material (id or designation, e.g. 1095-HR)");
  cmd->add_flag("--json", *json, "Print one JSON object {\"materials\": [...]}");
  cmd->callback([json, name] {
    std::vector<const MaterialGrade*> rows;
    if (!name->empty()) {
      rows.push_back(&find_material(*name));
    } else {
      for (const MaterialGrade& g : material_library()) rows.push_back(&g);
    }
    if (*json) {
      Json all = Json::array();
      for (const MaterialGrade* g : rows) all.push_back(material_json(*g));
      print_json(Json{{"units", "SI: Pa, kg/m^3"}, {"materials", all}});
      return;
    }
    std::cout << fmt::format("{:<24} {:>7} {:>5} {:>7} {:>7} {:>7} {:>6}  {}\n",
                             "id",
                             "E GPa",
                             "nu",
                             "S_y MPa",
                             "S_ut",
                             "S_e'",
                             "kg/m3",
                             "source");
    for (const MaterialGrade* g : rows) {
      std::cout << fmt::format(
          "{:<24} {:>7.4g} {:>5} {:>7} {:>7} {:>7} {:>6}  {}\n",
          g->id,
          g->E / 1e9,
          g->nu ? fmt::format("{:g}", *g->nu) : "-",
          mpa(g->yield_strength),
          mpa(g->ultimate_strength),
          mpa(g->fatigue_strength) +
              (g->fatigue_cycles ? fmt::format("@{:.0e}", *g->fatigue_cycles) : ""),
          g->density ? fmt::format("{:g}", *g->density) : "-",
          g->source);
      if (rows.size() == 1) {
        std::cout << fmt::format("  designation: {}\n", g->designation);
        if (!g->fatigue_source.empty()) std::cout << fmt::format("  S_e': {}\n", g->fatigue_source);
        if (!g->notes.empty()) std::cout << fmt::format("  notes: {}\n", g->notes);
      }
    }
    if (rows.size() > 1) {
      std::cout << "S_e': uncorrected endurance limit (@N: fatigue strength at N cycles); "
                   "`flexure materials NAME` shows the notes (creep of polymers)\n";
    }
  });
}

}  // namespace flexure::cli
