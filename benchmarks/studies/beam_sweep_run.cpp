#include "flexure/benchmarks/studies/beam_sweep_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/beam_sweep_solver.h"
#include "flexure/io/beam_sweep.h"
#include "flexure/io/hdf5_file.h"
#include "flexure/io/parallel/mpi_world.h"
#include "flexure/solver/common/errors.h"

namespace flexure {
namespace {

// The axes to store: none for the plain sweep over alpha2 (its /alpha2 is the axis, the layout of
// a 1-D sweep), else every axis.
std::vector<io::BeamSweepAxis> stored_axes(const BeamSweepGrid& grid) {
  std::vector<io::BeamSweepAxis> axes;
  if (grid.axes.size() == 1 && grid.axes[0].parameter == SweepParameter::kAlpha2) return axes;
  for (const SweepAxis& axis : grid.axes) {
    const char* what = axis.parameter == SweepParameter::kAlpha2       ? "load alpha2 = P l^2/EI"
                       : axis.parameter == SweepParameter::kLoadRatioN ? "load ratio n (n > 0 "
                                                                         "compressive)"
                       : axis.parameter == SweepParameter::kMu         ? "end moment mu = M l/EI"
                       : axis.parameter == SweepParameter::kTheta0
                           ? "given tip angle theta0 (the load alpha2 is found)"
                       : axis.parameter == SweepParameter::kBOverL
                           ? "given tip deflection b/l (the load alpha2 is found)"
                       : axis.parameter == SweepParameter::kFx
                           ? "tip force Fx along the undeformed beam of the physical beam"
                       : axis.parameter == SweepParameter::kFy
                           ? "tip force Fy across the undeformed beam of the physical beam"
                           : "tip moment M of the physical beam";
    // A chain file in its own units: its force and moment units.
    const bool file_units = grid.chain && !grid.chain_in_si && is_physical(axis.parameter);
    axes.push_back({dataset_name(axis.parameter),
                    axis.start,
                    axis.stop,
                    axis.count,
                    file_units
                        ? (axis.parameter == SweepParameter::kM ? "moment unit of the chain file"
                                                                : "force unit of the chain file")
                        : units_of(axis.parameter),
                    fmt::format("{}: axis {} of the datasets, {} equally spaced values",
                                what,
                                axes.size() + 1,
                                axis.count)});
  }
  return axes;
}

const char* given_name(const BeamProblem& problem) {
  switch (problem.given) {
    case BeamProblem::Given::kTheta0:
      return "theta0";
    case BeamProblem::Given::kBOverL:
      return "b_over_l";
    default:
      return "alpha2";
  }
}

}  // namespace

long max_beam_sweep_points() {
  return parallel::launched_size() > 1 ? 10'000'000'000L : 10'000'000L;
}

int default_beam_sweep_threads() { return parallel::launched_size() > 1 ? 1 : 2; }

long beam_sweep_chunk(long count, int threads) {
  return std::clamp(count / (64L * threads), 1L, 2048L);
}

long beam_sweep_min_block(BeamMethod method) {
  return method == BeamMethod::kElliptic || method == BeamMethod::kPrbm ? 1024 : 1;
}

std::string describe_sweep_point(const BeamSweepGrid& grid, long index) {
  std::string text;
  const std::vector<double> c = grid.coordinates(index);
  for (std::size_t k = 0; k < c.size(); ++k) {
    text += fmt::format("{}{} = {}", k ? ", " : "", dataset_name(grid.axes[k].parameter), c[k]);
  }
  return text;
}

BeamSweepFile::BeamSweepFile(const std::string& path, bool compress, const std::string& option)
    : path_(path), compress_(compress) {
  if (compress && parallel::launched_size() > 1) {
    throw InvalidInput(
        "compression is not available under mpirun with several ranks: parallel HDF5 writes "
        "compressed datasets only collectively; compress the file afterwards (h5repack -f "
        "SHUF -f GZIP=4)");
  }
  try {
    file_ = std::make_unique<io::AtomicHdf5File>(path, io::Hdf5Access::kCollective);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("{}: {}", option, e.what()));
  }
}

BeamSweepFile::~BeamSweepFile() = default;
BeamSweepFile::BeamSweepFile(BeamSweepFile&&) noexcept = default;
BeamSweepFile& BeamSweepFile::operator=(BeamSweepFile&&) noexcept = default;

BeamSweepRun BeamSweepFile::run(const BeamSweepGrid& grid,
                                BeamMethod requested,
                                const BeamSweepRunOptions& options) {
  if (!file_ || file_->committed()) {
    throw std::logic_error(path_ + ": a BeamSweepFile is written once only");
  }
  const int threads = options.threads == 0 ? default_beam_sweep_threads() : options.threads;
  if (threads < 1 || threads > 64) {
    throw InvalidInput(
        fmt::format("threads = {} is outside the allowed range [1, 64]", options.threads));
  }
  BeamSweepRun out;
  out.method = resolve_beam_method(requested);
  out.count = grid.size();
  // Shooting sweeps start each point from its neighbour where that gives the same answer.
  const BeamSweepSolver sweep_solver(grid, out.method);
  const io::BeamIndexSolver solve_point = [&](long index) {
    BeamSolution solution = sweep_solver.solve(index);
    io::BeamSweepPoint point;
    point.set_converged(solution.converged());
    point.tip = solution.tip;
    point.alpha2 = solution.alpha2;
    if ((grid.physical || grid.chain) && !std::isfinite(point.alpha2)) {
      // A physical point solved as a chain (distributed loads, a curvature, a held end...) has
      // no Howell's alpha2: its nondimensional Fy L^2/EI stands there.
      const BeamProblem problem = grid.at(index);
      if (problem.chain) point.alpha2 = problem.chain->tip_load.Fy;
    }
    if (solution.method == BeamMethod::kPrbm) point.within_validity = solution.prbm_inside_validity;
    point.stability = solution.stability.kind;
    point.stability_index = solution.stability.index;
    point.stability_margin = solution.stability.margin;
    if (!solution.converged()) point.message = std::move(solution.message);
    return point;
  };
  io::BeamSweepOptions sweep;
  sweep.threads = threads;
  sweep.describe = [&](long index) { return describe_sweep_point(grid, index); };
  sweep.chunk = beam_sweep_chunk(out.count, threads);
  sweep.min_block = beam_sweep_min_block(out.method);
  sweep.progress = options.progress;
  io::BeamSweepMetadata metadata;
  metadata.method = to_string(out.method);
  metadata.load_ratio_n = grid.base.load_ratio_n;
  metadata.mu = grid.base.mu;
  metadata.tolerance = beam_method_tolerance(out.method);
  metadata.axes = stored_axes(grid);
  metadata.given = given_name(grid.base);
  metadata.given_value = grid.base.value;
  for (const io::BeamSweepAxis& axis : metadata.axes) out.stored_axes.push_back(axis.name);
  io::Hdf5DatasetOptions layout;
  layout.compress = compress_;
  // Streamed: each block of points is written before the next is solved (flat memory).
  io::BeamSweepWriter writer(file_->root(), out.count, metadata, layout);
  const io::BeamSweepSummary table = io::stream_beam_sweep(out.count, solve_point, sweep, writer);
  if (grid.chain) {
    io::Hdf5Group& root = file_->root();
    root.set_attribute("units", grid.chain_in_si ? "SI" : "chain file");
    root.set_attribute("length", grid.chain->total_length());
  }
  if (grid.physical) {
    // The physical beam: its results are per unit length and in Howell's loads; these scale them
    // (tip x = a_over_l length_m; Fy = alpha2 EI_Nm2 / length_m^2).
    const PhysicalCantilever& b = *grid.physical;
    io::Hdf5Group& root = file_->root();
    root.set_attribute("units", "SI");
    root.set_attribute("length_m", b.length);
    root.set_attribute("EI_Nm2", b.flexural_rigidity());
    root.set_attribute("Fx_N", b.Fx);
    root.set_attribute("Fy_N", b.Fy);
    root.set_attribute("M_Nm", b.M);
  }
  file_->commit();
  out.converged_count = table.converged_count;
  out.first_failure = table.first_failure;
  out.first_failure_message = table.first_failure_message;
  return out;
}

}  // namespace flexure
