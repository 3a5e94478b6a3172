#pragma once
// Nondimensional PRBM model of a constant-force slider mechanism (Weight 2001 ch. 2, 4, 5 and
// App. B.1.3; Howell §10.1): force function Phi over a stroke, its mean, the percent constant force
// Xi' = 100 min F/max F, and the derived design quantities of the thesis tables (beta, lambda,
// kappa_i, primary pivot, Psi, d_N).
//
// Inputs are the thesis's design variables: configuration, R = r3/r2, K1 = k2/k1, K2 = k3/k1 and
// the stroke d in % of r2 + r3. Strokes past the toggle position are clamped as the thesis code
// does (App. B.1.3 `rimin`; docs/cfm.md §1.3); the result says so (stroke_clamped) and reports
// the effective stroke.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "flexure/solver/common/status.h"

namespace flexure::cfm {

// The nine constant-force slider configurations of Weight (2001), thesis §3.2 and Tables 4.4, 5.1,
// 8.1 (docs/cfm.md §1.2): a
// slider-crank (ground pivot 1, crank r2, middle pivot 2, coupler r3, slider pivot 3) whose three
// pivots are each a pin (p), a small-length flexural pivot (s) or a long fixed-pinned flexible
// segment (l). The configuration string lists the pivots in the order ground, middle, slider.
//
// Only what the nondimensional PRBM needs is kept here: which torsional springs exist, the PRBM
// constants of each flexible segment, and the link each long segment replaces. Dimensional
// segment sizes belong to the mechanism assembler (mechanism.h), not to this model.

enum class PivotType { kPin, kSmall, kLong };

// PRBM constants of one pivot type (Weight 2001 §2.2, App. A.2/A.3; code `gamma`, `Ktheta`,
// `roedata`), taken from the elements: s the small-length flexural pivot (gamma 1, K = EI/l,
// Howell eq. 5.14), l the fixed-pinned segment with Howell's averages (§5.2,
// howell_average_fixed_pinned()).
struct SegmentConstants {
  double gamma = 0.0;    // characteristic radius factor (s: 1)
  double K_theta = 0.0;  // stiffness coefficient (s: 1)
  double rho = 1.0;      // flexible length / associated rigid length (s: mu = 0.1, l: 1/gamma)
};
// Constants of each pivot type; a pin has gamma = K_theta = 0 (no spring, no stress).
SegmentConstants segment_constants(PivotType type);

struct CfmConfiguration {
  std::string name;                   // "lpp", "sss", ... (pivots 1, 2, 3)
  std::string class_name;             // PRBM class: "1A", "1B", "2A", "2B", "3A" (thesis §3.2.1)
  std::array<PivotType, 3> pivots{};  // pivot 1 (ground), 2 (middle), 3 (slider)
  // A long segment at pivot 2 replaces link 2 (r2, as in the tabulated plp rows, "pl2p") or
  // link 3 (r3, as in slp); thesis code `pivotparam(2,2)` (App. B.1.3).
  bool middle_long_on_r2 = false;

  bool has_spring(int pivot) const { return pivots[pivot - 1] != PivotType::kPin; }  // 1..3
  // Class 1B has no spring at the ground, so k2 is the reference stiffness (thesis eq. 2.19).
  bool is_class_1B() const { return !has_spring(1); }
};

// The nine configurations in the thesis's order (1A spp, lpp; 1B psp, plp; 2A ssp, slp;
// 2B sps, lps; 3A sss).
const std::vector<CfmConfiguration>& cfm_configurations();
// The configuration named `name` (lower case, e.g. "lps"); throws InvalidInput listing the nine
// names otherwise.
const CfmConfiguration& find_cfm_configuration(const std::string& name);

struct CfmParameters {
  std::string config;            // configuration name: spp, lpp, psp, plp, ssp, slp, sps, lps, sss
  double R = 1.0;                // r3/r2 (thesis eq. 2.10), > 0
  std::optional<double> K1;      // k2/k1 (eq. 2.11); required when pivot 2 has a spring, except
                                 // class 1B where k2 is the reference and K1 = 1 (eq. 2.19)
  std::optional<double> K2;      // k3/k1 (eq. 2.12); required when pivot 3 has a spring
  double stroke_percent = 16.0;  // d: design stroke in % of r2 + r3, 0 < d <= 100
};

// How the stroke 0 < Delta x <= d (r2 + r3) is sampled for the mean and the min/max.
enum class StrokeSampling {
  // Weight's Matlab model (App. B.1.3, `deltax=0.001:0.001*ri*d:ri*d`, last point forced to ri*d):
  // the mechanism is scaled to l_tot = 1 (r_tot = 1/lambda), the first point is Delta x = 0.001
  // and the step is 0.001 r_tot d, i.e. about 1000 points. The Ch. 7 tables (68 sub-classes) use
  // this sampling, which is why the first point depends on lambda (psp-a and plp-a differ in the
  // fourth digit of Phi).
  kThesisCode,
  // `points` equally spaced points Delta x = k d (r2 + r3)/points, k = 1..points: Howell §10.1
  // "50 equally spaced points" (Table 10.1 = thesis Table 2.1); the 0/0 point Delta x = 0 is left
  // out.
  kUniform,
};

struct CfmOptions {
  StrokeSampling sampling = StrokeSampling::kThesisCode;  // see StrokeSampling
  int points = 50;  // number of points for kUniform (>= 1); ignored by kThesisCode
  // Evaluate only every stride-th point of the sampling (the 1st, 1 + stride-th, ...) and its
  // last point: a subset of the full sampling with the same first and last points, so its
  // Phi_min/Phi_max lie inside the full sampling's and its Xi' and C are never below them; the
  // mean Phi counts the points in between on straight lines, which keeps it within
  // O((stride step)^2) of the full sampling's. For the coarse phase of a synthesis
  // (mechanisms/design/cfm_synthesis.h); 1 = every point.
  int stride = 1;
  bool keep_curve = false;  // fill CfmResult::curve (costs one allocation)

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

// One stroke point.
struct CfmCurvePoint {
  double stroke_percent = 0.0;  // 100 Delta x/(r2 + r3)
  double theta2 = 0.0;          // crank angle, rad
  double theta3 = 0.0;          // principal coupler angle, rad (<= 0)
  double Phi = 0.0;             // F r2/k1 (class 1B: F r2/k2)
};

struct CfmResult : SolveStatus {
  std::string config;      // configuration name
  std::string class_name;  // 1A ... 3A
  double R = 0.0;
  double K1 = 0.0;  // as used (0 for a missing spring, 1 for class 1B)
  double K2 = 0.0;
  double requested_stroke_percent = 0.0;  // d as given
  double stroke_percent = 0.0;            // effective stroke after the toggle clamp
  double toggle_stroke_percent = 0.0;     // d_lim of the clamp (docs/cfm.md §1.3)
  bool stroke_clamped = false;            // requested stroke was past the toggle position
  double Phi = 0.0;      // mean of Phi over the sampled stroke (thesis `average_phi`)
  double Phi_min = 0.0;  // smallest sampled Phi
  double Phi_max = 0.0;  // largest sampled Phi
  double Xi = 0.0;       // Phi_max/Phi_min (eq. 2.17); unbounded when force_vanishes
  // Phi_min <= kForceVanishesRelative |Phi_max| (mechanisms/cfm/constant_force.h): the force is
  // zero within the stroke to rounding (a class 1A mechanism at its toggle position, where the
  // crank spring's moment has no lever along the slider) or changes sign; Xi is then meaningless.
  bool force_vanishes = false;
  double percent_constant_force = 0.0;  // Xi' = 100 Phi_min/Phi_max (eq. 5.22)
  double lambda = 0.0;                  // l_tot/r_tot, length parameter (thesis Table 5.1)
  double beta = 0.0;  // F r_tot^2/(E I_ref) averaged over the stroke (eq. 4.43; 1B eq. 4.55)
  std::array<double, 3> kappa{};  // kappa_i = gamma zeta K_theta/rho (eq. 4.51); 0 for a pin
  int primary_pivot = 0;          // pivot (1..3) with the highest stress at the end of the stroke
  std::array<double, 3> alpha_end{};  // stress parameter alpha_i (eq. 4.16) at the end of stroke
  double Psi_raw = 0.0;               // stiffness parameter (eq. 5.19) before normalisation
  // Psi_raw divided by the thesis's normaliser for the same design stroke: 0.4518 (code `fgoal`,
  // lpp-a) at d = 16 %, 0.1032 (back-computed from lpp-b's printed Psi = 1.002, Table 7.2) at
  // d = 40 %; empty otherwise.
  std::optional<double> Psi;
  // Thickness and width ratios of the non-primary flexures (thesis eqs. 5.31-5.36, Tables 7.7,
  // 7.10, 7.13); empty for a pin, 1 for the primary pivot:
  //  C_i = min over the sampled stroke of alpha_p/alpha_i (largest thickness ratio h_i/h_p at
  //        equal stress);
  //  D_equal_i = K_{i-1} kappa_p/(K_{p-1} kappa_i) (width ratio b_i/b_p at equal thickness);
  //  D_min_i = D_equal_i/C_i^3 (width ratio at the largest allowed thickness).
  std::array<std::optional<double>, 3> C;
  std::array<std::optional<double>, 3> D_equal;
  std::array<std::optional<double>, 3> D_min;
  // min over the sampled stroke of alpha_j/alpha_i for every pair (j, i) of distinct sprung
  // pivots (+inf on the diagonal, for a pin, and where alpha_i is never positive): C_i is
  // alpha_ratio_min[p - 1][i]. A synthesis asks what C would be were another pivot the primary
  // one (mechanisms/design/cfm_synthesis.h).
  std::array<std::array<double, 3>, 3> alpha_ratio_min{};
  double d_N_max = 0.0;  // normal displacement of pivot 2 at the end of the stroke, % r_tot
                         // (eq. 5.45)
  std::vector<CfmCurvePoint> curve;  // only with CfmOptions::keep_curve

  // converged(): closed form: true whenever every sampled Phi is finite
  // iterations: stroke points evaluated
  // residual: largest loop-closure residual of eq. 2.3 over the stroke, / r2
  // warnings: kStrokeClamped when the stroke was clamped, kForceVanishes with force_vanishes
};

// Length parameter lambda = l_tot/r_tot (thesis Table 5.1): a long segment replacing link i is
// r_i/gamma long; an s-pivot at the ground or slider end adds half its flexure, 0.05 r_i.
double length_parameter_lambda(const CfmConfiguration& configuration, double R);

// kappa_i = gamma_i zeta_i K_theta_i/rho_i (thesis eq. 4.51); zeta = R+1 at the ground, 1/R+1 at
// the slider, 2 for a middle s-pivot, R+1 or 1/R+1 for a middle long segment replacing r2 or r3.
std::array<double, 3> pivot_kappa(const CfmConfiguration& configuration, double R);

class CfmModel {
 public:
  explicit CfmModel(CfmOptions options = {});
  // Throws InvalidInput for an unknown configuration, R <= 0 or non-finite, K < 0 or non-finite,
  // a missing K for an existing spring or a nonzero K for a missing one, d outside (0, 100], and
  // d = 100 with R = 1 (the fully folded position, where Phi is 0/0).
  CfmResult evaluate(const CfmParameters& parameters) const;

  const CfmOptions& options() const { return options_; }

 private:
  CfmOptions options_;
};

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
