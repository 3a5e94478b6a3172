// write_model_map (model_map.h): the model map's HDF5 file (docs/hdf5-schema.md "flexure models
// map").
#include <fmt/format.h>

#include <memory>

#include "flexure/benchmarks/studies/model_map.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/common/status.h"

namespace flexure::studies {
namespace {

const char* model_description(BeamMethod method) {
  switch (method) {
    case BeamMethod::kLinear:
      return "linear Euler-Bernoulli theory (equilibrium in the undeformed beam)";
    case BeamMethod::kPrbm:
      return "Howell's 1R pseudo-rigid-body model (fixed-pinned, end-moment or fixed-guided "
             "segment)";
    case BeamMethod::kPrbm3r:
      return "Su's pseudo-rigid-body 3R model (4 links, 3 torsion springs)";
    case BeamMethod::kBcm:
      return "the beam-constraint model, one element (Awtar et al. 2007)";
    case BeamMethod::kCbcm:
      return "the chained beam-constraint model (Ma and Chen 2016)";
    case BeamMethod::kChain:
      return "Howell's chain algorithm (exact as the number of elements grows)";
    case BeamMethod::kShooting:
      return "the shooting method (exact, rtol 1e-12)";
    case BeamMethod::kElliptic:
      return "the elliptic-integral solution (exact)";
    case BeamMethod::kAuto:
      break;
  }
  return "";
}

void write_columns(io::Hdf5Group& g,
                   const ModelMapColumns& c,
                   const std::vector<hsize_t>& dims,
                   bool reference) {
  const auto grid = [&](const char* name,
                        const std::vector<double>& v,
                        const char* units,
                        const std::string& text) {
    g.write_dataset(name, std::span<const double>(v), dims, units, text);
  };
  grid("a_over_l", c.a_over_l, "1", "tip coordinate a/l; NaN where status is not 0 or 3");
  grid("b_over_l", c.b_over_l, "1", "tip deflection b/l; NaN where status is not 0 or 3");
  grid("theta0", c.theta0, "rad", "tip angle; NaN where status is not 0 or 3");
  grid("seconds",
       c.seconds,
       "s",
       "mean time per solve (solve_beam, repeated to at least the file's min_seconds); NaN where "
       "status is not 0 or 3");
  if (!reference) {
    grid("position_error",
         c.position_error,
         "1",
         "tip position error per length |(a, b) - (a, b)_exact|/l; NaN where status != 0");
    grid("angle_error",
         c.angle_error,
         "rad",
         "tip angle error |theta0 - theta0_exact|; NaN where "
         "status != 0");
    grid("relative_error",
         c.relative_error,
         "1",
         "position_error / exact tip displacement |(a - l, b)_exact|; NaN where status != 0 or "
         "the exact tip does not move");
  }
  g.write_dataset("status",
                  std::span<const int>(c.status),
                  dims,
                  "1",
                  reference ? "0 converged, 1 the exact solution did not converge here"
                            : "0 converged, 1 not converged, 2 the model cannot represent this "
                              "load, 3 converged but no exact solution to compare with");
}

}  // namespace

void write_model_map(const ModelMap& map, const std::string& path) {
  io::check_output_path(path);
  std::unique_ptr<io::AtomicHdf5File> file;
  try {
    file = std::make_unique<io::AtomicHdf5File>(path);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("--out: {}", e.what()));
  }
  const ModelMapSpec& spec = map.spec;
  io::Hdf5Group& root = file->root();
  root.set_attribute("schema", "flexure-models-map 1");
  root.set_attribute("boundary", to_string(spec.boundary));
  root.set_attribute("reference", to_string(spec.reference()));
  root.set_attribute("min_seconds", spec.min_seconds);
  root.set_attribute("description",
                     fmt::format("Howell's uniform cantilever ({} end) solved by every model of "
                                 "the ladder over the grid n x alpha2 x {} (row-major, {} "
                                 "fastest), each compared with the exact solution (/reference)",
                                 to_string(spec.boundary),
                                 spec.third_axis_name(),
                                 spec.third_axis_name()));
  root.write_dataset(
      "n", std::span<const double>(spec.n), "1", "load ratio n (n > 0 compressive), axis 0");
  root.write_dataset(
      "alpha2", std::span<const double>(spec.alpha2), "1", "transverse tip load P l^2/EI, axis 1");
  if (spec.boundary == EndCondition::kGuided) {
    root.write_dataset("tip_angle",
                       std::span<const double>(spec.tip_angle),
                       "rad",
                       "prescribed tip angle of the guided end, axis 2");
  } else {
    root.write_dataset("mu", std::span<const double>(spec.mu), "1", "end moment M l/EI, axis 2");
  }
  const std::vector<hsize_t> dims = {spec.n.size(), spec.alpha2.size(), spec.third_axis().size()};
  {
    io::Hdf5Group g = root.create_group("reference");
    g.set_attribute("method", to_string(spec.reference()));
    g.set_attribute("description", model_description(spec.reference()));
    write_columns(g, map.reference, dims, true);
    g.write_dataset("limit_points",
                    std::span<const int>(map.reference_limit_points),
                    dims,
                    "1",
                    "folds the exact load path passes before this load (the beam snaps there under "
                    "load control; a model following the path may stop or answer on another "
                    "branch); 0 where status != 0");
  }
  for (const ModelMapModel& m : map.models) {
    io::Hdf5Group g = root.create_group(to_string(m.method));
    g.set_attribute("method", to_string(m.method));
    g.set_attribute("description", model_description(m.method));
    g.set_attribute("settings", m.settings);
    g.set_attribute("converged_points", static_cast<std::int64_t>(m.converged));
    g.set_attribute("max_position_error", m.max_position_error);
    g.set_attribute("median_position_error", m.median_position_error);
    g.set_attribute("median_seconds", m.median_seconds);
    write_columns(g, m.values, dims, false);
  }
  io::write_provenance(
      root,
      {{"status", 0, "converged (errors against /reference recorded)"},
       {"status", 1, "no converged solution at this load (values NaN)"},
       {"status", 2, "the model cannot represent this load (values NaN)"},
       {"status", 3, "the model converged but the exact solution did not: no error recorded"}});
  file->commit();
}

}  // namespace flexure::studies
