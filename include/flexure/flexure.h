#pragma once
// flexure's public C++ API in one include: the five module headers (docs/architecture.md, "Public
// API", lists what each header offers).
//
//   #include <flexure/flexure.h>
//   const flexure::EllipticResult r =
//       flexure::EllipticSolver().solve(flexure::EndLoad::howell(0, 3.087, 0));
//   // r.tip.a_over_l, r.tip.b_over_l, r.tip.theta0
//
// Link `flexure::flexure` after `find_package(flexure REQUIRED)`.
#include "flexure/beam.h"        // beam problems, the exact solvers, chains, sections, materials
#include "flexure/design.h"      // constant-force and mechanism design
#include "flexure/mechanisms.h"  // mechanism designs, analysis, catalogues, dynamics
#include "flexure/prbm.h"        // pseudo-rigid-body models and their derivation
#include "flexure/studies.h"     // chains and mechanisms from TOML files, drawings
#include "flexure/version.h"
