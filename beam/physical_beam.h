#pragma once
// Beams in physical units (SI): the cantilever a designer describes by its length, modulus,
// section and tip loads, and segment chains in SI units (built from objects or read from TOML).
// The solvers stay nondimensional (Howell's alpha2 = Fy L^2/EI, n = -Fx/Fy, mu = M L/EI, eqs.
// 2.67, 2.83); this layer converts in and out, and adds what the nondimensional keys do not say:
// the tip position in metres, the bending moment along the beam, the largest bending stress
// M c / I and the safety factor against yield (docs/units.md).
#include <optional>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/section.h"

namespace flexure {

// An initially straight cantilever of uniform section, clamped at the origin along +x, loaded at
// its free end. Fx and Fy are in the beam's frame: +x along the undeformed beam from the clamp, +y
// perpendicular; M counter-clockwise.
//
// Its cross-section and material are the library's one Section and Material (solver/common/
// section.h, as a PhysicalChain's segments have them): the section is the rectangle b x h (width
// out of the plane of bending, thickness in it: I = b h^3/12) or a general section given by I,
// with its thickness h where known (the stress M c/I needs c = h/2); the material gives E, the
// yield strength S_y for the safety factor, the density of the self-weight and Poisson's ratio.
// Poisson's ratio is used only where given (nu_given: the extensible beam, plate on or auto): set
// it with set_nu(), which keeps material.nu and nu_given together. A front end that reads I, width
// and thickness separately builds the section with set_section() (which refuses a section given
// twice or half a rectangle); validate() names a bad value by its flag (--width, --E, ...).
struct PhysicalCantilever {
  double length = 0.0;    // L, m
  Section section;        // at the clamp for a tapered beam; m, m^4
  Material material;      // E and S_y in Pa, density in kg/m^3, nu
  bool nu_given = false;  // whether material.nu was given (see set_nu)
  double Fx = 0.0;        // N
  double Fy = 0.0;        // N
  double M = 0.0;         // N m
  // Distributed loads and extension (docs/distributed-loads.md, docs/extensible.md); any of them
  // makes the beam a one-segment chain (shooting or chain method).
  double qx = 0.0;          // dead load per unit length along the undeformed beam, N/m
  double qy = 0.0;          // dead load per unit length perpendicular to it, N/m
  double q_follower = 0.0;  // pressure along the deflected normal, N/m
  // material.density (kg/m^3) adds the self-weight rho A g along -y (needs the rectangle).
  double g = 9.80665;       // m/s^2
  bool extensible = false;  // EA = E A, GAs = k E A / (2 (1 + nu)) (needs the rectangle and nu)
  double shear_coefficient = 5.0 / 6.0;  // Timoshenko's k of the rectangle
  // The bending modulus (docs/plate-modulus.md): off E, on E/(1 - nu^2), auto by the Searle
  // parameter b^2/(R h) at the beam's largest curvature. plate_applied is the decision the
  // flexural rigidity uses: on sets it, auto is decided by solve_physical_beam (which sets it on
  // its copy); the axial and shear rigidities keep E (the plate effect is a bending one).
  PlateRule plate = PlateRule::kOff;
  bool plate_given = false;  // --plate was given (then --nu is accepted even with off)
  bool plate_applied = false;
  // The shape of the beam (docs/cli.md "Curved, tapered and supported physical beams"): the
  // stress-free curvature kappa0 (1/m, positive bends toward +y: m = EI (theta' - kappa0)), and a
  // linear taper of the rectangle from (width, thickness) at the clamp to (width_tip,
  // thickness_tip) at the tip (either or both; the other keeps its root value). Any of them makes
  // the beam a one-segment chain.
  double curvature = 0.0;
  std::optional<double> width_tip;      // m
  std::optional<double> thickness_tip;  // m
  // The far end (`flexure beam --boundary`, `path --boundary`): free (the default, loads given)
  // or a prescribed tip, in metres and radians (unset: the stress-free tip value). A load
  // conjugate to a prescribed coordinate must be 0 (it is the support's reaction).
  EndCondition end = EndCondition::kFree;
  TipPrescription prescribed;

  // Whether any of the above is given.
  bool beyond_elastica() const {
    return qx != 0.0 || qy != 0.0 || q_follower != 0.0 || material.density.has_value() ||
           extensible;
  }
  // A stress-free curvature or a taper: not Howell's straight uniform beam (a one-segment chain,
  // solved by the shooting or chain method).
  bool shaped() const { return curvature != 0.0 || tapered(); }
  bool tapered() const { return width_tip.has_value() || thickness_tip.has_value(); }
  bool rectangle() const { return section.shape == Section::Shape::kRectangle; }

  // Poisson's ratio where given (nu_given), else empty: what the extensible beam and the plate
  // rules read. set_nu gives it (or, empty, returns material.nu to Material's default).
  std::optional<double> given_nu() const {
    return nu_given ? std::optional<double>(material.nu) : std::nullopt;
  }
  void set_nu(std::optional<double> nu) {
    nu_given = nu.has_value();
    material.nu = nu.value_or(Material{}.nu);
  }
  // The section from the values a front end reads one by one, each given or not: I alone (a
  // general section without a thickness), or width and thickness (the rectangle). Throws
  // InvalidInput naming --I, --width and --thickness for neither, both, or half a rectangle; the
  // values themselves are checked by validate() (a 0 or NaN width is refused there, naming
  // --width). The length and material.E are checked first, as validate() checks them before the
  // section: set them before calling it, and the messages come in validate()'s order.
  void set_section(std::optional<double> I,
                   std::optional<double> width,
                   std::optional<double> thickness);

  // b h, where the section is a rectangle (at the clamp, for a tapered beam).
  std::optional<double> area() const { return section.area(); }
  // The rectangle at arc length s (m) of a tapered beam, linear from the clamp to the tip; the
  // root's for a beam without a taper. The width of a rectangle only; the thickness where known.
  std::optional<double> width_at(double s) const;
  std::optional<double> thickness_at(double s) const;
  // b h^3/12 at s (I for a general section).
  double second_moment_at(double s) const;
  // The dead load per unit length including the self-weight, N/m (at the clamp for a taper, whose
  // self-weight varies along it: self_weight_profile()).
  double total_qy() const {
    return qy - (material.density ? *material.density * area().value_or(0.0) * g : 0.0);
  }

  // Throws InvalidInput naming the bad field by its flag (--length, --E, --I, --width, ...):
  // length, modulus and section > 0 and finite, finite loads, a yield strength > 0 with a thickness
  // to compute a stress with, a density or extension with the rectangle, nu where a rule needs it
  // and in (-1, 0.5), a taper of the rectangle; then Section::validate() and Material::validate()
  // for what no flag gives (an I on a rectangle: Section::I), and material.nu set without set_nu().
  void validate() const;
  // section.second_moment(): I, or b h^3/12 for the rectangle.
  double second_moment() const;
  // E, or E/(1 - nu^2) when the plate modulus applies (plate on, or auto decided for it).
  double bending_modulus() const;
  double flexural_rigidity() const { return bending_modulus() * second_moment(); }
  // Howell's nondimensional problem of this beam, forward (the load is given). A purely axial load
  // (Fy = 0, Fx != 0) has no Howell's n; it is then a one-segment chain with the same
  // nondimensional loads, which the shooting and chain methods solve; so is a curved or tapered
  // beam, one with distributed loads or extension, and any end but free (`end`, `prescribed`). The
  // method settings (tolerance, integrator, shape points, ...) are those of `settings`.
  BeamProblem to_problem(BeamProblem settings = {}) const;
  // Howell's nondimensional chain of this beam (length 1, EI 1 at the clamp: forces F L^2/EI,
  // moments M L/EI, kappa0 L; a taper as EI_profile relative to the clamp's EI at
  // kTaperStations stations) with the far end `end` and the prescribed tip values given in metres
  // and radians (`flexure path`, which takes any end condition). Throws InvalidInput for a load on
  // a prescribed coordinate (it is the support's reaction) and for loads that overflow.
  SegmentChain to_chain(EndCondition end, const TipPrescription& prescribed_m = {}) const;
  // The same with the beam's own `end` and `prescribed`.
  SegmentChain to_chain() const { return to_chain(end, prescribed); }
  // The section modulus I/c (m^3) and area (m^2) at `points` equally spaced arc lengths from the
  // clamp to the tip (the section there, for a taper): the fibre stresses N/A -+ m c/I of shapes
  // (`flexure path --shapes`). Both empty without the rectangle (a general section).
  void fibre_sections(int points, std::vector<double>& modulus, std::vector<double>& area) const;
  // Stations of a taper's EI_profile (and self-weight profile): a width taper makes EI linear in s
  // (exact with any count); a thickness taper cubic, whose linear interpolation between 1025
  // stations departs from b h(s)^3/12 by at most (1/1024)^2/8 max|EI''|/EI, below 1e-6 for a tip
  // thickness from 1/2 to 2 times the root's.
  static constexpr int kTaperStations = 1025;
};

// The internal forces at the points of a solved shape of `chain` (the chain's own units: the
// shape's s, x, y as the solver returns them), from the statics of the part between the clamp and
// each point, with `root` the clamp's reaction on the chain (docs/units.md "Internal forces"):
// the bending moment m, N . t and N . n (N the force the part beyond s exerts on the part before
// it, n the normal left of the tangent; dm/ds = -V). Joint loads and the distributed loads of
// `chain` (a dead load by the midpoint rule over the shape's intervals, a follower pressure exact
// for each chord) enter as in solve_physical_beam.
struct ShapeInternalForces {
  std::vector<double> moment, axial, shear;
};
ShapeInternalForces shape_internal_forces(const SegmentChain& chain,
                                          const std::vector<ShapePoint>& shape,
                                          const Reaction& root);

// One point of the deflected shape in SI units.
struct PhysicalShapePoint {
  double s = 0.0;       // arc length from the clamp, m
  double x = 0.0;       // m
  double y = 0.0;       // m
  double theta = 0.0;   // rad
  double moment = 0.0;  // bending moment, N m (counter-clockwise on the part nearer the clamp)
  std::optional<double> stress;  // |M| c / I (+ |N_a|/A for an extensible beam), Pa
  double axial_force = 0.0;      // N_a = N . t, N (tension positive)
  // V = N . n with n = (-sin theta, cos theta) the normal left of the tangent and N the force the
  // part beyond s exerts on the part before it; dm/ds = -V (docs/units.md "Internal forces").
  double shear_force = 0.0;
  // The stress at the fibre h/2 along +n and along -n: N_a/A -+ m c/I (a positive moment
  // compresses the +n fibre). Empty without the section's area and thickness (EI alone).
  std::optional<double> stress_pos_fibre, stress_neg_fibre;
};

struct PhysicalResults {
  double length = 0.0;                     // total arc length, m
  double tip_x = 0.0;                      // m
  double tip_y = 0.0;                      // m
  double theta0 = 0.0;                     // tip angle, rad
  double root_moment = 0.0;                // bending moment at the clamp, N m
  double max_moment = 0.0;                 // largest |bending moment| along the beam, N m
  double max_moment_at = 0.0;              // arc length where it acts, m
  std::optional<double> max_stress;        // largest M c / I, Pa (needs every flexible section)
  std::optional<double> max_stress_at;     // m
  std::optional<double> safety_factor;     // yield strength / max_stress (null when unloaded)
  double max_axial_force = 0.0;            // largest |N . t| along the beam, N
  std::optional<double> max_axial_strain;  // largest |N . t| / EA (extensible segments only)
  std::optional<double> yield_strength;
  // How the maximum was found: "shape" (sampled along the solved shape, refined by a parabola
  // through the largest sample and its neighbours) or "ends" (the PRBM, which has no shape: the
  // larger of the root and tip moments).
  const char* max_from = "shape";
  std::vector<PhysicalShapePoint> shape;  // the points the caller asked for
  // The bending modulus used and why (docs/plate-modulus.md); one per flexible segment of a
  // chain with a section (empty for segments given by EI), one for a cantilever.
  std::vector<ModulusChoice> modulus;
};

// Solves a physical cantilever with `method` (any beam method). `settings` gives the method's
// settings (tolerance, integrator, chain elements) and in shape_points (0 or >= 2) the shape points
// to report; its loads are replaced by the beam's. The moment maximum is searched on a denser
// shape (>= 2001 points) of which the reported points are a subset. The BeamSolution carries the
// nondimensional keys (its shape holds the requested points).
struct PhysicalBeamSolution {
  BeamSolution solution;
  PhysicalResults physical;
  std::vector<double> segment_max_moment;  // chains with plate = "auto": largest |m| per segment

  // The solve's status is the BeamSolution's (one SolveStatus, not a copy that could differ).
  const SolveStatus& status() const noexcept { return solution; }
  bool converged() const noexcept { return solution.converged(); }
};
PhysicalBeamSolution solve_physical_beam(BeamMethod method,
                                         const PhysicalCantilever& beam,
                                         BeamProblem settings);

// A segment chain in physical units (SI: lengths m, loads N and N m, EI N m^2) with what the
// stresses need: the section and material of each flexible segment that has one. The library's
// type for a physical chain, built from objects or read from a TOML file (io::read_chain_file
// returns an io::ChainFile, which is one).
struct SegmentProperties {
  Section section;    // the rectangle (width, thickness) or a general I with its thickness
  Material material;  // E (EI = E I), nu (the plate modulus), and S_y for the safety factor
  // The cross-section area of a general section given with A (docs/chain-toml.md), m^2: the axial
  // stress N/A of an extensible segment. A rectangle's area is width thickness.
  std::optional<double> area;
  // The bending modulus (docs/plate-modulus.md) with material.nu: off E; on E/(1 - nu^2), and the
  // segment's EI is then that modulus times I (the rigidity the chain is solved with, so the chain
  // alone, e.g. `path --chain`, bends as a plate too); auto decides by the Searle parameter
  // b^2/(R h) at the segment's largest curvature (a rectangle section only): the segment's EI is
  // E I, and solve_physical_chain solves again with E I/(1 - nu^2) where the strip is a plate.
  PlateRule plate = PlateRule::kOff;

  // E, or E/(1 - nu^2) with plate on: the modulus the segment's EI is made of.
  double chain_modulus() const;

  // `area`, or the rectangle's width thickness; unknown for a general section without A.
  std::optional<double> cross_section_area() const;
};

struct PhysicalChain {
  SegmentChain chain;
  // One entry per segment of `chain`: the properties of a flexible segment that gives them
  // (nullopt: a flexible segment given by EI only, or a rigid link).
  std::vector<std::optional<SegmentProperties>> segments;
  // The yield strength of the segments whose material gives none, Pa (a chain file's top-level
  // yield_strength).
  std::optional<double> yield_strength;

  // Throws InvalidInput naming the segment: one entry per segment, properties only on flexible
  // segments, each section and material valid, a flexible segment's EI equal to E I, or to
  // E I/(1 - nu^2) with plate on (SegmentProperties::chain_modulus(); relative 1e-12; no
  // EI_profile with properties), plate auto only on a rectangle, and one yield strength for the
  // chain (the safety factor is the yield strength over the largest stress, so segments of
  // different S_y are refused).
  void validate() const;
  // The yield strength of the chain: the segments' (all equal, see validate()) or yield_strength.
  std::optional<double> effective_yield_strength() const;
};

// The same for a chain in physical units: its sections give the stresses, where every flexible
// segment has one. `problem` gives the method's settings (tolerance, integrator, shape points); its
// chain and boundary are replaced by `chain`'s. Throws InvalidInput when chain.validate() does.
// Segments with plate auto are decided after a first solve (each at its own largest curvature
// |m|/EI) and the chain solved again where one turns out a plate; physical.modulus reports each
// sectioned segment's choice. (An io::ChainFile read from TOML is a PhysicalChain.)
PhysicalBeamSolution solve_physical_chain(BeamMethod method,
                                          BeamProblem problem,
                                          const PhysicalChain& chain);

}  // namespace flexure
