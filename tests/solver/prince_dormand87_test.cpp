// The written-out Prince-Dormand 8(7) of the shooting method (PrinceDormand87Piece, the default
// rk8pd backend) against
//   * GSL's gsl_odeiv2_step_rk8pd with its standard control (GslRk8pdPiece, the backend it
//     replaced): on seeded random elastica pieces (end forces, moments, stress-free curvature, a
//     varying EI, 0 to 6 sensitivity columns: the fixed lengths of 0-4 columns and the general
//     one; a stop on shape points) the same number of steps and the same state within 1e-14
//     relative to its size (it does GSL's operations in GSL's order: measured bit-identical on
//     the x86-64 build without contracted multiply-adds);
//   * the closed form of a beam under a pure end moment, the circular arc theta = theta0 + M s /
//     EI, x = EI / M (sin theta - sin theta0), y = EI / M (cos theta0 - cos theta), to 1e-12.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "flexure/solver/shooting/gsl_rk8pd_piece.h"
#include "flexure/solver/shooting/prince_dormand87_piece.h"

namespace flexure {
namespace {

struct Outcome {
  std::vector<double> y;
  std::vector<ShapePoint> shape;
  long steps = 0;
  bool ok = false;
};

Outcome run(ExplicitPieceIntegrator& integrator,
            const ElasticaPieceData& piece,
            int Ns,
            std::vector<double> y,
            const std::vector<double>* shape_s) {
  Outcome out;
  std::vector<ShapePoint> shape;
  ShapeCursor cursor;
  if (shape_s != nullptr) {
    cursor.shape_s = shape_s;
    cursor.shape = &shape;
  }
  std::string error;
  const PieceRun r{
      piece, Ns, 0.0, piece.segment->length, y, cursor, nullptr, 200000, out.steps, error};
  out.ok = integrator.integrate(r);
  out.y = y;
  out.shape = shape;
  return out;
}

TEST(PrinceDormand87, TakesGslRk8pdStepsOnRandomElasticaPieces) {
  std::mt19937 rng(20261129);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const ExplicitRkSettings settings{1e-12, 1e-14, 200000};
  for (int trial = 0; trial < 60; ++trial) {
    FlexibleSegment segment(0.5 + 1.5 * std::fabs(unit(rng)), 0.5 + std::fabs(unit(rng)));
    if (trial % 3 == 1) segment.kappa0 = 2.0 * unit(rng);
    if (trial % 4 == 2) segment.EI_profile = {1.0, 0.6 + 0.3 * unit(rng), 0.8};
    const int Ns = trial % 7;
    ElasticaPieceData piece;
    piece.segment = &segment;
    piece.Nx = 15.0 * unit(rng);
    piece.Ny = 15.0 * unit(rng);
    for (int i = 0; i < Ns; ++i) piece.dN.emplace_back(unit(rng), unit(rng));
    std::vector<double> y(kElasticaStates * (Ns + 1), 0.0);
    y[kElasticaTheta] = 0.3 * unit(rng);
    y[kElasticaM] = 5.0 * unit(rng);
    for (int i = 0; i < Ns; ++i) {
      y[kElasticaStates * (i + 1) + kElasticaTheta] = unit(rng);
      y[kElasticaStates * (i + 1) + kElasticaM] = unit(rng);
    }
    std::vector<double> shape_s;
    if (trial % 5 == 0) {
      for (int k = 0; k <= 10; ++k) shape_s.push_back(segment.length * k / 10.0);
    }
    const std::vector<double>* wanted = shape_s.empty() ? nullptr : &shape_s;
    GslRk8pdPiece gsl(settings);
    PrinceDormand87Piece written(settings);
    // Twice each: the second integration starts from the first step remembered for the piece.
    for (int pass = 0; pass < 2; ++pass) {
      const Outcome a = run(gsl, piece, Ns, y, wanted);
      const Outcome b = run(written, piece, Ns, y, wanted);
      ASSERT_TRUE(a.ok && b.ok) << "trial " << trial;
      EXPECT_EQ(a.steps, b.steps) << "trial " << trial << " pass " << pass;
      double size = 1.0;
      for (double v : a.y) size = std::max(size, std::fabs(v));
      for (std::size_t i = 0; i < a.y.size(); ++i) {
        EXPECT_LE(std::fabs(a.y[i] - b.y[i]), 1e-14 * size)
            << "trial " << trial << " component " << i;
      }
      ASSERT_EQ(a.shape.size(), b.shape.size());
      for (std::size_t i = 0; i < a.shape.size(); ++i) {
        EXPECT_LE(std::fabs(a.shape[i].theta - b.shape[i].theta), 1e-14 * size);
        EXPECT_LE(std::fabs(a.shape[i].x - b.shape[i].x), 1e-14 * size);
      }
    }
  }
}

TEST(PrinceDormand87, PureMomentGivesTheCircularArc) {
  const ExplicitRkSettings settings{1e-12, 1e-14, 200000};
  for (const double M : {0.3, 2.0, -5.0, 9.0}) {
    FlexibleSegment segment(1.3, 0.7);
    ElasticaPieceData piece;
    piece.segment = &segment;
    const double theta0 = 0.2;
    std::vector<double> y{0.0, 0.0, theta0, M};
    PrinceDormand87Piece integrator(settings);
    const Outcome out = run(integrator, piece, 0, y, nullptr);
    ASSERT_TRUE(out.ok);
    const double k = M / segment.EI;
    const double theta = theta0 + k * segment.length;
    EXPECT_NEAR(out.y[kElasticaTheta], theta, 1e-12) << M;
    EXPECT_NEAR(out.y[kElasticaX], (std::sin(theta) - std::sin(theta0)) / k, 1e-12) << M;
    EXPECT_NEAR(out.y[kElasticaY], (std::cos(theta0) - std::cos(theta)) / k, 1e-12) << M;
    EXPECT_NEAR(out.y[kElasticaM], M, 1e-12) << M;
  }
}

}  // namespace
}  // namespace flexure
