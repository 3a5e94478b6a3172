#include "flexure/io/beam_sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/work_distribution.h"
#include "flexure/solver/common/evenly_spaced.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool finite_pose(const TipPose& tip) {
  return std::isfinite(tip.a_over_l) && std::isfinite(tip.b_over_l) && std::isfinite(tip.theta0);
}

}  // namespace

BeamSweepTable run_beam_sweep(const std::vector<double>& alpha2,
                              const BeamPointSolver& solve,
                              const BeamSweepOptions& options) {
  BeamSweepOptions named = options;
  if (!named.describe) {
    named.describe = [&](long i) { return fmt::format("alpha2 = {}", alpha2[i]); };
  }
  BeamSweepTable table = run_beam_sweep(
      static_cast<long>(alpha2.size()),
      [&](long i) {
        BeamSweepPoint point = solve(alpha2[i]);
        point.alpha2 = alpha2[i];
        return point;
      },
      named);
  table.alpha2 = alpha2;  // the given loads, also where a solver threw
  return table;
}

BeamSweepTable run_beam_sweep(long total,
                              const BeamIndexSolver& solve,
                              const BeamSweepOptions& options) {
  const auto describe = [&](long i) {
    return options.describe ? options.describe(i) : fmt::format("point {}", i);
  };
  BeamSweepTable table;
  table.alpha2.assign(total, kNaN);
  table.a_over_l.assign(total, kNaN);
  table.b_over_l.assign(total, kNaN);
  table.theta0.assign(total, kNaN);
  table.status.assign(total, kSweepNotConverged);
  table.within_validity.assign(total, -1);
  table.stability.assign(total, stability_code(StabilityKind::kNotChecked));
  table.stability_index.assign(total, -1);
  table.stability_margin.assign(total, kNaN);

  const long chunk = std::max(1L, options.chunk);
  std::atomic<long> next{0};
  std::atomic<long> done{0};
  std::atomic<bool> stop{false};
  // A load that throws (invalid input at that load) ends the sweep. The error reported is that of
  // the first such load, whatever the number of threads: loads past it are skipped, those before
  // it are all still solved, so that a smaller one that throws too is found.
  std::atomic<long> error_at{std::numeric_limits<long>::max()};
  std::exception_ptr error;
  std::mutex error_mutex;
  // Points write disjoint entries of the table, so no locking is needed for the results.
  const auto work = [&] {
    long i = -1;
    try {
      while (!stop.load(std::memory_order_relaxed)) {
        const long begin = next.fetch_add(chunk);
        if (begin >= total || begin >= error_at.load()) break;
        const long end = std::min(total, begin + chunk);
        for (i = begin; i < end && i < error_at.load() && !stop.load(std::memory_order_relaxed);
             ++i) {
          BeamSweepPoint point;
          try {
            point = solve(i);
          } catch (const NoConvergence& e) {
            point.set_converged(false);
            point.message = e.what();
          } catch (const InvalidInput& e) {
            throw InvalidInput(fmt::format("at {}: {}", describe(i), e.what()));
          }
          table.alpha2[i] = point.alpha2;
          if (point.converged() && finite_pose(point.tip) && std::isfinite(point.alpha2)) {
            table.a_over_l[i] = point.tip.a_over_l;
            table.b_over_l[i] = point.tip.b_over_l;
            table.theta0[i] = point.tip.theta0;
            table.status[i] = kSweepConverged;
            table.within_validity[i] = point.within_validity;
            table.stability[i] = stability_code(point.stability);
            const bool judged = point.stability == StabilityKind::kStable ||
                                point.stability == StabilityKind::kUnstable ||
                                point.stability == StabilityKind::kCritical;
            if (judged && std::isfinite(point.stability_margin)) {
              table.stability_index[i] = point.stability_index;
              table.stability_margin[i] = point.stability_margin;
            } else {
              table.stability[i] =
                  stability_code(judged ? StabilityKind::kNotChecked : point.stability);
            }
          }
        }
        done.fetch_add(end - begin);
      }
    } catch (...) {
      const std::lock_guard lock(error_mutex);
      if (i < 0) {
        stop = true;  // not at a load (nothing is thrown outside the solve today)
        if (!error) error = std::current_exception();
      } else if (i < error_at.load()) {
        error_at = i;
        error = std::current_exception();
      }
    }
  };

  const int threads = static_cast<int>(
      std::clamp<long>(options.threads, 1, std::max(1L, (total + chunk - 1) / chunk)));
  std::vector<std::thread> helpers;
  helpers.reserve(threads - 1);
  for (int t = 1; t < threads; ++t) helpers.emplace_back(work);
  if (options.progress) {
    // The caller reports progress between its own chunks; helpers never touch the terminal.
    std::thread caller_worker(work);
    try {
      while (done.load() < total && !stop.load() &&
             error_at.load() == std::numeric_limits<long>::max()) {
        options.progress(done.load(), total);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    } catch (...) {
      // A progress hook that throws stops the sweep (the Python module's Ctrl-C): the threads
      // finish the load they are at and are joined before the exception goes on.
      stop = true;
      caller_worker.join();
      for (std::thread& helper : helpers) helper.join();
      throw;
    }
    caller_worker.join();
  } else {
    work();
  }
  for (std::thread& helper : helpers) helper.join();
  if (error) std::rethrow_exception(error);
  if (options.progress) options.progress(total, total);

  for (long i = 0; i < total; ++i) {
    if (table.status[i] == kSweepConverged) {
      ++table.converged_count;
    } else if (table.first_failure < 0) {
      table.first_failure = i;
    }
  }
  if (table.first_failure >= 0) {
    // Re-solve the first failure once, serially, for its message (cheaper than storing one
    // message per point).
    try {
      BeamSweepPoint point = solve(table.first_failure);
      table.first_failure_message =
          point.converged() ? "the solution contains a non-finite value" : point.message;
    } catch (const NoConvergence& e) {
      table.first_failure_message = e.what();
    }
  }
  return table;
}

const std::vector<CodeMeaning>& beam_sweep_code_meanings() {
  static const std::vector<CodeMeaning> codes = {
      {"status", kSweepConverged, "converged"},
      {"status",
       kSweepNotConverged,
       "no converged solution at this load (a_over_l, b_over_l, theta0 are NaN)"},
      {"within_validity", -1, "no validity limit: an exact method, or no solution at this load"},
      {"within_validity", 0, "PRBM: the PRB angle is outside the element's validity limit"},
      {"within_validity", 1, "PRBM: the PRB angle is within the element's validity limit"},
      {"stability", 0, "stable: the potential energy has a strict minimum (docs/stability.md)"},
      {"stability", 1, "unstable: the energy decreases in stability_index directions"},
      {"stability", 2, "critical: a buckling or limit point (|margin| <= 1e-6)"},
      {"stability",
       3,
       "not_conservative: a follower force, which the energy cannot judge (index -1, margin "
       "NaN)"},
      {"stability",
       4,
       "not_checked: not computed (no solution at this load, or the verdict was switched off; "
       "index -1, margin NaN)"}};
  return codes;
}

int stability_code(StabilityKind kind) { return static_cast<int>(kind); }

namespace {

constexpr long kAxisBlock = 65536;

std::vector<hsize_t> sweep_dims(long count, const BeamSweepMetadata& metadata) {
  std::vector<hsize_t> dims;
  for (const BeamSweepAxis& axis : metadata.axes) dims.push_back(static_cast<hsize_t>(axis.count));
  if (dims.empty()) dims.push_back(static_cast<hsize_t>(count));
  return dims;
}

}  // namespace

BeamSweepWriter::BeamSweepWriter(Hdf5Group& group,
                                 long count,
                                 const BeamSweepMetadata& metadata,
                                 const Hdf5DatasetOptions& options)
    : group_(group),
      count_(count),
      metadata_(metadata),
      alpha2_(group.create_dataset("alpha2",
                                   Hdf5Type::kFloat64,
                                   sweep_dims(count, metadata),
                                   "1",
                                   metadata.given == "alpha2"
                                       ? "load alpha2 = P l^2/EI (Howell eq. 2.83)"
                                       : "load alpha2 = P l^2/EI found for the given " +
                                             metadata.given +
                                             " (Howell eq. 2.83); NaN where none was found",
                                   options)),
      a_over_l_(group.create_dataset(
          "a_over_l",
          Hdf5Type::kFloat64,
          sweep_dims(count, metadata),
          "1",
          "tip coordinate along the undeformed beam a/l; NaN where status != 0",
          options)),
      b_over_l_(group.create_dataset(
          "b_over_l",
          Hdf5Type::kFloat64,
          sweep_dims(count, metadata),
          "1",
          "tip deflection perpendicular to the undeformed beam b/l; NaN where status != 0",
          options)),
      theta0_(group.create_dataset("theta0",
                                   Hdf5Type::kFloat64,
                                   sweep_dims(count, metadata),
                                   "rad",
                                   "tip angle theta0; NaN where status != 0",
                                   options)),
      status_(group.create_dataset(
          "status",
          Hdf5Type::kInt32,
          sweep_dims(count, metadata),
          "1",
          "0 converged, 1 no converged solution at this point (root status_meanings)",
          options)),
      within_validity_(group.create_dataset(
          "within_validity",
          Hdf5Type::kInt32,
          sweep_dims(count, metadata),
          "1",
          "PRBM: 1 PRB angle within the element's validity limit, 0 outside; -1 exact methods "
          "and failed points",
          options)),
      stability_(group.create_dataset(
          "stability",
          Hdf5Type::kInt32,
          sweep_dims(count, metadata),
          "1",
          "stability verdict of the equilibrium: 0 stable, 1 unstable, 2 critical, 3 "
          "not_conservative, 4 not_checked (root status_meanings; docs/stability.md)",
          options)),
      stability_index_(group.create_dataset(
          "stability_index",
          Hdf5Type::kInt32,
          sweep_dims(count, metadata),
          "1",
          "independent directions in which the potential energy decreases (0 stable); -1 where "
          "not judged (stability 3 or 4)",
          options)),
      stability_margin_(group.create_dataset(
          "stability_margin",
          Hdf5Type::kFloat64,
          sweep_dims(count, metadata),
          "1",
          "lowest eigenvalue of the second variation of the energy relative to the unloaded "
          "bending stiffness (1 - P/P_cr for a column; the PRBM: d2V/dTheta2 over the spring "
          "stiffness); NaN where not judged (stability 3 or 4)",
          options)) {
  hsize_t points = 1;
  for (hsize_t d : sweep_dims(count, metadata)) points *= d;
  if (points != static_cast<hsize_t>(count)) {
    throw Hdf5Error(fmt::format(
        "HDF5: a sweep of {} points does not fill its axes ({} points)", count, points));
  }
}

void BeamSweepWriter::write(long begin, const BeamSweepTable& block) {
  const auto at = static_cast<hsize_t>(begin);
  alpha2_.write_range(at, std::span<const double>(block.alpha2));
  a_over_l_.write_range(at, std::span<const double>(block.a_over_l));
  b_over_l_.write_range(at, std::span<const double>(block.b_over_l));
  theta0_.write_range(at, std::span<const double>(block.theta0));
  status_.write_range(at, std::span<const int>(block.status));
  within_validity_.write_range(at, std::span<const int>(block.within_validity));
  stability_.write_range(at, std::span<const int>(block.stability));
  stability_index_.write_range(at, std::span<const int>(block.stability_index));
  stability_margin_.write_range(at, std::span<const double>(block.stability_margin));
}

void BeamSweepWriter::finish(long converged_count) {
  Hdf5Group& group = group_;
  const BeamSweepMetadata& metadata = metadata_;
  bool n_axis = false, mu_axis = false, given_axis = false;
  if (!metadata.axes.empty()) {
    std::string names;
    Hdf5Group axes = group.create_group("axes");
    axes.set_attribute("description",
                       "the swept parameters in the order of the datasets' dimensions (root "
                       "attribute axes)");
    for (const BeamSweepAxis& axis : metadata.axes) {
      // Generated a block at a time: an axis may hold 10^7 values.
      Hdf5Dataset values = axes.create_dataset(axis.name,
                                               Hdf5Type::kFloat64,
                                               {static_cast<hsize_t>(axis.count)},
                                               axis.units,
                                               axis.description);
      // A collective file: every rank creates the axis and writes every size-th block of it, so
      // that a 10^9-point axis is not written by one rank alone.
      const int ranks = axes.collective() ? parallel::world().size() : 1;
      const int rank = axes.collective() ? parallel::world().rank() : 0;
      std::vector<double> block;
      for (long b = rank, begin = b * kAxisBlock; begin < axis.count;
           b += ranks, begin = b * kAxisBlock) {
        block.clear();
        for (long i = begin; i < std::min(axis.count, begin + kAxisBlock); ++i) {
          block.push_back(evenly_spaced(axis.start, axis.stop, axis.count, i));
        }
        values.write_range(static_cast<hsize_t>(begin), std::span<const double>(block));
      }
      names += (names.empty() ? "" : ",") + axis.name;
      n_axis = n_axis || axis.name == "load_ratio_n";
      mu_axis = mu_axis || axis.name == "mu";
      given_axis = given_axis || axis.name == metadata.given;
    }
    group.set_attribute("axes", names);
    group.set_attribute("given", metadata.given);
    if (!given_axis) {
      group.set_attribute("given_value", metadata.given_value);
      if (metadata.given == "theta0") group.set_attribute("attribute_units", "given_value: rad");
    }
  }
  group.set_attribute("method", std::string(to_string(metadata.method)));
  group.set_attribute("mpi_ranks",
                      static_cast<std::int64_t>(group.collective() ? parallel::world().size() : 1));
  if (!n_axis) group.set_attribute("load_ratio_n", metadata.load_ratio_n);
  if (!mu_axis) group.set_attribute("mu", metadata.mu);
  group.set_attribute("tolerance", metadata.tolerance);
  group.set_attribute("count", static_cast<std::int64_t>(count_));
  group.set_attribute("converged_count", static_cast<std::int64_t>(converged_count));
  write_provenance(group, beam_sweep_code_meanings());
}

void write_beam_sweep(Hdf5Group& group,
                      const BeamSweepTable& table,
                      const BeamSweepMetadata& metadata,
                      const Hdf5DatasetOptions& options) {
  BeamSweepWriter writer(group, static_cast<long>(table.alpha2.size()), metadata, options);
  writer.write(0, table);
  writer.finish(table.converged_count);
}

BeamSweepSummary stream_beam_sweep(long count,
                                   const BeamIndexSolver& solve,
                                   const BeamSweepOptions& options,
                                   BeamSweepWriter& writer,
                                   long block_points) {
  const parallel::World& world = parallel::world();
  BeamSweepSummary summary;
  summary.count = count;
  long converged = 0;
  long first_failure = -1;  // this rank's (its blocks come in increasing order)
  std::string first_message;
  parallel::DistributionOptions distribution;
  // Blocks of at most block_points; several ranks take a share of what is left, so that the blocks
  // shrink towards the end and the ranks finish together (work_distribution.h).
  distribution.max_block = std::max(1L, block_points);
  distribution.min_block = std::min(distribution.max_block, std::max(1L, options.min_block));
  if (world.parallel()) distribution.progress = options.progress;
  distribution.describe = options.describe;
  parallel::distribute(
      count,
      [&](long begin, long end) -> parallel::BlockWriter {
        BeamSweepOptions block_options = options;
        block_options.progress = nullptr;
        if (options.progress && !world.parallel()) {
          // One rank: progress within the block, as the points are solved.
          block_options.progress = [&, begin](long done, long) {
            options.progress(begin + done, count);
          };
        }
        if (options.describe) {
          block_options.describe = [&, begin](long i) { return options.describe(begin + i); };
        } else {
          block_options.describe = [begin](long i) { return fmt::format("point {}", begin + i); };
        }
        auto table = std::make_shared<BeamSweepTable>(run_beam_sweep(
            end - begin, [&, begin](long i) { return solve(begin + i); }, block_options));
        return [&, table, begin] {
          writer.write(begin, *table);
          converged += table->converged_count;
          if (first_failure < 0 && table->first_failure >= 0) {
            first_failure = begin + table->first_failure;
            first_message = table->first_failure_message;
          }
        };
      },
      distribution);
  summary.converged_count = world.sum(converged);
  // The first failure over the ranks; its message comes from the rank that met it.
  constexpr long kNone = std::numeric_limits<long>::max();
  const long first = world.min(first_failure < 0 ? kNone : first_failure);
  if (first != kNone) {
    summary.first_failure = first;
    const std::vector<std::int64_t> indices =
        world.gather(std::vector<std::int64_t>{first_failure});
    const std::vector<std::string> messages = world.gather(std::vector<std::string>{first_message});
    for (std::size_t r = 0; r < indices.size(); ++r) {
      if (indices[r] == first) summary.first_failure_message = messages[r];
    }
  }
  writer.finish(summary.converged_count);
  return summary;
}

}  // namespace flexure::io
