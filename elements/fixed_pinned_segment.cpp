#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "flexure/elements/prbm_curve_fits.h"
#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

FixedPinnedConstants FixedPinnedConstants::from_table(double n) {
  const FixedPinnedTableRow* exact = table_5_1_row(n);
  const FixedPinnedTableRow row = exact ? *exact : table_5_1_interpolated(n);
  FixedPinnedConstants c;
  c.load_ratio_n = n;
  c.gamma = row.gamma;
  c.c_theta = row.c_theta;
  c.K_theta = row.K_theta;
  c.theta_max_gamma = row.theta_max_gamma_deg * kDeg;
  c.theta_max_K = row.theta_max_K_deg * kDeg;
  c.source = exact ? fmt::format("Table 5.1, n = {}", n)
                   : fmt::format("Table 5.1 interpolated linearly in n at n = {}", n);
  return c;
}

FixedPinnedConstants FixedPinnedConstants::from_curve_fits(double n) {
  const FixedPinnedTableRow row = table_5_1_interpolated(n);
  FixedPinnedConstants c;
  c.load_ratio_n = n;
  c.gamma = gamma_curve_fit(n);
  c.K_theta = K_theta_curve_fit(n);
  c.c_theta = row.c_theta;
  c.theta_max_gamma = row.theta_max_gamma_deg * kDeg;
  c.theta_max_K = n < 0.0 ? theta_max_K_rule(n) : row.theta_max_K_deg * kDeg;
  c.source = fmt::format(
      "curve fits eqs. 5.48 and 5.60-5.62 at n = {} (c_theta and limits from Table 5.1)", n);
  return c;
}

FixedPinnedConstants FixedPinnedConstants::howell_average() {
  FixedPinnedConstants c = from_table(0.0);
  c.gamma = 0.85;    // Howell §5.2, eq. 5.51
  c.K_theta = 2.65;  // Howell §5.2, eq. 5.64
  c.source = fmt::format(
      "Howell's averages gamma = {:g}, K_theta = {:g} (§5.2, eqs. 5.51 and 5.64; c_theta and "
      "limits "
      "Table 5.1, n = 0)",
      c.gamma,
      c.K_theta);
  return c;
}

const FixedPinnedSegment& howell_average_fixed_pinned() {
  static const FixedPinnedSegment segment(FixedPinnedConstants::howell_average());
  return segment;
}

void FixedPinnedConstants::validate() const {
  require_finite(load_ratio_n, "load ratio n");
  const auto check = [](double value, double lo, double hi, const char* what) {
    if (!std::isfinite(value) || value <= lo || value > hi) {
      throw InvalidInput(
          fmt::format("{} = {} is outside the allowed range ({}, {}]", what, value, lo, hi));
    }
  };
  check(gamma, 0.0, 1.0, "characteristic radius factor gamma");
  check(c_theta, 0.0, 10.0, "parametric angle coefficient c_theta");
  check(K_theta, 0.0, 100.0, "stiffness coefficient K_theta");
  check(theta_max_gamma, 0.0, std::numbers::pi, "Theta_max(gamma) [rad]");
  check(theta_max_K, 0.0, std::numbers::pi, "Theta_max(K_theta) [rad]");
}

FixedPinnedSegment::FixedPinnedSegment(FixedPinnedConstants constants)
    : constants_(std::move(constants)) {
  constants_.validate();
}

PrbGeometry FixedPinnedSegment::geometry() const {
  return {constants_.gamma, constants_.gamma, 1.0 - constants_.gamma, 0.0, 1};
}

double FixedPinnedSegment::stiffness_coefficient() const {
  return constants_.gamma * constants_.K_theta;
}

TipPose FixedPinnedSegment::tip(double Theta) const {
  const double g = constants_.gamma;
  return {1.0 - g * (1.0 - std::cos(Theta)), g * std::sin(Theta), constants_.c_theta * Theta};
}

double FixedPinnedSegment::generalized_load(double Theta, const EndLoad& load) const {
  if (load.mu != 0.0) {
    throw InvalidInput(fmt::format(
        "tip moment mu = {} on a fixed-pinned segment: a pinned tip carries no moment (use the "
        "end-moment or fixed-fixed element)",
        load.mu));
  }
  return link_force_work(constants_.gamma, Theta, load);  // = gamma F_t, eq. 6.103
}

double FixedPinnedSegment::spring_moment(double Theta) const {
  return stiffness_coefficient() * Theta;
}

ValidityLimits FixedPinnedSegment::limits() const {
  return {constants_.theta_max_gamma, constants_.theta_max_K, constants_.source};
}

double FixedPinnedSegment::force_angle() const { return std::atan2(1.0, -constants_.load_ratio_n); }

double FixedPinnedSegment::alpha2_at(double Theta) const {
  const double n = constants_.load_ratio_n;
  const double eta = std::sqrt(1.0 + n * n);
  const double tangential = eta * std::sin(force_angle() - Theta);  // F_t / P, eq. 5.56
  if (!(tangential > 0.0)) {
    throw InvalidInput(fmt::format(
        "PRB angle Theta = {} rad is not below the force angle phi = {} rad: no tip force holds "
        "the fixed-pinned model there",
        Theta,
        force_angle()));
  }
  return constants_.K_theta * Theta / tangential;
}

}  // namespace flexure
