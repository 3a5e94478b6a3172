// flexure._core's classes for the cheaper models of the ladder (docs/models.md; docs/python.md
// "Objects"): linear theory, the PR-3R model, the BCM and the chained BCM, each with its validated
// Options (keyword construction; a bad value raises flexure.InvalidInput naming the field), the
// cantilever they solve (CantileverCase) and their read-only results.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <string>
#include <utility>

#include "flexure/elements/ladder_models.h"
#include "python/object_support.h"

namespace py = pybind11;

namespace flexure::python {
namespace {

void bind_cantilever_case(py::module_& m) {
  py::class_<CantileverCase>(m,
                             "CantileverCase",
                             "Howell's uniform cantilever for the ladder's models: a tip load and "
                             "a free or guided end (guided_tip_angle, rad).")
      .def(py::init([](EndLoad load, EndCondition end, double guided_tip_angle) {
             return CantileverCase{load, end, guided_tip_angle};
           }),
           py::kw_only(),
           py::arg("load") = EndLoad{},
           py::arg("end") = EndCondition::kFree,
           py::arg("guided_tip_angle") = 0.0)
      .def_readwrite("load", &CantileverCase::load)
      .def_readwrite("end", &CantileverCase::end)
      .def_readwrite("guided_tip_angle", &CantileverCase::guided_tip_angle)
      .def("to_chain", &CantileverCase::to_chain)
      .def("__repr__", [](const CantileverCase& c) {
        return fmt::format("CantileverCase(load=EndLoad(Fx={}, Fy={}, mu={}), end={})",
                           c.load.Fx,
                           c.load.Fy,
                           c.load.mu,
                           to_string(c.end));
      });
}

// What every ladder solver offers: construction from its validated Options, the options, and a
// solve of a CantileverCase or of a bare tip load (a free cantilever).
template <class Solver, class Result>
void def_cantilever_solver(py::class_<Solver>& solver) {
  using Options = typename Solver::Options;
  solver.def(py::init([](const Options& o) { return Solver(o); }), py::arg("options") = Options{})
      .def_property_readonly("options", &Solver::options)
      .def(
          "solve",
          [](const Solver& s, const CantileverCase& c) {
            return solve_released<Result>([&] { return s.solve(c); });
          },
          py::arg("problem"))
      .def(
          "solve",
          [](const Solver& s, const EndLoad& load) {
            return solve_released<Result>([&] { return s.solve(CantileverCase{load}); });
          },
          py::arg("load"));
}

void bind_linear(py::module_& m) {
  py::class_<LinearBeamResult, SolveStatus>(m, "LinearBeamResult")
      .def_readonly("tip", &LinearBeamResult::tip)
      .def_readonly("root_moment", &LinearBeamResult::root_moment)
      .def_readonly("end_moment", &LinearBeamResult::end_moment);
  py::class_<LinearBeamSolver> solver(
      m, "LinearBeamSolver", "Linear (small-deflection) theory of the cantilever, closed form.");
  py::class_<LinearBeamSolver::Options>(solver, "Options", "Nothing to choose (closed form).")
      .def(py::init([]() { return LinearBeamSolver::Options{}; }));
  def_cantilever_solver<LinearBeamSolver, LinearBeamResult>(solver);
  solver.def(
      "shape",
      [](const LinearBeamSolver& s, const CantileverCase& c, const LinearBeamResult& r, int count) {
        return Shape{s.shape(c, r, count)};
      },
      py::arg("problem"),
      py::arg("result"),
      py::arg("count"));
}

void bind_prbm3r(py::module_& m) {
  py::class_<Prbm3rConstants>(
      m, "Prbm3rConstants", "The PR-3R model's link lengths gamma and spring stiffnesses k.")
      .def_static("by_name", &Prbm3rConstants::by_name, py::arg("name"))
      .def_static("names", &Prbm3rConstants::names)
      .def_readonly("gamma", &Prbm3rConstants::gamma)
      .def_readonly("k", &Prbm3rConstants::k)
      .def_readonly("name", &Prbm3rConstants::name)
      .def_readonly("source", &Prbm3rConstants::source)
      .def("__repr__",
           [](const Prbm3rConstants& c) { return fmt::format("Prbm3rConstants('{}')", c.name); });
  py::class_<Prbm3rResult, SolveStatus>(m, "Prbm3rResult")
      .def_readonly("joint_angles", &Prbm3rResult::joint_angles)
      .def_readonly("tip", &Prbm3rResult::tip)
      .def_readonly("root_moment", &Prbm3rResult::root_moment)
      .def_readonly("end_moment", &Prbm3rResult::end_moment)
      .def_readonly("load_steps", &Prbm3rResult::load_steps)
      .def_readonly("load_factor", &Prbm3rResult::load_factor)
      .def_readonly("stable", &Prbm3rResult::stable);
  py::class_<Prbm3rSolver> solver(
      m, "Prbm3rSolver", "The PR-3R pseudo-rigid-body model (Su 2009), proportional loading.");
  using Options = Prbm3rSolver::Options;
  py::class_<Options>(solver, "Options")
      .def(py::init([](const std::string& constants,
                       double tolerance,
                       int max_iterations,
                       int max_load_steps) {
             Options o;
             o.constants = Prbm3rConstants::by_name(constants);
             o.tolerance = tolerance;
             o.max_iterations = max_iterations;
             o.max_load_steps = max_load_steps;
             o.validate();
             return o;
           }),
           py::kw_only(),
           py::arg("constants") = std::string("su"),
           py::arg("tolerance") = Options{}.tolerance,
           py::arg("max_iterations") = Options{}.max_iterations,
           py::arg("max_load_steps") = Options{}.max_load_steps)
      .def_readonly("constants", &Options::constants)
      .def_readonly("tolerance", &Options::tolerance)
      .def_readonly("max_iterations", &Options::max_iterations)
      .def_readonly("max_load_steps", &Options::max_load_steps);
  def_cantilever_solver<Prbm3rSolver, Prbm3rResult>(solver);
  solver.def(
      "shape",
      [](const Prbm3rSolver& s, const Prbm3rResult& r, int count) {
        return Shape{s.shape(r, count)};
      },
      py::arg("result"),
      py::arg("count"));
}

void bind_bcm(py::module_& m) {
  py::class_<BcmResult, SolveStatus>(m, "BcmResult")
      .def_readonly("y", &BcmResult::y)
      .def_readonly("theta", &BcmResult::theta)
      .def_readonly("x", &BcmResult::x)
      .def_readonly("p", &BcmResult::p)
      .def_readonly("f", &BcmResult::f)
      .def_readonly("m", &BcmResult::m)
      .def_readonly("tip", &BcmResult::tip)
      .def_readonly("root_moment", &BcmResult::root_moment)
      .def_readonly("end_moment", &BcmResult::end_moment)
      .def_readonly("inside_validity", &BcmResult::inside_validity);
  py::class_<BcmSolver> solver(
      m,
      "BcmSolver",
      "The beam-constraint model (Awtar et al. 2007) of the cantilever, closed form.");
  using Options = BcmSolver::Options;
  py::class_<Options>(solver, "Options")
      .def(py::init([](double slenderness) {
             Options o;
             o.slenderness = slenderness;
             o.validate();
             return o;
           }),
           py::kw_only(),
           py::arg("slenderness") = Options{}.slenderness)
      .def_readonly("slenderness", &Options::slenderness);
  def_cantilever_solver<BcmSolver, BcmResult>(solver);
  solver.def(
      "shape",
      [](const BcmSolver& s, const BcmResult& r, int count) { return Shape{s.shape(r, count)}; },
      py::arg("result"),
      py::arg("count"));
}

void bind_chained_bcm(py::module_& m) {
  py::class_<CbcmResult, SolveStatus>(m, "CbcmResult")
      .def_readonly("elements", &CbcmResult::elements)
      .def_readonly("load_steps", &CbcmResult::load_steps)
      .def_readonly("load_factor", &CbcmResult::load_factor)
      .def_readonly("tip", &CbcmResult::tip)
      .def_readonly("reaction", &CbcmResult::reaction)
      .def_readonly("tip_load", &CbcmResult::tip_load)
      .def_readonly("root_moment", &CbcmResult::root_moment)
      .def_property_readonly("nodes", [](const CbcmResult& r) { return Shape{r.nodes}; })
      .def_readonly("max_element_deflection", &CbcmResult::max_element_deflection)
      .def_readonly("inside_validity", &CbcmResult::inside_validity)
      .def_readonly("axial_stiffness", &CbcmResult::axial_stiffness)
      .def("tip_pose", &CbcmResult::tip_pose, py::arg("length") = 1.0);
  py::class_<ChainedBcmSolver> solver(
      m,
      "ChainedBcmSolver",
      "The chained beam-constraint model (Ma and Chen 2016): N BCM elements in deflected frames.");
  using Options = ChainedBcmSolver::Options;
  py::class_<Options>(solver, "Options")
      .def(py::init([](int elements,
                       double slenderness,
                       double tolerance,
                       int max_iterations,
                       int max_load_steps) {
             Options o;
             o.elements = elements;
             o.slenderness = slenderness;
             o.tolerance = tolerance;
             o.max_iterations = max_iterations;
             o.max_load_steps = max_load_steps;
             o.validate();
             return o;
           }),
           py::kw_only(),
           py::arg("elements") = Options{}.elements,
           py::arg("slenderness") = Options{}.slenderness,
           py::arg("tolerance") = Options{}.tolerance,
           py::arg("max_iterations") = Options{}.max_iterations,
           py::arg("max_load_steps") = Options{}.max_load_steps)
      .def_readonly("elements", &Options::elements)
      .def_readonly("slenderness", &Options::slenderness)
      .def_readonly("tolerance", &Options::tolerance)
      .def_readonly("max_iterations", &Options::max_iterations)
      .def_readonly("max_load_steps", &Options::max_load_steps);
  def_cantilever_solver<ChainedBcmSolver, CbcmResult>(solver);
  solver.def("model_name", &ChainedBcmSolver::model_name)
      .def(
          "solve",
          [](const ChainedBcmSolver& s, const SegmentChain& chain) {
            return solve_released<CbcmResult>([&] { return s.solve(chain); });
          },
          py::arg("chain"));
}

}  // namespace

void bind_ladder_objects(py::module_& m) {
  bind_cantilever_case(m);
  bind_linear(m);
  bind_prbm3r(m);
  bind_bcm(m);
  bind_chained_bcm(m);
}

}  // namespace flexure::python
