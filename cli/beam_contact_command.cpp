#include "cli/beam_contact_command.h"

#include <fmt/format.h>

#include <cmath>

#include "cli/cli_common.h"
#include "flexure/io/contact_file.h"
#include "flexure/io/platform/hdf5_error.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/toml_files.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/rigid_contact.h"

namespace flexure::cli {
namespace {

Json pose_json(const ChainPose& p) { return Json{{"x", p.x}, {"y", p.y}, {"theta", p.theta}}; }

Json result_json(const ContactResult& r, bool physical) {
  Json out;
  out["method"] = "shooting";
  out["contact_model"] = r.kind == ContactKind::kWrap    ? "wrap from the clamp"
                         : r.kind == ContactKind::kTip   ? "tip on the stop"
                         : r.kind == ContactKind::kPoint ? "one interior point, tangent"
                         : r.kind == ContactKind::kLine  ? "lying on the stop (line contact)"
                                                         : "no contact";
  out["contact_kind"] = to_string(r.kind);
  out["units"] = physical ? "SI" : "consistent";
  out["termination"] = std::string(termination_name(r.termination));
  out["surface"] = to_string(r.surface);
  // The [[contact]] table (1-based) whose surface the beam touches; null when free.
  out["contact_table"] = r.in_contact ? Json(r.surface_index + 1) : Json(nullptr);
  out["in_contact"] = r.in_contact;
  out["load_factor"] = r.load_factor;
  Json c;
  c["s_start"] = r.s_start;
  c["s_end"] = r.s_end;
  Json sep = Json::array();
  for (std::size_t i = 0; i < r.separation_s.size(); ++i) {
    Json p = pose_json(r.separation_points[i]);
    p["s"] = r.separation_s[i];
    sep.push_back(std::move(p));
  }
  c["separation_points"] = std::move(sep);
  c["contact_force"] = Json{{"Fx", r.contact_force[0]}, {"Fy", r.contact_force[1]}};
  c["point_force"] = Json{{"Fx", r.point_force[0]}, {"Fy", r.point_force[1]}};
  c["point_force_normal"] = r.point_force_normal;
  c["line_pressure"] = r.line_pressure;
  c["tip_reaction_normal"] = r.tip_reaction_normal;
  c["lying_axial_force"] = r.lying_axial_force;
  c["wrap_tension"] = r.wrap_tension;
  c["separation_moment"] = r.separation_moment;
  c["curvature_condition"] = r.curvature_condition;
  c["min_gap"] = r.min_gap;
  c["tip_gap"] = r.tip_gap;
  out["contact"] = std::move(c);
  out["tip"] = pose_json(r.tip);
  out["reaction"] = Json{{"Fx", r.reaction.Fx}, {"Fy", r.reaction.Fy}, {"M", r.reaction.M}};
  out["tip_load"] = Json{{"Fx", r.tip_load.Fx}, {"Fy", r.tip_load.Fy}, {"M", r.tip_load.M}};
  Json events = Json::array();
  for (const ContactEvent& e : r.events) {
    events.push_back(Json{{"kind", to_string(e.kind)}, {"load_factor", e.load_factor}});
  }
  out["events"] = std::move(events);
  Json path = Json::array();
  for (const ContactPathPoint& p : r.path) {
    path.push_back(Json{{"load_factor", p.load_factor},
                        {"in_contact", p.in_contact},
                        {"separation_s", p.separation_s},
                        {"normal_force", p.normal_force},
                        {"indicator", p.indicator},
                        {"tip", pose_json(p.tip)}});
  }
  out["path"] = std::move(path);
  out["steps"] = r.steps;
  out["shooting_solves"] = r.shooting_solves;
  out["residual"] = r.residual;
  // The stability keys of `flexure beam` (docs/cli.md): index and margin null unless judged.
  out["stability"] = std::string(stability_name(r.stability.kind));
  out["stability_index"] = r.stability.judged() ? Json(r.stability.index) : Json(nullptr);
  out["stability_margin"] = r.stability.judged() && std::isfinite(r.stability.margin)
                                ? Json(r.stability.margin)
                                : Json(nullptr);
  out["stability_message"] = r.stability.message;
  if (!r.shape.empty()) {
    Json shape = Json::array();
    for (const ShapePoint& p : r.shape) {
      shape.push_back(Json{{"s", p.s}, {"x", p.x}, {"y", p.y}, {"theta", p.theta}});
    }
    out["shape"] = std::move(shape);
  }
  return out;
}

void print_text(const ContactResult& r, bool physical, std::size_t surfaces) {
  const char* L = physical ? " m" : "";
  const char* F = physical ? " N" : "";
  const char* P = physical ? " N/m" : "";
  const char* M = physical ? " N m" : "";
  if (surfaces > 1) {
    fmt::print(
        "Contact with {} rigid surfaces (frictionless), method shooting, {} continuation steps; "
        "{}\n",
        surfaces,
        r.steps,
        r.in_contact
            ? fmt::format("touching contact {}, a {}", r.surface_index + 1, to_string(r.surface))
            : std::string("touching none"));
  } else {
    fmt::print("Contact with a rigid {} (frictionless), method shooting, {} continuation steps\n",
               to_string(r.surface),
               r.steps);
  }
  for (const ContactEvent& e : r.events) {
    fmt::print("  {} at load factor {:.10g}\n", to_string(e.kind), e.load_factor);
  }
  if (!r.in_contact) {
    fmt::print("  free of the {} at full load (smallest gap {:.6g}{})\n",
               to_string(r.surface),
               r.min_gap,
               L);
  } else if (r.kind == ContactKind::kPoint) {
    const ChainPose& p = r.separation_points[0];
    fmt::print(
        "  touching at one point s = {:.10g}{} ({:.10g}, {:.10g}){}, tangent, angle {:.10g} "
        "rad; contact force {:.10g}{} along the surface normal\n",
        r.s_end,
        L,
        p.x,
        p.y,
        L,
        p.theta,
        r.point_force_normal,
        F);
  } else if (r.kind == ContactKind::kLine) {
    const ChainPose& p = r.separation_points[0];
    fmt::print(
        "  lying on the stop over s = {:.10g} .. {:.10g}{}; separation point ({:.10g}, "
        "{:.10g}){}, angle {:.10g} rad\n",
        r.s_start,
        r.s_end,
        L,
        p.x,
        p.y,
        L,
        p.theta);
    fmt::print(
        "  point force at separation {:.10g}{}, line pressure {:.10g}{}, tip reaction "
        "{:.10g}{}, axial force of the lying part {:.10g}{}\n",
        r.point_force_normal,
        F,
        r.line_pressure,
        P,
        r.tip_reaction_normal + 0.0,
        F,
        r.lying_axial_force + 0.0,
        F);
  } else if (r.kind == ContactKind::kWrap) {
    fmt::print(
        "  wrapped over s = 0 .. {:.10g}{}; separation point ({:.10g}, {:.10g}){}, angle "
        "{:.10g} rad\n",
        r.s_end,
        L,
        r.separation_points[0].x,
        r.separation_points[0].y,
        L,
        r.separation_points[0].theta);
    fmt::print(
        "  point force at separation {:.10g}{}, line pressure {:.10g}{}, wrap tension "
        "{:.10g}{}; curvature condition m(s_c) - sigma EI/R = {:.3g}{}\n",
        r.point_force_normal,
        F,
        r.line_pressure,
        P,
        r.wrap_tension,
        F,
        r.curvature_condition,
        M);
  } else {
    fmt::print("  tip on the stop: normal reaction {:.10g}{}\n", r.point_force_normal, F);
  }
  fmt::print(
      "  contact force Fx = {:.10g}, Fy = {:.10g}{}\n", r.contact_force[0], r.contact_force[1], F);
  fmt::print(
      "  tip x = {:.10g}, y = {:.10g}{}, theta = {:.10g} rad\n", r.tip.x, r.tip.y, L, r.tip.theta);
  fmt::print("  clamp reaction Fx = {:.10g}, Fy = {:.10g}{}, M = {:.10g}{}\n",
             r.reaction.Fx + 0.0,
             r.reaction.Fy + 0.0,
             F,
             r.reaction.M + 0.0,
             M);
  if (r.stability.judged()) {
    fmt::print("  stability: {}, index {}, stability margin {:.6g} ({})\n",
               stability_name(r.stability.kind),
               r.stability.index,
               r.stability.margin,
               r.stability.message);
  } else {
    fmt::print("  stability: {} ({})\n", stability_name(r.stability.kind), r.stability.message);
  }
}

}  // namespace

bool run_beam_contact(const BeamContactArgs& args) {
  io::ChainFile file = io::read_chain_file(args.chain_file);
  if (file.contacts.empty()) {
    if (!args.out.empty()) {
      throw InvalidInput(
          "--out writes the HDF5 file of a contact solution; this --chain file has no [[contact]] "
          "(docs/contact.md)");
    }
    return false;
  }
  warn(file.warnings);
  if (!same_name(args.method, "auto") && !same_name(args.method, "shooting")) {
    throw InvalidInput(fmt::format(
        "--method {} cannot solve contact: contact with a rigid surface is solved by the shooting "
        "method only (use --method shooting or auto)",
        args.method));
  }
  if (!args.refused_flag.empty()) {
    throw InvalidInput(
        fmt::format("{} is not available with a [[contact]] (docs/contact.md)", args.refused_flag));
  }
  if (!args.out.empty()) io::check_output_path(args.out);
  // Several tables: several surfaces, one continuation (its start load and steps from the table
  // that gives them; chain_toml checks they agree).
  std::vector<RigidSurface> surfaces;
  TipLoad start;
  RigidContactSolver::Options options;
  for (const io::ChainFile::Contact& contact : file.contacts) {
    surfaces.push_back(contact.surface);
    if (contact.start_given) start = contact.start_tip_load;
    if (contact.steps) options.steps = *contact.steps;
  }
  if (args.integrator) {
    options.shooting.backend = integrator_backend_from_string(*args.integrator);
  }
  if (args.shape_points > 0) options.shape_points = std::max(args.shape_points, 2);
  const ContactResult r = RigidContactSolver(options).solve(file.chain, surfaces, start);
  if (!r.converged()) {
    Json reached;
    reached["method"] = "shooting";
    reached["surface"] = to_string(r.surface);
    reached["load_factor"] = r.load_factor;
    Json events = Json::array();
    for (const ContactEvent& e : r.events) {
      events.push_back(Json{{"kind", to_string(e.kind)}, {"load_factor", e.load_factor}});
    }
    reached["events"] = std::move(events);
    throw NoConvergenceReport(r.message, std::move(reached));
  }
  if (!args.out.empty()) {
    try {
      io::write_contact_hdf5(args.out, r, file.physical);
    } catch (const io::Hdf5Error& e) {
      throw InvalidInput(fmt::format("--out {}: {}", args.out, e.what()));
    }
  }
  if (args.json) {
    Json out = result_json(r, file.physical);
    if (!args.out.empty()) out["out"] = args.out;
    print_json(out);
  } else {
    print_text(r, file.physical, surfaces.size());
    if (!args.out.empty()) fmt::print("  written: {}\n", args.out);
  }
  return true;
}

}  // namespace flexure::cli
