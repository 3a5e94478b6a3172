#include "flexure/benchmarks/studies/subclass_table.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/io/platform/work_distribution.h"
#include "flexure/solver/common/status.h"

namespace flexure::studies {
namespace {

using design::SubclassRederivation;

// A numeric column of the table: its name, units, description, whether it holds integers, whether
// only the exact model writes it, and its value in a row.
struct Column {
  const char* name;
  const char* units;
  const char* description;
  bool integer;
  bool exact;
  double (*value)(const SubclassRederivation&);
};

const std::vector<Column>& columns() {
  using R = const SubclassRederivation&;
  static const std::vector<Column> c = {
      {"stroke_percent",
       "%",
       "effective design stroke",
       false,
       false,
       [](R r) { return r.stroke_percent; }},
      {"printed_objective",
       "1",
       "objective at the printed point (Psi_raw or Xi' in %)",
       false,
       false,
       [](R r) { return r.printed_objective; }},
      {"objective_value",
       "1",
       "objective at the re-derived optimum",
       false,
       false,
       [](R r) { return r.prbm.best.objective; }},
      {"R", "1", "re-derived R", false, false, [](R r) { return r.prbm.best.result.R; }},
      {"K1",
       "1",
       "re-derived K1 (0: no spring; class 1B: 1)",
       false,
       false,
       [](R r) { return r.prbm.best.result.K1; }},
      {"K2",
       "1",
       "re-derived K2 (0: no spring)",
       false,
       false,
       [](R r) { return r.prbm.best.result.K2; }},
      {"percent_constant_force",
       "%",
       "PRBM Xi' at the optimum",
       false,
       false,
       [](R r) { return r.prbm.best.result.percent_constant_force; }},
      {"converged",
       "1",
       "1: the synthesis converged",
       true,
       false,
       [](R r) { return r.prbm.converged() ? 1.0 : 0.0; }},
      {"evaluations",
       "1",
       "model evaluations",
       true,
       false,
       [](R r) { return static_cast<double>(r.prbm.evaluations); }},
      {"seconds", "s", "wall time of the row", false, false, [](R r) { return r.seconds; }},
      {"printed_percent_constant_force_exact",
       "%",
       "exact Xi' of the printed point (50 points)",
       false,
       true,
       [](R r) { return r.printed_percent_constant_force_exact.value_or(0.0); }},
      {"percent_constant_force_exact",
       "%",
       "exact Xi' of the exact optimum (0 where exact_found is 0)",
       false,
       true,
       [](R r) { return r.percent_constant_force_exact.value_or(0.0); }},
      {"exact_found",
       "1",
       "1: the exact search found a feasible optimum",
       true,
       true,
       [](R r) { return r.percent_constant_force_exact ? 1.0 : 0.0; }},
      {"exact_R", "1", "R of the exact optimum", false, true, [](R r) { return r.exact_R; }},
      {"exact_K1", "1", "K1 of the exact optimum", false, true, [](R r) { return r.exact_K1; }},
      {"exact_K2", "1", "K2 of the exact optimum", false, true, [](R r) { return r.exact_K2; }}};
  return c;
}

// A row as numbers and texts, to travel to rank 0 (NaN: an empty optional).
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

std::vector<double> pack_numbers(long index, const SubclassRederivation& r) {
  const auto opt = [](const std::optional<double>& v) { return v ? *v : kNone; };
  return {static_cast<double>(index),
          r.stroke_percent,
          static_cast<double>(r.objective),
          r.printed_objective,
          r.prbm.best.objective,
          r.prbm.best.result.R,
          r.prbm.best.result.K1,
          r.prbm.best.result.K2,
          r.prbm.best.result.percent_constant_force,
          r.prbm.converged() ? 1.0 : 0.0,
          static_cast<double>(r.prbm.evaluations),
          r.seconds,
          opt(r.printed_percent_constant_force_exact),
          opt(r.percent_constant_force_exact),
          r.exact_R,
          r.exact_K1,
          r.exact_K2,
          static_cast<double>(r.exact_evaluations)};
}
constexpr std::size_t kNumbers = 18;

SubclassRederivation unpack(const double* v, const std::string* texts) {
  SubclassRederivation r;
  const auto opt = [](double x) { return std::isnan(x) ? std::nullopt : std::optional<double>(x); };
  r.stroke_percent = v[1];
  r.objective = static_cast<design::DesignObjective>(static_cast<int>(v[2]));
  r.printed_objective = v[3];
  r.prbm.best.objective = v[4];
  r.prbm.best.result.R = v[5];
  r.prbm.best.result.K1 = v[6];
  r.prbm.best.result.K2 = v[7];
  r.prbm.best.result.percent_constant_force = v[8];
  r.prbm.set_converged(v[9] != 0.0);
  r.prbm.evaluations = static_cast<int>(v[10]);
  r.seconds = v[11];
  r.printed_percent_constant_force_exact = opt(v[12]);
  r.percent_constant_force_exact = opt(v[13]);
  r.exact_R = v[14];
  r.exact_K1 = v[15];
  r.exact_K2 = v[16];
  r.exact_evaluations = static_cast<int>(v[17]);
  r.name = texts[0];
  r.config = texts[1];
  r.exact_message = texts[2];
  return r;
}

}  // namespace

std::vector<SubclassRederivation> subclass_table(
    const SubclassTableOptions& options,
    const std::function<void(std::size_t, std::size_t)>& progress) {
  const design::RederivationOptions& o = options.rederivation;
  o.synthesis.validate();
  const std::vector<const cfm::CfmSubclass*> rows = design::thesis_rows(o.config);
  const parallel::World& world = parallel::world();
  std::unique_ptr<io::AtomicHdf5File> file;
  if (!options.out.empty()) {
    io::check_output_path(options.out);
    try {
      file = std::make_unique<io::AtomicHdf5File>(options.out, io::Hdf5Access::kCollective);
    } catch (const io::Hdf5Error& e) {
      throw InvalidInput(fmt::format("--out: {}", e.what()));
    }
  }
  // The numeric columns, created whole by every rank; each row written by the rank that made it.
  std::vector<const Column*> used;
  std::vector<io::Hdf5Dataset> datasets;
  if (file) {
    io::Hdf5Group& root = file->root();
    root.set_attribute("model", o.exact ? "exact" : "prbm");
    root.set_attribute("mpi_ranks",
                       static_cast<std::int64_t>(root.collective() ? world.size() : 1));
    root.set_attribute("seed", options.seed);
    for (const Column& c : columns()) {
      if (c.exact && !o.exact) continue;
      used.push_back(&c);
      datasets.push_back(
          root.create_dataset(c.name,
                              c.integer ? io::Hdf5Type::kInt32 : io::Hdf5Type::kFloat64,
                              {static_cast<hsize_t>(rows.size())},
                              c.units,
                              c.description));
    }
  }

  std::vector<double> numbers;     // this rank's rows, kNumbers each
  std::vector<std::string> texts;  // name, config, exact message of each
  parallel::DistributionOptions distribution;
  distribution.max_block = 1;
  if (progress) {
    distribution.progress = [&](long done, long total) {
      progress(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
    };
  }
  distribution.describe = [&](long i) { return std::string(rows[i]->name); };
  parallel::distribute(
      static_cast<long>(rows.size()),
      [&](long begin, long end) -> parallel::BlockWriter {
        auto done = std::make_shared<std::vector<SubclassRederivation>>();
        for (long i = begin; i < end; ++i) done->push_back(design::rederive_subclass(*rows[i], o));
        return [&, done, begin] {
          for (std::size_t k = 0; k < done->size(); ++k) {
            const SubclassRederivation& r = (*done)[k];
            const long index = begin + static_cast<long>(k);
            for (std::size_t c = 0; c < used.size(); ++c) {
              const double v = used[c]->value(r);
              if (used[c]->integer) {
                const int x = static_cast<int>(v);
                datasets[c].write_range(static_cast<hsize_t>(index), std::span<const int>(&x, 1));
              } else {
                datasets[c].write_range(static_cast<hsize_t>(index),
                                        std::span<const double>(&v, 1));
              }
            }
            const std::vector<double> packed = pack_numbers(index, r);
            numbers.insert(numbers.end(), packed.begin(), packed.end());
            texts.insert(texts.end(), {r.name, r.config, r.exact_message});
          }
        };
      },
      distribution);

  // Every row on rank 0, in the thesis's order.
  const std::vector<double> all_numbers = world.gather(numbers);
  const std::vector<std::string> all_texts = world.gather(texts);
  std::vector<SubclassRederivation> out;
  if (world.root()) {
    out.resize(rows.size());
    for (std::size_t k = 0; k * kNumbers < all_numbers.size(); ++k) {
      const double* v = all_numbers.data() + k * kNumbers;
      out[static_cast<std::size_t>(v[0])] = unpack(v, all_texts.data() + 3 * k);
    }
  }
  if (file) {
    // String datasets take rank 0's values (hdf5_file.h Hdf5Access::kCollective).
    std::vector<std::string> names, objectives;
    for (const SubclassRederivation& r : out) {
      names.push_back(r.name);
      objectives.push_back(to_string(r.objective));
    }
    io::Hdf5Group& root = file->root();
    root.write_dataset("name", names, "text", "thesis sub-class (Tables 7.2-7.12)");
    root.write_dataset("objective", objectives, "text", "the sub-class's objective");
    io::write_provenance(root, {});
    datasets.clear();
    file->commit();
  }
  return out;
}

}  // namespace flexure::studies
