#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

// Beyond this half-width t = lambda b/2 the two edge layers no longer interact: the fraction is
// 1 - 3/(4 t) up to terms of order exp(-2 t) < 1e-17 (docs/plate-modulus.md).
constexpr double kWideStrip = 20.0;

// 1 + f'(t)/t + (2/t) int_{-t}^{t} f^2 for the even solution f = A cosh(e) cos(e) +
// B sinh(e) sin(e) of f'''' + 4 f = 0 with f''(t) = -1, f'''(t) = 0: the share of the plate effect
// (the nu^2 cancels: docs/plate-modulus.md).
double fraction_of_half_width(double t) {
  if (t >= kWideStrip) return 1.0 - 0.75 / t;
  const double c = std::cos(t), s = std::sin(t), C = std::cosh(t), S = std::sinh(t);
  // (cosh cos)'' = -2 sinh sin, (cosh cos)''' = -2 (cosh sin + sinh cos);
  // (sinh sin)'' = 2 cosh cos,  (sinh sin)''' = 2 (sinh cos - cosh sin).
  const double a11 = -2.0 * S * s, a12 = 2.0 * C * c;
  const double a21 = -2.0 * (C * s + S * c), a22 = 2.0 * (S * c - C * s);
  const double det = a11 * a22 - a12 * a21;
  const double A = (-1.0 * a22) / det;  // right-hand side (-1, 0)
  const double B = -(a21 * -1.0) / det;
  const double fp = A * (S * c - C * s) + B * (C * s + S * c);
  // int_{-t}^{t} f^2 by Simpson's rule (f is smooth; 4000 intervals leave ~1e-13 relative).
  const int n = 4000;
  const double h = 2.0 * t / n;
  auto f = [&](double e) {
    return A * std::cosh(e) * std::cos(e) + B * std::sinh(e) * std::sin(e);
  };
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double e = -t + i * h;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += w * f(e) * f(e);
  }
  const double integral = sum * h / 3.0;
  return 1.0 + fp / t + 2.0 / t * integral;
}

// t = lambda b/2 with t^2 = sqrt(3 (1 - nu^2)) beta/4.
double half_width(double beta, double nu) {
  return std::sqrt(std::sqrt(3.0 * (1.0 - nu * nu)) * beta / 4.0);
}

void require_nu(double nu, const std::string& where) {
  if (!(std::isfinite(nu) && nu > -1.0 && nu < 0.5)) {
    throw InvalidInput(fmt::format("{}: nu must be finite and in (-1, 0.5) (got {})", where, nu));
  }
}

}  // namespace

PlateRule plate_rule_from_string(const std::string& text, const std::string& what) {
  std::string lower;
  for (char ch : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (lower == "off") return PlateRule::kOff;
  if (lower == "on") return PlateRule::kOn;
  if (lower == "auto") return PlateRule::kAuto;
  throw InvalidInput(
      fmt::format("{} must be \"off\", \"on\" or \"auto\" (got \"{}\")", what, text));
}

const char* to_string(PlateRule rule) {
  switch (rule) {
    case PlateRule::kOff:
      return "off";
    case PlateRule::kOn:
      return "on";
    case PlateRule::kAuto:
      return "auto";
  }
  return "off";
}

double searle_parameter(double width, double thickness, double curvature) {
  if (!(std::isfinite(width) && width > 0.0 && std::isfinite(thickness) && thickness > 0.0)) {
    throw InvalidInput(fmt::format(
        "the Searle parameter b^2/(R h) needs a width and thickness > 0 (got b = {}, h = {})",
        width,
        thickness));
  }
  if (!std::isfinite(curvature)) {
    throw InvalidInput(fmt::format("the curvature 1/R must be finite (got {})", curvature));
  }
  return width * width * std::fabs(curvature) / thickness;
}

double plate_fraction(double beta, double nu) {
  require_nu(nu, "plate_fraction");
  if (!(std::isfinite(beta) && beta >= 0.0)) {
    if (beta == INFINITY) return 1.0;
    throw InvalidInput(fmt::format("the Searle parameter must be >= 0 (got {})", beta));
  }
  if (beta == 0.0) return 0.0;
  // Narrow strips: the fraction is (8/45) t^4 + O(t^8) (docs/plate-modulus.md), below 1e-6 where
  // the closed form loses its digits in the cancellation of 1 + f'(t)/t.
  const double t = half_width(beta, nu);
  if (t < 0.05) return 8.0 / 45.0 * t * t * t * t;
  return std::clamp(fraction_of_half_width(t), 0.0, 1.0);
}

double searle_threshold(double nu) {
  require_nu(nu, "searle_threshold");
  // The fraction depends on t alone and rises monotonically: bisect in t, map back to beta.
  double lo = 0.5, hi = 5.0;  // fraction(0.5) ~ 0.004, fraction(5) ~ 0.85
  for (int i = 0; i < 200 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (fraction_of_half_width(mid) >= 0.5 ? hi : lo) = mid;
  }
  return 4.0 * hi * hi / std::sqrt(3.0 * (1.0 - nu * nu));
}

std::string ModulusChoice::modulus_rule() const {
  return fmt::format("{} ({})", plate ? "plate" : "beam", to_string(rule));
}

std::string ModulusChoice::reason() const {
  if (rule == PlateRule::kOff) return "beam modulus E (plate = off)";
  if (rule == PlateRule::kOn) return "plate modulus E/(1 - nu^2) (plate = on)";
  if (!note.empty()) return note;
  return fmt::format(
      "auto: Searle parameter b^2/(R h) = {:.4g} {} {:.4g} at 1/R = {:.4g} 1/m: {} ({:.0f} % of "
      "the "
      "plate stiffening present)",
      beta.value_or(0.0),
      plate ? ">=" : "<",
      threshold.value_or(0.0),
      curvature.value_or(0.0),
      plate ? "plate modulus E/(1 - nu^2)" : "beam modulus E",
      100.0 * fraction.value_or(0.0));
}

ModulusChoice choose_modulus(PlateRule rule,
                             double E,
                             std::optional<double> nu,
                             std::optional<double> width,
                             std::optional<double> thickness,
                             std::optional<double> curvature,
                             const std::string& where) {
  if (!(std::isfinite(E) && E > 0.0)) {
    throw InvalidInput(fmt::format("{}: E must be finite and > 0 (got {})", where, E));
  }
  ModulusChoice out;
  out.rule = rule;
  out.E = E;
  out.nu = nu;
  out.effective_E = E;
  if (rule == PlateRule::kOff) return out;
  if (!nu) {
    throw InvalidInput(
        fmt::format("{}: plate = {} needs Poisson's ratio nu (the plate modulus is E/(1 - nu^2))",
                    where,
                    to_string(rule)));
  }
  require_nu(*nu, where);
  if (rule == PlateRule::kOn) {
    out.plate = true;
  } else {
    if (!width || !thickness) {
      throw InvalidInput(fmt::format(
          "{}: plate = auto needs the strip's width and thickness (the Searle parameter "
          "b^2/(R h)); give the section as width and thickness, or choose plate = on or off",
          where));
    }
    if (!curvature) {
      throw InvalidInput(fmt::format("{}: plate = auto needs the curvature 1/R", where));
    }
    out.curvature = std::fabs(*curvature);
    out.beta = searle_parameter(*width, *thickness, *curvature);
    out.threshold = searle_threshold(*nu);
    out.fraction = plate_fraction(*out.beta, *nu);
    out.plate = *out.beta >= *out.threshold;
  }
  if (out.plate) out.effective_E = E / (1.0 - *nu * *nu);
  return out;
}

}  // namespace flexure
