#pragma once
// Writes a general planar mechanism (mechanisms/general/general_mechanism.h) as the TOML form that
// io/toml_files.h reads ([[body]], [[joint]], [[flexure]], [[spring]], [[load]],
// [input]; docs/mechanisms.md "General mechanisms"): every number in SI, printed with the
// shortest decimal that reads back to the same double, so that reading the text gives the same
// description (names, points, sections, moduli, models, input and its start_rotation) to the bit,
// a body's points in the reader's (key) order. What `flexure mechanism export` writes for a
// built-in design's general form (docs/mechanisms.md "The catalogue as general mechanisms").
#include <string>

#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism::general {

// The TOML text of `mechanism`, led by `header` (each line written as a "# " comment; empty:
// none). Throws InvalidInput for a description that does not validate (GeneralMechanism::validate)
// or whose names cannot be TOML bare keys of a points table (letters, digits, '_' and '-').
std::string general_mechanism_to_toml(const GeneralMechanism& mechanism,
                                      const std::string& header = "");

// A constant-force design (built-in or from a design file) as a general TOML file
// (`flexure mechanism export`): its general form (catalogue_general.h) over `points` stroke points,
// led by a comment naming the design, where its numbers come from, and how the general models'
// numbers read as the catalogue's (the slider force is minus input_load; the stroke
// Delta x = x0 - input). Throws InvalidInput as general_from_design does.
std::string design_as_general_toml(const MechanismDesign& design, int points);

}  // namespace flexure::mechanism::general
