// write_cfm_map (cfm_map.h): the map written block by block, by one rank or by every rank of an
// MPI run into one file (docs/hdf5-schema.md "flexure map cfm"; docs/scaling.md).
#include <fmt/format.h>

#include <algorithm>
#include <memory>

#include "flexure/benchmarks/studies/cfm_map.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/io/platform/work_distribution.h"
#include "flexure/solver/common/status.h"

namespace flexure::studies {
namespace {

// The grid quantities in file order: name, units, description, member of CfmMapPoint.
struct GridColumn {
  const char* name;
  const char* units;
  const char* description;
  double CfmMapPoint::*value;
};

const std::vector<GridColumn>& prbm_columns() {
  static const std::vector<GridColumn> columns = {
      {"Phi", "1", "PRBM mean of Phi = F r2/k1 (class 1B: k2) over the stroke", &CfmMapPoint::Phi},
      {"percent_constant_force",
       "%",
       "PRBM Xi' = 100 min F/max F",
       &CfmMapPoint::percent_constant_force},
      {"Psi_raw",
       "1",
       "PRBM stiffness parameter Psi before normalisation (eq. 5.19)",
       &CfmMapPoint::Psi_raw},
      {"toggle_stroke_percent",
       "%",
       "stroke limit of R (the toggle position, eq. 2.16)",
       &CfmMapPoint::toggle_stroke_percent},
      {"effective_stroke_percent",
       "%",
       "the stroke evaluated: d, or the toggle stroke where d is past it",
       &CfmMapPoint::effective_stroke_percent}};
  return columns;
}

const std::vector<GridColumn>& exact_columns() {
  static const std::vector<GridColumn> columns = {
      {"percent_constant_force_exact",
       "%",
       "exact-model Xi' (0 where it vanishes or changes sign, or status != 0)",
       &CfmMapPoint::percent_constant_force_exact},
      {"Phi_exact", "1", "exact-model mean Phi", &CfmMapPoint::Phi_exact},
      {"max_force_error",
       "1",
       "largest |F_prbm - F_exact|/|F_exact| over the stroke points",
       &CfmMapPoint::max_force_error}};
  return columns;
}

// Per-rank tallies, summed over the ranks at the end.
struct Tally {
  long ok = 0, not_converged = 0, invalid = 0;
  double best = -1.0;
  long best_index = -1;
};

}  // namespace

CfmMapSummary write_cfm_map(const CfmMapSpec& spec,
                            const std::string& path,
                            const std::function<void(std::size_t, std::size_t)>& progress) {
  spec.validate();
  io::check_output_path(path);
  std::unique_ptr<io::AtomicHdf5File> file;
  try {
    file = std::make_unique<io::AtomicHdf5File>(path, io::Hdf5Access::kCollective);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("--out: {}", e.what()));
  }
  io::Hdf5Group& root = file->root();
  const parallel::World& world = parallel::world();
  root.set_attribute("config", spec.config);
  root.set_attribute("model", spec.exact ? "exact" : "prbm");
  root.set_attribute("mpi_ranks", static_cast<std::int64_t>(world.size()));
  root.set_attribute("exact_points", static_cast<std::int64_t>(spec.points));
  root.set_attribute("description",
                     "design-space map over R x d x K1 x K2 (row-major, K2 fastest; a missing "
                     "spring's axis has one entry 0)");
  const auto axis = [&](const char* name, const std::vector<double>& v, const char* text) {
    const std::vector<double> values = v.empty() ? std::vector<double>{0.0} : v;
    root.write_dataset(name, std::span<const double>(values), "1", text);
  };
  axis("R", spec.R, "R = r3/r2, axis 0");
  root.write_dataset("d", std::span<const double>(spec.d), "%", "design stroke d, axis 1");
  axis("K1", spec.K1, "K1 = k2/k1, axis 2 (0: no such variable)");
  axis("K2", spec.K2, "K2 = k3/k1, axis 3 (0: no such variable)");

  const std::vector<std::size_t> dims = spec.dims();
  const std::vector<hsize_t> shape(dims.begin(), dims.end());
  const long total = static_cast<long>(dims[0] * dims[1] * dims[2] * dims[3]);
  std::vector<GridColumn> columns = prbm_columns();
  if (spec.exact) {
    columns.insert(columns.end(), exact_columns().begin(), exact_columns().end());
  }
  std::vector<io::Hdf5Dataset> values;
  for (const GridColumn& c : columns) {
    values.push_back(
        root.create_dataset(c.name, io::Hdf5Type::kFloat64, shape, c.units, c.description));
  }
  io::Hdf5Dataset clamped =
      root.create_dataset("stroke_clamped",
                          io::Hdf5Type::kInt32,
                          shape,
                          "1",
                          "1 where d was past the toggle position and the stroke was clamped");
  io::Hdf5Dataset status = root.create_dataset(
      "status",
      io::Hdf5Type::kInt32,
      shape,
      "1",
      "0 ok, 1 exact model not converged or refused (exact values 0), 2 PRBM model refused the "
      "point");

  Tally tally;
  parallel::DistributionOptions options;
  // PRBM points take microseconds, exact ones about 20 ms: blocks of up to 4096 and 16.
  options.max_block = spec.exact ? 16 : 4096;
  if (progress) {
    options.progress = [&](long done, long n) {
      progress(static_cast<std::size_t>(done), static_cast<std::size_t>(n));
    };
  }
  options.describe = [&](long k) {
    const std::size_t i = static_cast<std::size_t>(k) / (dims[1] * dims[2] * dims[3]);
    const std::size_t j = (static_cast<std::size_t>(k) / (dims[2] * dims[3])) % dims[1];
    return fmt::format("R = {}, d = {} %", spec.R[i], spec.d[j]);
  };
  parallel::distribute(
      total,
      [&](long begin, long end) -> parallel::BlockWriter {
        auto points = std::make_shared<std::vector<CfmMapPoint>>();
        for (long k = begin; k < end; ++k) {
          points->push_back(cfm_map_point(spec, static_cast<std::size_t>(k)));
        }
        return [&, points, begin] {
          const auto at = static_cast<hsize_t>(begin);
          std::vector<double> column(points->size());
          for (std::size_t c = 0; c < columns.size(); ++c) {
            std::transform(
                points->begin(), points->end(), column.begin(), [&](const CfmMapPoint& p) {
                  return p.*(columns[c].value);
                });
            values[c].write_range(at, std::span<const double>(column));
          }
          std::vector<int> codes(points->size()), clamps(points->size());
          for (std::size_t n = 0; n < points->size(); ++n) {
            const CfmMapPoint& p = (*points)[n];
            codes[n] = p.status;
            clamps[n] = p.stroke_clamped;
            (p.status == kMapOk
                 ? tally.ok
                 : (p.status == kMapInvalid ? tally.invalid : tally.not_converged)) += 1;
            const double pcf =
                spec.exact ? p.percent_constant_force_exact : p.percent_constant_force;
            if (pcf > tally.best) {
              tally.best = pcf;
              tally.best_index = begin + static_cast<long>(n);
            }
          }
          clamped.write_range(at, std::span<const int>(clamps));
          status.write_range(at, std::span<const int>(codes));
        };
      },
      options);

  io::write_provenance(root,
                       {{"status", kMapOk, "ok"},
                        {"status",
                         kMapExactNotConverged,
                         "the exact model did not converge or refused the point (exact values 0; "
                         "PRBM values valid)"},
                        {"status", kMapInvalid, "the model refused the point"}});
  values.clear();
  file->commit();

  CfmMapSummary summary;
  summary.dims = dims;
  summary.points = static_cast<std::size_t>(total);
  summary.ok = static_cast<std::size_t>(world.sum(tally.ok));
  summary.exact_not_converged = static_cast<std::size_t>(world.sum(tally.not_converged));
  summary.invalid = static_cast<std::size_t>(world.sum(tally.invalid));
  // The best value over the ranks, at its first index (as a serial scan finds it).
  const std::vector<double> best = world.gather(std::vector<double>{tally.best});
  const std::vector<std::int64_t> at = world.gather(std::vector<std::int64_t>{tally.best_index});
  bool found = false;
  for (std::size_t r = 0; r < best.size(); ++r) {
    if (at[r] < 0) continue;
    const auto index = static_cast<std::size_t>(at[r]);
    if (!found || best[r] > summary.best_percent_constant_force ||
        (best[r] == summary.best_percent_constant_force && index < summary.best_index)) {
      summary.best_percent_constant_force = best[r];
      summary.best_index = index;
      found = true;
    }
  }
  return summary;
}

}  // namespace flexure::studies
