#pragma once
// The shortest total length l_tot at which a sub-class is feasible (docs/design.md "--minimize"
// and "Length hints"): feasibility by the full sizing (subclass_sizing.h) is searched through a
// cheap necessary condition first -- the sizing without the exact model -- and the full sizing
// only from the cheap answer on, since an exact stroke costs a hundred PRBM strokes.
#include <functional>
#include <optional>

namespace flexure::design {

// One evaluation of the full condition at a length: feasible or not, and where the stress binds
// the largest stress over the allowed one (sigma SF/S_y of the least stressed section: <= 1
// feasible), which varies smoothly with the length and lets the search interpolate.
struct LengthProbe {
  bool feasible = false;
  std::optional<double> stress_ratio;
};

struct LengthSearchOptions {
  double scan_factor = 1.25;      // geometric scan from `lower` until the cheap condition holds
  double cheap_tolerance = 1e-6;  // relative width of the cheap condition's final bracket
  double full_tolerance = 1e-4;   // relative width of the full condition's final bracket
};

// The first l in [lower, upper] (scanning up from lower, which is tried first) at which `full`
// holds, where `cheap` holds wherever `full` does. Returns the feasible end of a bracket whose
// other end failed, at most full_tolerance apart (so l itself was sized feasible and
// l (1 - full_tolerance) was not); empty when no length tried is feasible.
std::optional<double> first_feasible_length(const std::function<bool(double)>& cheap,
                                            const std::function<LengthProbe(double)>& full,
                                            double lower,
                                            double upper,
                                            const LengthSearchOptions& options = {});

}  // namespace flexure::design
