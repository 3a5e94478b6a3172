#pragma once
// The PRBM's validity over a stroke (docs/mechanisms.md "Validity range of the PRBM"): at every
// stroke point, whether each long (fixed-pinned) segment is inside the range of Howell Table 5.1
// from which its Theta_max(K_theta) comes; where it first is not, WHAT is outside (the quantity,
// its value and the table's range), at how many points; and, from the exact model when it was
// solved, how large the PRBM's force error actually is there, so that "outside the table" is not
// read as "wrong" (lpp-a: load ratio n = 11.3 > 10 from the first point on, while the force error
// stays at 4.9-5.1 %, as inside the table).
//
// Three things put a point outside, checked in this order per l segment:
//  * the pin force points to the far side of the beam axis: load angle phi >= 180 deg, while the
//    table covers 11.3 deg (n = -5) to 174.3 deg (n = 10), phi = atan2(1, -n);
//  * the load ratio n lies outside -5 <= n <= 10;
//  * the PRB angle |Theta| exceeds Theta_max(K_theta) at that n (Howell eq. 5.63, Table 5.1).
// Small-length pivots (s) and fixed-fixed segments (paper 004) have no such table.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism {

struct PrbmStrokeValidity {
  bool has_table = false;   // the design has a fixed-pinned l segment (Table 5.1 applies)
  std::string no_table;     // when it has none: why ("s pivots only", "fixed-fixed segments")
  std::vector<int> inside;  // per stroke point: 1 inside, 0 outside; -1 where no table applies
  int points_outside = 0;
  // The first point outside (none: every point is inside, or no table applies).
  std::optional<std::size_t> first_outside;  // index into the stroke
  std::optional<double> limit;               // its Delta x, m
  int pivot = 0;           // the segment there (the described pivot number, 1 at the fixed body)
  std::string quantity;    // "load_angle_phi", "load_ratio_n" or "Theta"
  std::string unit;        // "deg" or "1"
  double value = 0.0;      // the quantity there (deg for angles)
  double table_min = 0.0;  // the range the table covers for it (Theta: 0 .. Theta_max(K_theta))
  double table_max = 0.0;
  std::string reason;  // the above in words
  // Delta x of each run of consecutive points outside, first and last point, m (lpp-a at 50
  // points: only the first point, where the pin force is nearly along the beam and n = 11.3).
  std::vector<std::pair<double, double>> outside_ranges;
  // |F_prbm - F_exact| / |F_exact| from the exact model (NaN where it was not solved, or no point
  // falls in the group): at the first point outside, the largest over the points outside, and
  // the largest over the points inside.
  double force_error_at_limit;
  double max_force_error_outside;
  double max_force_error_inside;
  PrbmStrokeValidity();
};

// The validity at each stroke point (Delta x > 0, design finalised); no force errors yet.
PrbmStrokeValidity prbm_stroke_validity(const MechanismDesign& design,
                                        const std::vector<double>& displacement);

// Fills the force errors from the two force curves of the same stroke points (exact forces of 0
// are left out: their relative error is undefined).
void add_force_errors(PrbmStrokeValidity& validity,
                      const std::vector<double>& force_prbm,
                      const std::vector<double>& force_exact);

// One line for people: "left at 1 of 50 stroke points (Delta x = 0.00032 m, 2 % of the stroke):
// <reason>; the PRBM force error (against the exact model) is 5.10 % there, at most 5.10 % outside
// the table and 5.05 % inside"; or "inside Howell Table 5.1 at all 50 stroke points; ...", or why
// no table applies.
std::string describe_validity(const PrbmStrokeValidity& validity, double stroke);

}  // namespace flexure::mechanism
