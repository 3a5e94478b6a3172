// flexure._core's classes for general planar mechanisms (issue 31; docs/mechanisms.md "General
// mechanisms", docs/python.md "General mechanisms"): the description built in Python with the
// C++ builder's calls (or read from TOML), the options of its two models and their results, and
// the solves themselves, without the command line in between.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/general/stable_selection.h"
#include "python/object_support.h"

namespace py = pybind11;

namespace flexure::python {
namespace {

using namespace flexure::mechanism::general;

void bind_kinds(py::module_& m) {
  py::enum_<JointKind>(m, "JointKind", "pin, slider or weld.")
      .value("pin", JointKind::kPin)
      .value("slider", JointKind::kSlider)
      .value("weld", JointKind::kWeld);
  py::enum_<PrbmKind>(m, "PrbmKind", "The PRBM element of a flexure (Howell ch. 5).")
      .value("small_length", PrbmKind::kSmallLengthPivot)
      .value("fixed_pinned", PrbmKind::kFixedPinned)
      .value("fixed_guided", PrbmKind::kFixedGuided);
  py::enum_<FlexureModel>(m, "FlexureModel", "A flexure's model under the mixed model.")
      .value("prbm", FlexureModel::kPrbm)
      .value("exact", FlexureModel::kExact)
      .value("linear", FlexureModel::kLinear)
      .value("bcm", FlexureModel::kBcm)
      .value("prbm3r", FlexureModel::kPrbm3r)
      .value("cbcm", FlexureModel::kCbcm)
      .value("chain", FlexureModel::kChain)
      .value("auto", FlexureModel::kAuto);
  py::enum_<InputCoordinate>(m, "InputCoordinate", "x, y of a body point, or a line's angle.")
      .value("x", InputCoordinate::kX)
      .value("y", InputCoordinate::kY)
      .value("angle", InputCoordinate::kAngle);
  py::enum_<InputControl>(m, "InputControl", "The input prescribed (displacement) or loaded.")
      .value("displacement", InputControl::kDisplacement)
      .value("force", InputControl::kForce);
}

// Points as {name: (x, y)} in metres, in the order given.
std::vector<NamedPoint> named_points(const std::vector<std::pair<std::string, Vec2>>& points) {
  std::vector<NamedPoint> out;
  out.reserve(points.size());
  for (const auto& [name, at] : points) out.push_back({name, at});
  return out;
}

std::vector<std::pair<std::string, Vec2>> points_of(const py::dict& points) {
  std::vector<std::pair<std::string, Vec2>> out;
  for (const auto& [key, value] : points) {
    const auto xy = value.cast<std::pair<double, double>>();
    out.emplace_back(key.cast<std::string>(), Vec2{xy.first, xy.second});
  }
  return out;
}

void bind_description(py::module_& m) {
  using GM = GeneralMechanism;
  // Builder calls return the mechanism itself, so that they chain as in C++.
  constexpr auto self = py::return_value_policy::reference_internal;
  py::class_<GM>(m,
                 "GeneralMechanism",
                 "Any planar compliant mechanism: bodies with named points, joints, flexures, "
                 "springs, dead loads and one input (SI units, points in the described "
                 "configuration; docs/mechanisms.md \"General mechanisms\").")
      .def(py::init([](const std::string& name) {
             GM g;
             g.name = name;
             return g;
           }),
           py::arg("name") = "")
      .def_static("from_toml",
                  &load_general_mechanism_toml,
                  py::arg("path"),
                  "Reads a [[body]] TOML description (docs/mechanisms.md).")
      .def_static("from_toml_text",
                  &parse_general_mechanism_toml,
                  py::arg("text"),
                  py::arg("source") = "<text>",
                  "Parses a [[body]] TOML description given as text; `source` names it in errors.")
      .def_readwrite("name", &GM::name)
      .def(
          "body",
          [](GM& g, const std::string& name, const py::dict& points) -> GM& {
            return g.body(name, named_points(points_of(points)));
          },
          py::arg("name"),
          py::arg("points"),
          self,
          "A rigid body (or points added to 'ground') with points {name: (x, y)} in m.")
      .def("pin", &GM::pin, py::arg("name"), py::arg("a"), py::arg("b"), self)
      .def("slider",
           &GM::slider,
           py::arg("name"),
           py::arg("a"),
           py::arg("b"),
           py::arg("axis_angle"),
           self,
           "Point b stays on the line of body a through point a at axis_angle (rad from +x); "
           "the bodies keep their relative angle.")
      .def("weld", &GM::weld, py::arg("name"), py::arg("a"), py::arg("b"), self)
      .def(
          "flexure",
          [](GM& g,
             const std::string& name,
             const std::string& a,
             const std::string& b,
             double width,
             double thickness,
             std::optional<double> E,
             PrbmKind prbm,
             FlexureModel model,
             double tolerance,
             int elements,
             double curvature,
             double length,
             double width_tip,
             double thickness_tip,
             std::optional<Material> material) -> GM& {
            // E alone, or a whole Material (E, nu, S_y, density); not both.
            if (E.has_value() == material.has_value()) {
              throw InvalidInput("flexure '" + name +
                                 "': give its material as E= (Pa) or as material=, one of them");
            }
            g.flexure(name, a, b, width, thickness, E ? *E : material->E, prbm);
            Flexure& f = g.flexures.back();
            if (material) f.material = *material;
            f.model = model;
            f.tolerance = tolerance;
            f.elements = elements;
            f.curvature = curvature;
            f.length = length;
            f.width_tip = width_tip;
            f.thickness_tip = thickness_tip;
            return g;
          },
          py::arg("name"),
          py::arg("a"),
          py::arg("b"),
          py::kw_only(),
          py::arg("width"),
          py::arg("thickness"),
          py::arg("E") = std::optional<double>(),
          py::arg("prbm") = PrbmKind::kSmallLengthPivot,
          py::arg("model") = FlexureModel::kPrbm,
          py::arg("tolerance") = 0.0,
          py::arg("elements") = 0,
          py::arg("curvature") = 0.0,
          py::arg("length") = 0.0,
          py::arg("width_tip") = 0.0,
          py::arg("thickness_tip") = 0.0,
          py::arg("material") = std::optional<Material>(),
          self,
          "A flexure from point a to point b ('body.point'): width b and thickness h (m), Young's "
          "modulus E (Pa) or a material (a Material), its PRBM element and its model under the "
          "mixed model; its rest shape: "
          "a stress-free curvature (1/m: an arc from a to b of the given length, or the minor arc) "
          "and a taper to width_tip, thickness_tip at b (m; 0: none).")
      .def(
          "linear_spring",
          [](GM& g,
             const std::string& name,
             const std::string& a,
             const std::string& b,
             double stiffness,
             double rest_length) -> GM& {
            g.linear_spring(name, a, b, stiffness);
            g.linear_springs.back().rest_length = rest_length;
            return g;
          },
          py::arg("name"),
          py::arg("a"),
          py::arg("b"),
          py::arg("stiffness"),
          py::arg("rest_length") = -1.0,
          self,
          "A linear spring (N/m) between two points; rest_length < 0: the described distance.")
      .def(
          "torsion_spring",
          [](GM& g,
             const std::string& name,
             const std::string& body_a,
             const std::string& body_b,
             double stiffness,
             double rest_angle) -> GM& {
            g.torsion_spring(name, body_a, body_b, stiffness);
            g.torsion_springs.back().rest_angle = rest_angle;
            return g;
          },
          py::arg("name"),
          py::arg("body_a"),
          py::arg("body_b"),
          py::arg("stiffness"),
          py::arg("rest_angle") = 0.0,
          self,
          "A torsion spring (N m/rad) on the relative rotation of two bodies.")
      .def("load",
           &GM::load,
           py::arg("name"),
           py::arg("at"),
           py::arg("fx") = 0.0,
           py::arg("fy") = 0.0,
           py::arg("moment") = 0.0,
           self,
           "A dead force (N) and moment (N m) on a body point.")
      .def(
          "input",
          [](GM& g,
             InputCoordinate coordinate,
             const std::string& point,
             const std::string& point_to,
             InputControl control,
             double start,
             double stop,
             int count,
             const std::map<std::string, double>& start_rotation) -> GM& {
            g.input_coordinate(coordinate, point, point_to, control, start, stop, count);
            g.input.start_rotation.assign(start_rotation.begin(), start_rotation.end());
            return g;
          },
          py::arg("coordinate"),
          py::arg("point"),
          py::arg("point_to") = "",
          py::kw_only(),
          py::arg("control") = InputControl::kDisplacement,
          py::arg("start"),
          py::arg("stop"),
          py::arg("count") = 51,
          py::arg("start_rotation") = std::map<std::string, double>{},
          self,
          "The one input: x or y of 'body.point', or the angle of the line point -> point_to; "
          "its range (m, rad, N or N m) and count.")
      .def(
          "set_flexure_model",
          [](GM& g, const std::string& flexure, FlexureModel model, double tolerance, int elements)
              -> GM& {
            set_flexure_model(g, flexure, model, tolerance, elements);
            return g;
          },
          py::arg("flexure"),
          py::arg("model"),
          py::arg("tolerance") = 0.0,
          py::arg("elements") = 0,
          self,
          "The model of one flexure (every flexure for ''), for the mixed model.")
      .def("validate", &GM::validate, "Raises flexure.InvalidInput naming the item.")
      .def(
          "point",
          [](const GM& g, const std::string& ref) {
            const Vec2 p = g.point(parse_point_ref(ref, "point"));
            return std::make_pair(p.x, p.y);
          },
          py::arg("ref"),
          "A point's (x, y) in the described configuration, m.")
      .def("size", &GM::size, "The largest distance between two points, m.")
      .def_property_readonly("bodies",
                             [](const GM& g) {
                               std::vector<std::string> names;
                               for (const Body& b : g.bodies) names.push_back(b.name);
                               return names;
                             })
      .def_property_readonly("flexures",
                             [](const GM& g) {
                               std::vector<std::string> names;
                               for (const Flexure& f : g.flexures) names.push_back(f.name);
                               return names;
                             })
      .def("__repr__", [](const GM& g) {
        return fmt::format("GeneralMechanism('{}': {} bodies, {} joints, {} flexures)",
                           g.name,
                           g.bodies.size(),
                           g.joints.size(),
                           g.flexures.size());
      });
}

void bind_results(py::module_& m) {
  py::class_<GeneralPrbmOptions>(m, "GeneralPrbmOptions", "The PRBM's continuation settings.")
      .def(
          py::init([](double tolerance, int max_newton_iterations, int max_steps, double max_step) {
            GeneralPrbmOptions o;
            o.tolerance = tolerance;
            o.max_newton_iterations = max_newton_iterations;
            o.max_steps = max_steps;
            o.max_step = max_step;
            o.validate();
            return o;
          }),
          py::kw_only(),
          py::arg("tolerance") = GeneralPrbmOptions{}.tolerance,
          py::arg("max_newton_iterations") = GeneralPrbmOptions{}.max_newton_iterations,
          py::arg("max_steps") = GeneralPrbmOptions{}.max_steps,
          py::arg("max_step") = GeneralPrbmOptions{}.max_step)
      .def_readonly("tolerance", &GeneralPrbmOptions::tolerance)
      .def_readonly("max_newton_iterations", &GeneralPrbmOptions::max_newton_iterations)
      .def_readonly("max_steps", &GeneralPrbmOptions::max_steps)
      .def_readonly("max_step", &GeneralPrbmOptions::max_step);
  py::class_<GeneralExactOptions>(m, "GeneralExactOptions", "The exact model's Newton settings.")
      .def(py::init([](double tolerance,
                       int max_newton_iterations,
                       int max_step_halvings,
                       bool measure_flexure_errors) {
             GeneralExactOptions o;
             o.tolerance = tolerance;
             o.max_newton_iterations = max_newton_iterations;
             o.max_step_halvings = max_step_halvings;
             o.measure_flexure_errors = measure_flexure_errors;
             o.validate();
             return o;
           }),
           py::kw_only(),
           py::arg("tolerance") = GeneralExactOptions{}.tolerance,
           py::arg("max_newton_iterations") = GeneralExactOptions{}.max_newton_iterations,
           py::arg("max_step_halvings") = GeneralExactOptions{}.max_step_halvings,
           py::arg("measure_flexure_errors") = false)
      .def_readonly("tolerance", &GeneralExactOptions::tolerance)
      .def_readonly("max_newton_iterations", &GeneralExactOptions::max_newton_iterations)
      .def_readonly("max_step_halvings", &GeneralExactOptions::max_step_halvings)
      .def_readonly("measure_flexure_errors", &GeneralExactOptions::measure_flexure_errors);

  py::class_<PointLoad>(m, "PointLoad", "A force (N) at a point and a moment (N m) about it.")
      .def_readonly("fx", &PointLoad::fx)
      .def_readonly("fy", &PointLoad::fy)
      .def_readonly("moment", &PointLoad::moment)
      .def("__repr__", [](const PointLoad& l) {
        return fmt::format("PointLoad(fx={}, fy={}, moment={})", l.fx, l.fy, l.moment);
      });
  py::class_<JointPointResult>(
      m, "JointPointResult", "A joint at one point: its point of body b and body a's load on b.")
      .def_readonly("x", &JointPointResult::x)
      .def_readonly("y", &JointPointResult::y)
      .def_readonly("on_b", &JointPointResult::on_b);
  py::class_<FlexurePointResult>(m,
                                 "FlexurePointResult",
                                 "One flexure at one point: its end loads, largest stress and "
                                 "shape (docs/mechanisms.md \"Reactions, stresses and shapes\").")
      .def_readonly("on_a", &FlexurePointResult::on_a)
      .def_readonly("on_b", &FlexurePointResult::on_b)
      .def_readonly("max_stress", &FlexurePointResult::max_stress)
      .def_readonly("max_stress_at", &FlexurePointResult::max_stress_at)
      .def_readonly("max_stress_fibre", &FlexurePointResult::max_stress_fibre)
      .def_readonly("stress_pos_fibre", &FlexurePointResult::stress_pos_fibre)
      .def_readonly("stress_neg_fibre", &FlexurePointResult::stress_neg_fibre)
      .def_readonly("moment", &FlexurePointResult::moment)
      .def_readonly("axial_force", &FlexurePointResult::axial_force)
      .def_property_readonly("max_stress_from",
                             [](const FlexurePointResult& f) { return std::string(f.max_from); })
      .def_readonly("shape_x", &FlexurePointResult::shape_x)
      .def_readonly("shape_y", &FlexurePointResult::shape_y)
      .def("__repr__", [](const FlexurePointResult& f) {
        return fmt::format(
            "FlexurePointResult(max_stress={}, at={})", f.max_stress, f.max_stress_at);
      });
  py::class_<GeneralPrbmPoint>(m, "GeneralMechanismPoint", "One equilibrium along the input.")
      .def_readonly("input", &GeneralPrbmPoint::input)
      .def_readonly("input_load", &GeneralPrbmPoint::input_load)
      .def_readonly("energy", &GeneralPrbmPoint::energy)
      .def_readonly("spring_energy", &GeneralPrbmPoint::spring_energy)
      .def_readonly("displacement_control", &GeneralPrbmPoint::displacement_control)
      .def_readonly("force_control", &GeneralPrbmPoint::force_control)
      .def_readonly("body_x", &GeneralPrbmPoint::body_x)
      .def_readonly("body_y", &GeneralPrbmPoint::body_y)
      .def_readonly("body_phi", &GeneralPrbmPoint::body_phi)
      .def_readonly("joints", &GeneralPrbmPoint::joints)
      .def_readonly("flexures", &GeneralPrbmPoint::flexures)
      .def_readonly("ground_reaction", &GeneralPrbmPoint::ground_reaction)
      .def("__repr__", [](const GeneralPrbmPoint& p) {
        return fmt::format("GeneralMechanismPoint(input={}, input_load={})", p.input, p.input_load);
      });
  py::class_<GeneralEquilibrium>(m, "GeneralEquilibrium", "An equilibrium of the unloaded input.")
      .def_readonly("input", &GeneralEquilibrium::input)
      .def_readonly("energy", &GeneralEquilibrium::energy)
      .def_readonly("stability", &GeneralEquilibrium::stability)
      .def("__repr__", [](const GeneralEquilibrium& e) {
        return fmt::format(
            "GeneralEquilibrium(input={}, energy={}, {})", e.input, e.energy, e.stability.message);
      });
  py::class_<FlexureTipLoad>(m, "FlexureTipLoad", "F l^2/EI and M l/EI in the root frame.")
      .def_readonly("Fx", &FlexureTipLoad::Fx)
      .def_readonly("Fy", &FlexureTipLoad::Fy)
      .def_readonly("mu", &FlexureTipLoad::mu);
  py::class_<FlexureModelReport>(m, "FlexureModelReport", "What one flexure's model was, and why.")
      .def_readonly("name", &FlexureModelReport::name)
      .def_readonly("requested", &FlexureModelReport::requested)
      .def_readonly("model", &FlexureModelReport::model)
      .def_readonly("elements", &FlexureModelReport::elements)
      .def_readonly("tolerance", &FlexureModelReport::tolerance)
      .def_readonly("reason", &FlexureModelReport::reason)
      .def_readonly("expected_error_per_length", &FlexureModelReport::expected_error_per_length)
      .def_readonly("unmapped_points", &FlexureModelReport::unmapped_points)
      .def_readonly("loads", &FlexureModelReport::loads)
      .def_readonly("mapped_error", &FlexureModelReport::mapped_error)
      .def_readonly("measured_error", &FlexureModelReport::measured_error)
      .def_readonly("measured_error_per_length", &FlexureModelReport::measured_error_per_length);
  // The columns a plot wants, as lists in path order.
  const auto column = [](double GeneralPrbmPoint::*field) {
    return [field](const GeneralPrbmResult& r) {
      std::vector<double> out;
      out.reserve(r.points.size());
      for (const GeneralPrbmPoint& p : r.points) out.push_back(p.*field);
      return out;
    };
  };
  py::class_<GeneralPrbmResult, SolveStatus>(
      m,
      "GeneralMechanismResult",
      "A general mechanism over its input: the points in path order, the unloaded equilibria, "
      "the limit points; `input`, `input_load`, `energy` as lists.")
      .def_readonly("body_names", &GeneralPrbmResult::body_names)
      .def_readonly("points", &GeneralPrbmResult::points)
      .def_readonly("equilibria", &GeneralPrbmResult::equilibria)
      .def_readonly("limit_inputs", &GeneralPrbmResult::limit_inputs)
      .def_readonly("limit_loads", &GeneralPrbmResult::limit_loads)
      .def_readonly("degrees_of_freedom", &GeneralPrbmResult::degrees_of_freedom)
      .def_readonly("flexure_models", &GeneralPrbmResult::flexure_models)
      .def_property_readonly("input", column(&GeneralPrbmPoint::input))
      .def_property_readonly("input_load", column(&GeneralPrbmPoint::input_load))
      .def_property_readonly("energy", column(&GeneralPrbmPoint::energy));

  m.def(
      "solve_general_prbm",
      [](const GeneralMechanism& g, const GeneralPrbmOptions& o, py::object progress) {
        ProgressBridge bridge(std::move(progress));
        GeneralPrbmOptions with = o;
        with.progress = [&bridge](std::size_t done, std::size_t total) { bridge(done, total); };
        return bridge.run<GeneralPrbmResult>([&] { return solve_general_prbm(g, with); });
      },
      py::arg("mechanism"),
      py::arg("options") = GeneralPrbmOptions{},
      py::kw_only(),
      py::arg("progress") = py::none(),
      "The PRBM of a general mechanism over its input range (continuation through limit points, "
      "stability under both controls, unloaded equilibria). `progress(done, total)` is called "
      "after each recorded point (total: the input's count); Ctrl-C stops it at the next "
      "point.");
  m.def(
      "solve_general_exact",
      [](const GeneralMechanism& g, const GeneralExactOptions& o, py::object progress) {
        ProgressBridge bridge(std::move(progress));
        GeneralExactOptions with = o;
        with.progress = [&bridge](std::size_t done, std::size_t total) { bridge(done, total); };
        return bridge.run<GeneralPrbmResult>([&] { return solve_general_exact(g, with); });
      },
      py::arg("mechanism"),
      py::arg("options") = GeneralExactOptions{},
      py::kw_only(),
      py::arg("progress") = py::none(),
      "The exact model of a general mechanism: every flexure an elastica, one Newton system. "
      "`progress(done, total)` is called after each "
      "recorded point (total: the input's count); Ctrl-C stops it at the next point.");
  m.def(
      "solve_general_mixed",
      [](const GeneralMechanism& g, const GeneralExactOptions& o, py::object progress) {
        ProgressBridge bridge(std::move(progress));
        GeneralExactOptions with = o;
        with.progress = [&bridge](std::size_t done, std::size_t total) { bridge(done, total); };
        return bridge.run<GeneralPrbmResult>([&] { return solve_general_mixed(g, with); });
      },
      py::arg("mechanism"),
      py::arg("options") = GeneralExactOptions{},
      py::kw_only(),
      py::arg("progress") = py::none(),
      "Each flexure under its own model (GeneralMechanism.set_flexure_model). `progress(done, "
      "total)` is called after each "
      "recorded point (total: the input's count); Ctrl-C stops it at the next point.");
  py::class_<StableSelection>(
      m,
      "StableSelection",
      "select_stable_points' answer (docs/mechanisms.md \"Stable equilibria (--stable)\"): "
      "result (the path with one stable point per grid value), stable, grid_values, "
      "without_stable, snaps, search.")
      .def_readonly("result", &StableSelection::result)
      .def_readonly("stable", &StableSelection::stable)
      .def_readonly("grid_values", &StableSelection::grid_values)
      .def_readonly("without_stable", &StableSelection::without_stable)
      .def_readonly("snaps", &StableSelection::snaps)
      .def_readonly("search", &StableSelection::search);
  m.def(
      "select_stable_points",
      [](const GeneralMechanism& g, const GeneralPrbmResult& path, py::object progress) {
        ProgressBridge bridge(std::move(progress));
        return bridge.run<StableSelection>([&] {
          return select_stable_points(
              g, path, [&bridge](std::size_t done, std::size_t total) { bridge(done, total); });
        });
      },
      py::arg("mechanism"),
      py::arg("path"),
      py::kw_only(),
      py::arg("progress") = py::none(),
      "At each grid value of the controlled quantity the traced equilibrium stable under the "
      "input's control, continuing the branch of the value before (`mechanism analyze "
      "--stable`). `progress(done, total)` is called after each grid value (total: the "
      "input's count); Ctrl-C stops it at the next one.");
  m.def("check_general_mechanism",
        &check_general_mechanism,
        py::arg("mechanism"),
        "The structural checks of both models; the linkage's degrees of freedom with the input "
        "free. Raises flexure.InvalidInput naming what is wrong.");
}

}  // namespace

void bind_mechanism_objects(py::module_& m) {
  bind_kinds(m);
  bind_description(m);
  bind_results(m);
}

}  // namespace flexure::python
