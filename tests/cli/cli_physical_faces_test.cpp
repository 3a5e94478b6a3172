// What is checked against what: the features of a one-segment beam reachable from `flexure beam`
// with units (docs/cli.md, "Physical beams"; issue 29 item 5):
//  * --curvature K: the identity m = EI (theta' - kappa0): a curved beam under a tip force has the
//    tip of the straight beam under the same force plus the end moment EI K (solved by another
//    method, the elliptic integrals), to 1e-9 of L; its shape's moment is the straight beam's
//    minus EI K at every point; and the same beam from a TOML chain file in SI gives the same tip
//    bit for bit;
//  * --width-tip / --thickness-tip: a tapered cantilever under a small tip force against linear
//    theory, delta = F int_0^L (L - s)^2 / (E I(s)) ds (Simpson's rule on 20 000 intervals), to
//    1e-5; the fibre stresses at each shape point against N/A(s) -+ m c(s)/I(s) with the local
//    section, and m against the statics of the part beyond the point (tip force times lever);
//  * --boundary with a physical beam: guided and pinned ends (tip in mm) against the same beam in
//    Howell's nondimensional form (alpha2 = F L^2/EI, x/l), tip and reactions scaled by EI/L^2;
//  * path --chain FILE in SI with --tip-y given with a unit: the same path as in plain metres;
//  * refusals: a taper with --I, an extensible taper, an elliptic method for a curved beam.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;
using Json = nlohmann::json;

Json run_json(const std::string& args) {
  const test::CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  return Json::parse(r.out.empty() ? "{}" : r.out);
}

// A steel strip 50 mm long, 10 mm wide, 0.5 mm thick: EI = 200e9 * 0.01 * 0.5e-3^3 / 12.
constexpr double kL = 0.05, kE = 200e9, kB = 0.01, kH = 0.5e-3;
const double kEI = kE * kB * kH * kH * kH / 12.0;
const char* kStrip = "--length 50mm --E 200GPa --width 10mm --thickness 0.5mm";

TEST(CliPhysicalFaces, CurvatureIsAnEndMomentOnTheStraightBeam) {
  const double kappa = 8.0;  // 1/m: kappa0 L = 0.4
  const Json curved = run_json(
      fmt::format("beam {} --Fy 0.3N --Fx -0.2N --curvature {} --shape 11", kStrip, kappa));
  const Json straight =
      run_json(fmt::format("beam {} --Fy 0.3N --Fx -0.2N --M {:.17g} --method elliptic --shape 11",
                           kStrip,
                           kEI * kappa));
  EXPECT_EQ(curved["method"], "shooting");
  EXPECT_NEAR(curved["tip_x"].get<double>(), straight["tip_x"].get<double>(), 1e-9 * kL);
  EXPECT_NEAR(curved["tip_y"].get<double>(), straight["tip_y"].get<double>(), 1e-9 * kL);
  EXPECT_NEAR(curved["theta0"].get<double>(), straight["theta0"].get<double>(), 1e-9);
  ASSERT_EQ(curved["shape"].size(), 11u);
  for (std::size_t i = 0; i < 11; ++i) {
    const Json& c = curved["shape"][i];
    const Json& s = straight["shape"][i];
    EXPECT_NEAR(c["m_Nm"].get<double>(), s["m_Nm"].get<double>() - kEI * kappa, 1e-9 * kEI * kappa)
        << i;
    EXPECT_NEAR(c["y_m"].get<double>(), s["y_m"].get<double>(), 1e-9 * kL) << i;
  }
  // The same beam from a chain file in SI units.
  test::ScratchDir dir;
  const std::string toml = (dir / "curved.toml").string();
  std::ofstream(toml) << fmt::format(
      "units = \"SI\"\n[[segment]]\ntype = \"flexible\"\nlength = \"50 mm\"\nE = \"200 GPa\"\n"
      "width = \"10 mm\"\nthickness = \"0.5 mm\"\nkappa0 = {:.17g}\n[tip_load]\nFx = -0.2\n"
      "Fy = 0.3\n",
      kappa);  // 1/m: the file's units are SI
  const Json file = run_json(fmt::format("beam --chain {}", toml));
  EXPECT_NEAR(file["tip_x"].get<double>(), curved["tip_x"].get<double>(), 1e-14);
  EXPECT_NEAR(file["tip_y"].get<double>(), curved["tip_y"].get<double>(), 1e-14);
}

// Linear theory of a cantilever with I(s): the tip deflection under a tip force F.
double linear_tip_deflection(double F, double b_tip, double h_tip) {
  const int n = 20000;  // Simpson's rule, even n
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double s = kL * k / n, t = s / kL;
    const double b = kB + t * (b_tip - kB), h = kH + t * (h_tip - kH);
    const double f = (kL - s) * (kL - s) / (kE * b * h * h * h / 12.0);
    sum += f * (k == 0 || k == n ? 1.0 : k % 2 == 1 ? 4.0 : 2.0);
  }
  return F * sum * kL / n / 3.0;
}

TEST(CliPhysicalFaces, TaperedBeamAgainstLinearTheoryAndLocalFibreStresses) {
  const double F = 1e-4;  // N: tip deflection ~ 1e-4 L, geometric nonlinearity ~ 1e-8
  for (const auto& [b_tip, h_tip] :
       {std::pair{0.005, kH}, std::pair{kB, 0.3e-3}, std::pair{0.006, 0.8e-3}}) {
    const Json j = run_json(fmt::format(
        "beam {} --Fy {} --width-tip {} --thickness-tip {} --shape 21", kStrip, F, b_tip, h_tip));
    const double expected = linear_tip_deflection(F, b_tip, h_tip);
    EXPECT_NEAR(j["tip_y"].get<double>() / expected, 1.0, 1e-5) << b_tip << " " << h_tip;
    const double tip_x = j["tip_x"].get<double>(), tip_y = j["tip_y"].get<double>();
    for (const Json& p : j["shape"]) {
      const double s = p["s_m"].get<double>(), t = s / kL;
      const double b = kB + t * (b_tip - kB), h = kH + t * (h_tip - kH);
      // Statics of the part beyond s: only the tip force acts on it.
      const double m = F * (tip_x - p["x_m"].get<double>());
      EXPECT_NEAR(p["m_Nm"].get<double>(), m, 1e-9 * F * kL) << s;
      const double N = F * std::sin(p["theta"].get<double>());
      const double c_over_I = 6.0 / (b * h * h);
      const double scale = F * kL * 6.0 / (kB * kH * kH);
      EXPECT_NEAR(p["stress_pos_fibre_Pa"].get<double>(), N / (b * h) - m * c_over_I, 1e-7 * scale);
      EXPECT_NEAR(p["stress_neg_fibre_Pa"].get<double>(), N / (b * h) + m * c_over_I, 1e-7 * scale);
    }
    (void)tip_y;
  }
  // The largest stress of a width taper (b falls to half at the tip) under a tip force:
  // sigma(s) = 6 F (L - s) / (b(s) h^2) is largest at the clamp.
  const Json w = run_json(fmt::format("beam {} --Fy {} --width-tip 5mm", kStrip, F));
  EXPECT_NEAR(w["max_stress"].get<double>() / (6.0 * F * kL / (kB * kH * kH)), 1.0, 1e-6);
}

TEST(CliPhysicalFaces, BoundaryOfAPhysicalBeamEqualsHowellsForm) {
  // Guided: the tip angle held at 0, Fy = 2 N; alpha2 = Fy L^2/EI.
  const double Fy = 2.0;
  const Json g = run_json(fmt::format("beam {} --Fy {} --boundary guided", kStrip, Fy));
  const Json h = run_json(
      fmt::format("beam --alpha2 {:.17g} --boundary guided --method shooting", Fy * kL * kL / kEI));
  EXPECT_EQ(g["boundary"], "guided");
  EXPECT_NEAR(g["tip_y"].get<double>() / kL, h["b_over_l"].get<double>(), 1e-9);
  EXPECT_NEAR(g["tip_x"].get<double>() / kL, h["a_over_l"].get<double>(), 1e-9);
  EXPECT_NEAR(g["theta0"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(g["reactions"]["M"].get<double>(), h["reactions"]["M"].get<double>(), 1e-8);
  // Pinned: the tip held at (45 mm, 5 mm), no moment.
  const Json p =
      run_json(fmt::format("beam {} --boundary pinned --tip-x 45mm --tip-y 5mm", kStrip));
  const Json q = run_json("beam --alpha2 0 --boundary pinned --tip-x 0.9 --tip-y 0.1");
  EXPECT_NEAR(p["tip_x"].get<double>(), 0.045, 1e-12);
  EXPECT_NEAR(p["tip_y"].get<double>(), 0.005, 1e-12);
  EXPECT_NEAR(p["theta0"].get<double>(), q["theta0"].get<double>(), 1e-9);
  EXPECT_NEAR(p["root_moment_Nm"].get<double>(),
              -q["reactions"]["M"].get<double>() * kEI / kL,
              1e-8 * kEI / kL);
  // A load on a prescribed coordinate is the support's reaction: refused.
  const test::CommandResult bad =
      run_flexure(fmt::format("beam {} --Fy 1N --boundary pinned --tip-x 45mm", kStrip));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--Fy must be 0"), std::string::npos) << bad.err;
}

TEST(CliPhysicalFaces, PathTipWithAUnitOnAnSiChainFile) {
  const std::string toml =
      std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/inclined_bistable_path.toml";
  test::ScratchDir dir;
  const std::string a = (dir / "a.h5").string(), b = (dir / "b.h5").string();
  const Json ja = run_json(fmt::format(
      "path --chain {} --control tip-y --tip-y 5.2mm --min-points 11 --out {}", toml, a));
  const Json jb = run_json(fmt::format(
      "path --chain {} --control tip-y --tip-y 0.0052 --min-points 11 --out {}", toml, b));
  EXPECT_NEAR(ja["control_target"].get<double>(), 0.0052, 1e-17);
  EXPECT_EQ(ja["points"], jb["points"]);
  const hid_t fa = test::open_read_only(a), fb = test::open_read_only(b);
  const std::vector<double> ya = test::read_doubles(fa, "tip_y");
  const std::vector<double> yb = test::read_doubles(fb, "tip_y");
  H5Fclose(fa);
  H5Fclose(fb);
  ASSERT_EQ(ya.size(), yb.size());
  EXPECT_NEAR(ya.back(), 0.0052, 1e-12);
  for (std::size_t i = 0; i < ya.size(); ++i) EXPECT_NEAR(ya[i], yb[i], 1e-12);
}

TEST(CliPhysicalFaces, SweepTakesAnglesWithUnits) {
  // --theta0 30deg:60deg:4 is the radian range pi/6 .. pi/3: the same axis and loads.
  test::ScratchDir dir;
  const std::string a = (dir / "deg.h5").string(), b = (dir / "rad.h5").string();
  run_json(fmt::format("sweep beam --theta0 30deg:60deg:4 --n 1 --out {}", a));
  run_json(fmt::format("sweep beam --theta0 {:.17g}:{:.17g}:4 --n 1 --out {}",
                       std::numbers::pi / 6.0,
                       std::numbers::pi / 3.0,
                       b));
  const hid_t fa = test::open_read_only(a), fb = test::open_read_only(b);
  const std::vector<double> axis = test::read_doubles(fa, "axes/theta0");
  const std::vector<double> alpha2_a = test::read_doubles(fa, "alpha2");
  const std::vector<double> alpha2_b = test::read_doubles(fb, "alpha2");
  H5Fclose(fa);
  H5Fclose(fb);
  ASSERT_EQ(axis.size(), 4u);
  EXPECT_NEAR(axis[1], 40.0 * std::numbers::pi / 180.0, 1e-15);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(alpha2_a[i], alpha2_b[i], 1e-12 * alpha2_b[i]);
  // A fixed angle with a unit, and a unit of another quantity refused naming the end.
  run_json(fmt::format("sweep beam --theta0 30deg --n 0:1:3 --out {}", (dir / "c.h5").string()));
  const test::CommandResult bad =
      run_flexure(fmt::format("sweep beam --theta0 30N:60deg:4 --out {}", (dir / "d.h5").string()));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--theta0 START"), std::string::npos) << bad.err;
}

double read_attribute(hid_t file, const char* name) {
  const hid_t a = H5Aopen(file, name, H5P_DEFAULT);
  double value = std::nan("");
  H5Aread(a, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(a);
  return value;
}

TEST(CliPhysicalFaces, PhysicalSweepIsHowellsSweepScaled) {
  // --Fy 0N:5N:11 on the strip is --alpha2 0:5 L^2/EI:11: the same tips per unit length.
  test::ScratchDir dir;
  const std::string a = (dir / "si.h5").string(), b = (dir / "howell.h5").string();
  const Json j = run_json(fmt::format("sweep beam {} --Fy 0N:5N:11 --out {}", kStrip, a));
  EXPECT_EQ(j["axes"], "Fy");
  run_json(fmt::format("sweep beam --alpha2 0:{:.17g}:11 --out {}", 5.0 * kL * kL / kEI, b));
  const hid_t fa = test::open_read_only(a), fb = test::open_read_only(b);
  const std::vector<double> Fy = test::read_doubles(fa, "axes/Fy");
  const std::vector<double> alpha2 = test::read_doubles(fa, "alpha2");
  const std::vector<double> ya = test::read_doubles(fa, "b_over_l");
  const std::vector<double> yb = test::read_doubles(fb, "b_over_l");
  EXPECT_NEAR(read_attribute(fa, "length_m"), kL, 1e-18);
  EXPECT_NEAR(read_attribute(fa, "EI_Nm2") / kEI, 1.0, 1e-14);
  H5Fclose(fa);
  H5Fclose(fb);
  ASSERT_EQ(Fy.size(), 11u);
  for (int i = 0; i < 11; ++i) {
    EXPECT_NEAR(Fy[i], 0.5 * i, 1e-15);
    EXPECT_NEAR(alpha2[i], Fy[i] * kL * kL / kEI, 1e-12 * (1.0 + alpha2[i]));
    EXPECT_NEAR(ya[i], yb[i], 1e-12);
  }
}

TEST(CliPhysicalFaces, PhysicalSweepPointsEqualTheBeamCommand) {
  // A grid Fx x Fy holding the axial-only point Fy = 0 (auto takes the shooting method), a guided
  // end, and a curved strip under a uniform load: every point against `flexure beam` alone.
  test::ScratchDir dir;
  struct Case {
    std::string sweep, beam;
    std::vector<std::pair<double, double>> loads;  // (Fx, Fy) of each point, row-major
  };
  const std::vector<Case> cases = {
      {"--Fx -1N:1N:3 --Fy 0N:2N:3",
       "",
       {{-1, 0}, {-1, 1}, {-1, 2}, {0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}}},
      {"--Fy 1N:3N:3 --boundary guided", "--boundary guided", {{0, 1}, {0, 2}, {0, 3}}},
      {"--Fy 0N:2N:3 --curvature 4 --qy 1", "--curvature 4 --qy 1", {{0, 0}, {0, 1}, {0, 2}}}};
  for (const Case& c : cases) {
    const std::string out = (dir / "grid.h5").string();
    std::filesystem::remove(out);
    run_json(fmt::format("sweep beam {} {} --out {}", kStrip, c.sweep, out));
    const hid_t f = test::open_read_only(out);
    const std::vector<double> x = test::read_doubles(f, "a_over_l");
    const std::vector<double> y = test::read_doubles(f, "b_over_l");
    H5Fclose(f);
    ASSERT_EQ(x.size(), c.loads.size()) << c.sweep;
    for (std::size_t i = 0; i < c.loads.size(); ++i) {
      const Json one = run_json(fmt::format("beam {} --Fx {} --Fy {} {} --method shooting",
                                            kStrip,
                                            c.loads[i].first,
                                            c.loads[i].second,
                                            c.beam));
      EXPECT_NEAR(x[i], one["tip_x"].get<double>() / kL, 1e-9) << c.sweep << " " << i;
      EXPECT_NEAR(y[i], one["tip_y"].get<double>() / kL, 1e-9) << c.sweep << " " << i;
    }
  }
  // Refused: a range in newtons without a physical beam, Howell's loads with one.
  const test::CommandResult r1 = run_flexure(fmt::format(
      "sweep beam {} --Fy 0N:1N:3 --alpha2 1 --out {}", kStrip, (dir / "x.h5").string()));
  EXPECT_EQ(r1.exit_code, 2);
  EXPECT_NE(r1.err.find("do not combine it with --alpha2"), std::string::npos) << r1.err;
  const test::CommandResult r2 =
      run_flexure(fmt::format("sweep beam {} --Fy 1N --out {}", kStrip, (dir / "y.h5").string()));
  EXPECT_EQ(r2.exit_code, 2);
  EXPECT_NE(r2.err.find("--Fx, --Fy, --M"), std::string::npos) << r2.err;
}

TEST(CliPhysicalFaces, ChainSweepEqualsThePhysicalSweep) {
  // The curved strip as a chain file in SI, its tip force swept by --Fy with units, against the
  // same strip from the flags (--curvature): the same tips at every point.
  test::ScratchDir dir;
  const std::string toml = (dir / "curved.toml").string();
  std::ofstream(toml) << "units = \"SI\"\n[[segment]]\ntype = \"flexible\"\nlength = \"50 mm\"\n"
                         "E = \"200 GPa\"\nwidth = \"10 mm\"\nthickness = \"0.5 mm\"\n"
                         "kappa0 = 8\n[tip_load]\nFx = -0.2\n";
  const std::string a = (dir / "chain.h5").string(), b = (dir / "flags.h5").string();
  const Json j = run_json(fmt::format("sweep beam --chain {} --Fy 0N:600mN:4 --out {}", toml, a));
  EXPECT_EQ(j["axes"], "Fy");
  run_json(fmt::format("sweep beam {} --curvature 8 --Fx -0.2 --Fy 0:0.6:4 --out {}", kStrip, b));
  const hid_t fa = test::open_read_only(a), fb = test::open_read_only(b);
  const std::vector<double> ya = test::read_doubles(fa, "b_over_l");
  const std::vector<double> yb = test::read_doubles(fb, "b_over_l");
  const std::vector<double> Fy = test::read_doubles(fa, "axes/Fy");
  H5Fclose(fa);
  H5Fclose(fb);
  ASSERT_EQ(ya.size(), 4u);
  EXPECT_NEAR(Fy[3], 0.6, 1e-15);
  // Two scalings of one problem (SI against l = 1, EI = 1): equal to the solver tolerance.
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(ya[i], yb[i], 1e-9) << i;
  // The file holds the beam: other beam flags are refused.
  const test::CommandResult bad = run_flexure(fmt::format(
      "sweep beam --chain {} --Fy 0:1:3 --length 1 --out {}", toml, (dir / "c.h5").string()));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--Fx, --Fy, --M only"), std::string::npos) << bad.err;
}

TEST(CliPhysicalFaces, HowellShapePointsCarryInternalForces) {
  // alpha2 = 2, n = 1, mu = 0.5: the tip load (Fx, Fy) = (-n alpha2, alpha2) is N everywhere;
  // m(s) = Fy (x_tip - x) - Fx (y_tip - y) + mu, the statics of the part beyond s.
  for (const char* method : {"elliptic", "shooting"}) {
    const Json j =
        run_json(fmt::format("beam --alpha2 2 --n 1 --mu 0.5 --shape 11 --method {}", method));
    const double Fx = -2.0, Fy = 2.0, mu = 0.5;
    const double xt = j["a_over_l"].get<double>(), yt = j["b_over_l"].get<double>();
    for (const Json& p : j["shape"]) {
      const double t = p["theta"].get<double>();
      EXPECT_NEAR(p["N"].get<double>(), Fx * std::cos(t) + Fy * std::sin(t), 1e-9) << method;
      EXPECT_NEAR(p["V"].get<double>(), -Fx * std::sin(t) + Fy * std::cos(t), 1e-9) << method;
      const double m = Fy * (xt - p["x"].get<double>()) - Fx * (yt - p["y"].get<double>()) + mu;
      EXPECT_NEAR(p["m"].get<double>(), m, 1e-9) << method;
    }
  }
}

TEST(CliPhysicalFaces, RefusalsNameTheFlag) {
  for (const auto& [args, needle] :
       {std::pair{"beam --length 50mm --E 200GPa --I 1e-13 --Fy 1 --width-tip 5mm", "--width"},
        std::pair{"beam --length 50mm --E 200GPa --width 10mm --thickness 0.5mm --Fy 1 "
                  "--thickness-tip 0.3mm --extensible --nu 0.3",
                  "--extensible with a taper"},
        std::pair{"beam --length 50mm --E 200GPa --width 10mm --thickness 0.5mm --Fy 1 "
                  "--curvature 5 --method elliptic",
                  "curved or tapered"},
        std::pair{"beam --length 50mm --E 200GPa --width 10mm --thickness 0.5mm --Fy 1 "
                  "--curvature 5N",
                  "--curvature"},
        std::pair{"beam --alpha2 1 --boundary pinned --tip-x 45mm", "plain number"},
        std::pair{"beam --length 50mm --E 200GPa --width 10mm --thickness 0.5mm --Fy 1 "
                  "--width-tip -1mm",
                  "--width-tip"}}) {
    const test::CommandResult r = run_flexure(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
  }
}

}  // namespace
}  // namespace flexure
