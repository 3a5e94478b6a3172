#include "flexure/benchmarks/studies/dynamics_study_file.h"

#include <fmt/format.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

void write_study(io::Hdf5Group& root, const DynamicsStudy& s) {
  std::vector<double> mean, median, min, max, p2p, pcf;
  for (const dynamics::ForceStatistics& r : s.rows) {
    mean.push_back(r.mean);
    median.push_back(r.median);
    min.push_back(r.min);
    max.push_back(r.max);
    p2p.push_back(r.peak_to_peak);
    pcf.push_back(r.percent_constant_force);
  }
  // Every force is of what force_of says (--force-of), as in the JSON.
  const std::string force_of_label = mechanism::force_of_label(s.force_of);
  const auto of = [&](const char* what) { return fmt::format("{} ({})", what, force_of_label); };
  root.write_dataset("omega", s.omegas, "rad/s", "drive frequency omega of the sinusoidal motion");
  root.write_dataset("mean_force", mean, "N", of("mean input force over one period"));
  root.write_dataset("median_force", median, "N", of("median input force over one period"));
  root.write_dataset("min_force", min, "N", of("smallest input force over one period"));
  root.write_dataset("max_force", max, "N", of("largest input force over one period"));
  root.write_dataset("peak_to_peak_force", p2p, "N", of("max_force - min_force over one period"));
  root.write_dataset("percent_constant_force",
                     pcf,
                     "%",
                     "percent constant force 100 min_force / max_force over one period");
  root.set_attribute("mechanism", s.design.name);
  root.set_attribute("stroke_m", s.motion.stroke);
  root.set_attribute("preload_m", s.motion.preload);
  root.set_attribute("samples_per_period", static_cast<std::int64_t>(s.samples));
  root.set_attribute("zero_slider_mass", static_cast<std::int64_t>(s.zero_slider_mass));
  root.set_attribute("zero_inertia", static_cast<std::int64_t>(s.zero_inertia));
  root.set_attribute("friction_C1", s.parameters.coulomb[0]);
  root.set_attribute("friction_C2", s.parameters.coulomb[1]);
  root.set_attribute("friction_C3", s.parameters.coulomb[2]);
  root.set_attribute("axial_alpha", s.parameters.axial_alpha);
  root.set_attribute("static_nominal_force", s.static_nominal_force);
  if (s.paper_nominal_force) root.set_attribute("paper_nominal_force", *s.paper_nominal_force);
  root.set_attribute("natural_frequency", s.natural_frequency);
  root.set_attribute("force_of", force_of_label);
  root.set_attribute(
      "spring_rule",
      std::string(s.design.spring_rule ? dynamics::to_string(*s.design.spring_rule) : "none"));
  root.set_attribute("attribute_units",
                     fmt::format("stroke_m, preload_m: m; friction_C1, friction_C2, friction_C3: "
                                 "N m; axial_alpha: rad; static_nominal_force, "
                                 "paper_nominal_force: N ({}); natural_frequency: rad/s",
                                 force_of_label));
  io::write_provenance(root, {});
  io::Hdf5Group history_group = root.create_group("history");
  history_group.set_attribute("description",
                              "one period of the motion at each --history frequency, groups 0, "
                              "1, ... in the order given");
  for (std::size_t i = 0; i < s.histories.size(); ++i) {
    const DynamicsForceHistory& h = s.histories[i];
    io::Hdf5Group g = history_group.create_group(fmt::format("{}", i));
    g.set_attribute("omega", h.omega);
    g.set_attribute("attribute_units", "omega: rad/s");
    g.write_dataset("t", h.t, "s", "time within the period, from 0");
    g.write_dataset("delta_x",
                    h.delta_x,
                    "m",
                    "slider displacement Delta x(t) = preload + stroke (1 - cos omega t)/2");
    g.write_dataset("theta2", h.theta2, "rad", "crank angle theta2 at Delta x(t)");
    g.write_dataset("force", h.force, "N", of("input force of the dynamic model"));
    g.write_dataset(
        "static_force", h.static_force, "N", of("static PRBM force at the same Delta x"));
  }
}

}  // namespace

DynamicsStudyFile::DynamicsStudyFile(const std::string& path) : path_(path) {
  try {
    file_ = std::make_unique<io::AtomicHdf5File>(path);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(e.what());
  }
}

DynamicsStudyFile::~DynamicsStudyFile() = default;
DynamicsStudyFile::DynamicsStudyFile(DynamicsStudyFile&&) noexcept = default;
DynamicsStudyFile& DynamicsStudyFile::operator=(DynamicsStudyFile&&) noexcept = default;

void DynamicsStudyFile::write(const DynamicsStudy& study) {
  if (!file_ || file_->committed()) {
    throw std::logic_error(path_ + ": a DynamicsStudyFile is written once only");
  }
  // A study that stopped has no complete table: nothing is written (the file stays absent).
  if (!study.converged()) throw NoConvergence(study.message);
  write_study(file_->root(), study);
  file_->commit();
}

}  // namespace flexure
