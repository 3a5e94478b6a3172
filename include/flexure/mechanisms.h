#pragma once
// flexure's compliant mechanisms in one include: mechanism designs and the built-in catalogues
// (Howell's, the modified designs, Weight's constant-force slider mechanisms), their analysis by
// the PRBM and the exact model with stresses and stability, the method choice, the constant-force
// configurations, the dynamics of the slider-crank, and general mechanisms (any topology of rigid
// bodies and flexures). Link `flexure::mechanisms` (or `flexure::flexure`).
//
//   #include <flexure/mechanisms.h>
//   namespace fm = flexure::mechanism;
//   const fm::MechanismAnalysis a = fm::analyze_mechanism(fm::howell_mechanisms().front(), {});
#include "flexure/prbm.h"

// Designs, their geometry, the catalogues and the PRBM-or-exact choice.
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/mechanism.h"

// Analysis: PRBM and exact strokes, stresses, stability, where the PRBM stays valid; the exact
// model of a nondimensional constant-force mechanism.
#include "flexure/mechanisms/mechanism_analysis.h"

// Constant-force mechanisms: Weight's configurations, their PRBM and the printed sub-classes.
#include "flexure/mechanisms/cfm/cfm_model.h"

// Dynamics of the slider-crank: inverse and forward.
#include "flexure/mechanisms/dynamics/dynamics.h"

// General mechanisms: any topology, by the PRBM and the exact model.
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"
