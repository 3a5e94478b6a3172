#include "flexure/mechanisms/general/catalogue_general.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "flexure/elements/fixed_pinned_segment.h"
#include "flexure/mechanisms/mechanism_prbm.h"
#include "flexure/solver/common/errors.h"

namespace flexure::mechanism::general {

GeneralMechanism general_from_design(const MechanismDesign& d, int points) {
  for (int i = 1; i < 3; ++i) {
    if (d.joints[static_cast<std::size_t>(i)].type == PivotType::kLong) {
      throw InvalidInput(d.name + ": a long (fixed-pinned) segment at pivot " +
                         std::to_string(i + 1) +
                         " has no general form yet (only at the ground pivot); the general "
                         "form takes spp, lpp, psp, ssp, sps, lps and sss designs");
    }
  }
  if (points < 2) {
    throw InvalidInput("general_from_design: points must be >= 2");
  }
  const auto& j = d.joints;
  const bool long_crank = j[0].type == PivotType::kLong;
  GeneralMechanism m;
  std::vector<NamedPoint> ground, crank, coupler, slider;
  auto section = [&](int i) { return std::array<double, 2>{j[i].width, j[i].thickness}; };
  double x1 = 0.0;
  if (j[0].type == PivotType::kSmall) {
    x1 = j[0].length / 2;
    ground.push_back({"c1", {0, 0}});
    crank.push_back({"c1", {j[0].length, 0}});
  } else if (long_crank) {
    x1 = howell_average_fixed_pinned().geometry().pivot_x * j[0].length;
    ground.push_back({"c1", {0, 0}});
  } else {
    ground.push_back({"p1", {0, 0}});
    crank.push_back({"p1", {0, 0}});
  }
  const double x2 = long_crank ? j[0].length : x1 + d.r2;
  if (j[1].type == PivotType::kSmall) {
    crank.push_back({"c2", {x2 - j[1].length / 2, 0}});
    coupler.push_back({"c2", {x2 + j[1].length / 2, 0}});
  } else {
    if (!long_crank) {
      crank.push_back({"p2", {x2, 0}});
    }
    coupler.push_back({"p2", {x2, 0}});
  }
  const double x3 = x2 + d.r3;
  double xs = x3;
  if (j[2].type == PivotType::kSmall) {
    coupler.push_back({"c3", {x3 - j[2].length / 2, 0}});
    xs = x3 + j[2].length / 2;
  } else {
    coupler.push_back({"p3", {x3, 0}});
  }
  slider.push_back({"S", {xs, 0}});
  ground.push_back({"S", {xs, 0}});
  m.name = d.name;
  m.body("ground", ground);
  if (!long_crank) {
    m.body("crank", crank);
  }
  m.body("coupler", coupler).body("slider", slider);
  if (j[0].type == PivotType::kSmall) {
    m.flexure("f1",
              "ground.c1",
              "crank.c1",
              section(0)[0],
              section(0)[1],
              d.E,
              PrbmKind::kSmallLengthPivot);
  } else if (long_crank) {
    m.flexure(
        "f1", "ground.c1", "coupler.p2", section(0)[0], section(0)[1], d.E, PrbmKind::kFixedPinned);
  } else {
    m.pin("p1", "ground.p1", "crank.p1");
  }
  if (j[1].type == PivotType::kSmall) {
    m.flexure("f2",
              "crank.c2",
              "coupler.c2",
              section(1)[0],
              section(1)[1],
              d.E,
              PrbmKind::kSmallLengthPivot);
  } else if (!long_crank) {
    m.pin("p2", "crank.p2", "coupler.p2");
  }
  if (j[2].type == PivotType::kSmall) {
    m.flexure("f3",
              "coupler.c3",
              "slider.S",
              section(2)[0],
              section(2)[1],
              d.E,
              PrbmKind::kSmallLengthPivot);
  } else {
    m.pin("p3", "coupler.p3", "slider.S");
  }
  m.slider("guide", "ground.S", "slider.S", 0.0);
  const std::vector<double> dx = stroke_displacements(d, points);
  m.input_coordinate(InputCoordinate::kX,
                     "slider.S",
                     "",
                     InputControl::kDisplacement,
                     xs - dx.front(),
                     xs - dx.back(),
                     points);
  // Small-angle guess of the first point: Delta x = theta2^2 r2 (1 + r2/r3)/2.
  const double theta2 = std::sqrt(2 * dx.front() / (d.r2 * (1 + d.r2 / d.r3)));
  if (!long_crank) {
    m.input.start_rotation.push_back({"crank", theta2});
  }
  m.input.start_rotation.push_back({"coupler", -theta2 * d.r2 / d.r3});
  return m;
}

}  // namespace flexure::mechanism::general
