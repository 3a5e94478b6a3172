#pragma once
// Reads a segment chain (solver/chain_model/segment_chain.h) from a TOML file, for
// `flexure beam --chain FILE.toml` and `flexure path --chain FILE.toml`. Format:
// docs/chain-toml.md; examples in docs/examples/. Unknown keys, missing values and wrong types are
// InvalidInput errors that name the file, the key and its line.
//
// A file is in physical units (SI) when it says units = "SI" or writes any value with a unit
// ("50 mm", "200 GPa", "4.33 N"; solver/common/quantity.h). Only then may a flexible segment give
// its section (E with I, or E with width and thickness) and the file a yield_strength, and only
// then are results reported in metres, newtons and pascals. `material = "NAME"` (the file's, or a
// segment's own) supplies E, nu and the yield strength from data/materials.csv
// (mechanisms/materials_fatigue.h); explicit values replace it with a warning.
#include <optional>
#include <string>
#include <vector>

#include "flexure/beam/physical_beam.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/shooting/rigid_contact.h"

namespace flexure::io {

// A chain file is a PhysicalChain (beam/physical_beam.h: the chain, each flexible segment's
// Section and Material where it gives one, the file's yield_strength, which the reader also puts
// into every such segment's Material) and what only a file says.
struct ChainFile : PhysicalChain {
  bool physical = false;              // SI units (units = "SI" or a value written with a unit)
  std::vector<std::string> warnings;  // likely unit mistakes, for stderr (solver/common/quantity.h)
  // [[contact]] tables (docs/contact.md): a rigid circle or straight stop, the tip load the
  // continuation starts from and its step count. Empty: no contact. Several tables: several
  // surfaces, one continuation (its start load and steps given in one table, or equal).
  struct Contact {
    RigidSurface surface;
    TipLoad start_tip_load;
    bool start_given = false;  // start_tip_load was in the table
    std::optional<int> steps;
    int line = 0;  // of the [[contact]] table, for messages
  };
  std::vector<Contact> contacts;
};

ChainFile read_chain_file(const std::string& path);
ChainFile parse_chain_file(const std::string& text, const std::string& source_name);

// The chain alone.
SegmentChain read_chain_toml(const std::string& path);
// The same from TOML text; `source_name` is used in messages.
SegmentChain parse_chain_toml(const std::string& text, const std::string& source_name);

}  // namespace flexure::io
