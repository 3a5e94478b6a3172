#include "flexure/solver/shooting/elastica_integrator.h"

#include <cvodes/cvodes.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>

#include "flexure/solver/common/errors.h"

namespace flexure {

namespace {
constexpr int kX = 0;
constexpr int kY = 1;
constexpr int kTheta = 2;
constexpr int kM = 3;
constexpr int kStates = 4;

}  // namespace

// What the right-hand side needs on the current flexible piece.
struct ElasticaPieceData {
  const FlexibleSegment* segment = nullptr;
  double segment_start = 0.0;  // global arc length where the segment starts
  double Nx = 0.0;
  double Ny = 0.0;
  std::vector<Eigen::Vector2d> dN;  // dN/dp on this segment, one per parameter
};

namespace {
using PieceData = ElasticaPieceData;

int rhs(realtype s, N_Vector y, N_Vector ydot, void* user_data) {
  const auto* piece = static_cast<const PieceData*>(user_data);
  const double* v = N_VGetArrayPointer(y);
  double* d = N_VGetArrayPointer(ydot);
  const double c = std::cos(v[kTheta]);
  const double sn = std::sin(v[kTheta]);
  const double EI = piece->segment->EI_at(s - piece->segment_start);
  d[kX] = c;
  d[kY] = sn;
  d[kTheta] = v[kM] / EI + piece->segment->kappa0;
  d[kM] = piece->Nx * sn - piece->Ny * c;
  return 0;
}

int jacobian(realtype s,
             N_Vector y,
             N_Vector /*fy*/,
             SUNMatrix J,
             void* user_data,
             N_Vector /*tmp1*/,
             N_Vector /*tmp2*/,
             N_Vector /*tmp3*/) {
  const auto* piece = static_cast<const PieceData*>(user_data);
  const double* v = N_VGetArrayPointer(y);
  const double c = std::cos(v[kTheta]);
  const double sn = std::sin(v[kTheta]);
  SUNMatZero(J);
  SM_ELEMENT_D(J, kX, kTheta) = -sn;
  SM_ELEMENT_D(J, kY, kTheta) = c;
  SM_ELEMENT_D(J, kTheta, kM) = 1.0 / piece->segment->EI_at(s - piece->segment_start);
  SM_ELEMENT_D(J, kM, kTheta) = piece->Nx * c + piece->Ny * sn;
  return 0;
}

// S_i' = J S_i + df/dp_i for every parameter at once.
int sensitivity_rhs(int Ns,
                    realtype s,
                    N_Vector y,
                    N_Vector /*ydot*/,
                    N_Vector* yS,
                    N_Vector* ySdot,
                    void* user_data,
                    N_Vector /*tmp1*/,
                    N_Vector /*tmp2*/) {
  const auto* piece = static_cast<const PieceData*>(user_data);
  const double* v = N_VGetArrayPointer(y);
  const double c = std::cos(v[kTheta]);
  const double sn = std::sin(v[kTheta]);
  const double inv_EI = 1.0 / piece->segment->EI_at(s - piece->segment_start);
  const double dm_dtheta = piece->Nx * c + piece->Ny * sn;
  for (int i = 0; i < Ns; ++i) {
    const double* S = N_VGetArrayPointer(yS[i]);
    double* dS = N_VGetArrayPointer(ySdot[i]);
    dS[kX] = -sn * S[kTheta];
    dS[kY] = c * S[kTheta];
    dS[kTheta] = inv_EI * S[kM];
    dS[kM] = dm_dtheta * S[kTheta] + piece->dN[i].x() * sn - piece->dN[i].y() * c;
  }
  return 0;
}

void silent_error_handler(int, const char*, const char*, char*, void*) {}

std::string flag_message(const char* function, int flag) {
  const char* name = CVodeGetReturnFlagName(flag);
  std::string text = fmt::format("CVODES {} failed with flag {} ({})", function, flag, name);
  free(const_cast<char*>(name));  // CVodeGetReturnFlagName allocates with malloc
  return text;
}

}  // namespace

using PieceData = ElasticaPieceData;

struct ElasticaIntegrator::Impl {
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  void* cvode = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  SUNNonlinearSolver NLS = nullptr;       // fixed-point corrector for the state (Adams)
  SUNNonlinearSolver NLS_sens = nullptr;  // fixed-point corrector for state + sensitivities
  N_Vector* yS = nullptr;
  long steps = 0;      // CVODES steps taken since construction
  int sens_count = 0;  // parameters CVodeSensInit was called with (0 = never)
  PieceData piece;
  FlexibleSegment dummy;

  ~Impl() {
    if (yS != nullptr) N_VDestroyVectorArray(yS, sens_count);
    if (cvode != nullptr) CVodeFree(&cvode);
    if (NLS_sens != nullptr) SUNNonlinSolFree(NLS_sens);
    if (NLS != nullptr) SUNNonlinSolFree(NLS);
    if (LS != nullptr) SUNLinSolFree(LS);
    if (A != nullptr) SUNMatDestroy(A);
    if (y != nullptr) N_VDestroy(y);
    if (context != nullptr) SUNContext_Free(&context);
  }
};

namespace {
void check_setup(int flag, const char* function) {
  if (flag != 0) throw std::runtime_error(flag_message(function, flag));
}
}  // namespace

void ElasticaIntegrator::Options::validate() const {
  if (!(rtol > 0.0 && rtol < 1e-2)) {
    throw InvalidInput(
        fmt::format("ElasticaIntegrator::Options::rtol must be in (0, 1e-2) (got {})", rtol));
  }
  if (!(atol > 0.0 && std::isfinite(atol))) {
    throw InvalidInput(fmt::format("ElasticaIntegrator::Options::atol must be > 0 (got {})", atol));
  }
  if (max_steps < 1) {
    throw InvalidInput(
        fmt::format("ElasticaIntegrator::Options::max_steps must be >= 1 (got {})", max_steps));
  }
}

ElasticaIntegrator::ElasticaIntegrator(Options options)
    : options_(options), impl_(std::make_unique<Impl>()) {
  options_.validate();
  Impl& d = *impl_;
  if (SUNContext_Create(nullptr, &d.context) != 0) {
    throw std::runtime_error("SUNContext_Create failed");
  }
  d.y = N_VNew_Serial(kStates, d.context);
  if (d.y == nullptr) throw std::runtime_error("N_VNew_Serial failed");
  N_VConst(0.0, d.y);
  d.cvode = CVodeCreate(options_.adams ? CV_ADAMS : CV_BDF, d.context);
  if (d.cvode == nullptr) throw std::runtime_error("CVodeCreate failed");
  d.piece.segment = &d.dummy;
  check_setup(CVodeInit(d.cvode, rhs, 0.0, d.y), "CVodeInit");
  check_setup(CVodeSStolerances(d.cvode, options_.rtol, options_.atol), "CVodeSStolerances");
  check_setup(CVodeSetUserData(d.cvode, &d.piece), "CVodeSetUserData");
  check_setup(CVodeSetMaxNumSteps(d.cvode, options_.max_steps), "CVodeSetMaxNumSteps");
  // Failures are reported through return flags and our messages, not CVODES' stderr printout.
  check_setup(CVodeSetErrHandlerFn(d.cvode, silent_error_handler, nullptr), "CVodeSetErrHandlerFn");
  if (options_.adams && options_.fixed_point) {
    d.NLS = SUNNonlinSol_FixedPoint(d.y, 0, d.context);
    if (d.NLS == nullptr) throw std::runtime_error("SUNNonlinSol_FixedPoint failed");
    check_setup(CVodeSetNonlinearSolver(d.cvode, d.NLS), "CVodeSetNonlinearSolver");
  } else {
    d.A = SUNDenseMatrix(kStates, kStates, d.context);
    if (d.A == nullptr) throw std::runtime_error("SUNDenseMatrix failed");
    d.LS = SUNLinSol_Dense(d.y, d.A, d.context);
    if (d.LS == nullptr) throw std::runtime_error("SUNLinSol_Dense failed");
    check_setup(CVodeSetLinearSolver(d.cvode, d.LS, d.A), "CVodeSetLinearSolver");
    check_setup(CVodeSetJacFn(d.cvode, jacobian), "CVodeSetJacFn");
  }
}

ElasticaIntegrator::~ElasticaIntegrator() = default;

long ElasticaIntegrator::steps_taken() const { return impl_->steps; }

bool ElasticaIntegrator::integrate(
    const SegmentChain& chain,
    const std::vector<IntegrationPiece>& pieces,
    const ChainForces& forces,
    const std::vector<ForceDerivative>& derivatives,
    const Eigen::Vector4d& start,
    const Eigen::Matrix<double, 4, Eigen::Dynamic>& start_sensitivity,
    TipState& end,
    std::string& error,
    const std::vector<double>* shape_s,
    std::vector<ShapePoint>* shape,
    bool last) {
  Impl& d = *impl_;
  const int n = chain.segment_count();
  const int Ns = static_cast<int>(derivatives.size());
  if (static_cast<int>(forces.N.size()) != n ||
      static_cast<int>(forces.moment_drop.size()) != n + 1 || start_sensitivity.cols() != Ns) {
    throw std::logic_error("ElasticaIntegrator: forces or sensitivities sized inconsistently");
  }
  if (!ensure_sensitivities(Ns, error)) return false;

  Eigen::Vector4d state = start;
  Eigen::Matrix<double, 4, Eigen::Dynamic> S = start_sensitivity;
  const bool want_shape = shape_s != nullptr && shape != nullptr;
  std::size_t next_shape = 0;
  if (want_shape) {
    // Skip points before this stretch (they belong to an earlier call).
    const double s0 = pieces.empty() ? 0.0 : pieces.front().segment_start + pieces.front().begin;
    while (next_shape < shape_s->size() && (*shape_s)[next_shape] < s0) ++next_shape;
  }
  auto emit_below = [&](double s_limit) {
    if (!want_shape) return;
    while (next_shape < shape_s->size() && (*shape_s)[next_shape] < s_limit) {
      shape->push_back(ShapePoint{(*shape_s)[next_shape], state[kX], state[kY], state[kTheta]});
      ++next_shape;
    }
  };

  d.piece.dN.resize(Ns);
  for (const IntegrationPiece& piece : pieces) {
    const int j = piece.segment;
    const Eigen::Vector2d N = forces.N[j];
    for (int i = 0; i < Ns; ++i) {
      d.piece.dN[i] = derivatives[i].dN.empty() ? Eigen::Vector2d::Zero() : derivatives[i].dN[j];
    }
    if (const auto* rigid = std::get_if<RigidSegment>(&chain.segments[j])) {
      // A straight link: theta jumps by the offset, the moment changes by L (N_x sin - N_y cos).
      const double th = state[kTheta] + rigid->angle_offset;
      const double L = rigid->length;
      const double c = std::cos(th), sn = std::sin(th);
      if (want_shape) {
        while (next_shape < shape_s->size() && (*shape_s)[next_shape] < piece.segment_start + L) {
          const double ds = std::max(0.0, (*shape_s)[next_shape] - piece.segment_start);
          shape->push_back(
              ShapePoint{(*shape_s)[next_shape], state[kX] + ds * c, state[kY] + ds * sn, th});
          ++next_shape;
        }
      }
      for (int i = 0; i < Ns; ++i) {
        const double dth = S(kTheta, i);
        S(kX, i) += -L * sn * dth;
        S(kY, i) += L * c * dth;
        S(kM, i) += L * (N.x() * c + N.y() * sn) * dth +
                    L * (d.piece.dN[i].x() * sn - d.piece.dN[i].y() * c);
      }
      state[kX] += L * c;
      state[kY] += L * sn;
      state[kM] += L * (N.x() * sn - N.y() * c);
      state[kTheta] = th;
    } else {
      const auto& flex = std::get<FlexibleSegment>(chain.segments[j]);
      d.piece.segment = &flex;
      d.piece.segment_start = piece.segment_start;
      d.piece.Nx = N.x();
      d.piece.Ny = N.y();
      // EI tabulated: integrate station to station so that the kinks in EI(s) fall on sub-piece
      // ends, where CVODES restarts.
      std::vector<double> cuts{piece.begin};
      if (flex.EI_profile.size() >= 2) {
        const int intervals = static_cast<int>(flex.EI_profile.size()) - 1;
        for (int p = 1; p < intervals; ++p) {
          const double station = flex.length * p / intervals;
          if (station > piece.begin && station < piece.end) cuts.push_back(station);
        }
      }
      cuts.push_back(piece.end);
      for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
        const double s_a = piece.segment_start + cuts[p];
        const double s_b = piece.segment_start + cuts[p + 1];
        emit_below(std::nextafter(s_a, std::numeric_limits<double>::infinity()));
        if (options_.backend == Backend::kDormandPrince) {
          if (!dormand_prince_piece(d.piece,
                                    s_a,
                                    s_b,
                                    state,
                                    S,
                                    error,
                                    want_shape ? shape_s : nullptr,
                                    shape,
                                    next_shape)) {
            return false;
          }
          continue;
        }
        double* yv = N_VGetArrayPointer(d.y);
        for (int k = 0; k < kStates; ++k) yv[k] = state[k];
        int flag = CVodeReInit(d.cvode, s_a, d.y);
        if (flag != CV_SUCCESS) {
          error = flag_message("CVodeReInit", flag);
          return false;
        }
        if (Ns > 0) {
          for (int i = 0; i < Ns; ++i) {
            double* Sv = N_VGetArrayPointer(d.yS[i]);
            for (int k = 0; k < kStates; ++k) Sv[k] = S(k, i);
          }
          flag = CVodeSensReInit(d.cvode, CV_SIMULTANEOUS, d.yS);
          if (flag != CV_SUCCESS) {
            error = flag_message("CVodeSensReInit", flag);
            return false;
          }
        } else if (d.sens_count > 0) {
          flag = CVodeSensToggleOff(d.cvode);
          if (flag != CV_SUCCESS) {
            error = flag_message("CVodeSensToggleOff", flag);
            return false;
          }
        }
        flag = CVodeSetStopTime(d.cvode, s_b);
        if (flag != CV_SUCCESS) {
          error = flag_message("CVodeSetStopTime", flag);
          return false;
        }
        realtype t = s_a;
        // CVODES refuses an output time within rounding of the current one (CV_TOO_CLOSE, e.g. a
        // shape point that coincides with a multiple-shooting cut); the state there is the
        // current state to that rounding.
        auto beyond = [](double s_out, double s_now) {
          return s_out - s_now > 1e-13 * std::max(1.0, std::fabs(s_now));
        };
        // Shape points strictly inside the sub-piece: CVODES interpolates at the method's order.
        while (want_shape && next_shape < shape_s->size() && (*shape_s)[next_shape] < s_b) {
          const double s_out = (*shape_s)[next_shape];
          if (beyond(s_out, t)) {
            flag = CVode(d.cvode, s_out, d.y, &t, CV_NORMAL);
            if (flag < 0) {
              error = flag_message("CVode", flag) + fmt::format(" at s = {}", t);
              return false;
            }
          }
          const double* yo = N_VGetArrayPointer(d.y);
          shape->push_back(ShapePoint{s_out, yo[kX], yo[kY], yo[kTheta]});
          ++next_shape;
        }
        if (beyond(s_b, t)) {
          flag = CVode(d.cvode, s_b, d.y, &t, CV_NORMAL);
          if (flag < 0) {
            error = flag_message("CVode", flag) + fmt::format(" at s = {}", t);
            return false;
          }
        }
        long piece_steps = 0;
        flag = CVodeGetNumSteps(d.cvode, &piece_steps);
        if (flag != CV_SUCCESS) {
          error = flag_message("CVodeGetNumSteps", flag);
          return false;
        }
        d.steps += piece_steps;
        const double* ye = N_VGetArrayPointer(d.y);
        for (int k = 0; k < kStates; ++k) state[k] = ye[k];
        if (Ns > 0) {
          flag = CVodeGetSens(d.cvode, &t, d.yS);
          if (flag != CV_SUCCESS) {
            error = flag_message("CVodeGetSens", flag);
            return false;
          }
          for (int i = 0; i < Ns; ++i) {
            const double* Sv = N_VGetArrayPointer(d.yS[i]);
            for (int k = 0; k < kStates; ++k) S(k, i) = Sv[k];
          }
        }
      }
    }
    if (!state.allFinite()) {
      error = fmt::format("integration produced a non-finite state on segment {}", j);
      return false;
    }
    if (piece.crosses_far_node) {
      // Crossing node j+1: the node's dead moment leaves the distal part.
      state[kM] -= forces.moment_drop[j + 1];
      for (int i = 0; i < Ns; ++i) {
        if (!derivatives[i].dmoment_drop.empty()) S(kM, i) -= derivatives[i].dmoment_drop[j + 1];
      }
    }
  }
  if (want_shape) {
    const double s_end = pieces.empty() ? 0.0 : pieces.back().segment_start + pieces.back().end;
    emit_below(last ? std::numeric_limits<double>::infinity() : s_end);
  }
  end.x = state[kX];
  end.y = state[kY];
  end.theta = state[kTheta];
  end.m = state[kM];
  end.sensitivity = S;
  return true;
}

namespace {

// Right-hand side of the state and all sensitivity columns, packed as [state(4), S(:,0), ...].
void full_rhs(const PieceData& piece, double s, const double* y, double* dy, int Ns) {
  const double c = std::cos(y[kTheta]);
  const double sn = std::sin(y[kTheta]);
  const double inv_EI = 1.0 / piece.segment->EI_at(s - piece.segment_start);
  dy[kX] = c;
  dy[kY] = sn;
  dy[kTheta] = y[kM] * inv_EI + piece.segment->kappa0;
  dy[kM] = piece.Nx * sn - piece.Ny * c;
  const double dm_dtheta = piece.Nx * c + piece.Ny * sn;
  for (int i = 0; i < Ns; ++i) {
    const double* S = y + kStates * (i + 1);
    double* dS = dy + kStates * (i + 1);
    dS[kX] = -sn * S[kTheta];
    dS[kY] = c * S[kTheta];
    dS[kTheta] = inv_EI * S[kM];
    dS[kM] = dm_dtheta * S[kTheta] + piece.dN[i].x() * sn - piece.dN[i].y() * c;
  }
}

}  // namespace

bool ElasticaIntegrator::dormand_prince_piece(const PieceData& piece,
                                              double s_a,
                                              double s_b,
                                              Eigen::Vector4d& state,
                                              Eigen::Matrix<double, 4, Eigen::Dynamic>& S,
                                              std::string& error,
                                              const std::vector<double>* shape_s,
                                              std::vector<ShapePoint>* shape,
                                              std::size_t& next_shape) {
  // Dormand-Prince 5(4) (Hairer, Norsett & Wanner, Solving ODEs I, Table 5.2), FSAL, error test
  // on state and sensitivities (the same reason as CVodeSetSensErrCon above).
  constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  constexpr double a21 = 1.0 / 5;
  constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                   a54 = -212.0 / 729;
  constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                   a65 = -5103.0 / 18656;
  constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                   b6 = 11.0 / 84;
  // Error coefficients: b - b_hat (fourth-order weights 5179/57600, 0, 7571/16695, 393/640,
  // -92097/339200, 187/2100, 1/40).
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                   e6 = 22.0 / 525, e7 = -1.0 / 40;
  const int Ns = static_cast<int>(S.cols());
  const int dim = kStates * (Ns + 1);
  std::vector<double> y(dim), y_new(dim), tmp(dim), k1(dim), k2(dim), k3(dim), k4(dim), k5(dim),
      k6(dim), k7(dim);
  for (int k = 0; k < kStates; ++k) y[k] = state[k];
  for (int i = 0; i < Ns; ++i) {
    for (int k = 0; k < kStates; ++k) y[kStates * (i + 1) + k] = S(k, i);
  }
  const double rtol = options_.rtol, atol = options_.atol;
  const double length = s_b - s_a;
  double s = s_a;
  // First step from the tolerance: the local error of a fifth-order step is ~ h^5.
  double h = std::min(length, 0.5 * std::pow(rtol, 0.2));
  full_rhs(piece, s, y.data(), k1.data(), Ns);
  long steps = 0;
  while (s < s_b) {
    if (++steps > options_.max_steps) {
      error = fmt::format("Dormand-Prince: more than {} steps at s = {}", options_.max_steps, s);
      return false;
    }
    double s_stop = s_b;
    if (shape_s != nullptr && next_shape < shape_s->size() && (*shape_s)[next_shape] < s_b) {
      s_stop = std::max((*shape_s)[next_shape], s);
    }
    bool last = false;
    if (s + h >= s_stop - 1e-14 * length) {
      h = s_stop - s;
      last = true;
    }
    if (h <= 0.0) {
      // A shape point at the current position.
      shape->push_back(ShapePoint{(*shape_s)[next_shape], y[kX], y[kY], y[kTheta]});
      ++next_shape;
      continue;
    }
    auto stage = [&](std::vector<double>& out,
                     std::initializer_list<std::pair<double, const std::vector<double>*>> terms) {
      for (int k = 0; k < dim; ++k) {
        double acc = y[k];
        for (const auto& [a, kv] : terms) acc += h * a * (*kv)[k];
        out[k] = acc;
      }
    };
    stage(tmp, {{a21, &k1}});
    full_rhs(piece, s + c2 * h, tmp.data(), k2.data(), Ns);
    stage(tmp, {{a31, &k1}, {a32, &k2}});
    full_rhs(piece, s + c3 * h, tmp.data(), k3.data(), Ns);
    stage(tmp, {{a41, &k1}, {a42, &k2}, {a43, &k3}});
    full_rhs(piece, s + c4 * h, tmp.data(), k4.data(), Ns);
    stage(tmp, {{a51, &k1}, {a52, &k2}, {a53, &k3}, {a54, &k4}});
    full_rhs(piece, s + c5 * h, tmp.data(), k5.data(), Ns);
    stage(tmp, {{a61, &k1}, {a62, &k2}, {a63, &k3}, {a64, &k4}, {a65, &k5}});
    full_rhs(piece, s + h, tmp.data(), k6.data(), Ns);
    stage(y_new, {{b1, &k1}, {b3, &k3}, {b4, &k4}, {b5, &k5}, {b6, &k6}});
    full_rhs(piece, s + h, y_new.data(), k7.data(), Ns);
    double err = 0.0;
    for (int k = 0; k < dim; ++k) {
      const double e =
          h * (e1 * k1[k] + e3 * k3[k] + e4 * k4[k] + e5 * k5[k] + e6 * k6[k] + e7 * k7[k]);
      const double scale = atol + rtol * std::max(std::abs(y[k]), std::abs(y_new[k]));
      err = std::max(err, std::abs(e) / scale);
    }
    if (!std::isfinite(err)) {
      error = fmt::format("Dormand-Prince: non-finite state at s = {}", s);
      return false;
    }
    if (err <= 1.0) {
      s = last ? s_stop : s + h;
      y.swap(y_new);
      k1.swap(k7);
      if (last && s_stop < s_b && shape != nullptr) {
        shape->push_back(ShapePoint{(*shape_s)[next_shape], y[kX], y[kY], y[kTheta]});
        ++next_shape;
      }
      if (last && s_stop >= s_b) break;
    }
    h *= std::clamp(0.9 * std::pow(std::max(err, 1e-10), -0.2), 0.2, 5.0);
  }
  impl_->steps += steps;
  for (int k = 0; k < kStates; ++k) state[k] = y[k];
  for (int i = 0; i < Ns; ++i) {
    for (int k = 0; k < kStates; ++k) S(k, i) = y[kStates * (i + 1) + k];
  }
  return true;
}

bool ElasticaIntegrator::ensure_sensitivities(int Ns, std::string& error) {
  Impl& d = *impl_;
  if (options_.backend == Backend::kDormandPrince) return true;
  if (Ns == 0 || Ns == d.sens_count) return true;
  // Sensitivity machinery: (re)created when the number of parameters changes.
  if (d.sens_count > 0) {
    CVodeSensFree(d.cvode);
    N_VDestroyVectorArray(d.yS, d.sens_count);
    d.yS = nullptr;
    d.sens_count = 0;
  }
  d.yS = N_VCloneVectorArray(Ns, d.y);
  if (d.yS == nullptr) {
    error = "N_VCloneVectorArray failed";
    return false;
  }
  for (int i = 0; i < Ns; ++i) N_VConst(0.0, d.yS[i]);
  d.sens_count = Ns;
  int flag = CVodeSensInit(d.cvode, Ns, CV_SIMULTANEOUS, sensitivity_rhs, d.yS);
  if (flag != CV_SUCCESS) {
    error = flag_message("CVodeSensInit", flag);
    return false;
  }
  std::vector<realtype> abstol(Ns, options_.atol);
  flag = CVodeSensSStolerances(d.cvode, options_.rtol, abstol.data());
  if (flag != CV_SUCCESS) {
    error = flag_message("CVodeSensSStolerances", flag);
    return false;
  }
  // Sensitivities in the error test: where the state is trivial (the unloaded straight beam) CVODES
  // would otherwise take one huge step and return wrong path tangents.
  flag = CVodeSetSensErrCon(d.cvode, options_.sensitivity_error_control ? SUNTRUE : SUNFALSE);
  if (flag != CV_SUCCESS) {
    error = flag_message("CVodeSetSensErrCon", flag);
    return false;
  }
  if (d.NLS != nullptr) {
    if (d.NLS_sens != nullptr) SUNNonlinSolFree(d.NLS_sens);
    d.NLS_sens = SUNNonlinSol_FixedPointSens(Ns + 1, d.y, 0, d.context);
    if (d.NLS_sens == nullptr) {
      error = "SUNNonlinSol_FixedPointSens failed";
      return false;
    }
    flag = CVodeSetNonlinearSolverSensSim(d.cvode, d.NLS_sens);
    if (flag != CV_SUCCESS) {
      error = flag_message("CVodeSetNonlinearSolverSensSim", flag);
      return false;
    }
  }
  return true;
}

}  // namespace flexure
