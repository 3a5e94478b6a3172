#pragma once
// The description of any planar compliant mechanism (issue 31; docs/mechanisms.md "General
// mechanisms"): rigid bodies with named points, joints between them, flexures between points of
// two bodies, linear and torsion springs, dead loads, and one input.
//
// Conventions. SI units (m, N, N m, Pa, rad). Every point is given in global coordinates in the
// *described configuration*, the as-made state in which every flexure is straight and unstressed
// and every spring is at its rest length or angle. A body's pose is its displacement (x, y) and
// rotation phi from there; the ground (body "ground") never moves. The input is an absolute
// coordinate: the x or y of a body point, or the angle of the line from one body point to another
// (measured from +x), so that a crank angle reads as in Howell's figures.
//
// The same description comes from the C++ builder below and from TOML
// (io/toml_files.h); `validate()` checks it and throws InvalidInput naming the item,
// and, for a TOML description, the file and line ("switch.toml:31: flexure 'f4': ...").
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "flexure/solver/common/section.h"

namespace flexure::mechanism::general {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

// A named point of a body, in global coordinates of the described configuration (m).
struct NamedPoint {
  std::string name;
  Vec2 position;
};

struct Body {
  std::string name;
  std::vector<NamedPoint> points;
  int line = 0;  // line of the TOML item, 0 when built in C++
};

// "body.point": a point of a body.
struct PointRef {
  std::string body;
  std::string point;
  std::string text() const { return body + "." + point; }
};

enum class JointKind {
  kPin,     // the two points coincide; relative rotation free
  kSlider,  // the point of b stays on the line of a through its point at `axis_angle`, and the two
            // bodies keep their relative angle (a prismatic joint)
  kWeld,    // the two bodies move as one
};

struct Joint {
  std::string name;
  JointKind kind = JointKind::kPin;
  PointRef a;
  PointRef b;
  double axis_angle = 0.0;  // slider: direction of the line on body a, rad from +x (described)
  int line = 0;
};

// The PRBM element that models a flexure (Howell ch. 5; elements/).
enum class PrbmKind {
  kSmallLengthPivot,  // both ends clamped; pivot at mid-length, K = EI/l (eq. 5.14)
  kFixedPinned,       // clamped to a, pinned to b at its far end; pivot (1 - gamma) l from the
                      // clamp, K = gamma K_Theta EI/l (eq. 5.72), Howell's averages gamma = 0.85,
                      // K_Theta = 2.65 (§5.2)
  kFixedGuided,       // both ends clamped; two pivots (1 - gamma) l/2 from the ends, each
                      // K = 2 gamma K_Theta EI/l (eq. 5.105), Table 5.1 n = 0
};

// The flexure's model. `--model prbm` assembles every flexure as its PRBM element and `--model
// exact` solves every one as an elastica, whatever this says; `--model mixed`
// (solve_general_mixed, general_analysis.h) gives each flexure the model named here: the exact
// elastica, its PRBM element (small-length or fixed-pinned), a rung of the model ladder
// (elements/: linear theory, the BCM, Su's PR-3R as a cantilever under the end loads its far body
// puts on it; the chained BCM marched from its root loads), Howell's chain algorithm (§7.2, N rigid
// elements; solver/chain/) as the same cantilever under its tip loads, or `auto`: the cheapest rung
// whose
// mapped tip error at the loads it carries is within `tolerance` of its length (docs/mechanisms.md
// "A model per flexure"; the ladder of `auto` has no chain: the error maps do not describe it).
enum class FlexureModel { kPrbm, kExact, kLinear, kBcm, kPrbm3r, kCbcm, kChain, kAuto };

// A straight flexure from point a (on one body) to point b (on another) in the described
// configuration; its length is their distance (a given length must agree to 1e-6).
struct Flexure {
  std::string name;
  PointRef a;
  PointRef b;
  double width = 0.0;      // b, out of the plane, m (at end a when tapered)
  double thickness = 0.0;  // h, in the plane, m (at end a when tapered)
  // Its material as the library's one Material (solver/common/section.h): E (Pa) bends it; a row
  // of the library (`material = "steel-1095-hr"` in TOML) brings its nu, S_y and density along.
  Material material;
  std::string material_id;  // the data/materials.csv id of `material`, or empty (given by value)
  double length = 0.0;      // l, m; 0: the distance from a to b
  PrbmKind prbm = PrbmKind::kSmallLengthPivot;
  FlexureModel model = FlexureModel::kPrbm;
  // auto: the largest mapped tip position error allowed, per length of the flexure (> 0).
  double tolerance = 0.0;
  // cbcm: BCM elements; chain: the chain algorithm's rigid elements N. 0: the model's default
  // (model_elements(): the CBCM's 6, the error map's; the chain's 100, as `flexure beam --method
  // chain`).
  int elements = 0;
  // The exact model only: an extensible elastica (Reissner's beam with axial strain N/EA,
  // EA = E b h; docs/extensible.md), for a flexure that must be compressed or stretched (a beam
  // between two bodies whose distance the joints fix). The mixed model's CBCM takes it too (its
  // axial stiffness d = EA l^2/EI); the PRBM and the other ladder models ignore it.
  bool extensible = false;
  // The rest shape (docs/mechanisms.md "Curved and tapered flexures"), as a physical beam's
  // (beam/physical_beam.h, `flexure beam --curvature --width-tip --thickness-tip`): a stress-free
  // curvature kappa0 (1/m; positive bends to the left of the tangent: m = EI (theta' - kappa0), a
  // chain segment's kappa0) makes the flexure a circular arc from a to b, of length `length` or,
  // when that is 0, the minor arc over the chord; a taper makes the rectangle linear from (width,
  // thickness) at end a to (width_tip, thickness_tip) at end b (0: the root's value). The exact
  // model solves either (the shooting integrator's kappa0 and EI_profile); the PRBM has Howell's
  // initially curved cantilever (§5.5, Table 5.2) for a curved fixed-pinned flexure with
  // |kappa0 l| <= 2, and no tapered element.
  double curvature = 0.0;
  double width_tip = 0.0;
  double thickness_tip = 0.0;
  int line = 0;

  // The elements its model uses: `elements`, or the model's default when 0 (see there).
  int model_elements() const {
    if (elements != 0) return elements;
    return model == FlexureModel::kChain ? kDefaultChainElements : kDefaultCbcmElements;
  }
  static constexpr int kDefaultCbcmElements = 6;
  static constexpr int kDefaultChainElements = 100;

  bool curved() const { return curvature != 0.0; }
  bool tapered() const { return width_tip > 0.0 || thickness_tip > 0.0; }
  // Its length (m) when its ends are `chord` apart: the chord for a straight flexure, else
  // `length` if given, else the minor arc 2 asin(kappa0 chord/2)/kappa0 (NaN: no arc of that
  // curvature spans the chord).
  double arc_length(double chord) const;
  // The angle of its rest tangent at end a (b) from the chord a -> b: -kappa0 l/2 (+kappa0 l/2).
  double end_angle_from_chord(double chord, int end) const;

  // The section at end a as the library's Section: the rectangle width x thickness (validated by
  // GeneralMechanism::validate, not here).
  Section section() const {
    Section s;
    s.width = width;
    s.thickness = thickness;
    return s;
  }
  // E I = E b h^3/12 and E A = E b h at end a, of section() and material.
  double flexural_rigidity() const { return material.E * section().second_moment(); }
  double axial_rigidity() const { return material.E * section().area().value_or(0.0); }
};

struct LinearSpring {
  std::string name;
  PointRef a;
  PointRef b;
  double stiffness = 0.0;     // N/m
  double rest_length = -1.0;  // m; < 0: the described distance
  int line = 0;
};

struct TorsionSpring {
  std::string name;
  std::string body_a;
  std::string body_b;
  double stiffness = 0.0;   // N m/rad, on phi_b - phi_a
  double rest_angle = 0.0;  // rad: phi_b - phi_a at which the spring is relaxed (0: described)
  int line = 0;
};

// A dead (constant, non-follower) force and moment on a body point.
struct DeadLoad {
  std::string name;
  PointRef at;
  double fx = 0.0;      // N
  double fy = 0.0;      // N
  double moment = 0.0;  // N m, counter-clockwise
  int line = 0;
};

enum class InputCoordinate { kX, kY, kAngle };
enum class InputControl {
  kDisplacement,  // the coordinate is prescribed over the range
  kForce,         // a dead load conjugate to the coordinate (a force along x or y on the point, a
                  // moment on the body) is prescribed over the range
};

struct Input {
  std::string body;
  InputCoordinate coordinate = InputCoordinate::kAngle;
  std::string point;     // x, y: the point; angle: the line's first point
  std::string point_to;  // angle: the line's second point
  InputControl control = InputControl::kDisplacement;
  double start = 0.0;  // coordinate (m or rad) or load (N or N m), SI
  double stop = 0.0;
  int count = 51;
  int line = 0;
  // Rotations (rad) of named bodies from which Newton finds the first point directly, for a
  // described configuration where the input cannot move to first order (a dead point: a straight
  // slider-crank moves its slider only at second order in the crank angle, and which way the crank
  // goes is a choice). Empty: the path is followed from the described configuration.
  std::vector<std::pair<std::string, double>> start_rotation;
};

std::string_view prbm_kind_name(PrbmKind kind);    // "small-length", "fixed-pinned", "fixed-guided"
std::string_view joint_kind_name(JointKind kind);  // "pin", "slider", "weld"
// "prbm", "exact", "linear", "bcm", "prbm3r", "cbcm", "chain", "auto" (the beam's --method names).
std::string_view flexure_model_name(FlexureModel model);
// The model of that name; throws InvalidInput listing the names.
FlexureModel parse_flexure_model(std::string_view name);
std::string_view input_coordinate_name(InputCoordinate c);  // "x", "y", "angle"
std::string_view input_control_name(InputControl c);        // "displacement", "force"

struct GeneralMechanism {
  std::string name;
  std::string source;        // file name for messages (empty when built in C++)
  std::vector<Body> bodies;  // "ground" is implicit: a body of that name adds points to it
  std::vector<Joint> joints;
  std::vector<Flexure> flexures;
  std::vector<LinearSpring> linear_springs;
  std::vector<TorsionSpring> torsion_springs;
  std::vector<DeadLoad> loads;
  Input input;
  bool has_input = false;

  // Builder: each returns *this so that calls chain. Angles in rad, everything SI.
  GeneralMechanism& body(const std::string& name, std::vector<NamedPoint> points);
  GeneralMechanism& pin(const std::string& name, const std::string& a, const std::string& b);
  GeneralMechanism& slider(const std::string& name,
                           const std::string& a,
                           const std::string& b,
                           double axis_angle);
  GeneralMechanism& weld(const std::string& name, const std::string& a, const std::string& b);
  GeneralMechanism& flexure(const std::string& name,
                            const std::string& a,
                            const std::string& b,
                            double width,
                            double thickness,
                            double E,
                            PrbmKind prbm);
  GeneralMechanism& linear_spring(const std::string& name,
                                  const std::string& a,
                                  const std::string& b,
                                  double stiffness);
  GeneralMechanism& torsion_spring(const std::string& name,
                                   const std::string& body_a,
                                   const std::string& body_b,
                                   double stiffness);
  GeneralMechanism& load(
      const std::string& name, const std::string& at, double fx, double fy, double moment = 0.0);
  // The input: "body.point" for x or y; for an angle, the line "body.P" -> "body.Q" as two refs.
  GeneralMechanism& input_coordinate(InputCoordinate coordinate,
                                     const std::string& point,
                                     const std::string& point_to,
                                     InputControl control,
                                     double start,
                                     double stop,
                                     int count);

  // Throws InvalidInput naming the item (and SOURCE:LINE for a TOML item): unknown bodies or
  // points, duplicate names, non-finite coordinates, a joint or flexure or spring between points
  // of one body, a pin whose points do not coincide or a slider point off its line in the
  // described configuration (a loop that cannot close there; tolerance 1e-6 of the mechanism's
  // size), a flexure without a section or modulus or whose length disagrees with its ends, a body
  // joined to the ground by no chain of joints and flexures (unconstrained), a missing input or a
  // range with count < 2. Stiffness-related checks (a body free to move with no stiffness) need
  // the assembled model: general_analysis.h.
  void validate() const;

  // Position of a point in the described configuration; throws InvalidInput for unknown names.
  Vec2 point(const PointRef& ref) const;
  const Body* find_body(const std::string& name) const;
  // The largest distance between two points of the description (m): the mechanism's size.
  double size() const;
  // "FILE:LINE: " when the item has a line in a file, else "".
  std::string where(int line) const;
};

// Sets the model of the flexure named `flexure` (every flexure when empty) of `mechanism`, with
// auto's tolerance (per length; kept when 0) and the CBCM's or chain's elements (kept when 0 and
// the model is unchanged; a new model without elements takes its default). Throws
// InvalidInput for an unknown flexure, listing the mechanism's.
void set_flexure_model(GeneralMechanism& mechanism,
                       const std::string& flexure,
                       FlexureModel model,
                       double tolerance = 0.0,
                       int elements = 0);

// "body.point" split at the first dot; throws InvalidInput naming `what` when malformed.
PointRef parse_point_ref(const std::string& text, const std::string& what);

// One flexure of a general mechanism under a model of its own (`mechanism analyze --model mixed`,
// solve_general_mixed in general_analysis.h; docs/mechanisms.md "A model per flexure").
//
// In the mixed Newton system a flexure that is not exact is a cantilever clamped into its root
// body and loaded at its tip by the end loads of its far body: its unknowns are those tip loads
// (the exact flexures keep their root loads), and the model gives the tip's pose in the root
// frame. The CBCM is the exception: it keeps the root loads too and is marched from them
// (elements/cbcm_march.h), which needs no load path (model_tip's CBCM remains for callers that
// give tip loads). The models are the beam's --method rungs (elements/): linear theory, the BCM,
// Su's PR-3R (general constants), the chained BCM, Howell's chain algorithm (§7.2, N elements,
// solver/chain/chain_algorithm_solver.h), and the flexure's own PRBM element
// (small-length: a pin at mid-length, K = EI/l, Howell eq. 5.14; fixed-pinned: Howell's average 1R,
// pivot (1 - gamma) l from the clamp, K = gamma K_Theta EI/l, eq. 5.72).
//
// The expected error of a rung is the tip position error per length that the model ladder's map
// gives at the loads the flexure carries (beam/ladder_selector.h: 1.5 times the largest measured
// at the map's loads around it, against the elliptic solution under the same dead loads; for
// 2 < |n| <= 100 the map of axially dominated loads, data/ladder_auto_error_map_axial.csv: a
// flexure in a mechanism carries its pin force nearly along it). A load outside both maps (|n| >
// 100, alpha2 above 10 or, for |n| > 2, above 2, |mu| > 2, no transverse force with an axial one)
// or a model they do not describe (the PRBM element with its average constants, a CBCM of other
// than 6 elements, the chain algorithm) has none.

// The end loads on a flexure's tip, nondimensional in its root frame (x along the undeflected
// flexure): the force its far body puts on the tip, F l^2/EI, and the moment there, M l/EI.
struct FlexureTipLoad {
  double Fx = 0.0, Fy = 0.0, mu = 0.0;
};

// A flexure's tip in its root frame: x/l, y/l and the tip angle (rad).
struct FlexureTip {
  double x = 1.0, y = 0.0, theta = 0.0;
};

// The tip of a flexure of `model` (prbm, linear, bcm, prbm3r, or cbcm or chain with `elements`)
// under `load`. False, with the reason in `why`, where the model has no answer (the BCM past its
// buckling load, a PR-3R, CBCM or chain path that does not converge, a fixed-guided PRBM element).
bool model_tip(FlexureModel model,
               PrbmKind prbm,
               int elements,
               const FlexureTipLoad& load,
               FlexureTip& tip,
               std::string* why = nullptr);

// The exact elastica's tip under `load` along proportional loading from the unloaded beam (the
// elliptic solution: the reference of the error map). False for a load without a transverse
// component and a nonzero axial one (no Howell load ratio n) or where it does not converge.
bool exact_flexure_tip(const FlexureTipLoad& load, FlexureTip& tip);

// The mapped tip error per length of `model` at `load` (see above); NaN where it has none.
double mapped_flexure_error(FlexureModel model, int elements, const FlexureTipLoad& load);

// |tip - exact elastica tip| per length under `load` (exact_flexure_tip); NaN without one.
double measured_tip_error(const FlexureTipLoad& load, const FlexureTip& tip);

// The model's tip displacement per length |(x - 1, y)|.
inline double tip_displacement(const FlexureTip& t) { return std::hypot(t.x - 1.0, t.y); }

// The rungs `auto` tries, cheapest first: linear, bcm, prbm3r, cbcm (6 elements); then exact.
const std::vector<FlexureModel>& auto_ladder();

// What one flexure of a mixed solution used, and its expected error.
struct FlexureModelReport {
  std::string name;                               // the flexure's
  FlexureModel requested = FlexureModel::kExact;  // its model key (auto, or the model itself)
  FlexureModel model = FlexureModel::kExact;      // the model solved with
  int elements = 6;                               // cbcm, chain
  double tolerance = 0.0;                         // auto's, per length (0: none given)
  std::string reason;                             // which model and why
  // The largest mapped tip error per length over the recorded points: 0 for the exact elastica,
  // NaN where the map gives none at some point (unmapped_points says at how many).
  double expected_error_per_length = std::numeric_limits<double>::quiet_NaN();
  int unmapped_points = 0;
  // Per recorded point: its tip loads, the model's tip under them, the mapped error (NaN: none).
  std::vector<FlexureTipLoad> loads;
  std::vector<FlexureTip> tips;
  std::vector<double> mapped_error;
  // With GeneralExactOptions::measure_flexure_errors: |model tip - exact elastica tip| per length
  // under the same loads at each point (NaN where the elliptic solution cannot be had), and its
  // largest value.
  std::vector<double> measured_error;
  double measured_error_per_length = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace flexure::mechanism::general
