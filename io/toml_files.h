#pragma once
// The TOML files in one header: chains, general mechanisms and mechanism designs, read and
// written.
//
// Reads a segment chain (solver/chain_model/segment_chain.h) from a TOML file, for
// `flexure beam --chain FILE.toml` and `flexure path --chain FILE.toml`. Format:
// docs/chain-toml.md; examples in docs/examples/. Unknown keys, missing values and wrong types are
// InvalidInput errors that name the file, the key and its line.
//
// A file is in physical units (SI) when it says units = "SI" or writes any value with a unit
// ("50 mm", "200 GPa", "4.33 N"; solver/common/section.h). Only then may a flexible segment give
// its section (E with I, or E with width and thickness) and the file a yield_strength, and only
// then are results reported in metres, newtons and pascals. `material = "NAME"` (the file's, or a
// segment's own) supplies E, nu and the yield strength from data/materials.csv
// (mechanisms/materials_fatigue.h); explicit values replace it with a warning.
//
// Reads a general planar mechanism (mechanisms/general/general_mechanism.h) from TOML: the form
// with [[body]] tables (docs/mechanisms.md "General mechanisms"; example
// docs/examples/howell_bistable_switch.toml). The constant-force forms (config = "lpp", ...) are
// read by load_mechanism_toml (below) as before.
//
// Every error is InvalidInput "SOURCE:LINE: item: message", naming the table and key (an unknown
// key, a missing or badly typed value, a unit of the wrong kind) or, after parsing, the item that
// GeneralMechanism::validate refuses (a flexure between points of one body, an unconstrained
// body, a loop that cannot close, a missing section).
//
// Reads a MechanismDesign from TOML (format: docs/mechanisms.md "TOML description"; examples in
// docs/examples/mechanism_*.toml). Errors throw InvalidInput "SOURCE:LINE: message" naming the key.
// The optional [dynamics] table (masses, spring constants) is what `flexure dynamics` needs beyond
// the design (mechanisms/dynamics/dynamics.h); it is checked here and ignored by analyze.
#include <optional>
#include <string>
#include <vector>

#include "flexure/beam/physical_beam.h"
#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/shooting/rigid_contact.h"

namespace flexure::io {

// A chain file is a PhysicalChain (beam/physical_beam.h: the chain, each flexible segment's
// Section and Material where it gives one, the file's yield_strength, which the reader also puts
// into every such segment's Material) and what only a file says.
struct ChainFile : PhysicalChain {
  bool physical = false;              // SI units (units = "SI" or a value written with a unit)
  std::vector<std::string> warnings;  // likely unit mistakes, for stderr (solver/common/section.h)
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

namespace flexure::mechanism::general {

// Whether a TOML text is the general form: it has a [[body]] array at the top level. Parses the
// text; throws InvalidInput "SOURCE:LINE: TOML syntax error" when it is not TOML.
bool is_general_mechanism_toml(const std::string& text, const std::string& source);

GeneralMechanism parse_general_mechanism_toml(const std::string& text, const std::string& source);
GeneralMechanism load_general_mechanism_toml(const std::string& path);

}  // namespace flexure::mechanism::general

namespace flexure::mechanism {

MechanismDesign parse_mechanism_toml(const std::string& text, const std::string& source);
MechanismDesign load_mechanism_toml(const std::string& path);

// The design and its [dynamics] table (all fields empty and line 0 when there is none).
struct MechanismFile {
  MechanismDesign design;
  dynamics::DynamicsData dynamics;
  // Likely unit mistakes, for stderr (solver/common/section.h): a modulus below 1e6 Pa (lengths
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
