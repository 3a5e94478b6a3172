#pragma once
// The bending modulus of a strip: a beam's E, or the plate (cylindrical-bending) modulus
// E/(1 - nu^2) of a strip many times wider than thick (issue 29 item 7; docs/plate-modulus.md).
//
// A bent strip's fibres contract sideways by nu times their axial strain. A narrow strip is free
// to do so: its cross-section takes the anticlastic curvature -nu/R and the bending stiffness is
// E I. A wide strip cannot: away from a boundary layer along each edge, about sqrt(R h) wide, the
// curved strip's own membrane stiffness keeps the section straight (plane strain across the
// width), and the stiffness is E I/(1 - nu^2). Which case holds is set by the anticlastic
// (Searle) parameter beta = b^2/(R h) -- the square of the width over the boundary layer's width.
//
// The transition is the exact linear solution of a strip bent to curvature 1/R (plate bending
// across the width on the elastic foundation E h/R^2 of the curved membrane; derivation in
// docs/plate-modulus.md): the bending stiffness is
//   E I/(1 - nu^2) * Phi,   Phi = 1 + nu^2 f'(t)/t + (2 nu^2/t) int_{-t}^{t} f^2,
// with t = lambda b/2, lambda^4 = 3 (1 - nu^2)/(R h)^2 (so t^2 = sqrt(3 (1 - nu^2)) beta/4) and f
// the even solution of f'''' + 4 f = 0 with f''(t) = -1, f'''(t) = 0 (free edges). Phi runs from
// 1 - nu^2 (beam, beta -> 0) to 1 (plate, beta -> inf). plate_fraction() is the share of the plate
// effect present, (Phi - (1 - nu^2))/nu^2, in [0, 1]; "auto" takes the plate modulus where it is at
// least 1/2 (the modulus nearer the exact one): beta >= 6.30 for nu = 0.3 (6.0 as nu -> 0, 6.9 as
// nu -> 0.5).
#include <optional>
#include <string>

namespace flexure {

enum class PlateRule { kOff, kOn, kAuto };

// "off", "on", "auto" (case-insensitive); throws InvalidInput naming `what` and the choices.
PlateRule plate_rule_from_string(const std::string& text, const std::string& what);
const char* to_string(PlateRule rule);

// beta = b^2/(R h) = b^2 |kappa|/h; throws InvalidInput unless b, h > 0 and kappa finite.
double searle_parameter(double width, double thickness, double curvature);

// The share of the plate stiffening present at beta, (Phi - (1 - nu^2))/nu^2 (see above), in
// [0, 1]; nu in (-1, 0.5), nu != 0 (at nu = 0 the two moduli agree; 0 is returned for beta = 0,
// the limit otherwise). Large beta: 1 - (3/4)/t + O(exp(-2t)); small beta: O(beta^2).
double plate_fraction(double beta, double nu);

// The smallest beta where plate_fraction(beta, nu) >= 1/2 (auto's threshold), by bisection.
double searle_threshold(double nu);

// The modulus a strip bends with, and why (reported in JSON as `modulus_rule`, `effective_E`).
struct ModulusChoice {
  PlateRule rule = PlateRule::kOff;
  double E = 0.0;            // Young's modulus as given, Pa
  std::optional<double> nu;  // Poisson's ratio (needed by on and auto)
  bool plate = false;        // whether E/(1 - nu^2) is used
  double effective_E = 0.0;  // E or E/(1 - nu^2)
  // auto: the Searle parameter at the decisive curvature, the threshold and the exact share of
  // the plate effect there (plate_fraction).
  std::optional<double> beta, threshold, fraction;
  std::optional<double> curvature;  // 1/R the decision was taken at, 1/m
  // Set where a caller overrides the parameter's verdict (a mechanism has one modulus for all its
  // strips): appended to reason().
  std::string note;
  // "beam modulus E (plate off)", "plate modulus E/(1 - nu^2) (plate on)", "auto: ...".
  std::string reason() const;
  // The rule's name for JSON: "beam" or "plate" plus how ("off", "on", "auto").
  std::string modulus_rule() const;
};

// The choice of `rule` for a material (E, nu) and strip (width, thickness) bent to `curvature`
// (|1/R| at the decisive point, for auto). Throws InvalidInput naming `where`: on or auto without
// nu; auto without the width and thickness of a rectangle; auto without a curvature. E must be
// > 0. With off, nu may be absent. At curvature 0 auto picks the beam (beta = 0).
ModulusChoice choose_modulus(PlateRule rule,
                             double E,
                             std::optional<double> nu,
                             std::optional<double> width,
                             std::optional<double> thickness,
                             std::optional<double> curvature,
                             const std::string& where);

}  // namespace flexure
