#include "cli/mechanism_argument.h"

#include <utility>

#include "cli/cli_common.h"
#include "flexure/io/toml_files.h"

namespace flexure::cli {

mechanism::MechanismDesign mechanism_design_argument(const std::string& what) {
  const bool is_file = what.size() > 5 && what.substr(what.size() - 5) == ".toml";
  if (!is_file) return mechanism::find_builtin_mechanism(what);
  mechanism::MechanismFile file = mechanism::load_mechanism_file(what);
  warn(file.warnings);
  return std::move(file.design);
}

}  // namespace flexure::cli
