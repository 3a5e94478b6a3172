#pragma once
// Percent constant force of a sampled force curve (Weight 2001, thesis eq. 5.22; docs/cfm.md):
// Xi' = 100 F_min/F_max over the stroke. The ratio measures how flat a force of ONE sign is; a
// force that reaches zero or changes sign within the stroke is no constant-force mechanism over
// that stroke (it unloads, then pulls), and min/max would be a meaningless, even negative number
// (issue 11: -5.45 % for an lpp driven to 0.99999 of its toggle stroke). Such a curve is flagged
// and its Xi' reported as 0, the value the ratio tends to as F_min -> 0+ (docs/mechanisms.md
// "Percent constant force").
#include <vector>

namespace flexure::mechanism {

struct ConstantForceMeasure {
  double percent = 0.0;       // Xi' = 100 min|F|/max|F| for a force of one sign, else 0
  bool vanishes = false;      // the force is zero somewhere in the stroke (incl. a sign change)
  bool changes_sign = false;  // samples of both signs: the force crosses zero between them
  double min_force = 0.0;     // smallest sampled force (signed), N
  double max_force = 0.0;     // largest sampled force (signed), N
};

// Rounding threshold of "zero": |F|_min <= 1e-9 |F|_max, the one threshold of the code base (also
// CfmResult::force_vanishes, cfm/cfm_model.h): below it the smallest force is the rounding noise
// of a closed form that is exactly zero there (class 1A at its toggle position).
inline constexpr double kForceVanishesRelative = 1e-9;

// Throws InvalidInput for an empty curve.
ConstantForceMeasure constant_force_measure(const std::vector<double>& force);

}  // namespace flexure::mechanism
