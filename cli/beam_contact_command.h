#pragma once
// `flexure beam --chain FILE` when FILE has a [[contact]] table: frictionless contact with a rigid
// circle or straight stop (solver/shooting/rigid_contact.h, docs/contact.md). Prints the text
// report or one JSON object, writes the HDF5 file of --out.
#include <optional>
#include <string>

namespace flexure::cli {

// The flags of `flexure beam` that matter with contact, and the ones it refuses.
struct BeamContactArgs {
  std::string chain_file;
  std::string method = "auto";  // auto or shooting; any other is refused (exit 2)
  std::optional<std::string> integrator;
  int shape_points = 0;
  bool json = false;
  std::string out;  // HDF5 file, empty: none
  // Flags given that contact does not take (each refused with the reason), e.g. "--stable".
  std::string refused_flag;
};

// Returns false (doing nothing) when the chain file has no [[contact]]; otherwise solves and
// prints. Throws InvalidInput (exit 2) for an unsupported combination, NoConvergenceReport
// (exit 3) when the contact solution is not reached.
bool run_beam_contact(const BeamContactArgs& args);

}  // namespace flexure::cli
