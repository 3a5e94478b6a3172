#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/mechanism_analysis.h"

namespace flexure::mechanism {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = 180.0 / std::numbers::pi;

// The ranges Table 5.1 covers: load ratio n and load angle phi = atan2(1, -n) (Howell Fig. 5.9).
struct TableRange {
  double n_min = 0.0, n_max = 0.0, phi_min = 0.0, phi_max = 0.0;
};
const TableRange& table_range() {
  static const TableRange r = [] {
    TableRange t{INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (const FixedPinnedTableRow& row : table_5_1()) {
      t.n_min = std::min(t.n_min, row.load_ratio_n);
      t.n_max = std::max(t.n_max, row.load_ratio_n);
      t.phi_min = std::min(t.phi_min, row.phi_deg);
      t.phi_max = std::max(t.phi_max, row.phi_deg);
    }
    return t;
  }();
  return r;
}

struct Outside {
  int pivot = 0;  // internal numbering (1 = the crank's root in the thesis's frame)
  std::string quantity, unit, reason;
  double value = 0.0, lo = 0.0, hi = 0.0;
};

bool is_table_segment(const JointDesign& j) {
  return j.type == PivotType::kLong && j.segment != SegmentKind::kFixedFixed;
}

// The first l segment outside Table 5.1 at this state (see the header), or nothing.
std::optional<Outside> outside_at(const MechanismDesign& d, const PrbmState& s) {
  const auto& cfg = d.configuration();
  const TableRange& range = table_range();
  for (int p = 1; p <= 3; ++p) {
    if (!is_table_segment(d.joints[p - 1])) continue;
    // Beam axis u at the clamp and PRB angle Theta of the segment (relative rotation of its
    // pseudo-rigid link), and the force on its pinned end.
    double ux = 1.0, uy = 0.0, Theta = s.theta2;
    double Fx = s.pin_force_x, Fy = s.pin_force_y;  // on the crank's tip (lpp, lps)
    if (p == 2 && !cfg.middle_long_on_r2) {         // slp: clamped to link 2, pin at the slider
      ux = std::cos(s.theta2), uy = std::sin(s.theta2), Theta = s.theta3 - s.theta2;
    } else if (p == 2) {  // plp: clamped into link 3, pinned at the ground; seen from the clamp
      ux = -std::cos(s.theta3), uy = -std::sin(s.theta3), Theta = s.theta2 - s.theta3;
      Fx = -Fx, Fy = -Fy;  // the ground pin's force on the beam
    }
    // Normal v on the side the segment deflects to; Pt across the beam, Pa along it.
    const double sign = Theta >= 0.0 ? 1.0 : -1.0;
    const double vx = -uy * sign, vy = ux * sign;
    const double Pt = Fx * vx + Fy * vy, Pa = Fx * ux + Fy * uy;
    const int described = described_pivot(d, p);
    if (Pt <= 0.0) {
      // Load angle measured like Table 5.1's phi = atan2(1, -n) = atan2(Pt, Pa), in [0, 360).
      double phi = std::atan2(Pt, Pa) * kDeg;
      if (phi < 0.0) phi += 360.0;
      return Outside{described,
                     "load_angle_phi",
                     "deg",
                     fmt::format("l segment at pivot {}: the pin force points to the far side of "
                                 "the beam axis, load angle phi = {:.1f} deg, outside Howell Table "
                                 "5.1 ({:.1f} to {:.1f} deg)",
                                 described,
                                 phi,
                                 range.phi_min,
                                 range.phi_max),
                     phi,
                     range.phi_min,
                     range.phi_max};
    }
    const double n = -Pa / Pt;  // Howell eq. 5.37 sense: compressive axial force for n > 0
    if (n < range.n_min || n > range.n_max) {
      return Outside{described,
                     "load_ratio_n",
                     "1",
                     fmt::format("l segment at pivot {}: load ratio n = {:.3g}, outside Howell "
                                 "Table 5.1 ({:g} <= n <= {:g}), which gives no Theta_max there",
                                 described,
                                 n,
                                 range.n_min,
                                 range.n_max),
                     n,
                     range.n_min,
                     range.n_max};
    }
    const ValidityLimits limits = FixedPinnedSegment(FixedPinnedConstants::from_table(n)).limits();
    if (!limits.contains_force(Theta)) {
      const double theta_max = limits.theta_max_force * kDeg;
      return Outside{described,
                     "Theta",
                     "deg",
                     fmt::format("l segment at pivot {}: PRB angle Theta = {:.1f} deg, beyond "
                                 "Theta_max(K_theta) = {:.1f} deg at n = {:.3g} (Howell Table 5.1)",
                                 described,
                                 std::abs(Theta) * kDeg,
                                 theta_max,
                                 n),
                     std::abs(Theta) * kDeg,
                     0.0,
                     theta_max};
    }
  }
  return std::nullopt;
}

std::string percent_or_dash(double error) {
  return std::isfinite(error) ? fmt::format("{:.2f} %", 100.0 * error) : std::string("-");
}

}  // namespace

PrbmStrokeValidity::PrbmStrokeValidity()
    : force_error_at_limit(kNaN), max_force_error_outside(kNaN), max_force_error_inside(kNaN) {}

PrbmStrokeValidity prbm_stroke_validity(const MechanismDesign& d,
                                        const std::vector<double>& displacement) {
  PrbmStrokeValidity v;
  v.has_table = std::any_of(d.joints.begin(), d.joints.end(), is_table_segment);
  if (!v.has_table) {
    const bool fixed_fixed =
        std::any_of(d.joints.begin(), d.joints.end(), [](const JointDesign& j) {
          return j.segment == SegmentKind::kFixedFixed;
        });
    v.no_table = fixed_fixed ? "fixed-fixed segments (Table 5.1 is for fixed-pinned segments)"
                             : "small-length pivots only (Table 5.1 is for fixed-pinned segments)";
    v.inside.assign(displacement.size(), -1);
    return v;
  }
  v.inside.reserve(displacement.size());
  for (std::size_t k = 0; k < displacement.size(); ++k) {
    const std::optional<Outside> out = outside_at(d, prbm_state(d, displacement[k]));
    v.inside.push_back(out ? 0 : 1);
    if (!out) continue;
    ++v.points_outside;
    if (k > 0 && v.inside[k - 1] == 0) {
      v.outside_ranges.back().second = displacement[k];
    } else {
      v.outside_ranges.emplace_back(displacement[k], displacement[k]);
    }
    if (v.first_outside) continue;
    v.first_outside = k;
    v.limit = displacement[k];
    v.pivot = out->pivot;
    v.quantity = out->quantity;
    v.unit = out->unit;
    v.value = out->value;
    v.table_min = out->lo;
    v.table_max = out->hi;
    v.reason = out->reason;
  }
  return v;
}

void add_force_errors(PrbmStrokeValidity& v,
                      const std::vector<double>& force_prbm,
                      const std::vector<double>& force_exact) {
  const std::size_t n = std::min({v.inside.size(), force_prbm.size(), force_exact.size()});
  const auto larger = [](double current, double e) {
    return std::isnan(current) ? e : std::max(current, e);
  };
  for (std::size_t k = 0; k < n; ++k) {
    if (force_exact[k] == 0.0 || !std::isfinite(force_exact[k])) continue;
    const double e = std::abs(force_prbm[k] - force_exact[k]) / std::abs(force_exact[k]);
    if (v.inside[k] == 0) {
      v.max_force_error_outside = larger(v.max_force_error_outside, e);
      if (v.first_outside && *v.first_outside == k) v.force_error_at_limit = e;
    } else {
      v.max_force_error_inside = larger(v.max_force_error_inside, e);
    }
  }
}

std::string describe_validity(const PrbmStrokeValidity& v, double stroke) {
  if (!v.has_table) {
    return fmt::format(
        "no Theta_max table for {}; the PRBM's error shows only against the exact "
        "model{}",
        v.no_table,
        std::isfinite(v.max_force_error_inside)
            ? fmt::format(" (at most {})", percent_or_dash(v.max_force_error_inside))
            : std::string());
  }
  const std::size_t points = v.inside.size();
  if (!v.first_outside) {
    return fmt::format("inside Howell Table 5.1 at all {} stroke points{}",
                       points,
                       std::isfinite(v.max_force_error_inside)
                           ? fmt::format("; PRBM force error at most {}",
                                         percent_or_dash(v.max_force_error_inside))
                           : std::string());
  }
  std::string errors;
  if (std::isfinite(v.max_force_error_outside)) {
    errors = fmt::format(
        "; the PRBM force error (against the exact model) is {} there, at most {} "
        "outside the table{}",
        percent_or_dash(v.force_error_at_limit),
        percent_or_dash(v.max_force_error_outside),
        std::isfinite(v.max_force_error_inside)
            ? fmt::format(" and {} inside", percent_or_dash(v.max_force_error_inside))
            : std::string(" (no point is inside)"));
  } else {
    errors = "; the exact model was not solved, so the PRBM's error there is not known";
  }
  std::string where;
  for (const auto& [first, last] : v.outside_ranges) {
    where += where.empty() ? "" : ", ";
    where +=
        first == last ? fmt::format("{:.5g}", first) : fmt::format("{:.5g} to {:.5g}", first, last);
  }
  const double from = 100.0 * v.outside_ranges.front().first / stroke;
  const double to = 100.0 * v.outside_ranges.back().second / stroke;
  return fmt::format("left at {} of {} stroke points (Delta x = {} m, {}): {}{}",
                     v.points_outside,
                     points,
                     where,
                     std::lround(from) == std::lround(to)
                         ? fmt::format("{:.0f} % of the stroke", from)
                         : fmt::format("{:.0f} to {:.0f} % of the stroke", from, to),
                     v.reason,
                     errors);
}

}  // namespace flexure::mechanism
