#include "flexure/io/design_history_file.h"

#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

void write_history(Hdf5Group& root,
                   const design::CfmDesignProblem& problem,
                   const design::CfmSynthesisResult& s,
                   const design::CfmExactRefinement* exact,
                   unsigned long seed) {
  root.set_attribute("config", problem.config);
  root.set_attribute("stroke_percent", problem.stroke_percent);
  root.set_attribute("objective", to_string(problem.objective));
  root.set_attribute("pcf_min", problem.pcf_min.value_or(0.0));
  root.set_attribute("orientation", to_string(problem.orientation));
  root.set_attribute("seed", static_cast<std::int64_t>(seed));
  root.set_attribute("algorithm",
                     "Halton scan, NLopt COBYLA / Nelder-Mead local runs per region of the "
                     "primary pivot, polish on the full sampling (docs/design.md)");
  root.set_attribute("R", s.best.result.R);
  root.set_attribute("K1", s.best.result.K1);
  root.set_attribute("K2", s.best.result.K2);
  root.set_attribute("objective_value", s.best.objective);
  root.set_attribute("converged", std::int64_t{s.converged() ? 1 : 0});
  root.set_attribute("attribute_units",
                     "stroke_percent: % of r2 + r3; pcf_min: % (0: none); R, K1, K2: 1");
  const auto columns = [](Hdf5Group& g, const auto& rows, const char* objective_text) {
    std::vector<int> run, full, valid, feasible;
    std::vector<double> R, K1, K2, objective, violation;
    for (const auto& e : rows) {
      run.push_back(e.run);
      full.push_back(e.full_sampling ? 1 : 0);
      valid.push_back(e.valid ? 1 : 0);
      feasible.push_back(e.feasible ? 1 : 0);
      R.push_back(e.R);
      K1.push_back(e.K1);
      K2.push_back(e.K2);
      objective.push_back(e.objective);
      violation.push_back(e.max_violation);
    }
    g.write_dataset(
        "run", std::span<const int>(run), "1", "local run of the evaluation (-1: the global scan)");
    g.write_dataset("full_sampling",
                    std::span<const int>(full),
                    "1",
                    "1: the requested stroke sampling, 0: the coarse one of the search");
    g.write_dataset(
        "valid", std::span<const int>(valid), "1", "1 where the model accepted the point");
    g.write_dataset("feasible",
                    std::span<const int>(feasible),
                    "1",
                    "1 where every constraint is met as posed");
    g.write_dataset("R", std::span<const double>(R), "1", "R = r3/r2");
    g.write_dataset("K1", std::span<const double>(K1), "1", "K1 = k2/k1 (0: no spring)");
    g.write_dataset("K2", std::span<const double>(K2), "1", "K2 = k3/k1 (0: no spring)");
    g.write_dataset("objective", std::span<const double>(objective), "1", objective_text);
    g.write_dataset("max_violation",
                    std::span<const double>(violation),
                    "1",
                    "largest normalised constraint violation (<= 0: all met)");
  };
  Hdf5Group h = root.create_group("history");
  h.set_attribute("description", "every distinct PRBM model evaluation, in order");
  columns(h, s.history, "the objective in the problem's sense (0 where not valid)");
  if (exact != nullptr) {
    Hdf5Group e = root.create_group("exact_history");
    e.set_attribute("description", "every exact stroke of --model exact, in order");
    e.set_attribute("percent_constant_force_exact", exact->percent_constant_force_exact);
    columns(e, exact->history, "exact percent constant force Xi' (%) at the search's points");
  }
  io::write_provenance(root, {});
}

}  // namespace

DesignHistoryFile::DesignHistoryFile(const std::string& path) : path_(path) {
  try {
    file_ = std::make_unique<AtomicHdf5File>(path);
  } catch (const Hdf5Error& e) {
    throw InvalidInput(e.what());
  }
}

DesignHistoryFile::~DesignHistoryFile() = default;
DesignHistoryFile::DesignHistoryFile(DesignHistoryFile&&) noexcept = default;
DesignHistoryFile& DesignHistoryFile::operator=(DesignHistoryFile&&) noexcept = default;

void DesignHistoryFile::write(const design::CfmDesignProblem& problem,
                              const design::CfmSynthesisResult& synthesis,
                              const design::CfmExactRefinement* exact,
                              unsigned long seed) {
  if (!file_ || file_->committed()) {
    throw std::logic_error(path_ + ": a DesignHistoryFile is written once only");
  }
  write_history(file_->root(), problem, synthesis, exact, seed);
  file_->commit();
}

}  // namespace flexure::io
