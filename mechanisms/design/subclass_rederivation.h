#pragma once
// Every thesis sub-class re-derived from its own problem (subclass_problem.h): the PRBM synthesis
// (cfm_synthesis.h) and, optionally, the optimum of the exact model (refine_cfm_exact), next
// to the printed point (`flexure design cfm --all-subclasses`; docs/design.md).
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"

namespace flexure::design {

struct SubclassRederivation {
  std::string name;  // "lps-b95I"
  std::string config;
  double stroke_percent = 0.0;  // the effective stroke of the problem
  DesignObjective objective = DesignObjective::kMaxPcf;
  double printed_objective = 0.0;  // the objective at the printed point (Psi_raw or Xi')
  CfmSynthesisResult prbm;         // the re-derived PRBM optimum
  double seconds = 0.0;            // wall time of this row (PRBM and exact)
  // With exact: the printed point's and the exact optimum's Xi'_exact (50 points); the optimum's
  // R, K1, K2; empty where the exact search found no feasible point (exact_message says why).
  std::optional<double> printed_percent_constant_force_exact;
  std::optional<double> percent_constant_force_exact;
  double exact_R = 0.0, exact_K1 = 0.0, exact_K2 = 0.0;
  int exact_evaluations = 0;
  std::string exact_message;
};

struct RederivationOptions {
  bool exact = false;
  SynthesisOptions synthesis;
  int exact_starts = -1;  // Halton starts of the exact search; -1: two per free variable
  std::string config;     // only this configuration's rows; empty: all 68
};

// The thesis rows of `config` (all 68 when empty), in the thesis's order. Throws InvalidInput for
// an unknown configuration.
std::vector<const cfm::CfmSubclass*> thesis_rows(const std::string& config);

// One row re-derived (options.synthesis validated by the caller).
SubclassRederivation rederive_subclass(const cfm::CfmSubclass& row,
                                       const RederivationOptions& options);

// The rows in the thesis's order; `progress(done, total)` after each (may be empty). Throws
// InvalidInput for an unknown configuration.
std::vector<SubclassRederivation> rederive_subclasses(
    const RederivationOptions& options,
    const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace flexure::design
