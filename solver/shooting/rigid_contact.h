#pragma once
// Frictionless contact of a segment chain with one rigid surface given in the root frame: a circle
// the beam wraps from its clamp, or a straight stop its tip lands on (theory, equations and
// validity: docs/contact.md).
//
// Circle (the flexure on a cylinder): the circle touches the first, flexible segment at the clamp
// (centre at distance R along the clamp's normal, on the side sigma = +1 (+y) or -1 (-y)). Once
// the root curvature of the free beam reaches sigma / R, the beam lies on the circle over
// [0, s_c] (curvature sigma / R, m = sigma EI / R, a known arc) and leaves it at the separation
// point s_c. The free span [s_c, L] is a cantilever clamped at the circle's pose at s_c, solved by
// the shooting solver; s_c closes the problem through the curvature condition
//     m(s_c+) = sigma EI / R                      (moment continuous, no concentrated moment),
// found by Brent's method on s_c. On the wrap m' = 0 makes the internal force tangent, N = T t,
// and frictionless tangential balance keeps T constant, so the circle presses with the line
// pressure p = T / R (per unit length, along the outward normal of the circle) and, at s_c, with
// the concentrated force P_c = sigma N(s_c+).n that turns the free span's shear into the wrap's
// tangent force. Contact is admissible while p >= 0 and P_c >= 0; both are checked.
//
// Line (a straight stop through `point` with unit `normal` toward the beam's side): the gap
// g = normal . (r - point) >= 0. Tip contact: a normal reaction R_n >= 0 at the tip with
// R_n g = 0 (complementarity); R_n is found by Brent's method on the tip gap.
//
// Line contact: past the load where the tip's tangent turns along the stop (t(L) . nu = 0), the
// beam lies on the stop over [a, L]: m = 0 and a straight part there, the stop carrying the
// lying part's normal loads directly (line pressure), and at a a concentrated reaction R_a; the
// free span [0, a] ends on the stop, tangent to it, with m(a) = 0. (a, R_a) solve
// gap(r(a)) = 0, t(a) . nu = 0 by Newton's method; each tip -> line change is an event.
//
// Point contact (a circle clear of the unloaded beam, e.g. a pin the beam is pressed over, or a
// stop met mid-span while the tip is free): the beam touches at one interior point s_p, tangent to
// the surface, with a force P along the surface normal grad g; the chain is cut at s_p and
// (s_p, P, phi) solve g(r(s_p)) = 0, t(s_p) . grad g = 0, (cos phi, sin phi) x grad g = 0 by
// Newton's method (forward-difference Jacobian). One contact point only: a second one is refused.
//
// Continuation: the loads follow load(lambda) = start + lambda (chain - start) (start: zero, or a
// given start tip load), in `steps` equal steps; at each step the previous contact variable
// brackets the next. Landing and lift-off are the zeros of one function of the free (contact-less)
// equilibrium, psi(lambda) = EI/R - sigma m(0) (wrap) or the free beam's smallest gap (tip or
// interior point): contact holds where psi < 0. Every sign change of psi between two steps is
// located by Brent's method and reported as an event.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

enum class ContactSurfaceType { kCircle, kLine };
const char* to_string(ContactSurfaceType type);  // "circle", "line"

struct RigidSurface {
  ContactSurfaceType type = ContactSurfaceType::kCircle;
  std::array<double, 2> center{0.0, 0.0};  // circle centre, root frame
  double radius = 0.0;                     // circle radius, > 0
  std::array<double, 2> point{0.0, 0.0};   // a point of the line, root frame
  std::array<double, 2> normal{0.0, 1.0};  // line normal toward the beam (normalised on use)
};

// What happens at an event of the continuation: contact begins (landing) or ends (lift-off), the
// tip contact opens into a line contact or closes back to the tip.
enum class ContactEventKind { kLanding, kLiftOff, kLineContact, kTipContact };
// "landing", "lift-off", "line-contact", "tip-contact" (the JSON key and HDF5 dataset `kind`).
const char* to_string(ContactEventKind kind);
// The kind of that name; throws InvalidInput listing the four.
ContactEventKind contact_event_kind_from_string(std::string_view name);

// Landing (contact begins) or lift-off (contact ends) along the continuation.
struct ContactEvent {
  ContactEventKind kind = ContactEventKind::kLanding;
  double load_factor = 0.0;  // located to RigidContactSolver::Options::event_tolerance
};

// How the beam touches at the returned point: not at all, a circle wrapped from the clamp, the tip
// on a stop, one interior point (tangent), or the beam lying on a stop from the separation point
// to its tip.
enum class ContactKind { kNone, kWrap, kTip, kPoint, kLine };
// "none", "wrap", "tip", "point", "line" (the JSON key and HDF5 attribute `contact_kind`).
const char* to_string(ContactKind kind);
// The kind of that name; throws InvalidInput listing the five.
ContactKind contact_kind_from_string(std::string_view name);

// One step of the continuation.
struct ContactPathPoint {
  double load_factor = 0.0;
  bool in_contact = false;
  double separation_s = 0.0;  // circle: s_c (0 without contact); line: the tip's s in contact
  double normal_force = 0.0;  // circle: P_c; line: R_n (0 without contact)
  double indicator = 0.0;     // psi(lambda): < 0 where contact holds
  ChainPose tip;
};

struct ContactResult : SolveStatus {
  // residual: |m(s_c) - sigma EI/R| (circle) or |gap at the tip| (line) at the returned point
  ContactSurfaceType surface = ContactSurfaceType::kCircle;
  int surface_index = 0;  // several surfaces: the one this result is about (0-based)
  bool in_contact = false;
  ContactKind kind = ContactKind::kNone;  // how the beam touches at the returned point
  double load_factor = 0.0;               // reached (1 when converged)
  // Contact region on the beam (arc lengths from the root); equal ends for point contact, both 0
  // without contact.
  double s_start = 0.0;
  double s_end = 0.0;
  // Separation points (circle: s_c, where the beam leaves the circle; line contact: a, where it
  // leaves the stop) and their poses.
  std::vector<double> separation_s;
  std::vector<ChainPose> separation_points;
  // Contact loads on the beam, root frame.
  std::array<double, 2> contact_force{0.0, 0.0};  // total: point force + pressure resultant
  std::array<double, 2> point_force{0.0, 0.0};    // concentrated force (at s_c or a, or the tip)
  double point_force_normal = 0.0;                // its magnitude along the surface normal, >= 0
  double line_pressure = 0.0;        // circle: p = T/R on the wrap; line contact: the stop's
                                     // pressure on the lying part, -(q + q_f n) . nu (force per
                                     // length), >= 0
  double tip_reaction_normal = 0.0;  // line contact: the stop's concentrated reaction at the tip
                                     // (the tip load's normal part), >= 0
  double lying_axial_force = 0.0;    // line contact: N . tau of the lying part at the separation
                                     // point (the load along the stop it carries to the span)
  double wrap_tension = 0.0;         // circle: T, the constant tangential force on the wrap
  double separation_moment = 0.0;    // circle: m(s_c+) of the free span
  double curvature_condition = 0.0;  // circle: m(s_c+) - sigma EI/R (0 at the solution)
  double min_gap = 0.0;              // smallest gap of the free part (>= -tolerance)
  double tip_gap = 0.0;              // gap at the tip
  ChainPose tip;
  Reaction reaction;              // loads the clamp applies to the chain
  Reaction tip_load;              // the applied tip load at the returned load factor
  std::vector<ShapePoint> shape;  // on request: wrap arc and free span together
  std::vector<ContactEvent> events;
  std::vector<ContactPathPoint> path;  // one point per continuation step (and per event)
  int steps = 0;
  long shooting_solves = 0;
  // The stability verdict of the returned equilibrium (docs/contact.md, "Stability"): the second
  // variation on the variations the contact admits. A contact with positive pressure holds the
  // beam to the surface there (bilateral to second order): the wrap is held to the circle, so the
  // free span is judged as a cantilever clamped at the separation point; a tip on a stop has its
  // normal coordinate held; an interior point on a stop has its normal coordinate held and the
  // rolling of the contact point adds P eta(s_p)^2 / |kappa(s_p)|. Without contact, the free
  // beam's verdict. An interior point contact with a circle and a line contact are not judged
  // (not_checked, the message says why); nor is an unconverged result.
  Stability stability;
};

class RigidContactSolver {
 public:
  struct Options {
    ShootingSolver::Options shooting;  // the free span's solver
    int steps = 20;                    // continuation steps from the start load to the full load
    double event_tolerance = 1e-12;    // landing / lift-off load factors, absolute
    double contact_tolerance = 1e-13;  // s_c (in lengths) and R_n root tolerances (relative)
    double gap_tolerance = 1e-9;       // penetration accepted in the free part (in lengths)
    int gap_samples = 401;             // shape samples for the penetration check
    int shape_points = 0;              // > 1: return the shape at this many points
    bool judge_stability = true;       // ContactResult::stability (false: not_checked)
    StabilityOptions stability;        // its accuracy (segment_chain.h)
    // Throws InvalidInput naming the first field outside its range.
    void validate() const;
  };

  RigidContactSolver() = default;
  explicit RigidContactSolver(Options options) : options_(options) {}

  // Throws InvalidInput for a combination the contact model does not cover (naming why): a
  // circle not tangent to the first segment at the clamp, an end other than free, a follower
  // force, distributed loads, extension, an EI_profile or kappa0 on the wrapped segment, a
  // stop the clamp lies behind. Never throws for non-convergence (converged() false, message).
  // `start_tip_load`: the tip load at lambda = 0 (default: none).
  ContactResult solve(const SegmentChain& chain,
                      const RigidSurface& surface,
                      const TipLoad& start_tip_load = {}) const;

  // Several surfaces, at most one touched at a time (docs/contact.md, "Several surfaces"): one
  // continuation per surface with every other one checked for crossing at each step (the 401
  // samples of the shape). The result is the run whose surface the beam touches (surface_index),
  // or the free beam; where the beam would touch two at once, the failure of the run that came
  // furthest, naming both contacts (converged() false). Throws InvalidInput for an empty list or
  // any surface the single-surface solve refuses.
  ContactResult solve(const SegmentChain& chain,
                      const std::vector<RigidSurface>& surfaces,
                      const TipLoad& start_tip_load = {}) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace flexure
