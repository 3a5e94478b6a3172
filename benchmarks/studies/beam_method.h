#pragma once
// The methods that solve a beam problem (benchmarks/studies/beam_problem.h): their names as the
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
};

// "auto", "elliptic", "shooting", "chain", "prbm", in the order of the enum.
inline constexpr std::array<const char*, 5> kBeamMethodNames = {
    "auto", "elliptic", "shooting", "chain", "prbm"};

const char* to_string(BeamMethod method);
// Throws InvalidInput naming the allowed names.
BeamMethod beam_method_from_string(std::string_view name);

// The convergence tolerance the method works to (recorded in output files); kAuto: elliptic's.
double beam_method_tolerance(BeamMethod method);

}  // namespace flexure
