// What is checked against what (the eleven modified configurations of paper 004 as dimensional
// designs, mechanisms/builtin_designs.h):
//  * Table 5's printed spring constants against the Table 5 rule (0.6 n gamma K_theta EI/L, 2 EI/L)
//    evaluated from Table 5's printed h, L, b, E -- and against Table 2's rule (half of it);
//  * Table 5's printed lengths and r2 + r3 against Table 3's rule (3/7 or 0.1 of the rigid
//    remainders) and Table 4's Lambda (r2 + r3 = 160 mm / Lambda);
//  * Table 6's printed F_Nom, Phi and x_b min/max against the PRBM of the design (Table 5 rule) and
//    the geometry of the physical chain (Table 1: x_b = r5 + r1 + r6);
//  * the exact model near the straight position against the closed-form buckling load of the
//    clamped strip + rigid crank + pinned coupler (beam-column equation), and that limit against
//    the PRBM with k = EI/L (the small-deflection limit, first order in L/r2);
//  * energy balance of the exact model, integral F dDelta_x (Simpson) = change of strain energy;
//  * the dynamics module's quasi-static force (mechanisms/dynamics: static_force, and the inverse
//    dynamics of a sinusoidal stroke at omega = 0) against the PRBM force of the same design and
//    spring constants (two code paths);
//  * the spring rules against the exact model (`validate --spring-rules`): k = EI/L has the
//  smallest
//    force error for every design, and each strip's energy-equivalent spring 2U/dtheta^2 is
//    >= EI/L (Cauchy-Schwarz: <m^2> >= <m>^2, equality for a pure moment);
//  * TOML description of a modified design (docs/examples/mechanism_lplm.toml) against the
//    built-in one, and its errors; the CLI keys of `mechanism analyze 2B-lplm --json`.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/gsl_guard.h"
#include "flexure/solver/common/status.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mechanism_test_support.h"

namespace flexure::mechanism {
namespace {

constexpr double mm = 1e-3;
// Table 5 prints h, L to 1e-4 mm and k to 1e-4 N m: the rounding of a k computed from h and L is
// 3 (0.5e-4 mm)/h + (0.5e-4 mm)/L relative, plus 0.5e-4 N m on the printed k.
double table5_k_rounding(double k, double h, double L) {
  return k * (3.0 * 0.05e-6 / h + 0.05e-6 / L) + 0.5e-4;
}
// Table 5's r2, r3 and L are rounded to 1e-4 mm; the Table 3 lengths solved from the rounded
// r2, r3 inherit ~0.35 x that, so 1.5e-4 mm covers both roundings.
constexpr double kTable3LengthTolerance = 1.5e-4 * mm;
// Table 4's Lambda is printed to 4 decimals: r2 + r3 = 160 mm / Lambda to 160 mm x 0.5e-4 /
// Lambda^2.
constexpr double kLambdaTolerance = 160.0 * mm * 0.5e-4;
// Table 6's F_Nom against our PRBM with k from the rounded h (Table 5 rule): h = 0.21 mm rounded to
// 1e-4 mm moves k (h^3) by up to 7e-4; Table 6 rounds to 1e-4 N and Table 5's r to 1e-4 mm.
constexpr double kFnomTolerance = 1e-3;
// Phi printed to 4 digits (~1e-4 relative) and F_Nom, k to 1e-4 N, 1e-4 N m.
constexpr double kPhiTolerance = 3e-4;
// Table 6's x_b to 1e-4 mm; our lengths from Table 5's rounded values (1e-4 mm each).
constexpr double kXbTolerance = 3e-4 * mm;
// Two code paths of one closed form (virtual work here, Lagrange's V'/(-r1') there).
constexpr double kClosedForm = 1e-10;
// Exact model vs the beam-column buckling load: the force is linear in Delta x near the straight
// position; a Richardson extrapolation of two points at 1e-3 and 2e-3 of the stroke leaves an
// O(Delta x^2) ~ 1e-6 relative error; shooting runs at rtol 1e-12.
constexpr double kBucklingTolerance = 1e-5;
// Energy balance, the 1e-8 (Simpson on 32 stroke intervals; strain energy by
// exact_strain_energy, the Richardson-extrapolated trapezoidal rule on kShapePoints shape
// samples: the plain trapezoid at 8001 samples left 6e-8 and 1.1e-7 on plpm and lllm).
constexpr int kShapePoints = 8001;
constexpr double kEnergyTolerance = 1e-8;

struct Table6Row {
  const char* name;
  double xb_max, xb_min;  // mm, as printed
  bool xb_max_erratum;    // printed x_b max disagrees with Table 1 and x_b min (docs/errata.md)
  int phi_reference;      // pivot whose k the printed Phi is referred to (3A-slsm: k2)
};
const Table6Row kTable6[] = {
    {"1A-lppm", 160.0, 101.1892, false, 1},
    {"1B-plpm", 160.0, 96.0, false, 2},
    {"2A-llpm", 160.0, 100.3326, true, 1},
    {"2B-lplm", 160.0, 105.6, false, 1},
    {"3A-lssm", 156.7374, 98.9265, false, 1},
    {"3A-slsm", 153.8462, 92.3077, false, 2},
    {"3A-llsm", 157.0771, 98.5825, false, 1},
    {"3A-lslm", 160.0, 105.2825, true, 1},
    {"3A-lllm", 160.0, 104.3478, false, 1},
};

MechanismDesign with_rule(const std::string& name, SpringRule rule) {
  MechanismDesign d = find_builtin_mechanism(name);
  apply_spring_rule(d, rule);
  return d;
}

TEST(MechanismModified, Table5SpringsAreTheTable5RuleNotTable2) {
  for (const dynamics::CfsmDesign& t : dynamics::cfsm_designs()) {
    const MechanismDesign d5 = with_rule(t.name, SpringRule::kTable5);
    const MechanismDesign d2 = with_rule(t.name, SpringRule::kTable2);
    for (int p = 1; p <= 3; ++p) {
      if (t.pivots[p - 1] == 'p') continue;
      const double tol = table5_k_rounding(t.k[p - 1], t.h[p - 1], t.l[p - 1]);
      EXPECT_NEAR(d5.spring_constant(p), t.k[p - 1], tol) << t.name << " k" << p;
      // Table 2's printed formula gives half of Table 5's value (docs/errata.md).
      EXPECT_NEAR(2.0 * d2.spring_constant(p), t.k[p - 1], tol) << t.name << " k" << p;
    }
  }
}

TEST(MechanismModified, Table5LengthsFollowTable3OfTheRigidRemainders) {
  for (const dynamics::CfsmDesign& t : dynamics::cfsm_designs()) {
    const ModifiedConfiguration& c = find_modified_configuration(t.name);
    const std::array<double, 3> L = table3_lengths(c, t.r2, t.r3);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(L[i], t.l[i], kTable3LengthTolerance) << t.name;
    EXPECT_NEAR(t.r2 + t.r3, 0.160 / c.Lambda, kLambdaTolerance) << t.name;
    EXPECT_NEAR(t.r3 / t.r2, c.R, 1e-5) << t.name;
  }
  // A single l on a link: L = (3/7)(r - L/2), i.e. L = (6/17) r = (0.3/gamma) r.
  const ModifiedConfiguration& lplm = find_modified_configuration("lplm");
  EXPECT_NEAR(table3_lengths(lplm, 1.0, 1.0)[0], 0.3 / 0.85, 1e-14);
}

TEST(MechanismModified, Table6NominalForcePhiAndStrokeFromThePrbm) {
  for (const Table6Row& row : kTable6) {
    const dynamics::CfsmDesign& t = dynamics::find_cfsm_design(row.name);
    const MechanismDesign d = with_rule(row.name, SpringRule::kTable5);
    // F_Nom of the whole (two-half) mechanism = 2 x mean PRBM force over 10 stroke points
    // (Delta x = 4 %, 8 %, ..., 40 % of r2 + r3 -- the sampling that reproduces Table 6).
    const PrbmStrokeResult r = prbm_stroke(d, 10);
    EXPECT_NEAR(2.0 * r.mean_force / t.F_nom_paper, 1.0, kFnomTolerance) << row.name;
    if (t.Phi_paper > 0.0) {
      // The paper's own relation F_Nom = 2 (k_ref/r2) Phi with its printed numbers.
      const double k_ref = t.k[row.phi_reference - 1];
      EXPECT_NEAR(t.F_nom_paper * t.r2 / (2.0 * k_ref) / t.Phi_paper, 1.0, kPhiTolerance)
          << row.name;
    }
    // Table 1: x_b = r5 + r1 + r6 with r5 = L1/2, r6 = L3/2 for l segments only; x_b min at 40 %.
    const double r5 = t.pivots[0] == 'l' ? 0.5 * t.l[0] : 0.0;
    const double r6 = t.pivots[2] == 'l' ? 0.5 * t.l[2] : 0.0;
    EXPECT_NEAR(t.r5, r5, kXbTolerance) << row.name;
    const double xb_max = r5 + d.r2 + d.r3 + r6;
    EXPECT_NEAR(xb_max - d.stroke, row.xb_min * mm, kXbTolerance) << row.name;
    if (row.xb_max_erratum) {
      EXPECT_GT(std::abs(xb_max - row.xb_max * mm), 0.01 * mm) << row.name;
    } else {
      EXPECT_NEAR(xb_max, row.xb_max * mm, kXbTolerance) << row.name;
    }
    // The physical chain's slider clamp: also half of each s segment at the ends (Table 1 omits
    // them), every segment being centred on its PRB pivot.
    const double s_ends =
        (t.pivots[0] == 's' ? 0.5 * t.l[0] : 0.0) + (t.pivots[2] == 's' ? 0.5 * t.l[2] : 0.0);
    EXPECT_NEAR(physical_chain(d).slider_x0, xb_max + s_ends, 1e-12) << row.name;
  }
}

// Buckling load of the straight 1A-lppm: a strip of length L clamped at the ground, a rigid link
// a = r2 - L/2 to the pin, a coupler r3 to the slider on the axis. Beam-column EI w'' + F w =
// F w2 (1 + (L + a - x)/r3) with w(0) = w'(0) = 0 and w2 = w(L) + a w'(L) gives
// lambda (r3 + L + a)(cos lambda L - a lambda sin lambda L) = sin lambda L + a lambda cos lambda L,
// F = EI lambda^2 (lowest root, by scanning and bisection).
double buckling_load(double EI, double L, double r2, double r3) {
  const double a = r2 - 0.5 * L;
  auto f = [&](double lam) {
    return lam * (r3 + L + a) * (std::cos(lam * L) - a * lam * std::sin(lam * L)) -
           (std::sin(lam * L) + a * lam * std::cos(lam * L));
  };
  double lo = 1e-9, step = 1e-3 / r2;
  while (f(lo) * f(lo + step) > 0.0) lo += step;
  double hi = lo + step;
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (lo + hi);
    (f(lo) * f(m) <= 0.0 ? hi : lo) = m;
  }
  const double lam = 0.5 * (lo + hi);
  return EI * lam * lam;
}

TEST(MechanismModified, ExactSmallStrokeIsTheBucklingLoadAndThePrbmItsShortStripLimit) {
  disable_gsl_abort();
  MechanismDesign d = find_builtin_mechanism("1A-lppm");  // k = EI/L (pure bending)
  for (double shrink : {1.0, 0.1}) {
    // Shorter strip at the same spring constant EI/L: h scaled by shrink^(1/3).
    MechanismDesign s = d;
    s.joints[0].length *= shrink;
    s.joints[0].thickness *= std::cbrt(shrink);
    s.finalise();
    const double EI = s.joints[0].flexural_rigidity(s.material), L = s.joints[0].length;
    const double F_cr = buckling_load(EI, L, s.r2, s.r3);
    const ExactMechanismSolver solver(s);
    const ExactPoint p1 = solver.solve(1e-3 * s.stroke);
    const ExactPoint p2 = solver.solve(2e-3 * s.stroke, &p1);
    ASSERT_TRUE(p1.converged() && p2.converged()) << p1.message << p2.message;
    const double F0 = 2.0 * p1.force - p2.force;  // linear extrapolation to Delta x = 0
    EXPECT_NEAR(F0 / F_cr, 1.0, kBucklingTolerance) << "shrink " << shrink;
    // PRBM at the straight position: F = k/(r2 (1 + 1/R)) with k = EI/L. The strip's finite
    // length makes the exact limit higher by a term first order in L/r2: 2.4 % at L/r2 = 0.353,
    // 0.29 % at a tenth of it (closed form); the bounds below allow 25 % above those values.
    const double F_prbm0 = s.spring_constant(1) / (s.r2 * (1.0 + s.r2 / s.r3));
    const double excess = F0 / F_prbm0 - 1.0;
    EXPECT_GT(excess, 0.0);
    EXPECT_LT(excess, shrink == 1.0 ? 0.030 : 0.0036) << "shrink " << shrink;
  }
}

using testing::simpson_work;

TEST(MechanismModified, ExactEnergyBalance) {
  disable_gsl_abort();
  // Two cantilevers at the middle pin (lplm), pins at both ends (plpm), a serial chain (lllm).
  for (const char* name : {"2B-lplm", "1B-plpm", "3A-lllm"}) {
    const MechanismDesign d = find_builtin_mechanism(name);
    const double a = 0.2 * d.stroke, b = d.stroke;
    const double W = simpson_work(d, a, b, 32);
    const double W_half = simpson_work(d, a, b, 16);
    const ExactMechanismSolver solver(d);
    const ExactStrokeResult ends = exact_stroke(d, {a, b});
    ASSERT_TRUE(ends.converged()) << ends.message;
    const double dU = exact_strain_energy(d, ends.points[1], kShapePoints) -
                      exact_strain_energy(d, ends.points[0], kShapePoints);
    EXPECT_LT(std::abs(W - W_half) / (15.0 * std::abs(W)), 0.1 * kEnergyTolerance) << name;
    EXPECT_NEAR(W / dU, 1.0, kEnergyTolerance) << name << ": work " << W << " J, dU " << dU;
  }
}

TEST(MechanismModified, DynamicsQuasiStaticForceIsThePrbmForce) {
  for (SpringRule rule : {SpringRule::kPureBending, SpringRule::kTable5}) {
    for (const MechanismDesign& base : modified_designs()) {
      MechanismDesign d = base;
      apply_spring_rule(d, rule);
      const std::array<double, 3> k = {
          d.spring_constant(1), d.spring_constant(2), d.spring_constant(3)};
      // One half, massless links: the quasi-static force V'/(-r1') of the Lagrangian model.
      const dynamics::SliderCrankDynamics model(
          dynamics::from_bar_links(d.r2, d.r3, 0.0, 0.0, 0.0, k, 1.0));
      for (double f : {0.05, 0.5, 1.0}) {
        const double dx = f * d.stroke;
        const double F_dyn = model.static_force(model.theta2_at(dx));
        const double F_prbm = prbm_state(d, dx).force;
        EXPECT_NEAR(F_dyn / F_prbm, 1.0, kClosedForm) << d.name << " at " << f;
      }
      // The inverse-dynamics force of a sinusoidal stroke at omega = 0 (inertia terms vanish).
      const dynamics::InverseDynamics inverse(model, {16, 0.0});
      for (const dynamics::ForceSample& q :
           inverse.history({0.01 * d.stroke, 0.99 * d.stroke, 0.0})) {
        EXPECT_NEAR(q.force / prbm_state(d, q.delta_x).force, 1.0, kClosedForm) << d.name;
      }
    }
  }
  // With Table 5's printed k (what `flexure dynamics` uses) against the Table 5 rule from h, L.
  for (const dynamics::CfsmDesign& t : dynamics::cfsm_designs()) {
    const MechanismDesign d = with_rule(t.name, SpringRule::kTable5);
    const dynamics::SliderCrankDynamics model(
        dynamics::from_bar_links(t.r2, t.r3, t.m2, t.m3, t.m_slider, t.k, 2.0));
    const double dx = 0.5 * d.stroke;
    EXPECT_NEAR(model.static_force(model.theta2_at(dx)) / (2.0 * prbm_state(d, dx).force),
                1.0,
                kFnomTolerance)
        << t.name;
  }
}

TEST(MechanismModified, NamesAndTheConstructedDesigns) {
  EXPECT_EQ(find_builtin_mechanism("lplm").name, "2B-lplm");
  EXPECT_EQ(find_builtin_mechanism("3a-LLLM").name, "3A-lllm");
  EXPECT_EQ(find_builtin_mechanism("sps").name, "2B-sps");  // the thesis design keeps its name
  EXPECT_EQ(modified_designs().size(), 11u);
  // 2A-slpm, 2B-lpsm: Table 4's R = 1.1 and Lambda; Table 3 lengths; the sibling's springs scaled
  // by r2 (Table 5 rule), so the spring ratio and k_ref/r2 equal the sibling's.
  for (auto [name, sibling] : {std::pair{"2A-slpm", "2A-llpm"}, std::pair{"2B-lpsm", "2B-lplm"}}) {
    const MechanismDesign d = with_rule(name, SpringRule::kTable5);
    const ModifiedConfiguration& c = find_modified_configuration(name);
    const dynamics::CfsmDesign& s = dynamics::find_cfsm_design(sibling);
    EXPECT_NEAR(d.R(), 1.1, 1e-12) << name;
    EXPECT_NEAR((d.r2 + d.r3) * c.Lambda, 0.160, kLambdaTolerance) << name;
    const std::array<double, 3> L = table3_lengths(c, d.r2, d.r3);
    for (int p = 1; p <= 3; ++p) {
      if (c.letters[p - 1] == 'p') continue;
      EXPECT_NEAR(d.joints[p - 1].length, L[p - 1], 1e-15) << name;
      EXPECT_NEAR(d.spring_constant(p) / d.r2, s.k[p - 1] / s.r2, 1e-12 * s.k[p - 1] / s.r2)
          << name << " k" << p;
    }
    EXPECT_NEAR(d.stroke, 0.4 * (d.r2 + d.r3), 1e-15);
  }
}

TEST(MechanismModified, AnalysisReportsYieldingSegments) {
  AnalysisOptions o;
  o.points = 10;
  const MechanismAnalysis a = analyze_mechanism(find_builtin_mechanism("2B-lplm"), o);
  ASSERT_TRUE(a.exact.converged()) << a.exact.message;
  // 24 mm strips 0.518 mm thick turned by 53 deg: E h psi/(2 L) ~ 2.07 GPa > 200 ksi.
  const double psi = std::acos(0.6);  // R = 1, Delta x = 40 % of r2 + r3: cos theta2 = 0.6
  EXPECT_NEAR(a.prbm.max_stress[0] / (207e9 * 0.5181e-3 * psi / (2.0 * 0.024)), 1.0, 0.02);
  EXPECT_LT(a.safety_factor, 1.0);
  EXPECT_EQ(a.yielding_pivots, (std::vector<int>{1, 3}));
  EXPECT_FALSE(a.prbm_validity_limit.has_value());  // Table 5.1 is for fixed-pinned l only
}

TEST(MechanismModifiedToml, ExampleFileIsTheBuiltInDesign) {
  const MechanismDesign f =
      load_mechanism_toml(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/mechanism_lplm.toml");
  const MechanismDesign b = find_builtin_mechanism("2B-lplm");
  EXPECT_EQ(f.config, "sps");
  EXPECT_EQ(f.paper_config, "lplm");
  for (int p = 1; p <= 3; ++p) EXPECT_DOUBLE_EQ(f.spring_constant(p), b.spring_constant(p));
  EXPECT_DOUBLE_EQ(prbm_state(f, 0.02).force, prbm_state(b, 0.02).force);
  EXPECT_DOUBLE_EQ(physical_chain(f).slider_x0, physical_chain(b).slider_x0);
}

void expect_toml_error(const std::string& text, const std::string& fragment) {
  try {
    parse_mechanism_toml(text, "t.toml");
    ADD_FAILURE() << "no error for: " << fragment;
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(MechanismModifiedToml, ErrorsNameTheProblem) {
  const std::string head =
      "r2 = 0.068\nr3 = 0.068\nstroke = 0.05\n[material]\nE = 207e9\nyield_strength = 1e9\n";
  const std::string strip = "thickness = 0.5e-3\nwidth = 0.0254\n";
  // Per-joint form: l segments declared fixed-fixed make lpl the pattern sps.
  const MechanismDesign ok = parse_mechanism_toml(
      "config = \"lpl\"\n" + head + "[ground]\nsegment = \"fixed-fixed\"\nlength = 0.024\n" +
          strip + "[slider]\nsegment = \"fixed-fixed\"\nlength = 0.024\n" + strip,
      "t.toml");
  EXPECT_EQ(ok.config, "sps");
  EXPECT_EQ(ok.paper_config, "lplm");
  expect_toml_error("config = \"lplm\"\n" + head + "[ground]\nsegment = \"hinged\"\nlength = " +
                        "0.024\n" + strip + "[slider]\nlength = 0.024\n" + strip,
                    "t.toml:9: ground.segment must be one of fixed-fixed, fixed-pinned");
  expect_toml_error(
      "config = \"lplm\"\n" + head + "[ground]\n" + strip + "[slider]\nlength = 0.024\n" + strip,
      "missing the required key 'length'");
  expect_toml_error("config = \"lplm\"\n" + head + "[ground]\nlength = 0.15\n" + strip +
                        "[slider]\nlength = 0.024\n" + strip,
                    "too long for r2");
  expect_toml_error("config = \"lpl\"\n" + head + "[ground]\nsegment = \"fixed-fixed\"\nlength = " +
                        "0.024\n" + strip + "[slider]\n" + strip,
                    "not one of the nine");
  expect_toml_error("config = \"lplm\"\nspring_rule = \"table9\"\n" + head +
                        "[ground]\nlength = 0.024\n" + strip + "[slider]\nlength = 0.024\n" + strip,
                    "t.toml:2: spring rule 'table9' is unknown (allowed: pure-bending, table2");
  expect_toml_error("config = \"lpp\"\nspring_rule = \"table5\"\n" + head + "[ground]\n" + strip,
                    "fixed-fixed segments only");
  expect_toml_error("config = \"lxpm\"\n" + head, "unknown modified configuration 'lxpm'");
}

TEST(MechanismModifiedCli, AnalyzeJsonSpringRuleAndHdf5) {
  using nlohmann::json;
  const test::CommandResult r =
      test::run_flexure("mechanism analyze 2B-lplm --points 10 --method exact --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  std::vector<std::string> keys = test::mechanism_analyze_contract_keys();
  keys.insert(keys.end(), {"spring_rule", "yielding_pivots"});
  for (const std::string& key : keys) {
    EXPECT_TRUE(j.contains(key) && !j[key].is_null()) << key;
  }
  EXPECT_EQ(j["spring_rule"], "pure-bending");
  EXPECT_EQ(j["design"]["paper_config"], "lplm");
  EXPECT_EQ(j["design"]["joints"][0]["segment"], "fixed-fixed");
  EXPECT_EQ(j["force_exact"].size(), 10u);
  EXPECT_NE(r.err.find("yields"), std::string::npos);
  // Table 5 rule: every spring of lplm is 0.6 gamma K_theta EI/L, so the PRBM force scales by
  // 0.6 x 0.85 x 2.65 (the force is linear in the spring constants); the exact force not at all.
  const test::CommandResult t5 = test::run_flexure(
      "mechanism analyze lplm --points 10 --method exact --spring-rule table5 --json");
  ASSERT_EQ(t5.exit_code, 0) << t5.err;
  const json k = json::parse(t5.out);
  EXPECT_EQ(k["spring_rule"], "table5");
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(k["force_prbm"][i].get<double>() / j["force_prbm"][i].get<double>(),
                0.6 * 0.85 * 2.65,
                kClosedForm);
    EXPECT_DOUBLE_EQ(k["force_exact"][i].get<double>(), j["force_exact"][i].get<double>());
  }
  EXPECT_EQ(test::run_flexure("mechanism analyze 2B-lplm --spring-rule table7").exit_code, 2);
  EXPECT_EQ(test::run_flexure("mechanism analyze 1A-lpp --spring-rule table5").exit_code, 2);
  test::ScratchDir dir;
  const test::CommandResult h =
      test::run_flexure("mechanism analyze 3A-lllm --points 8 --out lllm.h5", dir.path());
  ASSERT_EQ(h.exit_code, 0) << h.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "lllm.h5"));
}

TEST(MechanismModifiedCli, TheExactModelPicksThePureBendingRule) {
  using nlohmann::json;
  const test::CommandResult r =
      test::run_flexure("mechanism validate --spring-rules --json --points 20");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json rows = json::parse(r.out)["spring_rules"];
  ASSERT_EQ(rows.size(), 11u);
  for (const json& row : rows) {
    const auto e = row["max_force_error"].get<std::vector<double>>();
    EXPECT_LT(e[0], e[1]) << row["name"];  // pure bending beats Table 2
    EXPECT_LT(e[0], e[2]) << row["name"];  // and Table 5
    for (const char* key : {"k_equivalent_ratio_first", "k_equivalent_ratio_last"}) {
      for (const json& k : row[key]) {
        if (!k.is_null()) EXPECT_GE(k.get<double>(), 1.0 - 1e-6) << row["name"] << " " << key;
      }
    }
  }
}

}  // namespace
}  // namespace flexure::mechanism
