// flexure._core's classes for the constant-force slider mechanisms (docs/mechanisms.md;
// docs/python.md "Objects"): a design from the built-in catalogue or from TOML (text or file, in
// memory: no temporary file), the analysis options, and analyze_mechanism with a progress
// callable. A long analysis can be stopped with Ctrl-C: the bindings check for a pending
// KeyboardInterrupt at every progress step (python/object_support.h, ProgressBridge).
#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_plate.h"
#include "python/object_support.h"

namespace py = pybind11;

namespace flexure::python {
namespace {

using namespace flexure::mechanism;

void bind_design(py::module_& m) {
  py::class_<MechanismDesign>(m,
                              "MechanismDesign",
                              "A constant-force slider mechanism (Weight's configurations, "
                              "Howell's designs, the modified designs, inversions): a built-in "
                              "design or a TOML description (docs/mechanisms.md).")
      .def_static("builtin",
                  &find_builtin_mechanism,
                  py::arg("name"),
                  "A built-in design by name ('1A-lpp', 'lpp-b', 'howell-ex1', \"1A-lpp'\"); "
                  "raises InvalidInput listing the names.")
      .def_static(
          "builtin_names",
          [] {
            std::vector<std::string> names;
            for (const MechanismDesign& d : builtin_mechanisms()) names.push_back(d.name);
            return names;
          },
          "The names of `flexure mechanism list`.")
      .def_static("from_toml",
                  &load_mechanism_toml,
                  py::arg("path"),
                  "Reads a mechanism TOML file (config = \"lpp\", ...; docs/mechanisms.md).")
      .def_static("from_toml_text",
                  &parse_mechanism_toml,
                  py::arg("text"),
                  py::arg("source") = "<text>",
                  "Parses a mechanism TOML description given as text; `source` names it in "
                  "errors.")
      .def_readonly("name", &MechanismDesign::name)
      .def_readonly("config", &MechanismDesign::config)
      .def_readonly("note", &MechanismDesign::note)
      .def_readonly("r2", &MechanismDesign::r2)
      .def_readonly("r3", &MechanismDesign::r3)
      // E and yield_strength read the design's Material (kept as attributes of their own).
      .def_property_readonly("E", [](const MechanismDesign& d) { return d.material.E; })
      .def_property_readonly(
          "yield_strength",
          [](const MechanismDesign& d) { return d.material.yield_strength.value_or(0.0); })
      .def_readonly("material", &MechanismDesign::material, "The strips' Material (E, nu, S_y).")
      .def_property_readonly(
          "material_id",
          [](const MechanismDesign& d) -> py::object {
            return d.material_id.empty() ? py::object(py::none()) : py::str(d.material_id);
          },
          "The data/materials.csv id the material came from, or None (given by value).")
      .def_readonly("stroke", &MechanismDesign::stroke)
      .def("__repr__", [](const MechanismDesign& d) {
        return fmt::format("MechanismDesign('{}': {}, r2 = {} m, r3 = {} m, stroke {} m)",
                           d.name,
                           d.config,
                           d.r2,
                           d.r3,
                           d.stroke);
      });
}

void bind_analysis(py::module_& m) {
  py::class_<AnalysisOptions>(m, "AnalysisOptions", "What analyze_mechanism computes.")
      .def(py::init([](int points, bool exact, bool exact_stress, bool stability, bool stable) {
             AnalysisOptions o;
             o.points = points;
             o.exact = exact;
             o.exact_stress = exact_stress;
             o.stability = stability;
             o.stable = stable;
             o.validate();
             return o;
           }),
           py::kw_only(),
           py::arg("points") = AnalysisOptions{}.points,
           py::arg("exact") = true,
           py::arg("exact_stress") = true,
           py::arg("stability") = true,
           py::arg("stable") = false)
      .def_readonly("points", &AnalysisOptions::points)
      .def_readonly("exact", &AnalysisOptions::exact)
      .def_readonly("exact_stress", &AnalysisOptions::exact_stress)
      .def_readonly("stability", &AnalysisOptions::stability)
      .def_readonly("stable", &AnalysisOptions::stable);

  py::class_<StrokeStability>(m, "StrokeStability", "Stability verdicts along a stroke.")
      .def_readonly("points", &StrokeStability::points)
      .def_readonly("summary", &StrokeStability::summary)
      .def_readonly("unstable_points", &StrokeStability::unstable_points)
      .def_readonly("critical_points", &StrokeStability::critical_points)
      .def_readonly("not_checked_points", &StrokeStability::not_checked_points)
      .def_readonly("least_margin", &StrokeStability::least_margin);

  using MA = MechanismAnalysis;
  py::class_<MA, SolveStatus>(m,
                              "MechanismAnalysis",
                              "One stroke by the PRBM and (where it exists) the exact model: "
                              "forces (N, one half of a symmetric mechanism), stresses (Pa), "
                              "their comparison and the stability of every point.")
      .def_readonly("design", &MA::design)
      .def_property_readonly("displacement", [](const MA& a) { return a.prbm.displacement; })
      .def_property_readonly("force_prbm", [](const MA& a) { return a.prbm.force; })
      .def_readonly("force_exact", &MA::force_exact)
      .def_readonly("has_exact", &MA::has_exact)
      .def_readonly("exact_note", &MA::exact_note)
      .def_property_readonly("percent_constant_force_prbm",
                             [](const MA& a) { return a.prbm.percent_constant_force; })
      .def_readonly("percent_constant_force_exact", &MA::percent_constant_force_exact)
      .def_property_readonly("mean_force_prbm", [](const MA& a) { return a.prbm.mean_force; })
      .def_readonly("mean_force_exact", &MA::mean_force_exact)
      .def_readonly("max_force_error", &MA::max_force_error)
      .def_readonly("max_force_error_at", &MA::max_force_error_at)
      .def_readonly("prbm_validity_limit", &MA::prbm_validity_limit)
      .def_readonly("prbm_validity_reason", &MA::prbm_validity_reason)
      .def_readonly("max_stress", &MA::max_stress)
      .def_readonly("max_stress_all", &MA::max_stress_all)
      .def_readonly("safety_factor", &MA::safety_factor)
      .def_readonly("yielding_pivots", &MA::yielding_pivots)
      .def_property_readonly("stability_displacement_control_prbm",
                             [](const MA& a) { return a.stability_prbm.displacement_control; })
      .def_property_readonly("stability_force_control_prbm",
                             [](const MA& a) { return a.stability_prbm.force_control; })
      .def_property_readonly("stability_displacement_control_exact",
                             [](const MA& a) -> std::optional<StrokeStability> {
                               if (!a.has_exact_stability) return std::nullopt;
                               return a.stability_exact.displacement_control;
                             })
      .def_property_readonly("stability_force_control_exact",
                             [](const MA& a) -> std::optional<StrokeStability> {
                               if (!a.has_exact_stability) return std::nullopt;
                               return a.stability_exact.force_control;
                             })
      .def("__repr__", [](const MA& a) {
        return fmt::format("MechanismAnalysis('{}': {} points, {})",
                           a.design.name,
                           a.prbm.displacement.size(),
                           termination_name(a.termination));
      });

  m.def(
      "analyze_mechanism",
      [](const MechanismDesign& design, const AnalysisOptions& options, py::object progress) {
        ProgressBridge bridge(std::move(progress));
        AnalysisOptions o = options;
        o.progress = [&bridge](std::size_t done, std::size_t total) { bridge(done, total); };
        return bridge.run<MA>([&] { return analyze_mechanism_with_modulus(design, o); });
      },
      py::arg("design"),
      py::arg("options") = AnalysisOptions{},
      py::kw_only(),
      py::arg("progress") = py::none(),
      "Analyses one stroke of `design` (its plate-modulus choice applied). `progress(done, "
      "total)` is called as the exact model's points are computed; Ctrl-C raises "
      "KeyboardInterrupt at the next point.");
}

}  // namespace

void bind_catalogue_objects(py::module_& m) {
  bind_design(m);
  bind_analysis(m);
}

}  // namespace flexure::python
