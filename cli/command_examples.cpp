// The examples that end every command's --help, in one table (each runs as printed:
// tests/cli/cli_help_examples_test.cpp).
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.h"

namespace flexure::cli {
namespace {

struct CommandExamples {
  std::vector<std::string> path;  // e.g. {"mechanism", "analyze"}
  std::vector<std::string> examples;
};

const std::vector<CommandExamples>& command_examples() {
  static const std::vector<CommandExamples> table = {
      {{"beam"},
       {"flexure beam --alpha2 3.087 --json",
        "flexure beam --theta0 1 --n 1 --method shooting",
        "flexure beam --alpha2 8 --boundary guided --method prbm"}},
      {{"sweep", "beam"},
       {"flexure sweep beam --alpha2 0:10:101 --out sweep.h5",
        "flexure sweep beam --alpha2 0.5:8:16 --method prbm --out prbm.h5 --json"}},
      {{"validate"}, {"flexure validate", "flexure validate --out checks.h5 --json"}},
      {{"prbm", "derive"},
       {"flexure prbm derive --segment fixed-pinned --n 0",
        "flexure prbm derive --segment end-moment --json"}},
      {{"prbm", "table"},
       {"flexure prbm table --segment end-moment",
        "flexure prbm table --segment fixed-pinned --step 1"}},
      {{"prbm", "compare"},
       {"flexure prbm compare --segment fixed-pinned --n 0 --alpha2 2",
        "flexure prbm compare --segment end-moment --mu 1 --json",
        "flexure prbm compare --alpha2 1 --range 0.5:5:10"}},
      {{"design", "cfm"},
       {"flexure design cfm --config lpp --d 40 --objective min-xi",
        "flexure design cfm --config sss --d 16 --objective min-xi --K1 1 --json",
        "flexure design cfm --config lps --d 16 --objective max-psi --pcf-min 95 --orientation I"}},
      {{"design", "mechanism"},
       {"flexure design mechanism --force 25lbf --stroke 4in --E 30Msi --safety-factor 1.2 "
        "--length-range 12in:15in --width-range 3in:5in --thickness-range 0.04in:0.07in --config "
        "lpp --out design.toml",
        "flexure design mechanism --force 20N --stroke 10mm --E 200GPa --yield-strength 1200MPa "
        "--safety-factor 1.5 --length-range 30mm:150mm --minimize length",
        "flexure design mechanism --force 100lbf --stroke 6in --E 30Msi --yield-strength 200ksi "
        "--safety-factor 1 --length-range 24in --width-range 5in --thickness-range 0.01in:0.12in "
        "--stress-rule thesis --max-width-to-thickness 1e6 --json"}},
      {{"map", "cfm"},
       {"flexure map cfm --config lpp --R 0.5:1.5:11 --d 16:40:4 --out map.h5",
        "flexure map cfm --config lps --R 0.5:2:16 --d 40 --K2 0.5:5:10 --model exact --out "
        "map.h5 --json"}},
      {{"models", "map"},
       {"flexure models map --n 0 --alpha2 0.5:5:4 --mu 0 --out models.h5",
        "flexure models map --boundary guided --n 0 --alpha2 1:20:5 --models linear,bcm,cbcm "
        "--out guided.h5 --json"}},
      {{"models", "prbm3r-constants"},
       {"flexure models prbm3r-constants --json", "flexure models prbm3r-constants"}},
      {{"cfm"},
       {"flexure cfm --config lpp --R 1 --d 40",
        "flexure cfm --subclass lpp-b --json",
        "flexure cfm --list"}},
      {{"path"},
       {"flexure path --alpha2 10 --mu -6.2832 --out path.h5",
        "flexure path --length 1m --E 1GPa --I 1e-9 --Fx -3N --branch 1 --out buckled.h5",
        "flexure path --boundary guided --control tip-y --tip-y 0.3 --out guided.h5 --json"}},
      {{"mechanism", "list"}, {"flexure mechanism list", "flexure mechanism list --json"}},
      {{"materials"},
       {"flexure materials", "flexure materials polypropylene", "flexure materials --json"}},
      {{"mechanism", "analyze"},
       {"flexure mechanism analyze 1A-lpp --points 20",
        "flexure mechanism analyze 1A-lpp --method prbm --material polypropylene --Kf 1.2 --json",
        "flexure mechanism analyze 1A-spp --points 10 --out spp.h5"}},
      {{"mechanism", "export"},
       {"flexure mechanism export 2A-slp --out 2A-slp.toml",
        "flexure mechanism export \"1A-lpp'\" --points 20"}},
      {{"mechanism", "validate"},
       {"flexure mechanism validate --points 10",
        "flexure mechanism validate --designs howell --points 10 --markdown"}},
      {{"dynamics"},
       {"flexure dynamics --list",
        "flexure dynamics --mechanism 2B-lplm --omega 0:0:1 --force-of half --spring-rule "
        "pure-bending --json",
        "flexure dynamics --mechanism 2B-lplm --omega 0:100:5 --out d.h5"}},
      {{"bench"},
       {"flexure bench --quick --problems cantilever_force --out quick.h5",
        "flexure bench --quick --problems tip_moment --methods elliptic,prbm --out t.h5 --json"}},
      {{"help"}, {"flexure help beam", "flexure help mechanism analyze"}},
  };
  return table;
}

// The child of `parent` named `name`, or null (a stub has no children: command_table.h).
CLI::App* find_child(CLI::App* parent, const std::string& name) {
  for (CLI::App* child : parent->get_subcommands([](CLI::App*) { return true; })) {
    if (child->get_name() == name) return child;
  }
  return nullptr;
}

}  // namespace

void add_command_examples(CLI::App& app) {
  for (const CommandExamples& entry : command_examples()) {
    CLI::App* command = &app;
    for (const std::string& name : entry.path) {
      if (command != nullptr) command = find_child(command, name);
    }
    // Below a stub (command_table.h), which has no children; a stub's own footer is harmless:
    // its help is never printed.
    if (command == nullptr) continue;
    std::string footer = "\nExamples:";
    for (const std::string& example : entry.examples) footer += "\n  " + example;
    command->footer(footer);
  }
}

}  // namespace flexure::cli
