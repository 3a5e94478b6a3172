#pragma once
// What every integrator backend of ElasticaIntegrator integrates on one flexible piece: the state
// (x, y, theta, m) packed with its forward-sensitivity columns, and the right-hand side of both
// (Howell eqs. 2.67-2.69 in differential form, docs/theory-shooting.md §2 and §4). Internal to
// solver/shooting: no library type appears here.
#include <Eigen/Dense>
#include <array>
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
  // Segments beyond the elastica (distributed load, follower pressure, finite EA or GAs;
  // FlexibleSegment::beyond_elastica) take reissner_rhs: there N(s) = (Nx, Ny) - lf Q(s)
  // - lf p R90 r(s), Q the dead-load resultant from the segment start, p the follower pressure,
  // R90 (x, y) = (-y, x) (docs/distributed-loads.md), and (Nx, Ny) holds N at the segment start
  // minus the follower anchor.
  bool extended = false;
  double load_factor = 0.0;          // lf: the distributed loads' factor
  std::vector<double> dload_factor;  // d lf / dp, one per parameter
  double inv_EA = 0.0;               // 1/EA (0: inextensible)
  double inv_GA = 0.0;               // 1/GAs (0: shear-rigid)

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

// Internal force on an extended piece at s for the state y (see ElasticaPieceData).
inline Eigen::Vector2d reissner_force(const ElasticaPieceData& piece, double s, const double* y) {
  const FlexibleSegment& seg = *piece.segment;
  const double lf = piece.load_factor;
  const double p = seg.q_follower;
  Eigen::Vector2d N(piece.Nx + lf * p * y[kElasticaY], piece.Ny - lf * p * y[kElasticaX]);
  if (seg.has_dead_load()) {
    const std::array<double, 2> Q = seg.q_resultant(s - piece.segment_start);
    N.x() -= lf * Q[0];
    N.y() -= lf * Q[1];
  }
  return N;
}

// Reissner's planar geometrically exact beam (Reissner 1972, ZAMP 23; Simo & Vu-Quoc 1986) with
// the state (x, y, theta, m) and the internal force N(s) of reissner_force:
//   N_a = N.t, V = N.n (t = (cos, sin), n = (-sin, cos)), eps = N_a/EA, gamma = V/GAs,
//   r' = (1 + eps) t + gamma n, theta' = m/EI + kappa0,
//   m' = -(r' x N) = -V (1 + N_a (1/EA - 1/GAs)),
// and the sensitivity columns differentiated by hand (dN/dp from the shot forces, the load factor
// and, through the follower pressure, the position).
inline void reissner_rhs(
    const ElasticaPieceData& piece, double s, const double* y, double* dy, int Ns) {
  const FlexibleSegment& seg = *piece.segment;
  const double c = std::cos(y[kElasticaTheta]);
  const double sn = std::sin(y[kElasticaTheta]);
  const double inv_EI = piece.inv_EI(s);
  const Eigen::Vector2d N = reissner_force(piece, s, y);
  const double Nax = N.x() * c + N.y() * sn;
  const double V = -N.x() * sn + N.y() * c;
  const double iEA = piece.inv_EA, iGA = piece.inv_GA;
  const double eps = Nax * iEA, gam = V * iGA;
  const double k = 1.0 + Nax * (iEA - iGA);
  dy[kElasticaX] = (1.0 + eps) * c - gam * sn;
  dy[kElasticaY] = (1.0 + eps) * sn + gam * c;
  dy[kElasticaTheta] = y[kElasticaM] * inv_EI + seg.kappa0;
  dy[kElasticaM] = -V * k;
  if (Ns == 0) return;
  const double lf = piece.load_factor;
  const double p = seg.q_follower;
  std::array<double, 2> Q{0.0, 0.0};
  if (seg.has_dead_load()) Q = seg.q_resultant(s - piece.segment_start);
  for (int i = 0; i < Ns; ++i) {
    const double* S = y + kElasticaStates * (i + 1);
    double* dS = dy + kElasticaStates * (i + 1);
    const double dlf = piece.dload_factor[i];
    const double dNx =
        piece.dN[i].x() - dlf * Q[0] + dlf * p * y[kElasticaY] + lf * p * S[kElasticaY];
    const double dNy =
        piece.dN[i].y() - dlf * Q[1] - dlf * p * y[kElasticaX] - lf * p * S[kElasticaX];
    const double St = S[kElasticaTheta];
    const double dNax = dNx * c + dNy * sn + V * St;
    const double dV = -dNx * sn + dNy * c - Nax * St;
    const double deps = dNax * iEA, dgam = dV * iGA;
    dS[kElasticaX] = deps * c - (1.0 + eps) * sn * St - dgam * sn - gam * c * St;
    dS[kElasticaY] = deps * sn + (1.0 + eps) * c * St + dgam * c - gam * sn * St;
    dS[kElasticaTheta] = inv_EI * S[kElasticaM];
    dS[kElasticaM] = -(dV * k + V * dNax * (iEA - iGA));
  }
}

// d2m/ds2 at a state y with derivative f (the quintic moment interpolant of segment_moments.h and
// inflection_count.h): for the elastica (N_x cos theta + N_y sin theta) theta'; on an extended
// piece -(r'' x N) - (r' x N') with N' = -lf q - lf p R90 r'.
inline double moment_second_derivative(const ElasticaPieceData& piece,
                                       double s,
                                       const double* y,
                                       const double* f) {
  // On the elastica x' = cos theta and y' = sin theta: the derivative f holds the tangent, no
  // sine and cosine needed (two per accepted step of a sweep's inflection count).
  if (!piece.extended) {
    return (piece.Nx * f[kElasticaX] + piece.Ny * f[kElasticaY]) * f[kElasticaTheta];
  }
  const double th = y[kElasticaTheta];
  const double c = std::cos(th), sn = std::sin(th);
  const FlexibleSegment& seg = *piece.segment;
  const double lf = piece.load_factor;
  const Eigen::Vector2d N = reissner_force(piece, s, y);
  const std::array<double, 2> q = seg.q_at(s - piece.segment_start);
  const double p = seg.q_follower;
  const Eigen::Vector2d dN(-lf * q[0] + lf * p * f[kElasticaY],
                           -lf * q[1] - lf * p * f[kElasticaX]);
  const double Nax = N.x() * c + N.y() * sn, V = -N.x() * sn + N.y() * c;
  const double w = f[kElasticaTheta];
  const double dNax = dN.x() * c + dN.y() * sn + V * w;
  const double dV = -dN.x() * sn + dN.y() * c - Nax * w;
  const double eps = Nax * piece.inv_EA, gam = V * piece.inv_GA;
  const double deps = dNax * piece.inv_EA, dgam = dV * piece.inv_GA;
  // r'' = eps' t + (1 + eps) theta' n + gamma' n - gamma theta' t.
  const double a_t = deps - gam * w, a_n = (1.0 + eps) * w + dgam;
  const double rx2 = a_t * c - a_n * sn, ry2 = a_t * sn + a_n * c;
  const double cross_r2N = rx2 * N.y() - ry2 * N.x();
  const double cross_r1dN = f[kElasticaX] * dN.y() - f[kElasticaY] * dN.x();
  return -cross_r2N - cross_r1dN;
}

// Right-hand side of a plain (inextensible) piece's state and of `Ns` sensitivity columns packed
// as [state(4), S(:,0), ...]:
//   x' = cos theta, y' = sin theta, theta' = m/EI + kappa0, m' = N_x sin theta - N_y cos theta,
//   S' = J S + df/dp with df/dN_x = (0, 0, 0, sin theta), df/dN_y = (0, 0, 0, -cos theta).
// `Count` is int, or std::integral_constant<int, N> where the column count is known when compiled
// (the written-out Prince-Dormand stepper, prince_dormand87_piece.cpp: the loop then unrolls; the
// values are the same).
template <class Count>
inline void plain_elastica_rhs(
    const ElasticaPieceData& piece, double s, const double* y, double* dy, Count Ns) {
  const double c = std::cos(y[kElasticaTheta]);
  const double sn = std::sin(y[kElasticaTheta]);
  const double inv_EI = piece.inv_EI(s);
  dy[kElasticaX] = c;
  dy[kElasticaY] = sn;
  dy[kElasticaTheta] = y[kElasticaM] * inv_EI + piece.segment->kappa0;
  dy[kElasticaM] = piece.Nx * sn - piece.Ny * c;
  const double dm_dtheta = piece.Nx * c + piece.Ny * sn;
  for (int i = 0; i < static_cast<int>(Ns); ++i) {
    const double* S = y + kElasticaStates * (i + 1);
    double* dS = dy + kElasticaStates * (i + 1);
    dS[kElasticaX] = -sn * S[kElasticaTheta];
    dS[kElasticaY] = c * S[kElasticaTheta];
    dS[kElasticaTheta] = inv_EI * S[kElasticaM];
    dS[kElasticaM] = dm_dtheta * S[kElasticaTheta] + piece.dN[i].x() * sn - piece.dN[i].y() * c;
  }
}

// The same for any piece: Reissner's extensible and shear-flexible piece has its own.
inline void elastica_rhs(
    const ElasticaPieceData& piece, double s, const double* y, double* dy, int Ns) {
  if (piece.extended) {
    reissner_rhs(piece, s, y, dy, Ns);
    return;
  }
  plain_elastica_rhs(piece, s, y, dy, Ns);
}

// Where an explicit backend writes the pose at the requested arc lengths: it stops exactly on
// each of shape_s[next], shape_s[next + 1], ... that lies inside the stretch it integrates
// (explicit Runge-Kutta steps have no interpolant of the integrator's order here).
struct ShapeCursor {
  const std::vector<double>* shape_s = nullptr;  // null: no shape wanted
  std::vector<ShapePoint>* shape = nullptr;
  std::size_t next = 0;
  std::vector<double>* moment = nullptr;  // not null: the bending moment m at every point too

  bool pending_before(double s_end) const {
    return shape_s != nullptr && next < shape_s->size() && (*shape_s)[next] < s_end;
  }
  void emit(const double* y) {
    shape->push_back(ShapePoint{(*shape_s)[next], y[kElasticaX], y[kElasticaY], y[kElasticaTheta]});
    if (moment != nullptr) moment->push_back(y[kElasticaM]);
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
