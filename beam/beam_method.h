#pragma once
// The methods that solve a beam problem (beam/beam_problem.h): their names as the
// tool spells them, and the convergence tolerance each one works to.
#include <array>
#include <string>
#include <string_view>

namespace flexure {

enum class BeamMethod {
  kAuto,      // the cheapest method whose error is within the tolerance (method_selector.h)
  kElliptic,  // exact elliptic-integral elastica (solver/elliptic)
  kShooting,  // shooting method with continuation (solver/shooting)
  kChain,     // Howell's chain algorithm (solver/chain)
  kPrbm,      // pseudo-rigid-body model (elements/prbm_cantilever.h)
  // The cheaper models of the ladder (beam_ladder.h, docs/models.md):
  kLinear,  // linear Euler-Bernoulli theory (elements/ladder_models.h)
  kPrbm3r,  // Su's pseudo-rigid-body 3R model (elements/ladder_models.h)
  kBcm,     // the beam-constraint model, one element (elements/ladder_models.h)
  kCbcm,    // the chained beam-constraint model (elements/ladder_models.h)
};

// "auto", "elliptic", "shooting", "chain", "prbm", "linear", "prbm3r", "bcm", "cbcm", in the order
// of the enum.
inline constexpr std::array<const char*, 9> kBeamMethodNames = {
    "auto", "elliptic", "shooting", "chain", "prbm", "linear", "prbm3r", "bcm", "cbcm"};

const char* to_string(BeamMethod method);
// Throws InvalidInput naming the allowed names.
BeamMethod beam_method_from_string(std::string_view name);

// The convergence tolerance the method works to (recorded in output files); kAuto: elliptic's.
double beam_method_tolerance(BeamMethod method);

}  // namespace flexure
