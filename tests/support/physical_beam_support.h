#pragma once
// Shared by the physical-beam tests (tests/beam/physical_beam_test.cpp,
// tests/io/physical_chain_toml_test.cpp): US customary units of Howell's examples and a steel
// strip cantilever.
#include "flexure/beam/physical_beam.h"

namespace flexure::test {

constexpr double kInch = 0.0254;
constexpr double kPound = 4.4482216152605;
constexpr double kPsi = kPound / (kInch * kInch);

// A 50 mm x 10 mm x 0.5 mm steel strip (E = 200 GPa) under tip loads Fx, Fy (N) and M (N m).
inline PhysicalCantilever strip(double Fx, double Fy, double M) {
  PhysicalCantilever b;
  b.length = 0.05;
  b.material.E = 200e9;
  b.section = Section::rectangle(0.01, 0.0005);
  b.Fx = Fx;
  b.Fy = Fy;
  b.M = M;
  return b;
}

}  // namespace flexure::test
