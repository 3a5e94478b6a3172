#include "flexure/mechanisms/general/catalogue_general.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

// The four bodies of the half mechanism in the ORIGINAL orientation (mechanism.h): the ground
// block, link 2 (crank), link 3 (coupler), the slider block.
enum Role { kGround = 0, kCrank = 1, kCoupler = 2, kSlider = 3 };

struct RolePoint {
  Role role;
  std::string name;
  double x;  // on the slider axis, original frame, m
};

}  // namespace

GeneralMechanism general_from_design(const MechanismDesign& design, int points) {
  if (points < 2) {
    throw InvalidInput("general_from_design: points must be >= 2");
  }
  MechanismDesign d = design;
  d.finalise();
  for (const JointDesign& j : d.joints) {
    if (j.segment == SegmentKind::kFixedFixed && d.spring_rule != SpringRule::kPureBending) {
      throw InvalidInput(d.name + ": spring rule " + spring_rule_name(d.spring_rule) +
                         " has no general form: a general small-length pivot is K = EI/l "
                         "(Howell eq. 5.14), the pure-bending rule");
    }
  }
  const auto& j = d.joints;
  const auto& cfg = d.configuration();
  // Table 8.1 (Weight 2001): where each pivot's flexible segment lies on the slider axis.
  const double back = howell_average_fixed_pinned().geometry().pivot_x;  // 1 - gamma
  const double f1 = j[0].length, f2 = j[1].length, f3 = j[2].length;
  const bool long1 = j[0].type == PivotType::kLong;
  const bool long2 = j[1].type == PivotType::kLong;
  const bool plp = long2 && cfg.middle_long_on_r2;   // link 2 a beam pinned at the ground
  const bool slp = long2 && !cfg.middle_long_on_r2;  // link 3 a beam pinned at the slider
  // PRB pivots: 1 at x1, 2 at x2 = x1 + r2, 3 at x3 = x2 + r3.
  const double x1 = j[0].type == PivotType::kSmall ? f1 / 2 : long1 ? back * f1 : 0.0;
  const double x2 = x1 + d.r2;
  const double x3 = x2 + d.r3;
  const double xs = j[2].type == PivotType::kSmall ? x3 + f3 / 2 : x3;  // the slider's joint

  std::vector<RolePoint> pts;
  struct Item {
    bool flexure = true;
    int pivot = 0;  // stored pivot 1..3
    Role ra, rb;
    std::string pa, pb;
    PrbmKind prbm = PrbmKind::kSmallLengthPivot;
  };
  std::vector<Item> items;
  auto s_pivot = [&](int pivot, Role ra, Role rb, double x, double l) {
    const std::string c = fmt::format("c{}", pivot);
    pts.push_back({ra, c, x - l / 2});
    pts.push_back({rb, c, x + l / 2});
    items.push_back({true, pivot, ra, rb, c, c, PrbmKind::kSmallLengthPivot});
  };
  auto pin = [&](int pivot, Role ra, Role rb, double x) {
    const std::string p = fmt::format("p{}", pivot);
    pts.push_back({ra, p, x});
    pts.push_back({rb, p, x});
    items.push_back({false, pivot, ra, rb, p, p, PrbmKind::kSmallLengthPivot});
  };
  // A fixed-pinned segment clamped into `clamp` at x_clamp, pinned to `pinned` at x_pin.
  auto l_segment = [&](int pivot, Role clamp, double x_clamp, Role pinned, double x_pin) {
    const std::string c = fmt::format("c{}", pivot), p = fmt::format("p{}", pivot);
    pts.push_back({clamp, c, x_clamp});
    pts.push_back({pinned, p, x_pin});
    items.push_back({true, pivot, clamp, pinned, c, p, PrbmKind::kFixedPinned});
  };

  // Pivot 1 (ground): s centred on x1; l = link 2 clamped at the ground, pinned to link 3 at x2;
  // p a pin.
  if (j[0].type == PivotType::kSmall) {
    s_pivot(1, kGround, kCrank, x1, f1);
  } else if (long1) {
    l_segment(1, kGround, 0.0, kCoupler, x2);
  } else if (!plp) {
    pin(1, kGround, kCrank, 0.0);
  }
  // Pivot 2: s centred on x2; slp: link 3 a beam clamped into link 2 (1 - gamma) f2 before x2,
  // pinned at the slider; plp: link 2 a beam pinned at the ground, clamped into link 3
  // (1 - gamma) f2 after x2; p a pin (none when link 2 is pivot 1's beam, pinned there).
  if (j[1].type == PivotType::kSmall) {
    s_pivot(2, kCrank, kCoupler, x2, f2);
  } else if (slp) {
    l_segment(2, kCrank, x2 - back * f2, kSlider, x3);
  } else if (plp) {
    l_segment(2, kCoupler, x2 + back * f2, kGround, 0.0);
  } else if (!long1) {
    pin(2, kCrank, kCoupler, x2);
  }
  // Pivot 3 (slider): s centred on x3; p a pin (none when link 3 is pivot 2's beam).
  if (j[2].type == PivotType::kSmall) {
    s_pivot(3, kCoupler, kSlider, x3, f3);
  } else if (!slp) {
    pin(3, kCoupler, kSlider, x3);
  }
  // The guide: a point of each block at the block's own place (the ground's at 0, the slider's at
  // its joint), so that an inversion's moving block carries its point.
  pts.push_back({kGround, "S", 0.0});
  pts.push_back({kSlider, "S", xs});

  // An inversion (inversion.h): the slider block is fixed and the ground block slides. Described
  // as read from the fixed block: mirrored (x -> xs - x), the blocks' and links' roles swapped,
  // pivot i named 4 - i; the same relative motion, so the same numbers.
  const bool inv = d.inverted;
  auto body_of = [&](Role r) -> std::string {
    static const std::array<const char*, 4> names{"ground", "crank", "coupler", "slider"};
    return names[static_cast<std::size_t>(inv ? 3 - r : r)];
  };
  auto x_of = [&](double x) { return inv ? xs - x : x; };
  auto renamed = [&](const std::string& point) {
    if (!inv || point == "S") return point;
    return point.substr(0, 1) + std::to_string(4 - (point[1] - '0'));
  };
  auto ref = [&](Role r, const std::string& p) { return body_of(r) + "." + renamed(p); };

  GeneralMechanism m;
  m.name = d.name;
  // Bodies in the described order (ground, crank, coupler, slider), each the role it plays.
  for (const Role described : {kGround, kCrank, kCoupler, kSlider}) {
    const Role r = inv ? static_cast<Role>(3 - described) : described;
    std::vector<NamedPoint> body;
    for (const RolePoint& p : pts) {
      if (p.role == r) body.push_back({renamed(p.name), {x_of(p.x), 0.0}});
    }
    if (!body.empty()) m.body(body_of(r), body);
  }
  std::vector<std::string> body_names;
  for (const Body& b : m.bodies) body_names.push_back(b.name);
  for (const Item& it : items) {
    const int pivot = inv ? 4 - it.pivot : it.pivot;
    if (it.flexure) {
      const JointDesign& jd = j[static_cast<std::size_t>(it.pivot - 1)];
      m.flexure(fmt::format("f{}", pivot),
                ref(it.ra, it.pa),
                ref(it.rb, it.pb),
                jd.width,
                jd.thickness,
                d.material.E,
                it.prbm);
    } else {
      m.pin(fmt::format("p{}", pivot), ref(it.ra, it.pa), ref(it.rb, it.pb));
    }
  }
  m.slider("guide", "ground.S", "slider.S", 0.0);
  // The input: the moving block's x, moved inwards over the catalogue's stroke points; the same
  // numbers in the mirrored frame of an inversion (its moving block starts at xs too).
  const std::vector<double> dx = stroke_displacements(d, points);
  m.input_coordinate(InputCoordinate::kX,
                     "slider.S",
                     "",
                     InputControl::kDisplacement,
                     xs - dx.front(),
                     xs - dx.back(),
                     points);
  // The straight position is a dead point: start on the branch with pivot 2 above the axis, from
  // the small-angle PRBM pose Delta x = theta2^2 r2 (1 + r2/r3)/2 (mirrored: the turns reverse).
  const double theta2 = std::sqrt(2 * dx.front() / (d.r2 * (1 + d.r2 / d.r3)));
  const double sign = inv ? -1.0 : 1.0;
  auto has = [&](const std::string& name) {
    for (const std::string& b : body_names) {
      if (b == name) return true;
    }
    return false;
  };
  if (has(body_of(kCrank))) m.input.start_rotation.push_back({body_of(kCrank), sign * theta2});
  if (has(body_of(kCoupler))) {
    m.input.start_rotation.push_back({body_of(kCoupler), -sign * theta2 * d.r2 / d.r3});
  }
  return m;
}

std::string general_flexure_name(const MechanismDesign& design, int pivot) {
  if (pivot < 1 || pivot > 3) {
    throw InvalidInput("general_flexure_name: pivot must be 1, 2 or 3");
  }
  if (design.joints[static_cast<std::size_t>(pivot - 1)].type == PivotType::kPin) return "";
  return fmt::format("f{}", design.inverted ? 4 - pivot : pivot);
}

}  // namespace flexure::mechanism::general
