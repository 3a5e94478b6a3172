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

#include "flexure/solver/common/errors.h"

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

  const long chunk = std::max(1L, options.chunk);
  std::atomic<long> next{0};
  std::atomic<long> done{0};
  std::atomic<bool> stop{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  // Points write disjoint entries of the table, so no locking is needed for the results.
  const auto work = [&] {
    try {
      while (!stop.load(std::memory_order_relaxed)) {
        const long begin = next.fetch_add(chunk);
        if (begin >= total) break;
        const long end = std::min(total, begin + chunk);
        for (long i = begin; i < end; ++i) {
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
          }
        }
        done.fetch_add(end - begin);
      }
    } catch (...) {
      const std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
      stop = true;
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
    while (done.load() < total && !stop.load()) {
      options.progress(done.load(), total);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    caller_worker.join();
    if (!stop.load()) options.progress(total, total);
  } else {
    work();
  }
  for (std::thread& helper : helpers) helper.join();
  if (error) std::rethrow_exception(error);

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
      {"within_validity", 1, "PRBM: the PRB angle is within the element's validity limit"}};
  return codes;
}

void write_beam_sweep(Hdf5Group& group,
                      const BeamSweepTable& table,
                      const BeamSweepMetadata& metadata) {
  // The datasets' shape: the axes' counts, or 1-D.
  std::vector<hsize_t> dims;
  for (const BeamSweepAxis& axis : metadata.axes) dims.push_back(axis.values.size());
  if (dims.empty()) dims.push_back(table.alpha2.size());
  const auto doubles = [&](const char* name,
                           const std::vector<double>& values,
                           const char* units,
                           const std::string& description) {
    group.write_dataset(name, std::span<const double>(values), dims, units, description);
  };
  const auto ints =
      [&](const char* name, const std::vector<int>& values, const std::string& description) {
        group.write_dataset(name, std::span<const int>(values), dims, "1", description);
      };
  const bool forward = metadata.given == "alpha2";
  doubles("alpha2",
          table.alpha2,
          "1",
          forward ? "load alpha2 = P l^2/EI (Howell eq. 2.83)"
                  : "load alpha2 = P l^2/EI found for the given " + metadata.given +
                        " (Howell eq. 2.83); NaN where none was found");
  doubles("a_over_l",
          table.a_over_l,
          "1",
          "tip coordinate along the undeformed beam a/l; NaN where status != 0");
  doubles("b_over_l",
          table.b_over_l,
          "1",
          "tip deflection perpendicular to the undeformed beam b/l; NaN where status != 0");
  doubles("theta0", table.theta0, "rad", "tip angle theta0; NaN where status != 0");
  ints("status",
       table.status,
       "0 converged, 1 no converged solution at this point (root status_meanings)");
  ints("within_validity",
       table.within_validity,
       "PRBM: 1 PRB angle within the element's validity limit, 0 outside; -1 exact methods and "
       "failed points");
  std::string names;
  bool n_axis = false, mu_axis = false, given_axis = false;
  if (!metadata.axes.empty()) {
    Hdf5Group axes = group.create_group("axes");
    axes.set_attribute("description",
                       "the swept parameters in the order of the datasets' dimensions (root "
                       "attribute axes)");
    for (const BeamSweepAxis& axis : metadata.axes) {
      axes.write_dataset(
          axis.name, std::span<const double>(axis.values), axis.units, axis.description);
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
  group.set_attribute("method", metadata.method);
  if (!n_axis) group.set_attribute("load_ratio_n", metadata.load_ratio_n);
  if (!mu_axis) group.set_attribute("mu", metadata.mu);
  group.set_attribute("tolerance", metadata.tolerance);
  group.set_attribute("count", static_cast<std::int64_t>(table.alpha2.size()));
  group.set_attribute("converged_count", static_cast<std::int64_t>(table.converged_count));
  write_provenance(group, beam_sweep_code_meanings());
}

}  // namespace flexure::io
