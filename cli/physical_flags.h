#pragma once
// The physical-beam flags that `flexure beam` and `flexure path` share (docs/cli.md, "Physical
// beams"; docs/units.md): --length, --E, the section (--I, or --width and --thickness), the tip
// loads --Fx, --Fy, --M, the distributed loads --qx, --qy, --q-follower, the self-weight
// --density (--g), the extensible beam (--extensible, --nu, --shear-coefficient) and, for `beam`,
// --yield-strength, as SI numbers or values with units.
// --material NAME (data/materials.csv) gives E and S_y that --E and --yield-strength override.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "flexure/beam/physical_beam.h"

namespace flexure::cli {

struct PhysicalFlags {
  std::string length, E, I, width, thickness, Fx, Fy, M, yield_strength, material;
  // Distributed loads, self-weight and extension (docs/cli.md, "Physical beams").
  std::string qx, qy, q_follower, density, g, nu, shear_coefficient;
  // A curved or tapered beam: the stress-free curvature and the section at the tip.
  std::string curvature, width_tip, thickness_tip;
  // The bending modulus: off (E), on (E/(1 - nu^2)), auto (docs/plate-modulus.md).
  std::string plate;
  bool extensible = false;
  std::vector<CLI::Option*> options;
  bool with_yield_strength = false;  // add_to's argument: the command reports a safety factor

  // Adds the flags to `command` in an option group "physical beam".
  void add_to(CLI::App& command, bool with_yield_strength);
  // Whether any of them was given.
  bool given() const;
  // The cantilever they describe; throws InvalidInput naming the flag (missing length or modulus,
  // a bad unit, a section given twice, ...). Warns of likely unit mistakes.
  PhysicalCantilever parse() const;
};

}  // namespace flexure::cli
