#pragma once
// A design-space map of one constant-force configuration (issue 17, `flexure map cfm`;
// docs/design.md "Design-space maps"): over a grid of R, d, K1, K2, the PRBM's mean Phi, percent
// constant force and Psi, the toggle stroke (the stroke limit of eq. 2.16, and whether the
// requested d was clamped to it) and, with the exact model, the exact Xi', exact mean Phi and the
// PRBM's largest force error against it (cfm_exact.h).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"

namespace flexure::studies {

struct CfmMapSpec {
  std::string config;
  std::vector<double> R, d;  // axes (at least one value each)
  // Axes of the spring ratios; empty where the configuration has no such spring (class 1B: K1 is
  // 1 by definition and takes no axis).
  std::vector<double> K1, K2;
  bool exact = false;    // also solve the exact model at every point
  int points = 50;       // exact stroke points
  cfm::CfmOptions prbm;  // the PRBM's stroke sampling (default: the thesis code's)
  // Throws InvalidInput naming the first inconsistent field (unknown configuration, a K axis the
  // configuration cannot take or lacks, empty axes, non-finite or non-positive values).
  void validate() const;
  // The grid's shape: |R| x |d| x max(1, |K1|) x max(1, |K2|), row-major, K2 fastest.
  std::vector<std::size_t> dims() const;
};

// Status codes per point (written as status_meanings of the file).
inline constexpr int kMapOk = 0;
inline constexpr int kMapExactNotConverged = 1;  // PRBM values valid; the exact model did not
                                                 // converge or refused the point: exact 0
inline constexpr int kMapInvalid = 2;            // the model refused the point; every value 0

struct CfmMap {
  std::vector<std::size_t> dims;
  std::vector<double> Phi, percent_constant_force, Psi_raw, toggle_stroke_percent,
      effective_stroke_percent;
  std::vector<int> stroke_clamped;
  std::vector<double> percent_constant_force_exact, Phi_exact, max_force_error;  // with exact
  std::vector<int> status;
};

// Evaluates the map; `progress(done, total)` after every point (may be empty). Throws
// InvalidInput for an invalid spec.
CfmMap cfm_map(const CfmMapSpec& spec,
               const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace flexure::studies
