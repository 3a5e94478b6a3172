// `flexure mechanism draw MECH --out FILE.svg|FILE.dxf`: the buildable geometry of a design drawn
// to scale (io/mechanism_drawing.h; docs/drawings.md). Parses, calls the library, prints.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/mechanism_argument.h"
#include "cli/mechanism_geometry_output.h"
#include "flexure/io/mechanism_drawing.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact_geometry.h"

namespace flexure::cli {

void register_mechanism_draw_command(CLI::App& app) {
  CLI::App& mech = get_or_add_subcommand(
      app, "mechanism", "Constant-force slider mechanisms: PRBM and exact model of one design");
  struct DrawArgs {
    std::string what;
    std::string out;
    std::string stroke_end = "on";
    std::string deformed = "exact";
    std::string unit = "mm";
    bool json = false;
  };
  auto args = std::make_shared<DrawArgs>();
  CLI::App* draw = mech.add_subcommand(
      "draw",
      "Drawing to scale in mm (SVG or DXF): links, flexures, pins, slider, rest and stroke end");
  draw->add_option("mechanism",
                   args->what,
                   "Built-in name (1A-lpp, 3A-sss, howell-1A-spp-b, ...) or FILE.toml")
      ->required();
  draw->add_option("--out", args->out, "Drawing file: .svg or .dxf (written whole or not at all)")
      ->required();
  draw->add_option("--stroke-end", args->stroke_end, "Draw the end of the stroke too: on or off")
      ->default_str("on")
      ->transform(CLI::IsMember({"on", "off"}, CLI::ignore_case));
  draw->add_option("--deformed",
                   args->deformed,
                   "Shapes at the end of the stroke: exact (the exact model's bent flexures; PRBM "
                   "where the configuration has no exact model) or prbm (pseudo-rigid polylines)")
      ->default_str("exact")
      ->transform(CLI::IsMember({"exact", "prbm"}, CLI::ignore_case));
  draw->add_option("--unit", args->unit, "Length unit of the text output (mm, in, ...)")
      ->default_str("mm");
  draw->add_flag("--json", args->json, "Print one JSON object");
  draw->callback([args] {
    check_drawing_path(args->out, "--out");
    const mechanism::MechanismDesign d = mechanism_design_argument(args->what);
    mechanism::MechanismGeometry g = mechanism::mechanism_geometry(d);
    const std::string text = geometry_text(g, args->unit);  // checks --unit before writing
    io::DrawingOptions options;
    options.stroke_end = args->stroke_end == "on";
    if (options.stroke_end && args->deformed == "exact") {
      const std::string why_not = mechanism::add_exact_stroke_end(g, d);
      if (!why_not.empty()) {
        warn(
            fmt::format("{}: the end of the stroke is drawn with the PRBM's pseudo-rigid "
                        "flexures ({})",
                        d.name,
                        why_not));
      }
    }
    io::write_mechanism_drawing(args->out, g, options);
    const auto dims = io::principal_dimensions(g);
    if (args->json) {
      print_json(
          Json{{"design", d.name},
               {"config", d.config},
               {"out", args->out},
               {"format", io::drawing_format(args->out) == io::DrawingFormat::kSvg ? "svg" : "dxf"},
               {"stroke_end", options.stroke_end},
               {"deformed_model",
                !options.stroke_end ? Json(nullptr) : Json(g.exact_stroke_end ? "exact" : "prbm")},
               {"units", "SI: m, rad"},
               {"dimensions", dimensions_json(dims)},
               {"geometry", geometry_json(g)}});
      return;
    }
    std::cout << fmt::format("{} ({}): drawing written to {} (mm{})\n",
                             d.name,
                             d.config,
                             args->out,
                             options.stroke_end ? ", rest and end of the stroke" : ", rest");
    std::cout << text;
  });
}

}  // namespace flexure::cli
