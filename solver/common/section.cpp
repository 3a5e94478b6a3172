#include "flexure/solver/common/section.h"

#include <fmt/format.h>

#include <cmath>

#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

void require_positive(double value, const char* field) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InvalidInput(fmt::format("{} must be finite and > 0 (got {})", field, value));
  }
}

}  // namespace

Section Section::rectangle(double width, double thickness) {
  Section s;
  s.shape = Shape::kRectangle;
  s.width = width;
  s.thickness = thickness;
  s.validate();
  return s;
}

Section Section::general(double I, std::optional<double> thickness) {
  Section s;
  s.shape = Shape::kGeneral;
  s.I = I;
  if (thickness) {
    // Given means known: 0 would silently mean "unknown".
    require_positive(*thickness, "Section::thickness");
    s.thickness = *thickness;
  }
  s.validate();
  return s;
}

void Section::validate() const {
  if (shape == Shape::kRectangle) {
    require_positive(width, "Section::width");
    require_positive(thickness, "Section::thickness");
    if (I != 0.0) {
      throw InvalidInput(fmt::format(
          "Section::I = {} is given for a rectangle, whose I is b h^3/12; give I only for a "
          "general section",
          I));
    }
    return;
  }
  require_positive(I, "Section::I");
  if (thickness != 0.0) require_positive(thickness, "Section::thickness");
  if (width != 0.0) {
    throw InvalidInput(fmt::format(
        "Section::width = {} is given for a general section, which is described by I (and h)",
        width));
  }
}

double Section::second_moment() const {
  return shape == Shape::kRectangle ? width * thickness * thickness * thickness / 12.0 : I;
}

std::optional<double> Section::area() const {
  if (shape == Shape::kRectangle) return width * thickness;
  return std::nullopt;
}

std::optional<double> Section::section_modulus() const {
  if (!(thickness > 0.0)) return std::nullopt;
  return second_moment() / (thickness / 2.0);
}

double Material::shear_modulus() const { return E / (2.0 * (1.0 + nu)); }

void Material::validate() const {
  require_positive(E, "Material::E");
  if (!(std::isfinite(nu) && nu > -1.0 && nu < 0.5)) {
    throw InvalidInput(fmt::format("Material::nu must be finite and in (-1, 0.5) (got {})", nu));
  }
  if (yield_strength) require_positive(*yield_strength, "Material::yield_strength");
  if (density) require_positive(*density, "Material::density");
}

double flexural_rigidity(const Section& section, const Material& material) {
  section.validate();
  material.validate();
  return material.E * section.second_moment();
}

}  // namespace flexure
