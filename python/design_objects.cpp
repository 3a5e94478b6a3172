// flexure._core's classes for the dimensional design of constant-force slider mechanisms (Weight
// 2001 ch. 8; docs/design.md "Dimensional design"; docs/python.md "Objects"): the specification
// with keyword construction, design_mechanisms with a progress callable (Ctrl-C stops it between
// sub-classes: python/object_support.h, ProgressBridge), its report of feasible designs (best
// first) and rejected ones (closest first, with the binding constraint), and the refinement of a
// design against the exact model (with a progress callable too, per exact stroke). The same library
// calls as `flexure design mechanism`.
#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "flexure/mechanisms/design/mechanism_synthesis.h"
#include "python/object_support.h"

namespace py = pybind11;

namespace flexure::python {
namespace {

using namespace flexure::design;

// A range keyword: None (free: 0 to infinity), one value (fixed), or (lower, upper).
using RangeArg = std::variant<std::monostate, double, std::pair<double, double>>;

LengthRange range_of(const RangeArg& arg) {
  if (std::holds_alternative<double>(arg)) {
    const double v = std::get<double>(arg);
    return {v, v};
  }
  if (const auto* p = std::get_if<std::pair<double, double>>(&arg)) return {p->first, p->second};
  return MechanismSpec::free_range();
}

py::object range_value(const LengthRange& r) {
  if (r.lower == 0.0 && r.upper == MechanismSpec::free_range().upper) return py::none();
  return py::make_tuple(r.lower, r.upper);
}

std::vector<double> three(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

void bind_enums(py::module_& m) {
  py::enum_<FlexureOrientation>(m, "FlexureOrientation")
      .value("any", FlexureOrientation::kAny)
      .value("in_plane", FlexureOrientation::kInPlane)
      .value("out_of_plane", FlexureOrientation::kOutOfPlane);
  py::enum_<DesignRanking>(m, "DesignRanking")
      .value("prbm", DesignRanking::kPrbm)
      .value("exact", DesignRanking::kExact);
  py::enum_<StressRule>(m, "StressRule")
      .value("computed", StressRule::kComputed)
      .value("thesis", StressRule::kThesis);
  py::enum_<SizeObjective>(m, "SizeObjective")
      .value("none", SizeObjective::kNone)
      .value("length", SizeObjective::kLength)
      .value("footprint", SizeObjective::kFootprint)
      .value("mass", SizeObjective::kMass);
}

void bind_spec(py::module_& m) {
  py::class_<MechanismSpec>(m,
                            "MechanismSpec",
                            "What a constant-force slider mechanism must do, in SI units: the "
                            "mean force of one half, the stroke, the material and the ranges of "
                            "the sizes (`flexure design mechanism`'s flags; docs/design.md).")
      .def(py::init([](double force,
                       double stroke,
                       std::optional<double> E,
                       RangeArg length,
                       std::optional<double> yield_strength,
                       std::optional<Material> material,
                       double safety_factor,
                       RangeArg width,
                       RangeArg thickness,
                       FlexureOrientation orientation,
                       std::optional<double> pcf_min,
                       std::vector<std::string> configs,
                       DesignRanking ranking,
                       bool exact,
                       int points,
                       StressRule stress_rule,
                       double force_tolerance,
                       double max_width_to_thickness,
                       double max_width_to_length,
                       SizeObjective minimize) {
             MechanismSpec s;
             s.force = force;
             s.stroke = stroke;
             // The material as a Material, or as E (and S_y) alone; E or S_y beside a Material
             // would be a second value for the same field.
             if (material) {
               if (E || yield_strength) {
                 throw InvalidInput(
                     "MechanismSpec: give the material either as material=Material(...) or as "
                     "E= (and yield_strength=), not both");
               }
               s.material = *material;
             } else if (E) {
               s.material.E = *E;
               s.material.yield_strength = yield_strength;
             } else {
               throw InvalidInput("MechanismSpec: give the material: E= (Pa) or material=");
             }
             s.length = range_of(length);
             s.safety_factor = safety_factor;
             s.width = range_of(width);
             s.thickness = range_of(thickness);
             s.orientation = orientation;
             s.pcf_min = pcf_min;
             s.configs = std::move(configs);
             s.ranking = ranking;
             s.exact = exact;
             s.points = points;
             s.stress_rule = stress_rule;
             s.force_tolerance = force_tolerance;
             s.bounds.max_width_to_thickness = max_width_to_thickness;
             s.bounds.max_width_to_length = max_width_to_length;
             s.minimize = minimize;
             s.validate();
             return s;
           }),
           py::kw_only(),
           py::arg("force"),
           py::arg("stroke"),
           py::arg("E") = std::optional<double>(),
           py::arg("length"),
           py::arg("yield_strength") = std::optional<double>(),
           py::arg("material") = std::optional<Material>(),
           py::arg("safety_factor") = 1.0,
           py::arg("width") = py::none(),
           py::arg("thickness") = py::none(),
           py::arg("orientation") = FlexureOrientation::kAny,
           py::arg("pcf_min") = std::optional<double>(),
           py::arg("configs") = std::vector<std::string>(),
           py::arg("ranking") = DesignRanking::kPrbm,
           py::arg("exact") = true,
           py::arg("points") = 50,
           py::arg("stress_rule") = StressRule::kComputed,
           py::arg("force_tolerance") = 0.10,
           py::arg("max_width_to_thickness") = SectionBounds{}.max_width_to_thickness,
           py::arg("max_width_to_length") = SectionBounds{}.max_width_to_length,
           py::arg("minimize") = SizeObjective::kNone,
           "force: N (one half, eq. 8.2's F); stroke: m; E: Pa (or material: a Material with E, "
           "nu, yield_strength, density); length, width, thickness: m, a "
           "value or (lower, upper), width and thickness None for free; force_tolerance: a "
           "fraction (0.10 = 10 %). Validated: a bad field raises InvalidInput naming it.")
      .def_readonly("force", &MechanismSpec::force)
      .def_readonly("stroke", &MechanismSpec::stroke)
      .def_property_readonly("E", [](const MechanismSpec& s) { return s.material.E; })
      .def_property_readonly("yield_strength",
                             [](const MechanismSpec& s) { return s.material.yield_strength; })
      .def_readonly("material", &MechanismSpec::material, "The strips' Material.")
      .def_readonly("material_id", &MechanismSpec::material_id)
      .def_readonly("safety_factor", &MechanismSpec::safety_factor)
      .def_property_readonly(
          "length",
          [](const MechanismSpec& s) { return py::make_tuple(s.length.lower, s.length.upper); })
      .def_property_readonly("width", [](const MechanismSpec& s) { return range_value(s.width); })
      .def_property_readonly("thickness",
                             [](const MechanismSpec& s) { return range_value(s.thickness); })
      .def_readonly("orientation", &MechanismSpec::orientation)
      .def_readonly("pcf_min", &MechanismSpec::pcf_min)
      .def_readonly("configs", &MechanismSpec::configs)
      .def_readonly("ranking", &MechanismSpec::ranking)
      .def_readonly("exact", &MechanismSpec::exact)
      .def_readonly("points", &MechanismSpec::points)
      .def_readonly("stress_rule", &MechanismSpec::stress_rule)
      .def_readonly("force_tolerance", &MechanismSpec::force_tolerance)
      .def_readonly("minimize", &MechanismSpec::minimize)
      .def("__repr__", [](const MechanismSpec& s) {
        return fmt::format("MechanismSpec(force={}, stroke={}, E={}, length=({}, {}))",
                           s.force,
                           s.stroke,
                           s.material.E,
                           s.length.lower,
                           s.length.upper);
      });
}

void bind_report(py::module_& m) {
  using D = DimensionedDesign;
  py::class_<D, SolveStatus>(
      m,
      "DimensionedDesign",
      "One sub-class dimensioned for the specification: feasible (with its PRBM and exact values, "
      "and `design` ready for analyze_mechanism) or not (`binding` says which constraint, "
      "`shortfall` by how much). A SolveStatus: `termination` converged or infeasible. Lengths m, "
      "stresses Pa, forces N (one half).")
      .def_readonly("subclass", &D::subclass)
      .def_property_readonly("config", [](const D& d) { return std::string(d.config); })
      .def_readonly("feasible", &D::feasible)
      .def_readonly("binding", &D::binding)
      .def_readonly("shortfall", &D::shortfall)
      .def_readonly("length_needed", &D::length_needed)
      .def_property_readonly("R", [](const D& d) { return d.model.R; })
      .def_property_readonly("K1", [](const D& d) { return d.model.K1; })
      .def_property_readonly("K2", [](const D& d) { return d.model.K2; })
      .def_property_readonly("subclass_percent_constant_force",
                             [](const D& d) { return d.model.percent_constant_force; })
      .def_property_readonly("primary_pivot", [](const D& d) { return d.model.primary_pivot; })
      .def_readonly("M", &D::M)
      .def_readonly("n", &D::n)
      .def_readonly("stroke_percent", &D::stroke_percent)
      .def_readonly("l_tot", &D::l_tot)
      .def_readonly("r2", &D::r2)
      .def_readonly("r3", &D::r3)
      .def_readonly("section_rule", &D::section_rule)
      .def_property_readonly("segment_lengths", [](const D& d) { return three(d.segment_length); })
      .def_property_readonly("thicknesses", [](const D& d) { return three(d.thickness); })
      .def_property_readonly("widths", [](const D& d) { return three(d.width); })
      .def_readonly("primary_stress", &D::primary_stress)
      .def_readonly("required_yield_strength", &D::required_yield_strength)
      .def_readonly("required_yield_strength_prbm", &D::required_yield_strength_prbm)
      .def_readonly("required_yield_strength_exact", &D::required_yield_strength_exact)
      .def_readonly("force_prbm", &D::force_prbm)
      .def_readonly("percent_constant_force_prbm", &D::percent_constant_force_prbm)
      .def_readonly("safety_factor_prbm", &D::safety_factor_prbm)
      .def_readonly("force_exact", &D::force_exact)
      .def_readonly("percent_constant_force_exact", &D::percent_constant_force_exact)
      .def_readonly("safety_factor_exact", &D::safety_factor_exact)
      .def_readonly("exact_note", &D::exact_note)
      .def_readonly("footprint", &D::footprint)
      .def_readonly("flexure_volume", &D::flexure_volume)
      .def_readonly("width_to_thickness", &D::width_to_thickness)
      .def_readonly("width_to_length", &D::width_to_length)
      .def_readonly("exact_evaluations", &D::exact_evaluations)
      .def_readonly("design", &D::design)
      .def("__repr__", [](const D& d) {
        return d.feasible ? fmt::format("DimensionedDesign('{}', l_tot={})", d.subclass, d.l_tot)
                          : fmt::format(
                                "DimensionedDesign('{}', not feasible: {})", d.subclass, d.binding);
      });
  py::class_<MechanismDesignReport, SolveStatus>(
      m,
      "MechanismDesignReport",
      "The designs of a specification: `designs` feasible, best first; `rejected` with why, "
      "closest first; with nothing feasible, `length_needed` (m) and its sub-class. A "
      "SolveStatus: `termination` converged with a feasible design, else infeasible (`message` "
      "says why); `warnings` (raised as FlexureWarning) name designs short of the safety factor.")
      .def_readonly("designs", &MechanismDesignReport::designs)
      .def_readonly("rejected", &MechanismDesignReport::rejected)
      .def_readonly("length_needed", &MechanismDesignReport::length_needed)
      .def_readonly("length_needed_subclass", &MechanismDesignReport::length_needed_subclass)
      .def_readonly("sizing_safety_factor", &MechanismDesignReport::sizing_safety_factor)
      .def("__repr__", [](const MechanismDesignReport& r) {
        return fmt::format("MechanismDesignReport({} feasible, {} rejected{})",
                           r.designs.size(),
                           r.rejected.size(),
                           r.designs.empty() ? "" : ", best " + r.designs.front().subclass);
      });
}

void bind_calls(py::module_& m) {
  m.def(
      "design_mechanisms",
      [](const MechanismSpec& spec, py::object progress) {
        ProgressBridge bridge(std::move(progress));
        MechanismSpec s = spec;
        s.progress = [&bridge](std::size_t done, std::size_t total) { bridge(done, total); };
        return bridge.run<MechanismDesignReport>([&] { return design_mechanisms(s); });
      },
      py::arg("spec"),
      py::kw_only(),
      py::arg("progress") = py::none(),
      "Dimensions every sub-class the specification admits (`flexure design mechanism`). "
      "`progress(done, total)` is called after each sub-class; Ctrl-C (or an exception from "
      "the callable) stops the call at the next one.");
  m.def(
      "refine_design_exact",
      [](const MechanismSpec& spec, const DimensionedDesign& design, py::object progress) {
        ProgressBridge bridge(std::move(progress));
        MechanismSpec s = spec;
        s.progress = [&bridge](std::size_t done, std::size_t total) { bridge(done, total); };
        return bridge.run<DimensionedDesign>([&] { return refine_design_exact(s, design); });
      },
      py::arg("spec"),
      py::arg("design"),
      py::kw_only(),
      py::arg("progress") = py::none(),
      "A feasible design refined against the exact model (`design mechanism --model exact`). "
      "`progress(done, total)` is called after each exact stroke, total the most the search "
      "can take (1 + runs * 301: one run from the sub-class and two per free variable); a "
      "run that stops early moves done to its end. Ctrl-C (or an exception from the callable) "
      "stops it at the next stroke.");
}

}  // namespace

void bind_design_objects(py::module_& m) {
  bind_enums(m);
  bind_spec(m);
  bind_report(m);
  bind_calls(m);
}

}  // namespace flexure::python
