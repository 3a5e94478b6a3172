#include "flexure/io/general_mechanism_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>

#include "flexure/io/platform/provenance.h"
#include "flexure/solver/common/enum_names.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

using mechanism::general::FlexureModelReport;
using mechanism::general::GeneralPrbmPoint;
using mechanism::general::GeneralPrbmResult;
using mechanism::general::Input;
using mechanism::general::InputCoordinate;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <typename F>
std::vector<double> per_point(const GeneralPrbmResult& r, F value) {
  std::vector<double> out;
  out.reserve(r.points.size());
  for (const GeneralPrbmPoint& p : r.points) out.push_back(value(p));
  return out;
}

template <typename F>
std::vector<int> codes_per_point(const GeneralPrbmResult& r, F value) {
  std::vector<int> out;
  out.reserve(r.points.size());
  for (const GeneralPrbmPoint& p : r.points) out.push_back(static_cast<int>(value(p).kind));
  return out;
}

// The meanings of the `stability` codes (StabilityKind in its enum order), as the constant-force
// stroke's file gives them.
std::vector<CodeMeaning> stability_code_meanings() {
  std::vector<CodeMeaning> codes;
  for (const char* name : {"stability_displacement_control", "stability_force_control"}) {
    codes.push_back({name, 0, "stable: the potential energy has a strict minimum"});
    codes.push_back({name, 1, "unstable: some direction in which the energy decreases"});
    codes.push_back(
        {name, 2, "critical: the lowest eigenvalue is zero within 1e-6 (a limit point)"});
    codes.push_back({name, 3, "not_conservative: never for a mechanism"});
    codes.push_back({name, 4, "not_checked: no verdict at this point"});
  }
  return codes;
}

// input, input_load, energy and the stability of every point of one model into `g`.
void write_path(Hdf5Group& g, const GeneralPrbmResult& r, const Input& in, const std::string& who) {
  const std::string unit = general_input_unit(in), load_unit = general_input_load_unit(in);
  const std::vector<double> input = per_point(r, [](const auto& p) { return p.input; });
  const std::vector<double> load = per_point(r, [](const auto& p) { return p.input_load; });
  const std::vector<double> energy = per_point(r, [](const auto& p) { return p.energy; });
  g.write_dataset("input",
                  std::span<const double>(input),
                  unit,
                  fmt::format("{}: the input coordinate ({} of body {}) at each point, in path "
                              "order",
                              who,
                              input_coordinate_name(in.coordinate),
                              in.body));
  g.write_dataset("input_load",
                  std::span<const double>(load),
                  load_unit,
                  fmt::format("{}: the {} that holds the input there (dV/ds, virtual work)",
                              who,
                              in.coordinate == InputCoordinate::kAngle ? "moment" : "force"));
  g.write_dataset("energy",
                  std::span<const double>(energy),
                  "J",
                  who +
                      ": potential energy (springs minus the dead loads' work); NaN where a "
                      "flexure's model has no shape energy");
  for (const char* control : {"displacement_control", "force_control"}) {
    const bool dc = std::string(control) == "displacement_control";
    auto pick = [dc](const GeneralPrbmPoint& p) -> const Stability& {
      return dc ? p.displacement_control : p.force_control;
    };
    const std::vector<int> kind = codes_per_point(r, pick);
    const std::vector<double> margin = per_point(r, [&](const auto& p) { return pick(p).margin; });
    const std::string held = dc ? "with the input held"
                                : "under a dead input load equal to its "
                                  "load there";
    g.write_dataset(std::string("stability_") + control,
                    std::span<const int>(kind),
                    "1",
                    fmt::format("{}: verdict per point {}: 0 stable, 1 unstable, 2 critical, 4 not "
                                "checked (root status_meanings)",
                                who,
                                held));
    g.write_dataset(std::string("stability_") + control + "_margin",
                    std::span<const double>(margin),
                    "1",
                    who +
                        ": lowest eigenvalue of the energy's Hessian on the constraint manifold "
                        "relative to the springs' unloaded stiffness (1 unloaded, 0 critical)");
  }
}

void write_equilibria_and_limits(Hdf5Group& g, const GeneralPrbmResult& r, const Input& in) {
  const std::string unit = general_input_unit(in), load_unit = general_input_load_unit(in);
  Hdf5Group eq = g.create_group("equilibria");
  std::vector<double> input, energy, margin;
  std::vector<int> kind;
  for (const auto& e : r.equilibria) {
    input.push_back(e.input);
    energy.push_back(e.energy);
    kind.push_back(static_cast<int>(e.stability.kind));
    margin.push_back(e.stability.margin);
  }
  eq.write_dataset("input",
                   std::span<const double>(input),
                   unit,
                   "the input at each equilibrium of the unloaded mechanism (zero input load)");
  eq.write_dataset("energy", std::span<const double>(energy), "J", "its potential energy");
  eq.write_dataset("stability_force_control",
                   std::span<const int>(kind),
                   "1",
                   "its verdict with the input free: 0 stable, 1 unstable, 2 critical");
  eq.write_dataset("stability_force_control_margin",
                   std::span<const double>(margin),
                   "1",
                   "its lowest eigenvalue relative to the springs' unloaded stiffness");
  Hdf5Group lim = g.create_group("limit_points");
  lim.write_dataset("input",
                    std::span<const double>(r.limit_inputs),
                    unit,
                    "the input at each limit point of the controlled quantity along the path");
  lim.write_dataset(
      "input_load", std::span<const double>(r.limit_loads), load_unit, "the input load there");
}

void write_bodies(Hdf5Group& g, const GeneralPrbmResult& r) {
  if (r.body_names.empty() || r.points.empty()) return;
  Hdf5Group b = g.create_group("bodies");
  const std::size_t n = r.points.size(), m = r.body_names.size();
  b.write_dataset("name", r.body_names, "text", "the described moving bodies, in column order");
  for (const char* which : {"x", "y", "phi"}) {
    std::vector<double> values;
    values.reserve(n * m);
    for (const GeneralPrbmPoint& p : r.points) {
      const std::vector<double>& v = std::string(which) == "x"   ? p.body_x
                                     : std::string(which) == "y" ? p.body_y
                                                                 : p.body_phi;
      for (std::size_t k = 0; k < m; ++k) values.push_back(k < v.size() ? v[k] : kNaN);
    }
    const bool angle = std::string(which) == "phi";
    b.write_dataset(which,
                    std::span<const double>(values),
                    {static_cast<hsize_t>(n), static_cast<hsize_t>(m)},
                    angle ? "rad" : "m",
                    fmt::format("[point, body]: each body's {} from the described configuration",
                                angle ? "rotation" : std::string(which) + " displacement"));
  }
}

// The joints' positions and reactions, the ground's reaction and every flexure's end loads,
// largest stress and shape per point (GeneralPrbmPoint; docs/hdf5-schema.md).
void write_point_loads(
    Hdf5Group& g,
    const std::string& prefix,
    const GeneralPrbmResult& r,
    const std::function<const mechanism::general::PointLoad&(const GeneralPrbmPoint&)>& pick,
    const std::string& what) {
  g.write_dataset(prefix + "fx",
                  std::span<const double>(per_point(r, [&](const auto& p) { return pick(p).fx; })),
                  "N",
                  what + ": force, x");
  g.write_dataset(prefix + "fy",
                  std::span<const double>(per_point(r, [&](const auto& p) { return pick(p).fy; })),
                  "N",
                  what + ": force, y");
  g.write_dataset(
      prefix + "moment",
      std::span<const double>(per_point(r, [&](const auto& p) { return pick(p).moment; })),
      "N m",
      what + ": moment (counter-clockwise)");
}

void write_point_results(Hdf5Group& g,
                         const GeneralPrbmResult& r,
                         const mechanism::general::GeneralMechanism& m) {
  if (r.points.empty()) return;
  Hdf5Group ground = g.create_group("ground_reaction");
  write_point_loads(
      ground,
      "",
      r,
      [](const GeneralPrbmPoint& p) -> const mechanism::general::PointLoad& {
        return p.ground_reaction;
      },
      "the load the ground puts on the mechanism per point (moment about the origin)");
  auto all_have = [&](auto member, std::size_t k) {
    return std::all_of(
        r.points.begin(), r.points.end(), [&](const auto& p) { return k < (p.*member).size(); });
  };
  Hdf5Group joints = g.create_group("joints");
  for (std::size_t k = 0; k < m.joints.size(); ++k) {
    if (!all_have(&GeneralPrbmPoint::joints, k)) break;
    Hdf5Group j = joints.create_group(m.joints[k].name);
    j.set_attribute("kind", std::string(joint_kind_name(m.joints[k].kind)));
    j.write_dataset(
        "x",
        std::span<const double>(per_point(r, [&](const auto& p) { return p.joints[k].x; })),
        "m",
        "x of the joint's point of body b per point");
    j.write_dataset(
        "y",
        std::span<const double>(per_point(r, [&](const auto& p) { return p.joints[k].y; })),
        "m",
        "y of that point per point");
    write_point_loads(
        j,
        "on_b_",
        r,
        [k](const GeneralPrbmPoint& p) -> const mechanism::general::PointLoad& {
          return p.joints[k].on_b;
        },
        "the load body a puts on body b through the joint, at its point");
  }
  Hdf5Group flexures = g.create_group("flexures");
  for (std::size_t k = 0; k < m.flexures.size(); ++k) {
    if (!all_have(&GeneralPrbmPoint::flexures, k)) break;
    Hdf5Group f = flexures.create_group(m.flexures[k].name);
    f.set_attribute("max_stress_from", std::string(r.points.front().flexures[k].max_from));
    auto series = [&](const char* name, auto value, const char* unit, const std::string& what) {
      f.write_dataset(
          name,
          std::span<const double>(per_point(
              r, [&](const auto& p) { return static_cast<double>(value(p.flexures[k])); })),
          unit,
          what);
    };
    using FR = mechanism::general::FlexurePointResult;
    series(
        "max_stress",
        [](const FR& x) { return x.max_stress; },
        "Pa",
        "the largest |N_a/A -+ m c/I| along the flexure, both fibres");
    series(
        "max_stress_at",
        [](const FR& x) { return x.max_stress_at; },
        "m",
        "where it acts: arc length from end a");
    series(
        "max_stress_fibre",
        [](const FR& x) { return x.max_stress_fibre; },
        "1",
        "+1: the fibre h/2 on the +n side (left of the tangent), -1 the other");
    series(
        "stress_pos_fibre",
        [](const FR& x) { return x.stress_pos_fibre; },
        "Pa",
        "N_a/A - m c/I at that section");
    series(
        "stress_neg_fibre",
        [](const FR& x) { return x.stress_neg_fibre; },
        "Pa",
        "N_a/A + m c/I at that section");
    series(
        "moment", [](const FR& x) { return x.moment; }, "N m", "bending moment at that section");
    series(
        "axial_force",
        [](const FR& x) { return x.axial_force; },
        "N",
        "axial force N . t at that section (tension positive)");
    write_point_loads(
        f,
        "on_a_",
        r,
        [k](const GeneralPrbmPoint& p) -> const mechanism::general::PointLoad& {
          return p.flexures[k].on_a;
        },
        "the load the flexure puts on body a at end a");
    write_point_loads(
        f,
        "on_b_",
        r,
        [k](const GeneralPrbmPoint& p) -> const mechanism::general::PointLoad& {
          return p.flexures[k].on_b;
        },
        "the load the flexure puts on body b at end b");
    std::size_t samples = 0;
    for (const GeneralPrbmPoint& p : r.points) {
      samples = std::max(samples, p.flexures[k].shape_x.size());
    }
    if (samples == 0) continue;
    for (const char* which : {"shape_x", "shape_y"}) {
      std::vector<double> values;
      values.reserve(r.points.size() * samples);
      for (const GeneralPrbmPoint& p : r.points) {
        const std::vector<double>& v =
            std::string(which) == "shape_x" ? p.flexures[k].shape_x : p.flexures[k].shape_y;
        for (std::size_t i = 0; i < samples; ++i) values.push_back(i < v.size() ? v[i] : kNaN);
      }
      f.write_dataset(which,
                      std::span<const double>(values),
                      {static_cast<hsize_t>(r.points.size()), static_cast<hsize_t>(samples)},
                      "m",
                      fmt::format("[point, sample]: the flexure's {} from end a to end b, global "
                                  "(the exact model: the elastica at equal arc lengths; the PRBM: "
                                  "its PRB linkage's joints; a ladder model: the chord)",
                                  which[6]));
    }
  }
}

// The described configuration, for drawing the mechanism at any point: every named point of every
// body (the ground's too), each moving body's pose reference (the centroid of its points, as the
// assembly's: prbm_assembly.cpp) and each flexure's ends and end conditions. A point q of body B
// sits at reference + (x, y) + R(phi) (q - reference) at a point whose pose of B is (x, y, phi).
void write_geometry(Hdf5Group& root, const mechanism::general::GeneralMechanism& m) {
  Hdf5Group geo = root.create_group("geometry");
  geo.set_attribute("description",
                    "the described (as-made) configuration: bodies' named points, pose "
                    "references and flexure ends; docs/hdf5-schema.md");
  std::vector<std::string> point_body, point_name, body_name;
  std::vector<double> px, py, rx, ry;
  for (const mechanism::general::Body& b : m.bodies) {
    double cx = 0.0, cy = 0.0;
    for (const mechanism::general::NamedPoint& q : b.points) {
      point_body.push_back(b.name);
      point_name.push_back(q.name);
      px.push_back(q.position.x);
      py.push_back(q.position.y);
      cx += q.position.x;
      cy += q.position.y;
    }
    if (b.name == "ground") continue;
    const double n = b.points.empty() ? 1.0 : static_cast<double>(b.points.size());
    body_name.push_back(b.name);
    rx.push_back(cx / n);
    ry.push_back(cy / n);
  }
  Hdf5Group points = geo.create_group("points");
  points.write_dataset("body", point_body, "text", "the body of each named point");
  points.write_dataset("name", point_name, "text", "the point's name");
  points.write_dataset("x", std::span<const double>(px), "m", "x in the described configuration");
  points.write_dataset("y", std::span<const double>(py), "m", "y in the described configuration");
  Hdf5Group bodies = geo.create_group("bodies");
  bodies.write_dataset("name", body_name, "text", "the described moving bodies");
  bodies.write_dataset("reference_x",
                       std::span<const double>(rx),
                       "m",
                       "x of the point whose displacement the pose gives (the centroid of the "
                       "body's points), described configuration");
  bodies.write_dataset(
      "reference_y", std::span<const double>(ry), "m", "y of that point, described configuration");
  std::vector<std::string> f_name, f_a, f_b, f_end;
  std::vector<double> ax, ay, bx, by, length, curvature;
  for (const mechanism::general::Flexure& f : m.flexures) {
    const mechanism::general::Vec2 a = m.point(f.a), b = m.point(f.b);
    f_name.push_back(f.name);
    f_a.push_back(f.a.body);
    f_b.push_back(f.b.body);
    // The far end is a pin for a fixed-pinned flexure in both models (general_analysis.h).
    f_end.emplace_back(f.prbm == mechanism::general::PrbmKind::kFixedPinned ? "pinned" : "clamped");
    ax.push_back(a.x);
    ay.push_back(a.y);
    bx.push_back(b.x);
    by.push_back(b.y);
    length.push_back(f.arc_length(std::hypot(b.x - a.x, b.y - a.y)));
    curvature.push_back(f.curvature);
  }
  Hdf5Group flexures = geo.create_group("flexures");
  flexures.write_dataset("name", f_name, "text", "each flexure");
  flexures.write_dataset("body_a", f_a, "text", "the body its root (end a) is clamped into");
  flexures.write_dataset("body_b", f_b, "text", "the body of its far end (end b)");
  flexures.write_dataset("end_b", f_end, "text", "clamped or pinned into body b");
  flexures.write_dataset("a_x", std::span<const double>(ax), "m", "end a, described");
  flexures.write_dataset("a_y", std::span<const double>(ay), "m", "end a, described");
  flexures.write_dataset("b_x", std::span<const double>(bx), "m", "end b, described");
  flexures.write_dataset("b_y", std::span<const double>(by), "m", "end b, described");
  flexures.write_dataset("length", std::span<const double>(length), "m", "its length");
  flexures.write_dataset("curvature",
                         std::span<const double>(curvature),
                         "1/m",
                         "its stress-free curvature (0: straight; else an arc from a to b)");
}

void write_flexure_models(Hdf5Group& g,
                          const std::vector<FlexureModelReport>& reports,
                          bool checked) {
  if (reports.empty()) return;
  Hdf5Group all = g.create_group("flexure_models");
  for (const FlexureModelReport& r : reports) {
    Hdf5Group f = all.create_group(r.name);
    f.set_attribute("requested", std::string(flexure_model_name(r.requested)));
    f.set_attribute("model", std::string(flexure_model_name(r.model)));
    f.set_attribute("method_reason", r.reason);
    f.set_attribute("expected_error_per_length", r.expected_error_per_length);
    f.set_attribute("unmapped_points", static_cast<std::int64_t>(r.unmapped_points));
    if (r.requested == mechanism::general::FlexureModel::kAuto) {
      f.set_attribute("tolerance", r.tolerance);
    }
    std::vector<double> fx, fy, mu;
    for (const auto& l : r.loads) {
      fx.push_back(l.Fx);
      fy.push_back(l.Fy);
      mu.push_back(l.mu);
    }
    f.write_dataset("tip_load_Fx",
                    std::span<const double>(fx),
                    "1",
                    "tip force along the flexure's chord per point, F l^2/EI");
    f.write_dataset("tip_load_Fy",
                    std::span<const double>(fy),
                    "1",
                    "tip force across the flexure per point, F l^2/EI");
    f.write_dataset(
        "tip_load_mu", std::span<const double>(mu), "1", "tip moment per point, M l/EI");
    f.write_dataset("mapped_error_per_length",
                    std::span<const double>(r.mapped_error),
                    "1",
                    "the model's mapped tip error per length at each point (NaN: not mapped)");
    if (checked) {
      f.set_attribute("measured_error_per_length", r.measured_error_per_length);
      f.write_dataset("measured_error_per_length",
                      std::span<const double>(r.measured_error),
                      "1",
                      "|model tip - elastica tip| per length under the same loads, per point");
    }
  }
}

CsvColumn numbers(std::string name, std::string unit, std::vector<double> values) {
  CsvColumn c{std::move(name), std::move(unit), std::move(values), {}};
  return c;
}

CsvColumn texts(std::string name, std::vector<std::string> values) {
  CsvColumn c{std::move(name), "text", {}, std::move(values)};
  return c;
}

// The columns of one model's path, prefixed by `prefix` ("" or "exact/").
void add_path_columns(std::vector<CsvColumn>& columns,
                      const GeneralPrbmResult& r,
                      const Input& in,
                      const std::string& prefix,
                      bool with_input) {
  if (with_input) {
    columns.push_back(numbers(prefix + "input",
                              general_input_unit(in),
                              per_point(r, [](const auto& p) { return p.input; })));
  }
  columns.push_back(numbers(prefix + "input_load",
                            general_input_load_unit(in),
                            per_point(r, [](const auto& p) { return p.input_load; })));
  columns.push_back(
      numbers(prefix + "energy", "J", per_point(r, [](const auto& p) { return p.energy; })));
  for (const char* control : {"displacement_control", "force_control"}) {
    const bool dc = std::string(control) == "displacement_control";
    std::vector<std::string> kind;
    std::vector<double> margin;
    for (const GeneralPrbmPoint& p : r.points) {
      const Stability& s = dc ? p.displacement_control : p.force_control;
      kind.emplace_back(stability_name(s.kind));
      margin.push_back(s.margin);
    }
    columns.push_back(texts(prefix + "stability_" + control, std::move(kind)));
    columns.push_back(numbers(prefix + "stability_" + control + "_margin", "1", std::move(margin)));
  }
}

constexpr std::array<const char*, 4> kGeneralAnalysisModelNames = {
    "prbm", "exact", "both", "mixed"};

void check(const GeneralAnalysisOutput& out) {
  if (out.mechanism == nullptr || out.results.empty()) {
    throw std::invalid_argument("general mechanism output: no mechanism or no model solved");
  }
}

}  // namespace

const char* to_string(GeneralAnalysisModel model) {
  return enum_name(kGeneralAnalysisModelNames, model);
}

GeneralAnalysisModel general_analysis_model_from_string(std::string_view name) {
  return enum_from_name<GeneralAnalysisModel>(kGeneralAnalysisModelNames, name, "model");
}

std::vector<double> design_stroke_displacement(const GeneralPrbmResult& r, double x0) {
  return per_point(r, [x0](const GeneralPrbmPoint& p) { return x0 - p.input; });
}

std::vector<double> design_stroke_force(const GeneralPrbmResult& r) {
  return per_point(r, [](const GeneralPrbmPoint& p) { return -p.input_load; });
}

std::string general_input_unit(const Input& input) {
  return input.coordinate == InputCoordinate::kAngle ? "rad" : "m";
}

std::string general_input_load_unit(const Input& input) {
  return input.coordinate == InputCoordinate::kAngle ? "N m" : "N";
}

void write_general_mechanism(Hdf5Group& root, const GeneralAnalysisOutput& out) {
  check(out);
  const mechanism::general::GeneralMechanism& m = *out.mechanism;
  const Input& in = m.input;
  const GeneralPrbmResult& first = *out.results.front().second;
  root.set_attribute("mechanism", m.name);
  root.set_attribute("form", "general");
  root.set_attribute("model", std::string(to_string(out.model)));
  root.set_attribute("first_model", out.results.front().first);
  root.set_attribute("input_body", in.body);
  root.set_attribute("input_coordinate", std::string(input_coordinate_name(in.coordinate)));
  root.set_attribute("control", std::string(input_control_name(in.control)));
  root.set_attribute("input_unit", general_input_unit(in));
  root.set_attribute("input_load_unit", general_input_load_unit(in));
  root.set_attribute("degrees_of_freedom", static_cast<std::int64_t>(first.degrees_of_freedom));
  if (out.design_x0) {
    // The slider force of one half, as `mechanism analyze` reports a built-in design.
    root.set_attribute("force_of", "one half");
    const std::vector<double> dx = design_stroke_displacement(first, *out.design_x0);
    const std::vector<double> force = design_stroke_force(first);
    root.write_dataset("displacement",
                       std::span<const double>(dx),
                       "m",
                       "slider displacement Delta x (inwards) at each point of the first model");
    root.write_dataset("force",
                       std::span<const double>(force),
                       "N",
                       "slider input force of one half (positive pushes the slider inward), the "
                       "first model's");
  }
  write_path(root, first, in, out.results.front().first);
  write_geometry(root, m);
  Hdf5Group models = root.create_group("models");
  for (const auto& [name, r] : out.results) {
    Hdf5Group g = models.create_group(name);
    g.set_attribute("termination", std::string(termination_name(r->termination)));
    g.set_attribute("steps", static_cast<std::int64_t>(r->iterations));
    write_path(g, *r, in, name);
    write_equilibria_and_limits(g, *r, in);
    write_bodies(g, *r);
    write_point_results(g, *r, m);
    write_flexure_models(g, r->flexure_models, out.checked_flexures);
  }
  write_provenance(root, stability_code_meanings());
}

void write_general_mechanism_hdf5(const std::string& path, const GeneralAnalysisOutput& out) {
  AtomicHdf5File file(path);
  write_general_mechanism(file.root(), out);
  file.commit();
}

std::vector<CsvColumn> general_mechanism_csv_columns(const GeneralAnalysisOutput& out,
                                                     std::string* note) {
  check(out);
  const Input& in = out.mechanism->input;
  const GeneralPrbmResult& first = *out.results.front().second;
  std::vector<CsvColumn> columns;
  if (out.design_x0) {
    columns.push_back(
        numbers("displacement", "m", design_stroke_displacement(first, *out.design_x0)));
    // The unit says whose force it is (docs/cli.md "CSV output").
    columns.push_back(numbers("force", force_unit("half"), design_stroke_force(first)));
  }
  add_path_columns(columns, first, in, "", true);
  for (std::size_t k = 1; k < out.results.size(); ++k) {
    const auto& [name, r] = out.results[k];
    bool same = r->points.size() == first.points.size();
    for (std::size_t i = 0; same && i < first.points.size(); ++i) {
      same = r->points[i].input == first.points[i].input;
    }
    if (!same) {
      if (note != nullptr) {
        *note += fmt::format(
            "the CSV holds the {} model only: the {} model's {} points do not lie at its {} "
            "inputs (a limit point crossed); the --out HDF5 file holds both",
            out.results.front().first,
            name,
            r->points.size(),
            first.points.size());
      }
      continue;
    }
    add_path_columns(columns, *r, in, name + "/", false);
  }
  return columns;
}

}  // namespace flexure::io
