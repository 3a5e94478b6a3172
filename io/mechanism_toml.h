#pragma once
// Reads a MechanismDesign from TOML (format: docs/mechanisms.md "TOML description"; examples in
// docs/examples/mechanism_*.toml). Errors throw InvalidInput "SOURCE:LINE: message" naming the key.
// The optional [dynamics] table (masses, spring constants) is what `flexure dynamics` needs beyond
// the design (mechanisms/dynamics/dynamics_design.h); it is checked here and ignored by analyze.
#include <string>
#include <vector>

#include "flexure/mechanisms/dynamics/dynamics_design.h"
#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism {

MechanismDesign parse_mechanism_toml(const std::string& text, const std::string& source);
MechanismDesign load_mechanism_toml(const std::string& path);

// The design and its [dynamics] table (all fields empty and line 0 when there is none).
struct MechanismFile {
  MechanismDesign design;
  dynamics::DynamicsData dynamics;
  // Likely unit mistakes, for stderr (solver/common/quantity.h): a modulus below 1e6 Pa (lengths
  // are in metres), a flexure thicker than a tenth of its length.
  std::vector<std::string> warnings;
};
MechanismFile parse_mechanism_file(const std::string& text, const std::string& source);
MechanismFile load_mechanism_file(const std::string& path);

// The TOML description of `design` that parse_mechanism_toml reads back to the same design
// (every number with 17 significant digits, so the round trip is exact), headed by `comment`
// lines (each prefixed "# "). A fixed-fixed segment is written with its segment kind, length and
// table2_factor; the derived lengths of l segments are not written (they are r/gamma). An
// inverted design is written in its original orientation (the inversion is a reading of the same
// mechanism, mechanisms/inversion.h) with a comment saying so.
std::string mechanism_toml(const MechanismDesign& design, const std::string& comment = "");

}  // namespace flexure::mechanism
