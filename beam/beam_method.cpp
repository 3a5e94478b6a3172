#include <fmt/format.h>

#include "flexure/beam/beam_problem.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/common/enum_names.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

const char* to_string(BeamMethod method) { return enum_name(kBeamMethodNames, method); }

BeamMethod beam_method_from_string(std::string_view name) {
  return enum_from_name<BeamMethod>(kBeamMethodNames, name, "method");
}

double beam_method_tolerance(BeamMethod method) {
  switch (method) {
    case BeamMethod::kAuto:
    case BeamMethod::kElliptic:
      return EllipticSolver::Options{}.tolerance;
    case BeamMethod::kShooting:
      return ShootingSolver::Options{}.rtol;
    case BeamMethod::kChain:
      return ChainAlgorithmSolver::Options{}.tolerance;
    case BeamMethod::kPrbm:
      return 1e-13;  // virtual-work residual of PrbmElement::solve
    case BeamMethod::kLinear:
    case BeamMethod::kBcm:
      return 0.0;  // closed forms
    case BeamMethod::kPrbm3r:
      return Prbm3rSolver::Options{}.tolerance;
    case BeamMethod::kCbcm:
      return ChainedBcmSolver::Options{}.tolerance;
  }
  return EllipticSolver::Options{}.tolerance;
}

}  // namespace flexure
