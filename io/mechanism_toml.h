#pragma once
// Reads a MechanismDesign from TOML (format: docs/mechanisms.md "TOML description"; examples in
// docs/examples/mechanism_*.toml). Errors throw InvalidInput "SOURCE:LINE: message" naming the key.
#include <string>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism {

MechanismDesign parse_mechanism_toml(const std::string& text, const std::string& source);
MechanismDesign load_mechanism_toml(const std::string& path);

}  // namespace flexure::mechanism
