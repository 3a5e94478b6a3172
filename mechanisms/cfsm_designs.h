#pragma once
// The modified constant-force slider mechanisms of Ugwuoke & Abolarin (JETIR 2023), with the
// dimensions, masses and spring constants of their Table 5 (data/paper_table_5.csv) and the nominal
// force and non-dimensional force of Table 6 (data/paper_table_6.csv); docs/dynamics.md. The files
// are compiled into the library and read at the first call.
//
// Only nine of the eleven configurations of Tables 1-4 have a column in Table 5 (2A-slpm and
// 2B-lpsm have none); the "3A-lllRig" column has no counterpart elsewhere and is left out. The
// spring constants are Table 5's values: for every flexible pivot they are twice Table 2's formula
// (0.6 gamma K_theta EI/L where Table 2 prints 0.3, 2 EI/L where it prints EI/L) and they
// reproduce Table 6's F_Nom = 2 (k_ref/r2) Phi, so Table 5 is taken as the consistent data set
// (docs/dynamics.md §2).
#include <array>
#include <string>
#include <vector>

namespace flexure::dynamics {

struct CfsmDesign {
  std::string name;              // "2B-lplm": class, pivots (ground, middle, slider), trailing m
  double r2 = 0.0;               // crank (PRBM link 2) length, m
  double r3 = 0.0;               // coupler (PRBM link 3) length, m
  double r5 = 0.0;               // rigid extension at the ground, m (0 where Table 5 prints "-")
  double r6 = 0.0;               // rigid extension at the slider, m
  double m2 = 0.0;               // mass of link 2 (one half of the mechanism), kg
  double m3 = 0.0;               // mass of link 3 (one half), kg
  double m_slider = 0.0;         // slider mass (shared by both halves), kg
  std::array<double, 3> k{};     // torsional springs at pivots 1, 2, 3 (one half), N m
  std::array<char, 3> pivots{};  // 'p' pin, 's' small-length pivot, 'l' long segment
  double width_b = 0.0;          // flexure width, m
  std::array<double, 3> h{};     // flexure thicknesses, m (0 for a pin)
  std::array<double, 3> l{};     // flexure lengths, m (0 for a pin)
  double E = 0.0;                // Young's modulus, Pa
  double F_nom_paper = 0.0;      // Table 6 nominal force of the whole mechanism, N (0: none)
  double Phi_paper = 0.0;        // Table 6 mean non-dimensional force (0: not printed)
};

// The nine designs with a Table 5 column, in the paper's order.
const std::vector<CfsmDesign>& cfsm_designs();
// The design named `name` (e.g. "2B-lplm"); throws InvalidInput listing the names otherwise.
const CfsmDesign& find_cfsm_design(const std::string& name);

}  // namespace flexure::dynamics
