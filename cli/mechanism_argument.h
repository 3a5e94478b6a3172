#pragma once
// The NAME|FILE.toml argument of the mechanism commands (analyze, draw, export): a built-in
// design's name, or a mechanism file whose reader's warnings go through warn().
#include <string>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::cli {

mechanism::MechanismDesign mechanism_design_argument(const std::string& what);

}  // namespace flexure::cli
