#include "flexure/io/mechanism_validation_file.h"

#include <fmt/format.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/io/platform/work_distribution.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {

using mechanism::MechanismValidationRow;

struct MechanismValidationFile::Impl {
  std::unique_ptr<AtomicHdf5File> file;
  std::vector<Hdf5Dataset> columns;
  std::optional<Hdf5Dataset> status;
};

MechanismValidationFile::MechanismValidationFile(
    const std::string& path,
    mechanism::DesignSet designs,
    const mechanism::MechanismValidationOptions& options,
    std::size_t count)
    : impl_(std::make_unique<Impl>()) {
  try {
    impl_->file = std::make_unique<AtomicHdf5File>(path, Hdf5Access::kCollective);
  } catch (const Hdf5Error& e) {
    throw InvalidInput(fmt::format("--out: {}", e.what()));
  }
  const auto n = static_cast<hsize_t>(count);
  Hdf5Group& root = impl_->file->root();
  root.set_attribute("designs", mechanism::to_string(designs));
  root.set_attribute("points", static_cast<std::int64_t>(options.points));
  root.set_attribute("mpi_ranks",
                     static_cast<std::int64_t>(root.collective() ? parallel::world().size() : 1));
  if (options.toggle_fraction) root.set_attribute("toggle_fraction", *options.toggle_fraction);
  if (options.spring_rule) {
    root.set_attribute("spring_rule", mechanism::spring_rule_name(*options.spring_rule));
  }
  for (const mechanism::ValidationColumn& c : mechanism::validation_columns()) {
    impl_->columns.push_back(
        root.create_dataset(c.name, Hdf5Type::kFloat64, {n}, c.units, c.description));
  }
  impl_->status.emplace(root.create_dataset(
      "status",
      Hdf5Type::kInt32,
      {n},
      "1",
      "0 exact model converged, 1 exact model did not converge, 2 PRBM only (no exact model), 3 "
      "the chain-algorithm check did not converge"));
}

MechanismValidationFile::~MechanismValidationFile() = default;

void MechanismValidationFile::write_row(std::size_t index, const MechanismValidationRow& row) {
  const auto at = static_cast<hsize_t>(index);
  for (std::size_t c = 0; c < impl_->columns.size(); ++c) {
    impl_->columns[c].write_range(at, std::span<const double>(&row.values[c], 1));
  }
  const int status = static_cast<int>(row.status);
  impl_->status->write_range(at, std::span<const int>(&status, 1));
}

void MechanismValidationFile::commit(const std::vector<std::string>& names) {
  Hdf5Group& root = impl_->file->root();
  root.write_dataset("name", names, "text", "the design");
  write_provenance(root,
                   {{"status", 0, "the exact model converged"},
                    {"status", 1, "the exact model did not converge"},
                    {"status", 2, "PRBM only: the configuration has no exact model"},
                    {"status", 3, "the chain-algorithm check did not converge"}});
  impl_->columns.clear();
  impl_->status.reset();
  impl_->file->commit();
}

std::vector<FormattedValidationRow> validate_mechanisms(
    mechanism::DesignSet set,
    const mechanism::MechanismValidationOptions& options,
    const std::string& out,
    const ValidationRowFormat& format) {
  options.validate();
  const std::vector<mechanism::MechanismDesign> designs = mechanism::mechanism_designs(set);
  std::optional<MechanismValidationFile> file;
  if (!out.empty()) file.emplace(out, set, options, designs.size());

  // Each row travels to rank 0 as text: its index, the number of texts, the texts, the number of
  // warnings, the warnings.
  std::vector<std::string> mine;
  parallel::DistributionOptions distribution;
  distribution.max_block = 1;
  distribution.describe = [&](long i) { return designs[i].name; };
  parallel::distribute(
      static_cast<long>(designs.size()),
      [&](long begin, long end) -> parallel::BlockWriter {
        auto rows = std::make_shared<std::vector<MechanismValidationRow>>();
        auto texts = std::make_shared<std::vector<std::vector<std::string>>>();
        for (long i = begin; i < end; ++i) {
          rows->push_back(mechanism::validate_mechanism(designs[i], options));
          texts->push_back(format ? format(rows->back()) : std::vector<std::string>{});
        }
        return [&, rows, texts, begin] {
          for (std::size_t k = 0; k < rows->size(); ++k) {
            const MechanismValidationRow& row = (*rows)[k];
            const std::size_t at = static_cast<std::size_t>(begin) + k;
            if (file) file->write_row(at, row);
            mine.push_back(std::to_string(at));
            mine.push_back(std::to_string((*texts)[k].size()));
            mine.insert(mine.end(), (*texts)[k].begin(), (*texts)[k].end());
            mine.push_back(std::to_string(row.warnings.size()));
            mine.insert(mine.end(), row.warnings.begin(), row.warnings.end());
          }
        };
      },
      distribution);
  const std::vector<std::string> all = parallel::world().gather(mine);
  std::vector<FormattedValidationRow> rows;
  if (parallel::world().root()) {
    rows.resize(designs.size());
    for (std::size_t k = 0; k < all.size();) {
      FormattedValidationRow& row = rows.at(std::stoul(all[k++]));
      const std::size_t n_texts = std::stoul(all[k++]);
      row.texts.assign(all.begin() + static_cast<long>(k),
                       all.begin() + static_cast<long>(k + n_texts));
      k += n_texts;
      const std::size_t n_warnings = std::stoul(all[k++]);
      row.warnings.assign(all.begin() + static_cast<long>(k),
                          all.begin() + static_cast<long>(k + n_warnings));
      k += n_warnings;
    }
  }
  if (file) {
    std::vector<std::string> names;
    for (const mechanism::MechanismDesign& d : designs) names.push_back(d.name);
    file->commit(names);
  }
  return rows;
}

}  // namespace flexure::io
