#include "flexure/benchmarks/studies/beam_sweep_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/beam_sweep_solver.h"
#include "flexure/beam/physical_beam.h"
#include "flexure/benchmarks/studies/shapes_group.h"
#include "flexure/io/beam_sweep.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/mpi_world.h"
#include "flexure/solver/common/status.h"

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

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The shapes of a sweep, gathered point by point (each thread writes its own rows).
struct SweepShapes {
  int points = 0;  // shape points per sweep point
  std::vector<double> s, x, y, theta, moment, axial, shear, stress_pos, stress_neg;
  bool forces = true;                         // N, V, m known at every point (see store)
  std::vector<double> section_modulus, area;  // a physical beam with a rectangle (SI)
  // Scales from the solution's units (per unit length, Howell's loads) to the stored ones.
  double length = 1.0, force = 1.0, moment_scale = 1.0;

  void store(long index, const BeamProblem& problem, const BeamSolution& solution) {
    const std::size_t row = static_cast<std::size_t>(index) * points;
    const bool have = solution.converged() && static_cast<int>(solution.shape.size()) == points;
    // N . t, N . n and m from the statics of the part before each point (the clamp's reaction;
    // docs/units.md "Internal forces"), exact for tip and joint loads; a distributed load by the
    // midpoint rule over the shape's intervals, as the single solve's shapes
    // (shape_internal_forces). A chain's solution holds its shape per unit total length (the tips
    // a/l, b/l), its reactions in the chain's own units: the shape in those units first (a physical
    // beam's chain has length 1).
    std::vector<ShapePoint> shape = solution.shape;
    const double chain_length = problem.chain ? problem.chain->total_length() : 1.0;
    for (ShapePoint& p : shape) {
      p.s *= chain_length;
      p.x *= chain_length;
      p.y *= chain_length;
    }
    ShapeInternalForces f;
    if (have) {
      if (!problem.chain) {
        f = shape_internal_forces(
            uniform_cantilever(EndLoad{0.0, 0.0, 0.0}), shape, solution.reactions);
      } else {
        f = shape_internal_forces(*problem.chain, shape, solution.chain_reactions);
      }
    }
    const bool known = f.moment.size() == static_cast<std::size_t>(points);
    for (int k = 0; k < points; ++k) {
      const std::size_t i = row + k;
      x[i] = have ? shape[k].x * length : kNaN;
      y[i] = have ? shape[k].y * length : kNaN;
      theta[i] = have ? shape[k].theta : kNaN;
      moment[i] = known ? f.moment[k] * moment_scale : kNaN;
      axial[i] = known ? f.axial[k] * force : kNaN;
      shear[i] = known ? f.shear[k] * force : kNaN;
      if (!section_modulus.empty()) {
        // N/A -+ m c/I: a positive moment compresses the +n fibre (docs/units.md).
        stress_pos[i] = axial[i] / area[k] - moment[i] / section_modulus[k];
        stress_neg[i] = axial[i] / area[k] + moment[i] / section_modulus[k];
      }
    }
  }
};

}  // namespace

long max_beam_sweep_shape_values() { return 5'000'000L; }

void check_beam_sweep_shapes(long count, int shape_points) {
  if (shape_points == 0) return;
  if (shape_points < 2 || shape_points > 100'000) {
    throw InvalidInput(fmt::format(
        "--shapes = {} is outside the allowed range [2, 100000] (shape points per sweep point)",
        shape_points));
  }
  if (static_cast<double>(count) * shape_points >
      static_cast<double>(max_beam_sweep_shape_values())) {
    throw InvalidInput(fmt::format(
        "--shapes {}: {} sweep points x {} shape points = {:.0f} values exceeds the {} a sweep "
        "stores (the shapes are held in memory until the sweep ends); ask for fewer shape points "
        "or fewer sweep points",
        shape_points,
        count,
        shape_points,
        static_cast<double>(count) * shape_points,
        max_beam_sweep_shape_values()));
  }
  if (parallel::launched_size() > 1) {
    throw InvalidInput(
        "--shapes is not available under mpirun with several ranks: the shapes are gathered in "
        "one process; run the sweep with shapes on one rank");
  }
}

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
  const int K = options.shape_points;
  check_beam_sweep_shapes(out.count, K);
  SweepShapes shapes;
  BeamSweepGrid solved_grid = grid;
  if (K > 0) {
    // The solver returns the shape at K points (a shooting sweep's points still start from their
    // neighbours: BeamSweepSolver integrates the shape with the warm-started solve).
    solved_grid.base.shape_points = K;
    shapes.points = K;
    const std::size_t n = static_cast<std::size_t>(out.count) * K;
    for (std::vector<double>* v :
         {&shapes.x, &shapes.y, &shapes.theta, &shapes.moment, &shapes.axial, &shapes.shear}) {
      v->assign(n, kNaN);
    }
    const double total = grid.chain ? grid.chain->total_length() : 1.0;
    if (grid.physical) {
      // Howell's units per unit length -> SI: x L, F EI/L^2, M EI/L.
      const PhysicalCantilever& b = *grid.physical;
      shapes.length = b.length;
      shapes.force = b.flexural_rigidity() / (b.length * b.length);
      shapes.moment_scale = b.flexural_rigidity() / b.length;
      b.fibre_sections(K, shapes.section_modulus, shapes.area);
      if (!shapes.section_modulus.empty()) {
        shapes.stress_pos.assign(n, kNaN);
        shapes.stress_neg.assign(n, kNaN);
      }
    }
    for (int k = 0; k < K; ++k) shapes.s.push_back(total * k / (K - 1) * shapes.length);
  }
  // Shooting sweeps start each point from its neighbour where that gives the same answer.
  const BeamSweepSolver sweep_solver(solved_grid, out.method);
  const io::BeamIndexSolver solve_point = [&](long index) {
    BeamSolution solution = sweep_solver.solve(index);
    if (K > 0) shapes.store(index, solved_grid.at(index), solution);
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
  metadata.method = out.method;
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
  ShapesView view;
  std::vector<double> times;
  if (K > 0) {
    view.rows = out.count;
    view.shape_points = K;
    view.s = shapes.s;
    view.x = shapes.x;
    view.y = shapes.y;
    view.theta = shapes.theta;
    view.moment = shapes.moment;
    view.axial = shapes.axial;
    view.shear = shapes.shear;
    view.stress_pos = shapes.stress_pos;
    view.stress_neg = shapes.stress_neg;
    view.row_name = "sweep point";
    if (grid.physical) {
      view.length_unit = "m";
      view.force_unit = "N";
      view.moment_unit = "N m";
    } else if (grid.chain) {
      view.length_unit = grid.chain_in_si ? "m" : "length unit of the chain file";
      view.force_unit = grid.chain_in_si ? "N" : "force unit of the chain file";
      view.moment_unit = grid.chain_in_si ? "N m" : "moment unit of the chain file";
    } else {
      view.scaled = " (nondimensional: l = 1, EI = 1)";
    }
    write_shapes_group(file_->root(), view);
    file_->root().set_attribute("shape_points", static_cast<std::int64_t>(K));
    // The XDMF time of a row: the swept value of a sweep along one axis, else the point's index.
    for (long i = 0; i < out.count; ++i) {
      times.push_back(grid.axes.size() == 1 ? grid.coordinates(i)[0] : static_cast<double>(i));
    }
  }
  file_->commit();
  if (K > 0) out.xdmf = write_shapes_xdmf(path_, view, times);
  out.converged_count = table.converged_count;
  out.first_failure = table.first_failure;
  out.first_failure_message = table.first_failure_message;
  return out;
}

}  // namespace flexure
