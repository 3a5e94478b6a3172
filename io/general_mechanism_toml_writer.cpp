#include "flexure/io/general_mechanism_toml_writer.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <sstream>

#include "flexure/mechanisms/general/catalogue_general.h"
#include "flexure/mechanisms/mechanism_plate.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

// The shortest decimal that reads back to `v` (fmt's round-trip form), always a TOML float.
std::string number(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // "3" -> "3.0"; inf/nan refused
  return s;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04x}", static_cast<int>(c));
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// A key of an inline table: bare when it can be, else quoted.
std::string key(const std::string& name) {
  bool bare = !name.empty();
  for (const char c : name) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    bare = bare && ok;
  }
  return bare ? name : quoted(name);
}

}  // namespace

std::string general_mechanism_to_toml(const GeneralMechanism& m, const std::string& header) {
  m.validate();
  for (const Body& b : m.bodies) {
    for (const NamedPoint& p : b.points) {
      if (!std::isfinite(p.position.x) || !std::isfinite(p.position.y)) {
        throw InvalidInput("body '" + b.name + "': point '" + p.name + "' is not finite");
      }
    }
  }
  std::ostringstream out;
  if (!header.empty()) {
    std::istringstream lines(header);
    std::string line;
    while (std::getline(lines, line)) out << (line.empty() ? "#" : "# " + line) << "\n";
    out << "\n";
  }
  out << "name = " << quoted(m.name) << "\n";
  for (const Body& b : m.bodies) {
    if (b.name == "ground" && b.points.empty()) continue;  // implicit
    out << "\n[[body]]\nname = " << quoted(b.name) << "\npoints = { ";
    for (std::size_t i = 0; i < b.points.size(); ++i) {
      const NamedPoint& p = b.points[i];
      out << (i > 0 ? ", " : "") << key(p.name) << " = [" << number(p.position.x) << ", "
          << number(p.position.y) << "]";
    }
    out << " }\n";
  }
  for (const Joint& j : m.joints) {
    out << "\n[[joint]]\nname = " << quoted(j.name)
        << "\ntype = " << quoted(std::string(joint_kind_name(j.kind)))
        << "\na = " << quoted(j.a.text()) << "\nb = " << quoted(j.b.text()) << "\n";
    if (j.kind == JointKind::kSlider) out << "axis = " << number(j.axis_angle) << "\n";
  }
  for (const Flexure& f : m.flexures) {
    out << "\n[[flexure]]\nname = " << quoted(f.name) << "\na = " << quoted(f.a.text())
        << "\nb = " << quoted(f.b.text()) << "\nwidth = " << number(f.width)
        << "\nthickness = " << number(f.thickness) << "\nE = " << number(f.material.E)
        << "\nprbm = " << quoted(std::string(prbm_kind_name(f.prbm))) << "\n";
    if (f.length > 0.0) out << "length = " << number(f.length) << "\n";
    if (f.model != FlexureModel::kPrbm) {
      out << "model = " << quoted(std::string(flexure_model_name(f.model))) << "\n";
    }
    if (f.model == FlexureModel::kAuto) out << "tolerance = " << number(f.tolerance) << "\n";
    if ((f.model == FlexureModel::kCbcm || f.model == FlexureModel::kChain) && f.elements != 0) {
      out << "elements = " << f.elements << "\n";
    }
    if (f.extensible) out << "extensible = true\n";
  }
  for (const LinearSpring& s : m.linear_springs) {
    out << "\n[[spring]]\nname = " << quoted(s.name)
        << "\ntype = \"linear\"\na = " << quoted(s.a.text()) << "\nb = " << quoted(s.b.text())
        << "\nstiffness = " << number(s.stiffness) << "\n";
    if (s.rest_length >= 0.0) out << "rest_length = " << number(s.rest_length) << "\n";
  }
  for (const TorsionSpring& s : m.torsion_springs) {
    out << "\n[[spring]]\nname = " << quoted(s.name)
        << "\ntype = \"torsion\"\na = " << quoted(s.body_a) << "\nb = " << quoted(s.body_b)
        << "\nstiffness = " << number(s.stiffness) << "\nrest_angle = " << number(s.rest_angle)
        << "\n";
  }
  for (const DeadLoad& l : m.loads) {
    out << "\n[[load]]\nname = " << quoted(l.name) << "\nat = " << quoted(l.at.text())
        << "\nfx = " << number(l.fx) << "\nfy = " << number(l.fy)
        << "\nmoment = " << number(l.moment) << "\n";
  }
  if (m.has_input) {
    const Input& in = m.input;
    out << "\n[input]\ncoordinate = " << quoted(std::string(input_coordinate_name(in.coordinate)))
        << "\npoint = " << quoted(in.body + "." + in.point) << "\n";
    if (in.coordinate == InputCoordinate::kAngle) {
      out << "to = " << quoted(in.body + "." + in.point_to) << "\n";
    }
    out << "control = " << quoted(std::string(input_control_name(in.control)))
        << "\nstart = " << number(in.start) << "\nstop = " << number(in.stop)
        << "\ncount = " << in.count << "\n";
    if (!in.start_rotation.empty()) {
      out << "start_rotation = { ";
      for (std::size_t i = 0; i < in.start_rotation.size(); ++i) {
        out << (i > 0 ? ", " : "") << key(in.start_rotation[i].first) << " = "
            << number(in.start_rotation[i].second);
      }
      out << " }\n";
    }
  }
  return out.str();
}

std::string design_as_general_toml(const MechanismDesign& given, int points) {
  // The bending modulus the analysis uses (--plate, a design's plate key: mechanism_plate.h).
  MechanismDesign design = given;
  apply_plate_modulus(design);
  const GeneralMechanism m = general_from_design(design, points);
  std::string header = fmt::format(
      "{} ({}{}) as a general mechanism (docs/mechanisms.md \"The catalogue as general "
      "mechanisms\"), written by `flexure mechanism export`.\n",
      design.name,
      design.config,
      design.inverted ? ", inverted: described from its fixed slider block" : "");
  if (!design.note.empty()) header += design.note + "\n";
  header += fmt::format(
      "Weight's Table 8.1 on the slider axis, SI units; {} stroke points Delta x = k stroke/{}, "
      "the moving block's x = {} m - Delta x.\n"
      "  flexure mechanism analyze FILE --model prbm|exact|both --json\n"
      "gives the catalogue's slider force (one half) as minus input_load, to 1e-9 "
      "(`flexure mechanism analyze {}`).",
      points,
      points,
      number(m.input.start - (m.input.stop - m.input.start) / (points - 1)),
      design.name);
  return general_mechanism_to_toml(m, header);
}

}  // namespace flexure::mechanism::general
