#pragma once
// Reads a general planar mechanism (mechanisms/general/general_mechanism.h) from TOML: the form
// with [[body]] tables (docs/mechanisms.md "General mechanisms"; example
// docs/examples/howell_bistable_switch.toml). The constant-force forms (config = "lpp", ...) are
// read by io/mechanism_toml.h as before.
//
// Every error is InvalidInput "SOURCE:LINE: item: message", naming the table and key (an unknown
// key, a missing or badly typed value, a unit of the wrong kind) or, after parsing, the item that
// GeneralMechanism::validate refuses (a flexure between points of one body, an unconstrained
// body, a loop that cannot close, a missing section).
#include <string>

#include "flexure/mechanisms/general/general_mechanism.h"

namespace flexure::mechanism::general {

// Whether a TOML text is the general form: it has a [[body]] array at the top level. Parses the
// text; throws InvalidInput "SOURCE:LINE: TOML syntax error" when it is not TOML.
bool is_general_mechanism_toml(const std::string& text, const std::string& source);

GeneralMechanism parse_general_mechanism_toml(const std::string& text, const std::string& source);
GeneralMechanism load_general_mechanism_toml(const std::string& path);

}  // namespace flexure::mechanism::general
