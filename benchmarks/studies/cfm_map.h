#pragma once
// A design-space map of one constant-force configuration (issue 17, `flexure map cfm`;
// docs/design.md "Design-space maps"): over a grid of R, d, K1, K2, the PRBM's mean Phi, percent
// constant force and Psi, the toggle stroke (the stroke limit of eq. 2.16, and whether the
// requested d was clamped to it) and, with the exact model, the exact Xi', exact mean Phi and the
// PRBM's largest force error against it (mechanisms/mechanism_analysis.h, solve_cfm_exact).
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

// One point of the map (index row-major over dims()).
struct CfmMapPoint {
  double Phi = 0.0, percent_constant_force = 0.0, Psi_raw = 0.0, toggle_stroke_percent = 0.0,
         effective_stroke_percent = 0.0;
  int stroke_clamped = 0;
  double percent_constant_force_exact = 0.0, Phi_exact = 0.0, max_force_error = 0.0;  // exact
  int status = kMapOk;
};

// Evaluates point `index` of a validated spec (the PRBM, and the exact model with spec.exact).
CfmMapPoint cfm_map_point(const CfmMapSpec& spec, std::size_t index);

// What a written map holds (on rank 0 under MPI; the counts and the best point over all ranks).
struct CfmMapSummary {
  std::vector<std::size_t> dims;
  std::size_t points = 0, ok = 0, exact_not_converged = 0, invalid = 0;
  double best_percent_constant_force = 0.0;  // exact Xi' with spec.exact, else the PRBM's
  std::size_t best_index = 0;                // the first point of the best value
};

// Evaluates the map and writes it to `path` (docs/hdf5-schema.md "flexure map cfm") as it goes:
// under mpirun every rank takes blocks of points (parallel/work_distribution.h) and writes them
// into the one file; `progress(done, total)` on rank 0 (may be empty). Throws InvalidInput for an
// invalid spec or an unwritable path, before any point is evaluated.
CfmMapSummary write_cfm_map(const CfmMapSpec& spec,
                            const std::string& path,
                            const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace flexure::studies
