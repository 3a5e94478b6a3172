// flexure._core's classes over the library's own types (docs/python.md "Objects"; issue 28): end
// loads, segments and chains, the elliptic, shooting and chain-algorithm solvers (and the ladder's
// models, python/ladder_objects.cpp) with their
// validated Options, their results (SolveStatus: termination, message, warnings), beam problems
// and solve_beam. Under the C++ names, constructible with keyword arguments (an unknown keyword is
// a TypeError that names it), results read-only. The library's exceptions become the module's
// (InvalidInput -> flexure.InvalidInput, a ValueError; NoConvergence -> flexure.NoConvergence, a
// RuntimeError) and a result's warnings are emitted as FlexureWarning when the call returns.
#include "python/objects.h"

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/physical_beam.h"
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/shooting_solver.h"
#include "python/object_support.h"

namespace py = pybind11;

namespace flexure::python {
namespace {

py::array_t<double> shape_column(const Shape& shape, double ShapePoint::*member) {
  py::array_t<double> out(static_cast<py::ssize_t>(shape.points.size()));
  double* p = out.mutable_data();
  for (const ShapePoint& point : shape.points) *p++ = point.*member;
  return out;
}

py::array_t<double> shape_matrix(const Shape& shape) {
  py::array_t<double> out({static_cast<py::ssize_t>(shape.points.size()), py::ssize_t{4}});
  double* p = out.mutable_data();
  for (const ShapePoint& point : shape.points) {
    *p++ = point.s;
    *p++ = point.x;
    *p++ = point.y;
    *p++ = point.theta;
  }
  return out;
}

void bind_status(py::module_& m) {
  py::enum_<Termination>(m, "Termination", "How a solve ended (solver/common/status.h).")
      .value("converged", Termination::kConverged)
      .value("no_convergence", Termination::kNoConvergence)
      .value("limit_point", Termination::kLimitPoint)
      .value("invalid_input", Termination::kInvalidInput)
      .value("infeasible", Termination::kInfeasible);
  py::enum_<WarningKind>(m, "WarningKind")
      .value("units", WarningKind::kUnits)
      .value("outside_validity", WarningKind::kOutsideValidity)
      .value("stroke_clamped", WarningKind::kStrokeClamped)
      .value("force_vanishes", WarningKind::kForceVanishes)
      .value("yield_", WarningKind::kYield)
      .value("safety_factor", WarningKind::kSafetyFactor)
      .value("design", WarningKind::kDesign)
      .value("other", WarningKind::kOther);
  py::class_<Warning>(m, "Warning", "One warning of a result: its kind and one sentence.")
      .def_readonly("kind", &Warning::kind)
      .def_readonly("text", &Warning::text)
      .def("__repr__", [](const Warning& w) { return fmt::format("Warning('{}')", w.text); });
  py::class_<SolveStatus>(m, "SolveStatus", "What every result says about its solve.")
      .def_readonly("termination", &SolveStatus::termination)
      .def_readonly("message", &SolveStatus::message)
      .def_readonly("iterations", &SolveStatus::iterations)
      .def_readonly("residual", &SolveStatus::residual)
      .def_readonly("warnings", &SolveStatus::warnings)
      .def("converged", &SolveStatus::converged);
  py::enum_<StabilityKind>(m, "StabilityKind")
      .value("stable", StabilityKind::kStable)
      .value("unstable", StabilityKind::kUnstable)
      .value("critical", StabilityKind::kCritical)
      .value("not_conservative", StabilityKind::kNotConservative)
      .value("not_checked", StabilityKind::kNotChecked);
  py::class_<Stability>(m, "Stability", "The stability verdict of an equilibrium.")
      .def_readonly("kind", &Stability::kind)
      .def_readonly("index", &Stability::index)
      .def_readonly("margin", &Stability::margin)
      .def_readonly("message", &Stability::message);
}

void bind_loads(py::module_& m) {
  py::class_<EndLoad>(
      m, "EndLoad", "A tip load per unit EI/l^2: Fx, Fy and the moment mu = M l/EI.")
      .def(py::init([](double Fx, double Fy, double mu) {
             return EndLoad{Fx, Fy, mu};
           }),
           py::kw_only(),
           py::arg("Fx") = 0.0,
           py::arg("Fy") = 0.0,
           py::arg("mu") = 0.0)
      .def_static("howell",
                  &EndLoad::howell,
                  py::arg("n"),
                  py::arg("alpha2"),
                  py::arg("mu") = 0.0,
                  "Howell's load: alpha2 = P l^2/EI, n P compressive along the beam (eq. 2.83).")
      .def_readwrite("Fx", &EndLoad::Fx)
      .def_readwrite("Fy", &EndLoad::Fy)
      .def_readwrite("mu", &EndLoad::mu)
      .def("__repr__", [](const EndLoad& l) {
        return fmt::format("EndLoad(Fx={}, Fy={}, mu={})", l.Fx, l.Fy, l.mu);
      });
  py::class_<TipPose>(m, "TipPose", "The tip as Howell's a/l, b/l and theta0 (rad).")
      .def_readonly("a_over_l", &TipPose::a_over_l)
      .def_readonly("b_over_l", &TipPose::b_over_l)
      .def_readonly("theta0", &TipPose::theta0)
      .def("__repr__", [](const TipPose& t) {
        return fmt::format(
            "TipPose(a_over_l={}, b_over_l={}, theta0={})", t.a_over_l, t.b_over_l, t.theta0);
      });
  py::class_<Reaction>(m, "Reaction", "Forces Fx, Fy and the moment M.")
      .def_readonly("Fx", &Reaction::Fx)
      .def_readonly("Fy", &Reaction::Fy)
      .def_readonly("M", &Reaction::M)
      .def("__repr__", [](const Reaction& r) {
        return fmt::format("Reaction(Fx={}, Fy={}, M={})", r.Fx, r.Fy, r.M);
      });
  py::class_<ChainPose>(m, "ChainPose", "A pose in the root frame: x, y, theta (rad).")
      .def_readonly("x", &ChainPose::x)
      .def_readonly("y", &ChainPose::y)
      .def_readonly("theta", &ChainPose::theta)
      .def("__repr__", [](const ChainPose& p) {
        return fmt::format("ChainPose(x={}, y={}, theta={})", p.x, p.y, p.theta);
      });
  py::class_<Shape>(
      m, "Shape", "A deflected shape: arrays s, x, y, theta; numpy.asarray -> (N, 4).")
      .def_property_readonly("s", [](const Shape& s) { return shape_column(s, &ShapePoint::s); })
      .def_property_readonly("x", [](const Shape& s) { return shape_column(s, &ShapePoint::x); })
      .def_property_readonly("y", [](const Shape& s) { return shape_column(s, &ShapePoint::y); })
      .def_property_readonly("theta",
                             [](const Shape& s) { return shape_column(s, &ShapePoint::theta); })
      .def("__len__", [](const Shape& s) { return s.points.size(); })
      .def(
          "__array__",
          [](const Shape& s, py::object /*dtype*/, py::object /*copy*/) { return shape_matrix(s); },
          py::arg("dtype") = py::none(),
          py::arg("copy") = py::none());
}

void bind_section(py::module_& m) {
  py::class_<Section>(m, "Section", "A cross-section: a rectangle, or a general I (docs/units.md).")
      .def_static("rectangle", &Section::rectangle, py::arg("width"), py::arg("thickness"))
      .def_static("general",
                  &Section::general,
                  py::arg("I"),
                  py::arg("thickness") = std::optional<double>())
      .def_readonly("width", &Section::width)
      .def_readonly("thickness", &Section::thickness)
      .def("second_moment", &Section::second_moment)
      .def("area", &Section::area)
      .def("section_modulus", &Section::section_modulus)
      .def("__repr__", [](const Section& s) {
        return s.shape == Section::Shape::kRectangle
                   ? fmt::format("Section.rectangle(width={}, thickness={})", s.width, s.thickness)
                   : fmt::format("Section.general(I={}, thickness={})", s.I, s.thickness);
      });
  py::class_<Material>(m, "Material", "E, Poisson's ratio nu, yield strength S_y, density.")
      .def(py::init([](double E,
                       double nu,
                       std::optional<double> yield_strength,
                       std::optional<double> density) {
             Material material{E, nu, yield_strength, density};
             material.validate();
             return material;
           }),
           py::kw_only(),
           py::arg("E"),
           py::arg("nu") = 0.3,
           py::arg("yield_strength") = std::optional<double>(),
           py::arg("density") = std::optional<double>())
      .def_readonly("E", &Material::E)
      .def_readonly("nu", &Material::nu)
      .def_readonly("yield_strength", &Material::yield_strength)
      .def_readonly("density", &Material::density)
      .def("__repr__",
           [](const Material& mat) { return fmt::format("Material(E={}, nu={})", mat.E, mat.nu); });
  m.def("flexural_rigidity",
        &flexural_rigidity,
        py::arg("section"),
        py::arg("material"),
        "E I of the section in the material (both validated): E b h^3/12 for a rectangle.");
}

void bind_chain(py::module_& m) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  py::class_<FlexibleSegment>(m, "FlexibleSegment", "A flexible segment of a chain.")
      .def(py::init([](double length,
                       double EI,
                       std::vector<double> EI_profile,
                       double kappa0,
                       double qx,
                       double qy,
                       double q_follower,
                       double EA,
                       double GAs) {
             FlexibleSegment s(length, EI, std::move(EI_profile), kappa0);
             s.qx = qx;
             s.qy = qy;
             s.q_follower = q_follower;
             s.EA = EA;
             s.GAs = GAs;
             return s;
           }),
           py::kw_only(),
           py::arg("length") = 1.0,
           py::arg("EI") = 1.0,
           py::arg("EI_profile") = std::vector<double>(),
           py::arg("kappa0") = 0.0,
           py::arg("qx") = 0.0,
           py::arg("qy") = 0.0,
           py::arg("q_follower") = 0.0,
           py::arg("EA") = kInf,
           py::arg("GAs") = kInf)
      .def_readwrite("length", &FlexibleSegment::length)
      .def_readwrite("EI", &FlexibleSegment::EI)
      .def_readwrite("EI_profile", &FlexibleSegment::EI_profile)
      .def_readwrite("kappa0", &FlexibleSegment::kappa0)
      .def_readwrite("qx", &FlexibleSegment::qx)
      .def_readwrite("qy", &FlexibleSegment::qy)
      .def_readwrite("q_follower", &FlexibleSegment::q_follower)
      .def_readwrite("EA", &FlexibleSegment::EA)
      .def_readwrite("GAs", &FlexibleSegment::GAs)
      .def("__repr__", [](const FlexibleSegment& s) {
        return fmt::format("FlexibleSegment(length={}, EI={})", s.length, s.EI);
      });
  py::class_<RigidSegment>(m, "RigidSegment", "A rigid link (length 0: a kink of angle_offset).")
      .def(py::init([](double length, double angle_offset) {
             return RigidSegment{length, angle_offset};
           }),
           py::kw_only(),
           py::arg("length") = 1.0,
           py::arg("angle_offset") = 0.0)
      .def_readwrite("length", &RigidSegment::length)
      .def_readwrite("angle_offset", &RigidSegment::angle_offset)
      .def("__repr__", [](const RigidSegment& s) {
        return fmt::format("RigidSegment(length={}, angle_offset={})", s.length, s.angle_offset);
      });
  py::class_<NodeLoad>(m, "NodeLoad", "A dead load at joint `node` (1 .. segments - 1).")
      .def(py::init([](int node, double Fx, double Fy, double M) {
             return NodeLoad{node, Fx, Fy, M};
           }),
           py::kw_only(),
           py::arg("node") = 1,
           py::arg("Fx") = 0.0,
           py::arg("Fy") = 0.0,
           py::arg("M") = 0.0)
      .def_readwrite("node", &NodeLoad::node)
      .def_readwrite("Fx", &NodeLoad::Fx)
      .def_readwrite("Fy", &NodeLoad::Fy)
      .def_readwrite("M", &NodeLoad::M);
  py::class_<TipLoad>(m, "TipLoad", "The tip's dead force and moment and a follower force.")
      .def(py::init([](double Fx, double Fy, double M, double follower) {
             return TipLoad{Fx, Fy, M, follower};
           }),
           py::kw_only(),
           py::arg("Fx") = 0.0,
           py::arg("Fy") = 0.0,
           py::arg("M") = 0.0,
           py::arg("follower") = 0.0)
      .def_readwrite("Fx", &TipLoad::Fx)
      .def_readwrite("Fy", &TipLoad::Fy)
      .def_readwrite("M", &TipLoad::M)
      .def_readwrite("follower", &TipLoad::follower)
      .def("__repr__", [](const TipLoad& t) {
        return fmt::format("TipLoad(Fx={}, Fy={}, M={}, follower={})", t.Fx, t.Fy, t.M, t.follower);
      });
  py::enum_<EndCondition>(m, "EndCondition")
      .value("free", EndCondition::kFree)
      .value("guided", EndCondition::kGuided)
      .value("pinned", EndCondition::kPinned)
      .value("slider", EndCondition::kSlider)
      .value("fixed", EndCondition::kFixed);
  py::class_<TipPrescription>(m, "TipPrescription", "Prescribed tip x, y, theta (None: free).")
      .def(py::init(
               [](std::optional<double> x, std::optional<double> y, std::optional<double> theta) {
                 return TipPrescription{x, y, theta};
               }),
           py::kw_only(),
           py::arg("x") = std::optional<double>(),
           py::arg("y") = std::optional<double>(),
           py::arg("theta") = std::optional<double>())
      .def_readwrite("x", &TipPrescription::x)
      .def_readwrite("y", &TipPrescription::y)
      .def_readwrite("theta", &TipPrescription::theta);
  py::class_<SegmentChain>(m, "SegmentChain", "Segments root to tip, their loads and the far end.")
      .def(py::init([](std::vector<Segment> segments,
                       std::vector<NodeLoad> node_loads,
                       TipLoad tip_load,
                       EndCondition end,
                       TipPrescription prescribed) {
             SegmentChain chain{
                 std::move(segments), std::move(node_loads), tip_load, end, prescribed};
             chain.validate();
             return chain;
           }),
           py::kw_only(),
           py::arg("segments"),
           py::arg("node_loads") = std::vector<NodeLoad>(),
           py::arg("tip_load") = TipLoad{},
           py::arg("end") = EndCondition::kFree,
           py::arg("prescribed") = TipPrescription{})
      .def_static("uniform_cantilever", &uniform_cantilever, py::arg("load"))
      .def_readwrite("segments", &SegmentChain::segments)
      .def_readwrite("node_loads", &SegmentChain::node_loads)
      .def_readwrite("tip_load", &SegmentChain::tip_load)
      .def_readwrite("end", &SegmentChain::end)
      .def_readwrite("prescribed", &SegmentChain::prescribed)
      .def("total_length", &SegmentChain::total_length)
      .def("validate", &SegmentChain::validate)
      .def("__repr__", [](const SegmentChain& c) {
        return fmt::format(
            "SegmentChain({} segments, end={})", c.segments.size(), to_string(c.end));
      });
}

void bind_elliptic(py::module_& m) {
  py::enum_<EllipticBranch>(m, "EllipticBranch")
      .value("pure_moment", EllipticBranch::kPureMoment)
      .value("straight", EllipticBranch::kStraight)
      .value("linear_theory", EllipticBranch::kLinearTheory)
      .value("proportional_unique", EllipticBranch::kProportionalUnique)
      .value("proportional_continued", EllipticBranch::kProportionalContinued)
      .value("proportional_tabulated", EllipticBranch::kProportionalTabulated);
  py::class_<EllipticResult, SolveStatus>(m, "EllipticResult")
      .def_readonly("continuation_steps", &EllipticResult::continuation_steps)
      .def_readonly("limit_points", &EllipticResult::limit_points)
      .def_readonly("first_limit_load_factor", &EllipticResult::first_limit_load_factor)
      .def_readonly("load", &EllipticResult::load)
      .def_readonly("tip", &EllipticResult::tip)
      .def_readonly("root_moment", &EllipticResult::root_moment)
      .def_readonly("inflection_points", &EllipticResult::inflection_points)
      .def_readonly("branch_kind", &EllipticResult::branch_kind)
      .def_readonly("branch", &EllipticResult::branch);
  py::class_<EllipticSolver> solver(m, "EllipticSolver", "The elliptic-integral elastica (exact).");
  py::class_<EllipticSolver::Options>(solver, "Options")
      .def(py::init([](double tolerance,
                       int max_iterations,
                       int max_continuation_steps,
                       bool tabulated_predictor) {
             EllipticSolver::Options o;
             o.tolerance = tolerance;
             o.max_iterations = max_iterations;
             o.max_continuation_steps = max_continuation_steps;
             o.tabulated_predictor = tabulated_predictor;
             o.validate();
             return o;
           }),
           py::kw_only(),
           py::arg("tolerance") = EllipticSolver::Options{}.tolerance,
           py::arg("max_iterations") = EllipticSolver::Options{}.max_iterations,
           py::arg("max_continuation_steps") = EllipticSolver::Options{}.max_continuation_steps,
           py::arg("tabulated_predictor") = EllipticSolver::Options{}.tabulated_predictor)
      .def_readonly("tolerance", &EllipticSolver::Options::tolerance)
      .def_readonly("max_iterations", &EllipticSolver::Options::max_iterations)
      .def_readonly("max_continuation_steps", &EllipticSolver::Options::max_continuation_steps)
      .def_readonly("tabulated_predictor", &EllipticSolver::Options::tabulated_predictor);
  solver
      .def(py::init([](const EllipticSolver::Options& options) { return EllipticSolver(options); }),
           py::arg("options") = EllipticSolver::Options{})
      .def_property_readonly("options", &EllipticSolver::options)
      .def(
          "solve",
          [](const EllipticSolver& s, const EndLoad& load) {
            return solve_released<EllipticResult>([&] { return s.solve(load); });
          },
          py::arg("load"))
      .def(
          "solve_for_tip_angle",
          [](const EllipticSolver& s, double n, double theta0, double mu) {
            return solve_released<EllipticResult>(
                [&] { return s.solve_for_tip_angle(n, theta0, mu); });
          },
          py::arg("n"),
          py::arg("theta0"),
          py::arg("mu") = 0.0)
      .def(
          "solve_for_deflection",
          [](const EllipticSolver& s, double n, double b_over_l, double mu) {
            return solve_released<EllipticResult>(
                [&] { return s.solve_for_deflection(n, b_over_l, mu); });
          },
          py::arg("n"),
          py::arg("b_over_l"),
          py::arg("mu") = 0.0)
      .def(
          "shape",
          [](const EllipticSolver& s, const EllipticResult& result, int count) {
            return Shape{s.shape(result, count)};
          },
          py::arg("result"),
          py::arg("count"));
}

void bind_shooting(py::module_& m) {
  py::enum_<ElasticaIntegrator::Backend>(m, "Integrator")
      .value("rk8pd", ElasticaIntegrator::Backend::kRk8pd)
      .value("cvodes", ElasticaIntegrator::Backend::kCvodes)
      .value("dormand_prince", ElasticaIntegrator::Backend::kDormandPrince);
  py::enum_<ShootingStrategy>(m, "ShootingStrategy")
      .value("auto", ShootingStrategy::kAuto)
      .value("continuation", ShootingStrategy::kContinuation)
      .value("direct", ShootingStrategy::kDirect);
  py::enum_<ShootingPath>(m, "ShootingPath")
      .value("direct_newton", ShootingPath::kDirectNewton)
      .value("continuation", ShootingPath::kContinuation)
      .value("two_stage_continuation", ShootingPath::kTwoStageContinuation)
      .value("newton_from_guess", ShootingPath::kNewtonFromGuess)
      .value("from_neighbour", ShootingPath::kFromNeighbour);
  py::class_<ShootingResult, SolveStatus>(m, "ShootingResult")
      .def_readonly("path", &ShootingResult::path)
      .def_readonly("method", &ShootingResult::method)
      .def_readonly("continuation_steps", &ShootingResult::continuation_steps)
      .def_readonly("limit_points", &ShootingResult::limit_points)
      .def_readonly("first_limit_load_factor", &ShootingResult::first_limit_load_factor)
      .def_readonly("bifurcation_points", &ShootingResult::bifurcation_points)
      .def_readonly("load_factor", &ShootingResult::load_factor)
      .def_readonly("tip", &ShootingResult::tip)
      .def_readonly("reaction", &ShootingResult::reaction)
      .def_readonly("tip_load", &ShootingResult::tip_load)
      .def_readonly("inflection_points", &ShootingResult::inflection_points)
      .def_property_readonly("shape", [](const ShootingResult& r) { return Shape{r.shape}; })
      .def("tip_pose", &ShootingResult::tip_pose, py::arg("length") = 1.0);
  py::class_<ShootingSolver> solver(m, "ShootingSolver", "The shooting method with continuation.");
  using Options = ShootingSolver::Options;
  py::class_<Options>(solver, "Options")
      .def(py::init([](double rtol,
                       double atol,
                       ShootingStrategy strategy,
                       ElasticaIntegrator::Backend backend,
                       int shape_points,
                       bool count_inflections) {
             Options o;
             o.rtol = rtol;
             o.atol = atol;
             o.strategy = strategy;
             o.backend = backend;
             o.shape_points = shape_points;
             o.count_inflections = count_inflections;
             o.validate();
             return o;
           }),
           py::kw_only(),
           py::arg("rtol") = Options{}.rtol,
           py::arg("atol") = Options{}.atol,
           py::arg("strategy") = Options{}.strategy,
           py::arg("backend") = Options{}.backend,
           py::arg("shape_points") = Options{}.shape_points,
           py::arg("count_inflections") = Options{}.count_inflections)
      .def_readonly("rtol", &Options::rtol)
      .def_readonly("atol", &Options::atol)
      .def_readonly("strategy", &Options::strategy)
      .def_readonly("backend", &Options::backend)
      .def_readonly("shape_points", &Options::shape_points)
      .def_readonly("count_inflections", &Options::count_inflections);
  solver
      .def(py::init([](const Options& options) {
             options.validate();
             return ShootingSolver(options);
           }),
           py::arg("options") = Options{})
      .def_property_readonly("options", &ShootingSolver::options)
      .def(
          "solve",
          [](const ShootingSolver& s, const SegmentChain& chain) {
            return solve_released<ShootingResult>([&] { return s.solve(chain); });
          },
          py::arg("chain"))
      .def(
          "solve",
          [](const ShootingSolver& s, const EndLoad& load) {
            return solve_released<ShootingResult>([&] { return s.solve(load); });
          },
          py::arg("load"));
}

void bind_chain_algorithm(py::module_& m) {
  py::enum_<ChainVariant>(m, "ChainVariant")
      .value("howell", ChainVariant::kHowell)
      .value("corrected", ChainVariant::kCorrected);
  py::class_<ChainResult, SolveStatus>(m, "ChainResult")
      .def_readonly("increments", &ChainResult::increments)
      .def_readonly("load_factor", &ChainResult::load_factor)
      .def_readonly("elements", &ChainResult::elements)
      .def_readonly("tip", &ChainResult::tip)
      .def_readonly("tip_pose", &ChainResult::tip_pose)
      .def_readonly("root_reaction", &ChainResult::root_reaction)
      .def_readonly("root_moment", &ChainResult::root_moment)
      .def_property_readonly("nodes", [](const ChainResult& r) { return Shape{r.nodes}; })
      .def_readonly("stability", &ChainResult::stability);
  py::class_<ChainAlgorithmSolver> solver(m, "ChainAlgorithmSolver", "Howell's chain algorithm.");
  using Options = ChainAlgorithmSolver::Options;
  py::class_<Options>(solver, "Options")
      .def(py::init([](int elements, int increments, ChainVariant variant, double tolerance) {
             Options o;
             o.elements = elements;
             o.increments = increments;
             o.variant = variant;
             o.tolerance = tolerance;
             o.validate();
             return o;
           }),
           py::kw_only(),
           py::arg("elements") = Options{}.elements,
           py::arg("increments") = Options{}.increments,
           py::arg("variant") = Options{}.variant,
           py::arg("tolerance") = Options{}.tolerance)
      .def_readonly("elements", &Options::elements)
      .def_readonly("increments", &Options::increments)
      .def_readonly("variant", &Options::variant)
      .def_readonly("tolerance", &Options::tolerance);
  solver
      .def(py::init([](const Options& options) {
             options.validate();
             return ChainAlgorithmSolver(options);
           }),
           py::arg("options") = Options{})
      .def_property_readonly("options", &ChainAlgorithmSolver::options)
      .def(
          "solve",
          [](const ChainAlgorithmSolver& s, const SegmentChain& chain) {
            return solve_released<ChainResult>([&] { return s.solve(chain); });
          },
          py::arg("chain"))
      .def(
          "solve",
          [](const ChainAlgorithmSolver& s, const EndLoad& load) {
            return solve_released<ChainResult>([&] { return s.solve(load); });
          },
          py::arg("load"));
}

void bind_beam(py::module_& m) {
  py::enum_<BeamMethod>(m, "BeamMethod")
      .value("auto", BeamMethod::kAuto)
      .value("elliptic", BeamMethod::kElliptic)
      .value("shooting", BeamMethod::kShooting)
      .value("chain", BeamMethod::kChain)
      .value("prbm", BeamMethod::kPrbm)
      .value("linear", BeamMethod::kLinear)
      .value("prbm3r", BeamMethod::kPrbm3r)
      .value("bcm", BeamMethod::kBcm)
      .value("cbcm", BeamMethod::kCbcm);
  py::class_<BeamProblem>(m,
                          "BeamProblem",
                          "A cantilever problem: exactly one of alpha2, theta0, b_over_l (or a "
                          "chain), with n, mu, the far end and the method settings.")
      .def(py::init([](std::optional<double> alpha2,
                       std::optional<double> theta0,
                       std::optional<double> b_over_l,
                       double n,
                       double mu,
                       EndCondition boundary,
                       TipPrescription prescribed,
                       double follower,
                       std::optional<SegmentChain> chain,
                       double tolerance,
                       int shape_points,
                       bool judge_stability) {
             const int given = alpha2.has_value() + theta0.has_value() + b_over_l.has_value();
             if (chain ? given != 0 : given != 1) {
               throw InvalidInput(
                   chain ? "BeamProblem: a chain describes its loads; give none of alpha2, theta0 "
                           "and b_over_l"
                         : "BeamProblem: give exactly one of alpha2, theta0 and b_over_l (or a "
                           "chain)");
             }
             BeamProblem p;
             if (alpha2) {
               p.given = BeamProblem::Given::kAlpha2;
               p.value = *alpha2;
             } else if (theta0) {
               p.given = BeamProblem::Given::kTheta0;
               p.value = *theta0;
             } else if (b_over_l) {
               p.given = BeamProblem::Given::kBOverL;
               p.value = *b_over_l;
             }
             p.load_ratio_n = n;
             p.mu = mu;
             p.boundary = chain ? chain->end : boundary;
             p.prescribed = prescribed;
             p.follower = follower;
             p.chain = std::move(chain);
             p.tolerance = tolerance;
             p.shape_points = shape_points;
             p.judge_stability = judge_stability;
             return p;
           }),
           py::kw_only(),
           py::arg("alpha2") = std::optional<double>(),
           py::arg("theta0") = std::optional<double>(),
           py::arg("b_over_l") = std::optional<double>(),
           py::arg("n") = 0.0,
           py::arg("mu") = 0.0,
           py::arg("boundary") = EndCondition::kFree,
           py::arg("prescribed") = TipPrescription{},
           py::arg("follower") = 0.0,
           py::arg("chain") = std::optional<SegmentChain>(),
           py::arg("tolerance") = 1e-6,
           py::arg("shape_points") = 0,
           py::arg("judge_stability") = true)
      .def_readonly("value", &BeamProblem::value)
      .def_readonly("n", &BeamProblem::load_ratio_n)
      .def_readonly("mu", &BeamProblem::mu)
      .def_readonly("boundary", &BeamProblem::boundary)
      .def_readonly("chain", &BeamProblem::chain)
      .def_readonly("tolerance", &BeamProblem::tolerance);
  py::class_<BeamSolution, SolveStatus>(m, "BeamSolution")
      .def_readonly("method", &BeamSolution::method)
      .def_readonly("method_reason", &BeamSolution::method_reason)
      .def_readonly("expected_error", &BeamSolution::expected_error)
      .def_readonly("alpha2", &BeamSolution::alpha2)
      .def_readonly("n", &BeamSolution::load_ratio_n)
      .def_readonly("mu", &BeamSolution::mu)
      .def_readonly("tip", &BeamSolution::tip)
      .def_readonly("branch", &BeamSolution::branch)
      .def_readonly("inflection_points", &BeamSolution::inflection_points)
      .def_readonly("root_moment", &BeamSolution::root_moment)
      .def_readonly("family", &BeamSolution::family)
      .def_readonly("reactions", &BeamSolution::reactions)
      .def_readonly("load_factor", &BeamSolution::load_factor)
      .def_readonly("limit_points", &BeamSolution::limit_points)
      .def_readonly("stability", &BeamSolution::stability)
      .def_property_readonly("shape", [](const BeamSolution& s) { return Shape{s.shape}; });
  m.def(
      "solve_beam",
      [](const BeamProblem& problem, BeamMethod method) {
        return solve_released<BeamSolution>([&] { return solve_beam(method, problem); });
      },
      py::arg("problem"),
      py::arg("method") = BeamMethod::kAuto,
      "Solves a beam problem by `method` (auto: the cheapest method within problem.tolerance).");
}

void bind_physical(py::module_& m) {
  py::class_<SegmentProperties>(
      m, "SegmentProperties", "The section and material of a flexible segment in SI units.")
      .def(py::init([](Section section,
                       Material material,
                       std::optional<double> area,
                       const std::string& plate) {
             SegmentProperties out{section, material, area};
             out.plate = plate_rule_from_string(plate, "plate");
             return out;
           }),
           py::kw_only(),
           py::arg("section"),
           py::arg("material"),
           py::arg("area") = std::optional<double>(),
           py::arg("plate") = "off",
           "plate: the bending modulus (docs/plate-modulus.md): \"off\" (E), \"on\" "
           "(E/(1 - nu^2) with material.nu; the segment's EI must then be E I/(1 - nu^2)) or "
           "\"auto\" (EI = E I, decided by the Searle parameter when solving; rectangles only)")
      .def_readonly("section", &SegmentProperties::section)
      .def_readonly("material", &SegmentProperties::material)
      .def_readonly("area", &SegmentProperties::area)
      .def_property_readonly(
          "plate", [](const SegmentProperties& p) { return std::string(to_string(p.plate)); })
      .def("chain_modulus",
           &SegmentProperties::chain_modulus,
           "E, or E/(1 - nu^2) with plate \"on\": the modulus the segment's EI is made of.");
  py::class_<PhysicalChain>(m, "PhysicalChain", "A segment chain in SI units with its sections.")
      .def(py::init([](SegmentChain chain,
                       std::vector<std::optional<SegmentProperties>> segments,
                       std::optional<double> yield_strength) {
             PhysicalChain out{std::move(chain), std::move(segments), yield_strength};
             out.validate();
             return out;
           }),
           py::kw_only(),
           py::arg("chain"),
           py::arg("segments"),
           py::arg("yield_strength") = std::optional<double>())
      .def_readonly("chain", &PhysicalChain::chain)
      .def_readonly("segments", &PhysicalChain::segments)
      .def_readonly("yield_strength", &PhysicalChain::yield_strength);
  py::class_<PhysicalResults>(m, "PhysicalResults", "The answer in SI units.")
      .def_readonly("length", &PhysicalResults::length)
      .def_readonly("tip_x", &PhysicalResults::tip_x)
      .def_readonly("tip_y", &PhysicalResults::tip_y)
      .def_readonly("theta0", &PhysicalResults::theta0)
      .def_readonly("root_moment", &PhysicalResults::root_moment)
      .def_readonly("max_moment", &PhysicalResults::max_moment)
      .def_readonly("max_moment_at", &PhysicalResults::max_moment_at)
      .def_readonly("max_stress", &PhysicalResults::max_stress)
      .def_readonly("max_stress_at", &PhysicalResults::max_stress_at)
      .def_readonly("safety_factor", &PhysicalResults::safety_factor)
      .def_readonly("yield_strength", &PhysicalResults::yield_strength);
  py::class_<PhysicalBeamSolution>(m, "PhysicalBeamSolution")
      .def_readonly("solution", &PhysicalBeamSolution::solution)
      .def_readonly("physical", &PhysicalBeamSolution::physical)
      .def_property_readonly(
          "status",
          [](const PhysicalBeamSolution& p) -> const SolveStatus& { return p.status(); },
          py::return_value_policy::reference_internal)
      .def("converged", &PhysicalBeamSolution::converged);
  m.def(
      "solve_physical_chain",
      [](const PhysicalChain& chain, BeamMethod method, double tolerance, int shape_points) {
        BeamProblem problem;
        problem.tolerance = tolerance;
        problem.shape_points = shape_points;
        std::optional<PhysicalBeamSolution> out;
        {
          py::gil_scoped_release release;
          out.emplace(solve_physical_chain(method, problem, chain));
        }
        emit_warnings(out->solution);
        return std::move(*out);
      },
      py::arg("chain"),
      py::arg("method") = BeamMethod::kAuto,
      py::arg("tolerance") = 1e-6,
      py::arg("shape_points") = 0,
      "Solves a physical chain: the answer, and its tip, moments, stress and safety factor in SI.");
}

}  // namespace

void bind_objects(py::module_& m) {
  // The library's exceptions as the module's (the Python half defines the classes).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      PyErr_SetString(module_class("InvalidInput").ptr(), e.what());
    } catch (const NoConvergence& e) {
      PyErr_SetString(module_class("NoConvergence").ptr(), e.what());
    }
  });
  bind_status(m);
  bind_loads(m);
  bind_section(m);
  bind_chain(m);
  bind_elliptic(m);
  bind_shooting(m);
  bind_chain_algorithm(m);
  bind_beam(m);
  bind_physical(m);
  bind_ladder_objects(m);
  bind_mechanism_objects(m);
  bind_catalogue_objects(m);
  bind_design_objects(m);
}

}  // namespace flexure::python
