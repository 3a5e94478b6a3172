#pragma once
// One cross-section and one material for every part of the library that needs them (physical
// beams and chains, PRBM elements, mechanism designs, design synthesis; issue 28, docs/units.md).
// Any consistent units: SI throughout the tool (m, m^4, Pa, kg/m^3).
//
// A Section is a rectangle (width b out of the plane of bending, thickness h in it: I = b h^3/12,
// Howell §2.1) or a general section given by its second moment I, with its thickness h when known
// (the extreme fibre c = h/2 gives the bending stress M c/I). A Material has Young's modulus E,
// Poisson's ratio nu, and optionally the yield strength S_y and the density.
//
// The factories and validate() throw InvalidInput naming the field (Section::width, Material::E,
// ...); code that receives a Section or Material it did not build validates it.
#include <optional>

namespace flexure {

struct Section {
  enum class Shape { kRectangle, kGeneral };
  Shape shape = Shape::kRectangle;
  double width = 0.0;      // b, out of the plane of bending (rectangle only; 0 for a general one)
  double thickness = 0.0;  // h, in the plane of bending (general: 0 when unknown)
  double I = 0.0;          // second moment of a general section (0 for a rectangle: computed)

  // Validated constructions.
  static Section rectangle(double width, double thickness);
  static Section general(double I, std::optional<double> thickness = {});

  // b h^3/12 for a rectangle, I for a general section.
  double second_moment() const;
  // b h for a rectangle; unknown for a general section.
  std::optional<double> area() const;
  // I/c with c = h/2 (b h^2/6 for a rectangle): the bending stress is |M|/S; unknown without h.
  std::optional<double> section_modulus() const;

  // Throws InvalidInput naming the field: a rectangle needs a finite width and thickness > 0 and
  // no I; a general section a finite I > 0, a thickness that is 0 (unknown) or finite and > 0, and
  // no width.
  void validate() const;
};

struct Material {
  double E = 0.0;   // Young's modulus
  double nu = 0.3;  // Poisson's ratio, -1 < nu < 0.5 (isotropic: positive shear and bulk moduli)
  std::optional<double> yield_strength;  // S_y, for stresses and safety factors
  std::optional<double> density;         // for masses (dynamics)

  // G = E/(2 (1 + nu)).
  double shear_modulus() const;

  // Throws InvalidInput naming the field: E finite and > 0, nu finite in (-1, 0.5), a yield
  // strength or density finite and > 0 when given.
  void validate() const;
};

// E I, after validating both.
double flexural_rigidity(const Section& section, const Material& material);

}  // namespace flexure
