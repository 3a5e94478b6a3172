#pragma once
// Printed results of the sources, kept as data to compare against (never as model input beyond
// the design variables config, R, K1, K2 and d):
//  * the 68 sub-classes of Weight (2001) Tables 7.2, 7.4, 7.6, 7.9, 7.12 (= App. D Tables D.1/D.2),
//    data/weight_thesis_subclasses.csv, and their thickness and width ratios of Tables 7.7, 7.10,
//    7.13, data/weight_thesis_thickness_ratios.csv;
//  * the ten class-level rows of thesis Table 2.1, data/weight_table_2_1.csv;
//  * the ten rows of Howell's Table 10.1, data/howell_table_10_1.csv.
// Numbers are copied as printed, including known errata; the traps are flagged per row. The files
// are compiled into the library (cmake/embed_data.cmake) and read at the first call; a malformed
// file throws InvalidInput naming the file, row and column.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace flexure::cfm {

// Decimal places printed in the Ch. 7 tables (the tolerance of "reproduced within rounding").
inline constexpr int kPrintedDecimalsPhi = 4;
inline constexpr int kPrintedDecimalsBeta = 3;
inline constexpr int kPrintedDecimalsPsi = 3;
inline constexpr int kPrintedDecimalsLambda = 3;
inline constexpr int kPrintedDecimalsXiPrime = 1;
inline constexpr int kPrintedDecimalsKappa = 2;
inline constexpr int kPrintedDecimalsDN = 2;
inline constexpr int kPrintedDecimalsInputs = 4;  // R, K1, K2

// One row of the Ch. 7 master table. Name = configuration-subclass as in the thesis: a letter for
// the design stroke (a = 16 %, b = 40 %), the Xi' constraint of the optimisation (99, 95, ...) and
// orientation flags (I in-plane, O out-of-plane, o possibly out-of-plane); see docs/cfm.md.
struct CfmSubclass {
  const char* name;               // e.g. "lpp-a", "slp-bIO"
  const char* config;             // e.g. "lpp"
  double stroke_percent;          // design stroke d: 16 (a) or 40 (b)
  int primary_pivot;              // p
  double percent_constant_force;  // Xi'_ex as printed
  double R;
  double K1;  // printed (0 for a missing spring, 1 for class 1B)
  double K2;
  std::optional<double> kappa1;  // "-" where the pivot has no spring
  std::optional<double> kappa2;
  std::optional<double> kappa3;
  double Phi;   // stroke average
  double beta;  // stroke average
  double Psi;   // normalised within the same d
  double lambda;
  double M;  // power-law fit alpha_p = M d^n (nonlinear LSQ, Ch. 7)
  double n;
  double d_N_max;  // normal displacement at the end of the stroke, % r_tot
  // The row reproduces only with the stroke clamped at the toggle position:
  // R = 0.4323 -> 37.04 %, R = 0.3000 -> 26.62 %.
  bool toggle_clamped;
};

// The 68 rows in the thesis's order.
const std::vector<CfmSubclass>& thesis_subclasses();

// The sub-class `name`: an exact match, else a unique match ignoring case and the orientation
// flags (so "slp-b" finds "slp-bIO"), optionally prefixed by the class ("2A-slp-bIO"). Throws
// InvalidInput naming the candidates when the name is unknown or ambiguous.
const CfmSubclass& find_thesis_subclass(const std::string& name);

// One row of thesis Tables 7.7, 7.10, 7.13 (= App. D): thickness and width
// ratios of the flexures of the multi-flexure sub-classes (2A, 2B, 3A). Index 0..2 = pivot 1..3;
// empty where the pivot is a pin.
struct CfmThicknessRatios {
  const char* name;  // sub-class, as in thesis_subclasses()
  int primary_pivot;
  int decimals;                                  // printed decimals (2; 3 for the sss rows)
  std::array<std::optional<double>, 3> C;        // min over the stroke of alpha_p/alpha_i
  std::array<std::optional<double>, 3> D_equal;  // K_{i-1} kappa_p/(K_{p-1} kappa_i)
  std::array<std::optional<double>, 3> D_min;    // D_equal/C^3
};
// The 45 rows in the thesis's order.
const std::vector<CfmThicknessRatios>& thesis_thickness_ratios();

// One class-level row of thesis Table 2.1 or Howell Table 10.1 (the original optimisation of
// Millar et al. 1996, 50 equally spaced stroke points).
struct CfmClassRow {
  const char* name;        // "table2.1-1A-a", "howell10.1-2B-b", ...
  const char* class_name;  // "1A" ... "3A"
  const char* config;      // configuration evaluated for the class (the all-s-pivot member; Phi
                           // and Xi depend only on the class with uniform sampling)
  double stroke_percent;   // 16 or 40
  double R;
  std::optional<double> K1;  // "-" printed where the class has no such spring
  std::optional<double> K2;
  double Xi;   // max F/min F as printed
  double Phi;  // mean Phi as printed
  // Howell's 2B rows print K2 = 0.1208 with Xi and Phi that belong to K2 ~ 1 (docs/errata.md):
  // not reproducible from the printed inputs.
  bool reproducible;
};

const std::vector<CfmClassRow>& thesis_table_2_1();
const std::vector<CfmClassRow>& howell_table_10_1();
// A row of either table by exact name; nullptr if there is none.
const CfmClassRow* find_class_row(const std::string& name);

}  // namespace flexure::cfm
