#pragma once
// The sets of built-in constant-force designs that `flexure mechanism list` and `mechanism
// validate --designs` go through (docs/mechanisms.md, docs/validation.md): the thesis designs
// (Weight 2001, one per configuration), the modified designs of the dynamics paper (paper 004),
// Howell's Table 10.1 designs (builtin_designs.h) and the inversions of those with a
// type-asymmetric configuration (inversion.h).
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism {

enum class DesignSet {
  kBuiltin,     // builtin_mechanisms(): the thesis designs, then the modified ones
  kThesis,      // the thesis designs (builtin_mechanisms() without a paper_config)
  kModified,    // the modified designs (paper 004; builtin_mechanisms() with a paper_config)
  kHowell,      // howell_mechanisms()
  kInversions,  // the inversions of the thesis and Howell designs (the modified ones: none)
  kAll,         // builtin, Howell, inversions, in that order
};

// "builtin", "thesis", "modified", "howell", "inversions", "all" (any case); throws InvalidInput
// listing them.
DesignSet design_set_from_string(const std::string& name);
std::string to_string(DesignSet set);

// The designs of `set` in the order of the printed table: the built-in designs (thesis, then
// modified), Howell's, then the inversions.
std::vector<MechanismDesign> mechanism_designs(DesignSet set);

}  // namespace flexure::mechanism
