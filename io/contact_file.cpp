#include "flexure/io/contact_file.h"

#include <limits>
#include <vector>

#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/provenance.h"

namespace flexure::io {

void write_contact_hdf5(const std::string& path, const ContactResult& r, bool physical) {
  const std::string length = physical ? "m" : "1";
  const std::string force = physical ? "N" : "1";
  const std::string moment = physical ? "N m" : "1";
  const std::string pressure = physical ? "N/m" : "1";
  AtomicHdf5File file(path);
  Hdf5Group& root = file.root();
  write_provenance(root,
                   {{"path/in_contact", 0, "free of the surface"},
                    {"path/in_contact", 1, "in contact with the surface"}});
  root.set_attribute("surface", to_string(r.surface));
  root.set_attribute("in_contact", static_cast<std::int64_t>(r.in_contact ? 1 : 0));
  root.set_attribute("contact_kind", std::string(to_string(r.kind)));
  // The [[contact]] table (1-based) whose surface is touched; 0 when none.
  root.set_attribute("contact_table",
                     static_cast<std::int64_t>(r.in_contact ? r.surface_index + 1 : 0));
  root.set_attribute("load_factor", r.load_factor);
  // The stability verdict (docs/contact.md "Stability"): its name, the count of negative
  // directions (-1 where not judged) and the margin (NaN where not judged).
  root.set_attribute("stability", std::string(stability_name(r.stability.kind)));
  root.set_attribute("stability_index",
                     static_cast<std::int64_t>(r.stability.judged() ? r.stability.index : -1));
  root.set_attribute(
      "stability_margin",
      r.stability.judged() ? r.stability.margin : std::numeric_limits<double>::quiet_NaN());
  root.set_attribute("stability_message", r.stability.message);

  Hdf5Group contact = root.create_group("contact");
  contact.write_scalar("s_start", r.s_start, length, "arc length where the contact region begins");
  contact.write_scalar("s_end", r.s_end, length, "arc length where the contact region ends");
  std::vector<double> sx, sy, st;
  for (const ChainPose& p : r.separation_points) {
    sx.push_back(p.x);
    sy.push_back(p.y);
    st.push_back(p.theta);
  }
  contact.write_dataset(
      "separation_s", r.separation_s, length, "arc length of each separation (or contact) point");
  contact.write_dataset("separation_x", sx, length, "x of each separation point, root frame");
  contact.write_dataset("separation_y", sy, length, "y of each separation point, root frame");
  contact.write_dataset("separation_theta", st, "rad", "tangent angle at each separation point");
  contact.write_dataset("contact_force",
                        std::vector<double>{r.contact_force[0], r.contact_force[1]},
                        force,
                        "total contact force on the beam (Fx, Fy), root frame");
  contact.write_dataset("point_force",
                        std::vector<double>{r.point_force[0], r.point_force[1]},
                        force,
                        "concentrated contact force at the separation point or tip (Fx, Fy)");
  contact.write_scalar("point_force_normal",
                       r.point_force_normal,
                       force,
                       "magnitude of the concentrated contact force along the surface normal");
  contact.write_scalar("line_pressure",
                       r.line_pressure,
                       pressure,
                       "circle: contact pressure T/R on the wrap; line contact: the stop's "
                       "pressure on the lying part");
  contact.write_scalar("tip_reaction_normal",
                       r.tip_reaction_normal,
                       force,
                       "line contact: the stop's concentrated normal reaction at the tip");
  contact.write_scalar("lying_axial_force",
                       r.lying_axial_force,
                       force,
                       "line contact: axial force of the lying part at the separation point");
  contact.write_scalar(
      "wrap_tension", r.wrap_tension, force, "circle: tangential force T along the wrap");
  contact.write_scalar(
      "separation_moment", r.separation_moment, moment, "circle: bending moment m(s_c+)");
  contact.write_scalar("curvature_condition",
                       r.curvature_condition,
                       moment,
                       "circle: m(s_c+) - sigma EI/R, zero at the solution");
  contact.write_scalar("min_gap", r.min_gap, length, "smallest gap of the free part of the beam");
  contact.write_scalar("tip_gap", r.tip_gap, length, "gap at the tip");

  Hdf5Group tip = root.create_group("tip");
  tip.write_scalar("x", r.tip.x, length, "tip x, root frame");
  tip.write_scalar("y", r.tip.y, length, "tip y, root frame");
  tip.write_scalar("theta", r.tip.theta, "rad", "tip tangent angle");
  Hdf5Group reaction = root.create_group("reaction");
  reaction.write_scalar("Fx", r.reaction.Fx, force, "force the clamp applies to the beam, x");
  reaction.write_scalar("Fy", r.reaction.Fy, force, "force the clamp applies to the beam, y");
  reaction.write_scalar("M", r.reaction.M, moment, "moment the clamp applies to the beam");

  Hdf5Group events = root.create_group("events");
  std::vector<double> lf;
  std::vector<std::string> kinds;
  for (const ContactEvent& e : r.events) {
    lf.push_back(e.load_factor);
    kinds.push_back(to_string(e.kind));
  }
  events.write_dataset(
      "load_factor", lf, "1", "load factor of each landing, lift-off, line-contact or tip-contact");
  events.write_dataset(
      "kind", kinds, "text", "landing, lift-off, line-contact (opening) or tip-contact (closing)");

  Hdf5Group path_group = root.create_group("path");
  std::vector<double> plf, ps, pn, pi, px, py, pt;
  std::vector<int> pc;
  for (const ContactPathPoint& p : r.path) {
    plf.push_back(p.load_factor);
    pc.push_back(p.in_contact ? 1 : 0);
    ps.push_back(p.separation_s);
    pn.push_back(p.normal_force);
    pi.push_back(p.indicator);
    px.push_back(p.tip.x);
    py.push_back(p.tip.y);
    pt.push_back(p.tip.theta);
  }
  path_group.write_dataset("load_factor", plf, "1", "load factor of each continuation step");
  path_group.write_dataset("in_contact", pc, "1", "1 in contact, 0 free");
  path_group.write_dataset("separation_s", ps, length, "separation (or contact) point, 0 if free");
  path_group.write_dataset("normal_force", pn, force, "concentrated normal contact force");
  path_group.write_dataset(
      "indicator",
      pi,
      r.surface == ContactSurfaceType::kCircle ? moment : length,
      "psi: EI/R - sigma m(0) (circle) or the free tip gap (line); < 0 where contact holds");
  path_group.write_dataset("tip_x", px, length, "tip x");
  path_group.write_dataset("tip_y", py, length, "tip y");
  path_group.write_dataset("tip_theta", pt, "rad", "tip angle");

  if (!r.shape.empty()) {
    Hdf5Group shape = root.create_group("shape");
    std::vector<double> s, x, y, t;
    for (const ShapePoint& p : r.shape) {
      s.push_back(p.s);
      x.push_back(p.x);
      y.push_back(p.y);
      t.push_back(p.theta);
    }
    shape.write_dataset("s", s, length, "arc length from the root");
    shape.write_dataset("x", x, length, "x, root frame");
    shape.write_dataset("y", y, length, "y, root frame");
    shape.write_dataset("theta", t, "rad", "tangent angle");
  }
  file.commit();
}

}  // namespace flexure::io
