#pragma once
// What a slider force is the force of. A constant-force slider mechanism is symmetric (thesis
// §2.1.1; Howell §10.1; the dynamics paper models "only half of the symmetric mechanism", its
// Fig. 2): two mirror-image halves -- crank, coupler and their springs -- push one slider in
// parallel. Every model in mechanisms/ computes one half; `flexure mechanism` reports that
// half, `flexure dynamics` (and the paper's Table 6 F_Nom) the whole mechanism
// (docs/mechanisms.md "Half or whole mechanism").
//
// F_whole = 2 F_half exactly: the two halves carry equal and opposite transverse loads at the
// slider, which cancel, and equal axial ones, which add. In the dynamics the same holds with the
// slider's inertia shared equally by the halves (docs/dynamics.md §1: the equation of motion is
// linear in the number of halves and the slider mass together).
#include <string>

namespace flexure::mechanism {

enum class ForceOf { kOneHalf, kWholeMechanism };

// "half" or "whole" (case-insensitive); throws InvalidInput naming the allowed values.
ForceOf parse_force_of(const std::string& text);
// The value of the output key `force_of`: "one half" or "whole symmetric mechanism".
std::string force_of_label(ForceOf of);
// The factor that turns a force of `from` into a force of `to` (1, 2 or 1/2).
double force_of_factor(ForceOf from, ForceOf to);

}  // namespace flexure::mechanism
