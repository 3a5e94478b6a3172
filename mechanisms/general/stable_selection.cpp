#include "flexure/mechanisms/general/stable_selection.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <vector>

#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

// A value of the controlled quantity for messages, with its unit.
std::string controlled_text(const Input& in, double v) {
  if (in.control == InputControl::kDisplacement) return input_value_text(in, v);
  return fmt::format("{:.6g} {}", v, in.coordinate == InputCoordinate::kAngle ? "N m" : "N");
}

}  // namespace

StableSelection select_stable_points(
    const GeneralMechanism& mechanism,
    const GeneralPrbmResult& path,
    const std::function<void(std::size_t done, std::size_t total)>& progress) {
  if (path.points.empty()) {
    throw InvalidInput("--stable: the path recorded no points to choose from");
  }
  const Input& in = mechanism.input;
  const bool force = in.control == InputControl::kForce;
  auto controlled = [&](const GeneralPrbmPoint& p) { return force ? p.input_load : p.input; };
  auto other = [&](const GeneralPrbmPoint& p) { return force ? p.input : p.input_load; };
  auto verdict = [&](const GeneralPrbmPoint& p) -> const Stability& {
    return force ? p.force_control : p.displacement_control;
  };
  // The grid values are recorded exactly up to the SI/scaled round trip: match to 1e-9 of the
  // range (or of the value).
  const double span = std::fabs(in.stop - in.start);
  StableSelection out;
  out.result = path;
  out.result.points.clear();
  out.grid_values = in.count;
  std::vector<std::string> snaps;
  std::vector<double> missing;
  int unstable_on_path = 0;
  for (const GeneralPrbmPoint& p : path.points) {
    unstable_on_path += verdict(p).kind == StabilityKind::kStable ? 0 : 1;
  }
  const GeneralPrbmPoint* previous = nullptr;
  const auto grid_value_done = [&](int k) {
    if (progress) progress(static_cast<std::size_t>(k + 1), static_cast<std::size_t>(in.count));
  };
  for (int k = 0; k < in.count; ++k) {
    const double v = in.start + (in.stop - in.start) * k / (in.count - 1);
    const double tolerance = 1e-9 * std::max(span, std::fabs(v));
    const GeneralPrbmPoint* chosen = nullptr;
    const GeneralPrbmPoint* first = nullptr;
    for (const GeneralPrbmPoint& p : path.points) {
      if (std::fabs(controlled(p) - v) > tolerance) continue;
      if (first == nullptr) first = &p;
      if (verdict(p).kind != StabilityKind::kStable) continue;
      if (chosen == nullptr ||
          (previous != nullptr &&
           std::fabs(other(p) - other(*previous)) < std::fabs(other(*chosen) - other(*previous)))) {
        chosen = &p;
      }
    }
    if (chosen == nullptr) {
      missing.push_back(v);
      if (first != nullptr) out.result.points.push_back(*first);
      grid_value_done(k);
      continue;
    }
    if (previous != nullptr) {
      // A jump to another branch between two grid values (the previous point's branch ended at a
      // limit point of the load, or turned unstable): the two points are not neighbours in the
      // path's order.
      const std::ptrdiff_t a = previous - path.points.data(), b = chosen - path.points.data();
      if (std::abs(a - b) != 1) {
        snaps.push_back(fmt::format("between {} and {} (input {} to {})",
                                    controlled_text(in, controlled(*previous)),
                                    controlled_text(in, v),
                                    input_value_text(in, previous->input),
                                    input_value_text(in, chosen->input)));
      }
    }
    out.result.points.push_back(*chosen);
    previous = chosen;
    grid_value_done(k);
  }
  out.without_stable = static_cast<int>(missing.size());
  out.snaps = static_cast<int>(snaps.size());
  out.stable = missing.empty();
  const std::string control = force ? "force" : "displacement";
  if (unstable_on_path == 0 && static_cast<int>(path.points.size()) == in.count) {
    out.search =
        fmt::format("not needed: every point of the path is stable under {} control", control);
    return out;
  }
  if (!missing.empty()) {
    out.search = fmt::format(
        "no stable equilibrium found under {} control at {} of {} grid values (from {} to {}): "
        "the path's points there are unstable, and the model does not switch branches at "
        "bifurcations",
        control,
        missing.size(),
        in.count,
        controlled_text(in, missing.front()),
        controlled_text(in, missing.back()));
    return out;
  }
  out.search = fmt::format(
      "the stable equilibrium at each of the {} grid values under {} control ({} unstable "
      "point(s) of the path left out)",
      in.count,
      control,
      unstable_on_path);
  if (!snaps.empty()) {
    out.search += "; it snaps to another branch ";
    for (std::size_t i = 0; i < snaps.size(); ++i) out.search += (i ? "; " : "") + snaps[i];
  }
  return out;
}

}  // namespace flexure::mechanism::general
