#pragma once
// `flexure design cfm --all-subclasses`: every thesis sub-class re-derived
// (mechanisms/design/subclass_rederivation.h), divided over the ranks of an MPI run one row at a
// time (a row takes 5 ms to several seconds: dynamic balancing, io/platform/work_distribution.h),
// and the table written to one HDF5 file (docs/hdf5-schema.md "flexure design cfm
// --all-subclasses").
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "flexure/mechanisms/design/subclass_rederivation.h"

namespace flexure::studies {

struct SubclassTableOptions {
  design::RederivationOptions rederivation;
  std::string out;        // the HDF5 table; empty: none
  std::int64_t seed = 0;  // recorded in the file (the synthesis's seed)
};

// The rows in the thesis's order, on rank 0 (none on the other ranks). Under MPI the rows that
// other ranks computed come back with the table's fields: name, config, stroke, objective, printed
// objective, the PRBM optimum (R, K1, K2, Xi', objective, converged, evaluations), seconds and
// the exact fields. `progress(done, total)` on rank 0. Throws InvalidInput for invalid options or
// an unwritable --out, before any row is computed.
std::vector<design::SubclassRederivation> subclass_table(
    const SubclassTableOptions& options,
    const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace flexure::studies
