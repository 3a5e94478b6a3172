#pragma once
// What every integrator backend of ElasticaIntegrator integrates on one flexible piece: the state
// (x, y, theta, m) packed with its forward-sensitivity columns, and the right-hand side of both
// (Howell eqs. 2.67-2.69 in differential form, docs/theory-shooting.md §2 and §4). Internal to
// solver/shooting: no library type appears here.
#include <Eigen/Dense>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure {

// What the right-hand side needs on the current flexible piece.
struct ElasticaPieceData {
  const FlexibleSegment* segment = nullptr;
  double segment_start = 0.0;  // global arc length where the segment starts
  double Nx = 0.0;
  double Ny = 0.0;
  std::vector<Eigen::Vector2d> dN;  // dN/dp on this segment, one per parameter

  double inv_EI(double s) const {
    // A constant EI (no profile) needs no interpolation: the common case, evaluated per stage.
    return segment->EI_profile.empty() ? 1.0 / segment->EI
                                       : 1.0 / segment->EI_at(s - segment_start);
  }
};

// Components of the packed state.
inline constexpr int kElasticaX = 0;
inline constexpr int kElasticaY = 1;
inline constexpr int kElasticaTheta = 2;
inline constexpr int kElasticaM = 3;
inline constexpr int kElasticaStates = 4;

// Right-hand side of the state and of `Ns` sensitivity columns packed as [state(4), S(:,0), ...]:
//   x' = cos theta, y' = sin theta, theta' = m/EI + kappa0, m' = N_x sin theta - N_y cos theta,
//   S' = J S + df/dp with df/dN_x = (0, 0, 0, sin theta), df/dN_y = (0, 0, 0, -cos theta).
inline void elastica_rhs(
    const ElasticaPieceData& piece, double s, const double* y, double* dy, int Ns) {
  const double c = std::cos(y[kElasticaTheta]);
  const double sn = std::sin(y[kElasticaTheta]);
  const double inv_EI = piece.inv_EI(s);
  dy[kElasticaX] = c;
  dy[kElasticaY] = sn;
  dy[kElasticaTheta] = y[kElasticaM] * inv_EI + piece.segment->kappa0;
  dy[kElasticaM] = piece.Nx * sn - piece.Ny * c;
  const double dm_dtheta = piece.Nx * c + piece.Ny * sn;
  for (int i = 0; i < Ns; ++i) {
    const double* S = y + kElasticaStates * (i + 1);
    double* dS = dy + kElasticaStates * (i + 1);
    dS[kElasticaX] = -sn * S[kElasticaTheta];
    dS[kElasticaY] = c * S[kElasticaTheta];
    dS[kElasticaTheta] = inv_EI * S[kElasticaM];
    dS[kElasticaM] = dm_dtheta * S[kElasticaTheta] + piece.dN[i].x() * sn - piece.dN[i].y() * c;
  }
}

// Where an explicit backend writes the pose at the requested arc lengths: it stops exactly on
// each of shape_s[next], shape_s[next + 1], ... that lies inside the stretch it integrates
// (explicit Runge-Kutta steps have no interpolant of the integrator's order here).
struct ShapeCursor {
  const std::vector<double>* shape_s = nullptr;  // null: no shape wanted
  std::vector<ShapePoint>* shape = nullptr;
  std::size_t next = 0;

  bool pending_before(double s_end) const {
    return shape_s != nullptr && next < shape_s->size() && (*shape_s)[next] < s_end;
  }
  void emit(const double* y) {
    shape->push_back(ShapePoint{(*shape_s)[next], y[kElasticaX], y[kElasticaY], y[kElasticaTheta]});
    ++next;
  }
};

// Sees every accepted step of an explicit backend on a flexible piece: the state (x, y, theta, m)
// and its derivative at both ends of the step (the sensitivity columns follow them in the packed
// arrays). Used to collect per-segment moment statistics from one integration without sampling
// the shape (segment_moments.h).
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  virtual void accepted_step(const ElasticaPieceData& piece,
                             double s0,
                             const double* y0,
                             const double* f0,
                             double s1,
                             const double* y1,
                             const double* f1) = 0;
};

// Tolerances and limits shared by the explicit backends (ElasticaIntegrator::Options).
struct ExplicitRkSettings {
  double rtol = 1e-12;
  double atol = 1e-14;
  long max_steps = 200000;
};

// One integration by an explicit backend: the packed state `y` (4 (Ns + 1) components) of one
// flexible piece from s_a to s_b, stopping on every pending shape point of `shape` before s_b.
struct PieceRun {
  const ElasticaPieceData& piece;
  int Ns;
  double s_a;
  double s_b;
  std::vector<double>& y;  // in: the state at s_a; out: at s_b
  ShapeCursor& shape;
  StepObserver* observer;  // may be null: sees every accepted step (backends that have steps)
  long max_steps;          // the limit of this run (at most ExplicitRkSettings::max_steps)
  long& steps;             // the steps taken are added
  std::string& error;      // set when integrate() returns false
};

// An explicit integrator backend of ElasticaIntegrator. integrate() returns false with
// run.error set when the library fails, more than run.max_steps steps are needed or the state is
// not finite.
class ExplicitPieceIntegrator {
 public:
  ExplicitPieceIntegrator() = default;
  virtual ~ExplicitPieceIntegrator() = default;
  ExplicitPieceIntegrator(const ExplicitPieceIntegrator&) = delete;
  ExplicitPieceIntegrator& operator=(const ExplicitPieceIntegrator&) = delete;
  virtual bool integrate(const PieceRun& run) = 0;
};

}  // namespace flexure
