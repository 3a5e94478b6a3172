#include "flexure/mechanisms/dynamics/cfsm_designs.h"

#include <fmt/format.h>

#include "flexure/solver/common/errors.h"

namespace flexure::dynamics {
namespace {

constexpr double mm = 1e-3;
constexpr double g = 1e-3;
constexpr double GPa = 1e9;

// Transcribed from Table 5 (lengths mm, masses g, k N m) and Table 6 (F_Nom N, Phi). Table 6
// prints no Phi for 3A-lslm and 3A-lllm (the conversion lost the row); 0 there.
std::vector<CfsmDesign> make_designs() {
  std::vector<CfsmDesign> d;
  auto add = [&](std::string name,
                 double r2,
                 double r3,
                 double r5,
                 double r6,
                 double m2,
                 double m3,
                 double ms,
                 std::array<double, 3> h,
                 std::array<double, 3> l,
                 std::array<double, 3> k,
                 double F_nom,
                 double Phi) {
    CfsmDesign x;
    x.name = name;
    x.r2 = r2 * mm;
    x.r3 = r3 * mm;
    x.r5 = r5 * mm;
    x.r6 = r6 * mm;
    x.m2 = m2 * g;
    x.m3 = m3 * g;
    x.m_slider = ms * g;
    x.k = k;
    // The pivot letters sit between the class and the trailing 'm': "2B-lplm" -> l, p, l.
    const std::size_t dash = name.find('-');
    for (int i = 0; i < 3; ++i) x.pivots[i] = name[dash + 1 + i];
    x.width_b = 25.4 * mm;
    for (int i = 0; i < 3; ++i) {
      x.h[i] = h[i] * mm;
      x.l[i] = l[i] * mm;
    }
    x.E = 207 * GPa;
    x.F_nom_paper = F_nom;
    x.Phi_paper = Phi;
    d.push_back(x);
  };
  add("1A-lppm",
      73.5135,
      73.5135,
      12.9730,
      0,
      76.1446,
      51.8910,
      75.7979,
      {0.5602, 0, 0},
      {25.9459, 0, 0},
      {4.0113, 0, 0},
      59.0781,
      0.5413);
  add("1B-plpm",
      84.2105,
      75.7895,
      0,
      0,
      78.3494,
      75.3607,
      75.7979,
      {0, 0.3042, 0},
      {0, 28.2353, 0},
      {0, 0.5903, 0},
      32.0878,
      2.2889);
  add("2A-llpm",
      71.3580,
      78.4938,
      10.4215,
      0,
      97.1555,
      76.5531,
      75.7979,
      {0.2102, 0.2652, 0},
      {20.8431, 24.6054, 0},
      {0.5279, 0.4487, 0},
      34.8222,
      2.3533);
  add("2B-lplm",
      68.0,
      68.0,
      12.0,
      12.0,
      74.1147,
      74.1147,
      116.7138,
      {0.5181, 0, 0.5181},
      {24.0, 0, 24.0},
      {3.4322, 0, 3.4322},
      109.2944,
      1.0827);
  add("3A-lssm",
      72.2635,
      72.2635,
      12.2103,
      0,
      100.5655,
      101.2889,
      116.7138,
      {0.5272, 0.0448, 0.0961},
      {24.4206, 6.1439, 6.5897},
      {3.5535, 0.0128, 0.1182},
      55.7807,
      0.5672);
  add("3A-slsm",
      76.9231,
      76.9231,
      0,
      0,
      100.8852,
      100.8852,
      116.7138,
      {0.0888, 0.2815, 0.0888},
      {6.0843, 26.0756, 6.0843},
      {0.1007, 0.5064, 0.1007},
      31.3481,
      2.3807);
  add("3A-llsm",
      73.1183,
      73.1183,
      10.8405,
      0,
      97.8628,
      99.7599,
      116.7138,
      {0.2340, 0.2523, 0.0854},
      {21.6811, 23.3772, 5.8504},
      {0.7002, 0.4070, 0.0931},
      35.8571,
      0);
  add("3A-lslm",
      68.4105,
      68.4105,
      11.5950,
      11.5950,
      99.2904,
      99.2904,
      116.7138,
      {0.5007, 0.0395, 0.5007},
      {23.19, 5.4110, 23.19},
      {3.2044, 0.0100, 3.2044},
      102.0596,
      0);
  add("3A-lllm",
      69.5652,
      69.5652,
      10.4348,
      10.4348,
      96.4089,
      96.4089,
      116.7138,
      {0.2253, 0.1126, 0.2253},
      {20.8696, 20.8696, 20.8696},
      {0.6488, 0.0811, 0.6488},
      25.2446,
      0);
  return d;
}

}  // namespace

const std::vector<CfsmDesign>& cfsm_designs() {
  static const std::vector<CfsmDesign> designs = make_designs();
  return designs;
}

const CfsmDesign& find_cfsm_design(const std::string& name) {
  std::string names;
  for (const CfsmDesign& d : cfsm_designs()) {
    if (d.name == name) return d;
    names += (names.empty() ? "" : ", ") + d.name;
  }
  throw InvalidInput(fmt::format("mechanism '{}' is unknown; allowed: {}", name, names));
}

}  // namespace flexure::dynamics
