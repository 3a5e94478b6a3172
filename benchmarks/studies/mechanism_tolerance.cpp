#include "flexure/benchmarks/studies/mechanism_tolerance.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <span>

#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/io/platform/work_distribution.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

// One perturbable parameter: its group (0 thickness, 1 width, 2 length, 3 E) and how to scale it.
struct Parameter {
  std::string name;
  int group = 0;
  std::function<void(MechanismDesign&, double factor)> scale;
};

std::vector<Parameter> parameters_of(const MechanismDesign& d) {
  std::vector<Parameter> out;
  for (int p = 0; p < 3; ++p) {
    if (d.joints[p].type == PivotType::kPin) continue;
    out.push_back({fmt::format("thickness {}", p + 1), 0, [p](MechanismDesign& x, double f) {
                     x.joints[p].thickness *= f;
                   }});
  }
  for (int p = 0; p < 3; ++p) {
    if (d.joints[p].type == PivotType::kPin) continue;
    out.push_back({fmt::format("width {}", p + 1), 1, [p](MechanismDesign& x, double f) {
                     x.joints[p].width *= f;
                   }});
  }
  out.push_back({"r2", 2, [](MechanismDesign& x, double f) { x.r2 *= f; }});
  out.push_back({"r3", 2, [](MechanismDesign& x, double f) { x.r3 *= f; }});
  for (int p = 0; p < 3; ++p) {
    // A small-length flexure's own length (a long segment's is r/gamma: it follows r2 or r3).
    if (d.joints[p].type != PivotType::kSmall) continue;
    out.push_back({fmt::format("length {}", p + 1), 2, [p](MechanismDesign& x, double f) {
                     x.joints[p].length *= f;
                   }});
  }
  out.push_back({"E", 3, [](MechanismDesign& x, double f) { x.material.E *= f; }});
  return out;
}

double spread_of(const ToleranceSpread& s, int group) {
  return group == 0 ? s.thickness : group == 1 ? s.width : group == 2 ? s.length : s.E;
}

struct Values {
  std::vector<double> q;  // per quantity
};

// The quantities of one design, in the order of quantity_names.
Values evaluate(MechanismDesign d, const ToleranceOptions& o) {
  // Long segments' lengths are re-derived from the (perturbed) links.
  for (JointDesign& j : d.joints) {
    if (j.type == PivotType::kLong) j.length = 0.0;
  }
  d.finalise();
  AnalysisOptions ao;
  ao.points = o.points;
  ao.exact = o.exact;
  ao.stability = false;
  MechanismAnalysis a = analyze_mechanism(d, ao);
  report_forces_of(a, o.force_of);
  Values v;
  v.q = {a.prbm.mean_force, a.prbm.percent_constant_force, a.safety_factor};
  if (o.exact) {
    if (!a.has_exact || !a.exact.converged()) {
      throw NoConvergence(a.has_exact ? a.exact.message : a.exact_note);
    }
    v.q.push_back(a.mean_force_exact);
    v.q.push_back(a.percent_constant_force_exact);
  }
  for (double x : v.q) {
    if (!std::isfinite(x)) throw NoConvergence("a quantity is not finite");
  }
  return v;
}

// Linear interpolation between order statistics (Hyndman & Fan type 7).
double percentile(const std::vector<double>& sorted, double p) {
  const double h = (sorted.size() - 1) * p;
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - lo) * (sorted[hi] - sorted[lo]);
}

// Every rank gets rank 0's `values` (the same size on every rank), bit for bit.
void broadcast_values(std::vector<double>& values) {
  const parallel::World& world = parallel::world();
  if (!world.parallel()) return;
  std::string bytes(values.size() * sizeof(double), '\0');
  if (world.root()) std::memcpy(bytes.data(), values.data(), bytes.size());
  bytes = world.broadcast(bytes);
  std::memcpy(values.data(), bytes.data(), bytes.size());
}

// The analyses of the study, items [0, total): item 2k and 2k + 1 the design with parameter k
// scaled by 1 + step and 1 - step (the central differences), item 2 np + s sample s. Divided over
// the MPI ranks (one item per block: each is a whole mechanism analysis, like a design of
// `mechanism validate`); on return every rank holds every item's quantities (NaN where it failed)
// and reason of failure ("" where it did not), in item order.
struct ItemResults {
  std::vector<double> values;         // total x nq, row-major
  std::vector<std::string> failures;  // per item
};

// `design_of(i)` makes item i's design (called on any thread: it reads shared data only), and
// `describe(i)` names it in a failure message.
ItemResults analyse_items(long total,
                          const std::function<MechanismDesign(long)>& design_of,
                          const std::function<std::string(long)>& describe,
                          std::size_t nq,
                          const ToleranceOptions& o) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // This rank's items: index, then its nq quantities; failures as (index, reason) pairs.
  std::vector<double> mine;
  std::vector<std::string> my_failures;
  parallel::DistributionOptions distribution;
  distribution.max_block = 1;
  distribution.describe = describe;
  parallel::distribute(
      total,
      [&](long begin, long end) -> parallel::BlockWriter {
        auto block = std::make_shared<std::vector<double>>();
        auto failed = std::make_shared<std::vector<std::string>>();
        for (long i = begin; i < end; ++i) {
          block->push_back(static_cast<double>(i));
          try {
            const Values v = evaluate(design_of(i), o);
            block->insert(block->end(), v.q.begin(), v.q.end());
          } catch (const std::exception& e) {
            block->insert(block->end(), nq, nan);
            failed->insert(failed->end(), {std::to_string(i), e.what()});
          }
        }
        return [&, block, failed] {
          mine.insert(mine.end(), block->begin(), block->end());
          my_failures.insert(my_failures.end(), failed->begin(), failed->end());
        };
      },
      distribution);
  const parallel::World& world = parallel::world();
  const std::vector<double> all = world.gather(mine);
  const std::vector<std::string> all_failures = world.gather(my_failures);
  ItemResults r;
  r.values.assign(static_cast<std::size_t>(total) * nq, nan);
  r.failures.assign(static_cast<std::size_t>(total), std::string());
  for (std::size_t k = 0; k + nq < all.size(); k += nq + 1) {
    const auto i = static_cast<std::size_t>(all[k]);
    std::copy(all.begin() + k + 1, all.begin() + k + 1 + nq, r.values.begin() + i * nq);
  }
  for (std::size_t k = 0; k + 1 < all_failures.size(); k += 2) {
    r.failures[std::stoul(all_failures[k])] = all_failures[k + 1];
  }
  broadcast_values(r.values);
  // The reasons (few: one per failed analysis), in item order.
  if (world.parallel()) {
    for (std::string& reason : r.failures) reason = world.broadcast(reason);
  }
  return r;
}

}  // namespace

const char* spread_distribution_name(SpreadDistribution d) {
  return d == SpreadDistribution::kNormal ? "normal" : "uniform";
}

SpreadDistribution parse_spread_distribution(const std::string& name) {
  if (name == "normal") return SpreadDistribution::kNormal;
  if (name == "uniform") return SpreadDistribution::kUniform;
  throw InvalidInput(
      fmt::format("unknown distribution '{}'; allowed: normal (the spread is the standard "
                  "deviation), uniform (the spread is the half-width)",
                  name));
}

void ToleranceOptions::validate() const {
  for (const auto& [v, what] : {std::pair{spread.thickness, "thickness"},
                                std::pair{spread.width, "width"},
                                std::pair{spread.length, "length"},
                                std::pair{spread.E, "E"}}) {
    if (!std::isfinite(v) || v < 0.0 || v >= 0.3) {
      throw InvalidInput(
          fmt::format("the {} spread must be finite and in [0, 30 %) (got {})", what, v));
    }
  }
  if (samples < 2 || samples > 100000) {
    throw InvalidInput(fmt::format("samples must be in [2, 100000] (got {})", samples));
  }
  if (points < 2 || points > 10000) {
    throw InvalidInput(fmt::format("points must be in [2, 10000] (got {})", points));
  }
}

ToleranceStudy mechanism_tolerance(const MechanismDesign& design, const ToleranceOptions& o) {
  o.validate();
  ToleranceStudy study;
  study.design = design.name;
  study.options = o;
  const std::vector<Parameter> params = parameters_of(design);
  for (const Parameter& p : params) study.parameters.push_back(p.name);
  std::vector<std::pair<std::string, std::string>> names = {
      {"mean_force_prbm", "N"}, {"percent_constant_force_prbm", "%"}, {"safety_factor", "1"}};
  if (o.exact) {
    names.push_back({"mean_force_exact", "N"});
    names.push_back({"percent_constant_force_exact", "%"});
  }
  const Values nominal = [&] {
    try {
      return evaluate(design, o);
    } catch (const NoConvergence& e) {
      throw InvalidInput(fmt::format("{}: the nominal design: {}", design.name, e.what()));
    }
  }();
  const std::size_t nq = names.size(), np = params.size();
  // The draws, all made up front from the one seeded stream (sample by sample, parameter by
  // parameter), so that a sample's design does not depend on which rank analyses it.
  std::mt19937_64 rng(o.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto draw = [&](double spread) {
    if (spread == 0.0) return 0.0;
    if (o.distribution == SpreadDistribution::kUniform) return spread * uniform(rng);
    double z;
    do {
      z = normal(rng);
    } while (std::abs(z) > 3.5);  // no dimension at or below zero (spread < 0.3)
    return spread * z;
  };
  // First-order sensitivities: central differences in each relative change (step 1e-4; the
  // quantities are smooth in the dimensions, and the exact model's 1e-9 force tolerance leaves
  // ~1e-5 relative error in the derivative). Items 2k, 2k + 1; the samples follow.
  constexpr double kStep = 1e-4;
  for (int s = 0; s < o.samples; ++s) {
    for (std::size_t k = 0; k < np; ++k) {
      study.draws.push_back(draw(spread_of(o.spread, params[k].group)));
    }
  }
  const long sensitivity_items = 2 * static_cast<long>(np);
  const auto design_of = [&](long i) {
    MechanismDesign x = design;
    if (i < sensitivity_items) {
      params[i / 2].scale(x, i % 2 == 0 ? 1.0 + kStep : 1.0 - kStep);
      return x;
    }
    const std::size_t row = static_cast<std::size_t>(i - sensitivity_items) * np;
    for (std::size_t k = 0; k < np; ++k) params[k].scale(x, 1.0 + study.draws[row + k]);
    return x;
  };
  const auto describe = [&](long i) {
    return i < sensitivity_items
               ? fmt::format("{} {} 1e-4", params[i / 2].name, i % 2 == 0 ? "+" : "-")
               : fmt::format("sample {}", i - sensitivity_items);
  };
  const ItemResults items =
      analyse_items(sensitivity_items + o.samples, design_of, describe, nq, o);
  study.mpi_ranks = parallel::world().size();
  study.parameter_sensitivity.assign(nq * np, 0.0);
  for (std::size_t k = 0; k < np; ++k) {
    for (const std::size_t item : {2 * k, 2 * k + 1}) {
      if (!items.failures[item].empty()) {
        throw NoConvergence(
            fmt::format("{}: the design with {} {} 1e-4 (for the sensitivities): {}",
                        design.name,
                        params[k].name,
                        item == 2 * k ? "+" : "-",
                        items.failures[item]));
      }
    }
    for (std::size_t i = 0; i < nq; ++i) {
      study.parameter_sensitivity[i * np + k] =
          (items.values[2 * k * nq + i] - items.values[(2 * k + 1) * nq + i]) / (2.0 * kStep);
    }
  }
  study.quantities.resize(nq);
  for (std::size_t i = 0; i < nq; ++i) {
    study.quantities[i].name = names[i].first;
    study.quantities[i].unit = names[i].second;
    study.quantities[i].nominal = nominal.q[i];
  }
  for (int s = 0; s < o.samples; ++s) {
    const std::size_t item = 2 * np + static_cast<std::size_t>(s);
    if (!items.failures[item].empty() && study.failed_samples++ == 0) {
      study.first_failure = fmt::format("sample {}: {}", s, items.failures[item]);
    }
    for (std::size_t i = 0; i < nq; ++i) {
      study.quantities[i].values.push_back(items.values[item * nq + i]);
    }
  }
  if (study.failed_samples > 0) {
    study.warnings.push_back(
        {WarningKind::kOther,
         fmt::format("{} of {} samples could not be analysed and are left out (first: {})",
                     study.failed_samples,
                     o.samples,
                     study.first_failure)});
  }
  // A uniform draw on [-a, a] has standard deviation a/sqrt(3); the normal one (cut at 3.5
  // sigma) sigma to 1e-3.
  const double std_factor =
      o.distribution == SpreadDistribution::kUniform ? 1.0 / std::sqrt(3.0) : 1.0;
  for (std::size_t i = 0; i < nq; ++i) {
    ToleranceStats& q = study.quantities[i];
    std::vector<double> ok;
    for (double v : q.values) {
      if (std::isfinite(v)) ok.push_back(v);
    }
    if (ok.size() < 2) {
      throw NoConvergence(fmt::format(
          "{}: fewer than two samples could be analysed ({})", design.name, study.first_failure));
    }
    double sum = 0.0;
    for (double v : ok) sum += v;
    q.mean = sum / ok.size();
    double ss = 0.0;
    for (double v : ok) ss += (v - q.mean) * (v - q.mean);
    q.std = std::sqrt(ss / (ok.size() - 1));
    std::sort(ok.begin(), ok.end());
    q.p05 = percentile(ok, 0.05);
    q.p50 = percentile(ok, 0.50);
    q.p95 = percentile(ok, 0.95);
    double var = 0.0;
    for (std::size_t k = 0; k < np; ++k) {
      const double dq = study.parameter_sensitivity[i * np + k];
      q.sensitivity[params[k].group] += dq;
      const double sigma = spread_of(o.spread, params[k].group) * std_factor;
      var += dq * dq * sigma * sigma;
    }
    q.first_order_std = std::sqrt(var);
  }
  return study;
}

}  // namespace flexure::mechanism

namespace flexure::mechanism {

void write_tolerance_file(io::Hdf5Group& root, const ToleranceStudy& s) {
  const ToleranceOptions& o = s.options;
  root.set_attribute("mechanism", s.design);
  root.set_attribute("distribution", spread_distribution_name(o.distribution));
  root.set_attribute("samples", static_cast<std::int64_t>(o.samples));
  root.set_attribute("seed", static_cast<std::int64_t>(o.seed));
  root.set_attribute("failed_samples", static_cast<std::int64_t>(s.failed_samples));
  // What mean_force_prbm and mean_force_exact are the force of (mechanism.h), as in the JSON.
  root.set_attribute("force_of", force_of_label(o.force_of));
  root.set_attribute("mpi_ranks", static_cast<std::int64_t>(s.mpi_ranks));
  root.set_attribute("spread_thickness", o.spread.thickness);
  root.set_attribute("spread_width", o.spread.width);
  root.set_attribute("spread_length", o.spread.length);
  root.set_attribute("spread_E", o.spread.E);
  root.set_attribute("attribute_units",
                     "spread_*: 1 (relative; normal: standard deviation, uniform: half-width)");
  root.write_dataset("parameters", s.parameters, "text", "the sampled parameters, in column order");
  root.write_dataset("draws",
                     std::span<const double>(s.draws),
                     {static_cast<hsize_t>(o.samples), static_cast<hsize_t>(s.parameters.size())},
                     "1",
                     "relative change of each parameter in each sample (samples x parameters)");
  for (std::size_t i = 0; i < s.quantities.size(); ++i) {
    const ToleranceStats& q = s.quantities[i];
    io::Hdf5Group g = root.create_group(q.name);
    g.write_dataset("values",
                    std::span<const double>(q.values),
                    q.unit,
                    q.name + " of each sample (NaN where its analysis failed)");
    const std::size_t np = s.parameters.size();
    g.write_dataset("parameter_sensitivity",
                    std::span<const double>(s.parameter_sensitivity.data() + i * np, np),
                    q.unit,
                    "dQ/d(relative change) of each parameter at the nominal design (central "
                    "differences)");
    g.write_dataset("group_sensitivity",
                    std::span<const double>(q.sensitivity),
                    q.unit,
                    "dQ/d(relative change) of all thicknesses, widths, lengths, E together");
    for (const auto& [name, v] : {std::pair{"nominal", q.nominal},
                                  std::pair{"mean", q.mean},
                                  std::pair{"std", q.std},
                                  std::pair{"p05", q.p05},
                                  std::pair{"p50", q.p50},
                                  std::pair{"p95", q.p95},
                                  std::pair{"first_order_std", q.first_order_std}}) {
      g.write_scalar(name, v, q.unit, std::string(name) + " of " + q.name + " over the samples");
    }
  }
  io::write_provenance(root, {});
}

void write_tolerance_hdf5(const std::string& path, const ToleranceStudy& study) {
  io::AtomicHdf5File file(path);
  write_tolerance_file(file.root(), study);
  file.commit();
}

std::vector<io::CsvColumn> tolerance_csv_columns(const ToleranceStudy& s) {
  const std::size_t samples = static_cast<std::size_t>(s.options.samples);
  const std::size_t np = s.parameters.size();
  std::vector<io::CsvColumn> columns;
  io::CsvColumn index{"sample", "1", {}, {}};
  for (std::size_t k = 0; k < samples; ++k) index.numbers.push_back(static_cast<double>(k));
  columns.push_back(std::move(index));
  for (std::size_t p = 0; p < np; ++p) {
    // "thickness 1" -> "draws/thickness_1": a header name without spaces.
    std::string name = s.parameters[p];
    std::replace(name.begin(), name.end(), ' ', '_');
    io::CsvColumn c{"draws/" + name, "1", {}, {}};
    for (std::size_t k = 0; k < samples; ++k) c.numbers.push_back(s.draws[k * np + p]);
    columns.push_back(std::move(c));
  }
  for (const ToleranceStats& q : s.quantities) columns.push_back({q.name, q.unit, q.values, {}});
  // The mean forces' unit says whose force they are: N (half) or N (whole).
  io::mark_force_columns(columns, force_of_label(s.options.force_of));
  return columns;
}

}  // namespace flexure::mechanism
