#include "flexure/solver/shooting/elastica_integrator.h"

#include <cvodes/cvodes.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>

#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/arkode_erk_piece.h"
#include "flexure/solver/shooting/dormand_prince_piece.h"
#include "flexure/solver/shooting/elastica_piece.h"
#include "flexure/solver/shooting/prince_dormand87_piece.h"

namespace flexure {

namespace {
constexpr int kX = kElasticaX;
constexpr int kY = kElasticaY;
constexpr int kTheta = kElasticaTheta;
constexpr int kM = kElasticaM;
constexpr int kStates = kElasticaStates;

}  // namespace

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
  long steps = 0;      // integrator steps taken since construction (every backend)
  int sens_count = 0;  // parameters CVodeSensInit was called with (0 = never)
  PieceData piece;
  FlexibleSegment dummy;
  std::unique_ptr<ExplicitPieceIntegrator> explicit_backend;  // every backend but kCvodes
  std::vector<double> packed;  // state and sensitivities of the explicit backends
  // Scratch of integrate(), kept so that a call reuses their storage (a sweep point makes dozens
  // of calls; their allocations were a few per cent of its time).
  Eigen::Matrix<double, 4, Eigen::Dynamic> S;
  Eigen::Matrix<double, 2, Eigen::Dynamic> dG, dN_end;

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

const char* to_string(ElasticaIntegrator::Backend backend) {
  switch (backend) {
    case ElasticaIntegrator::Backend::kRk8pd:
      return "rk8pd";
    case ElasticaIntegrator::Backend::kCvodes:
      return "cvodes";
    case ElasticaIntegrator::Backend::kDormandPrince:
      return "dormand-prince";
    case ElasticaIntegrator::Backend::kArkodeErk:
      return "arkode-erk";
  }
  return "unknown";
}

ElasticaIntegrator::Backend integrator_backend_from_string(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) {
    return static_cast<char>(std::tolower(c));
  });
  for (auto backend : {ElasticaIntegrator::Backend::kRk8pd,
                       ElasticaIntegrator::Backend::kCvodes,
                       ElasticaIntegrator::Backend::kDormandPrince,
                       ElasticaIntegrator::Backend::kArkodeErk}) {
    if (lower == to_string(backend)) return backend;
  }
  throw InvalidInput(fmt::format(
      "integrator '{}' is unknown; allowed: rk8pd, cvodes, dormand-prince, arkode-erk", name));
}

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
  d.piece.segment = &d.dummy;
  const ExplicitRkSettings settings{options_.rtol, options_.atol, options_.max_steps};
  switch (options_.backend) {
    case Backend::kRk8pd:
      d.explicit_backend = std::make_unique<PrinceDormand87Piece>(settings);
      break;
    case Backend::kArkodeErk:
      d.explicit_backend = std::make_unique<ArkodeErkPiece>(settings);
      break;
    case Backend::kDormandPrince:
      d.explicit_backend = std::make_unique<DormandPrincePiece>(settings);
      break;
    case Backend::kCvodes:
      break;
  }
  // The CVODES objects only for the CVODES backend: their set-up costs as much as a whole solve
  // with an explicit backend (ElasticaIntegrator is made once per solve).
  if (options_.backend != Backend::kCvodes) return;
  if (SUNContext_Create(nullptr, &d.context) != 0) {
    throw std::runtime_error("SUNContext_Create failed");
  }
  d.y = N_VNew_Serial(kStates, d.context);
  if (d.y == nullptr) throw std::runtime_error("N_VNew_Serial failed");
  N_VConst(0.0, d.y);
  d.cvode = CVodeCreate(options_.adams ? CV_ADAMS : CV_BDF, d.context);
  if (d.cvode == nullptr) throw std::runtime_error("CVodeCreate failed");
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
  if (observer_ != nullptr && options_.backend != Backend::kRk8pd &&
      options_.backend != Backend::kDormandPrince) {
    error = fmt::format(
        "a step observer needs an explicit Runge-Kutta backend (rk8pd or "
        "dormand-prince), not {}",
        to_string(options_.backend));
    return false;
  }

  Eigen::Vector4d state = start;
  Eigen::Matrix<double, 4, Eigen::Dynamic>& S = d.S;
  S = start_sensitivity;
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
      if (shape_moment_ != nullptr) shape_moment_->push_back(state[kM]);
      ++next_shape;
    }
  };

  // The explicit backends integrate state and sensitivities as one packed system.
  auto explicit_piece = [&](double s_a, double s_b) {
    std::vector<double>& y = d.packed;
    y.resize(kStates * (Ns + 1));
    for (int k = 0; k < kStates; ++k) y[k] = state[k];
    for (int i = 0; i < Ns; ++i) {
      for (int k = 0; k < kStates; ++k) y[kStates * (i + 1) + k] = S(k, i);
    }
    ShapeCursor cursor{want_shape ? shape_s : nullptr, shape, next_shape, shape_moment_};
    const long max_steps =
        step_limit_ > 0 ? std::min(options_.max_steps, step_limit_ - d.steps) : options_.max_steps;
    const bool ok = d.explicit_backend->integrate(
        PieceRun{d.piece, Ns, s_a, s_b, y, cursor, observer_, max_steps, d.steps, error});
    next_shape = cursor.next;
    if (!ok) return false;
    for (int k = 0; k < kStates; ++k) state[k] = y[k];
    for (int i = 0; i < Ns; ++i) {
      for (int k = 0; k < kStates; ++k) S(k, i) = y[kStates * (i + 1) + k];
    }
    return true;
  };

  d.piece.dN.resize(Ns);
  d.piece.dload_factor.resize(Ns);
  d.piece.load_factor = forces.load_factor;
  for (int i = 0; i < Ns; ++i) d.piece.dload_factor[i] = derivatives[i].dload_factor;
  // G: the follower pressures' resultant accumulated since the start of these pieces (they start
  // at the clamp whenever a follower pressure acts: ShootingProblem makes no cuts then), and dG/dp.
  Eigen::Vector2d G = Eigen::Vector2d::Zero();
  Eigen::Matrix<double, 2, Eigen::Dynamic>& dG = d.dG;
  dG.setZero(2, Ns);
  Eigen::Vector2d N_end = Eigen::Vector2d::Zero();
  Eigen::Matrix<double, 2, Eigen::Dynamic>& dN_end = d.dN_end;
  dN_end.setZero(2, Ns);
  const double lf = forces.load_factor;
  for (const IntegrationPiece& piece : pieces) {
    const int j = piece.segment;
    const Eigen::Vector2d N = forces.N[j] - G;
    for (int i = 0; i < Ns; ++i) {
      d.piece.dN[i] =
          (derivatives[i].dN.empty() ? Eigen::Vector2d::Zero() : derivatives[i].dN[j]) - dG.col(i);
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
          if (shape_moment_ != nullptr) {
            shape_moment_->push_back(state[kM] + ds * (N.x() * sn - N.y() * c));
          }
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
      N_end = N;
      for (int i = 0; i < Ns; ++i) dN_end.col(i) = d.piece.dN[i];
    } else {
      const auto& flex = std::get<FlexibleSegment>(chain.segments[j]);
      d.piece.segment = &flex;
      d.piece.segment_start = piece.segment_start;
      d.piece.Nx = N.x();
      d.piece.Ny = N.y();
      d.piece.extended = flex.beyond_elastica();
      d.piece.inv_EA = flex.extensible() ? 1.0 / flex.EA : 0.0;
      d.piece.inv_GA = flex.shear_flexible() ? 1.0 / flex.GAs : 0.0;
      if (d.piece.extended && options_.backend == Backend::kCvodes) {
        error = fmt::format(
            "segment {} carries a distributed load or is extensible: the cvodes integrator does "
            "not support it (use rk8pd, dormand-prince or arkode-erk)",
            j + 1);
        return false;
      }
      const double p = flex.q_follower;
      // The follower anchor: on this piece G(s) = G_a + lf p R90 (r(s) - r_a), so the constant
      // part of N is N - G_a + lf p R90 r_a, R90 (x, y) = (-y, x).
      // Follower pressure p: on a sub-piece from r_a, G(s) = G_a + lf p R90 (r(s) - r_a), so the
      // constant part of N(s) (reissner_force) is N[j] - G_a + lf p R90 r_a, R90 (x, y) = (-y, x).
      auto dN_start = [&](int i) -> Eigen::Vector2d {
        return derivatives[i].dN.empty() ? Eigen::Vector2d::Zero() : derivatives[i].dN[j];
      };
      auto set_anchor = [&]() {
        if (p == 0.0) return;
        const Eigen::Vector2d Nc =
            forces.N[j] - G + lf * p * Eigen::Vector2d(-state[kY], state[kX]);
        d.piece.Nx = Nc.x();
        d.piece.Ny = Nc.y();
        for (int i = 0; i < Ns; ++i) {
          const double dlf = derivatives[i].dload_factor;
          d.piece.dN[i] = dN_start(i) - dG.col(i) +
                          dlf * p * Eigen::Vector2d(-state[kY], state[kX]) +
                          lf * p * Eigen::Vector2d(-S(kY, i), S(kX, i));
        }
      };
      // G at the end r_b of the sub-piece: G_a + lf p R90 (r_b - r_a) = N[j] - N_c + lf p R90 r_b.
      auto close_anchor = [&]() {
        if (p == 0.0) return;
        const Eigen::Vector2d Nc(d.piece.Nx, d.piece.Ny);
        G = forces.N[j] - Nc + lf * p * Eigen::Vector2d(-state[kY], state[kX]);
        for (int i = 0; i < Ns; ++i) {
          const double dlf = derivatives[i].dload_factor;
          dG.col(i) = dN_start(i) - d.piece.dN[i] +
                      dlf * p * Eigen::Vector2d(-state[kY], state[kX]) +
                      lf * p * Eigen::Vector2d(-S(kY, i), S(kX, i));
        }
      };
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
      if (flex.q_profile.size() >= 2) {
        // The dead load's stations too: its kinks fall on sub-piece ends.
        const int intervals = static_cast<int>(flex.q_profile.size()) - 1;
        for (int p = 1; p < intervals; ++p) {
          const double station = flex.length * p / intervals;
          if (station > piece.begin && station < piece.end) cuts.push_back(station);
        }
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
      }
      cuts.push_back(piece.end);
      for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
        const double s_a = piece.segment_start + cuts[p];
        const double s_b = piece.segment_start + cuts[p + 1];
        emit_below(std::nextafter(s_a, std::numeric_limits<double>::infinity()));
        if (step_limit_ > 0 && d.steps >= step_limit_) {
          error = fmt::format("integration step limit {} reached at s = {}", step_limit_, s_a);
          return false;
        }
        if (options_.backend != Backend::kCvodes) {
          set_anchor();
          if (!explicit_piece(s_a, s_b)) return false;
          close_anchor();
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
          if (shape_moment_ != nullptr) shape_moment_->push_back(yo[kM]);
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
    if (const auto* flex = std::get_if<FlexibleSegment>(&chain.segments[j])) {
      // N at the end of the piece: N[j] - lf Q_j(end) - G (G updated by close_anchor).
      N_end = forces.N[j] - G;
      for (int i = 0; i < Ns; ++i) {
        dN_end.col(i) =
            (derivatives[i].dN.empty() ? Eigen::Vector2d::Zero() : derivatives[i].dN[j]) -
            dG.col(i);
      }
      if (flex->has_dead_load()) {
        const std::array<double, 2> Q = flex->q_resultant(piece.end);
        N_end -= lf * Eigen::Vector2d(Q[0], Q[1]);
        for (int i = 0; i < Ns; ++i) {
          dN_end.col(i) -= derivatives[i].dload_factor * Eigen::Vector2d(Q[0], Q[1]);
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
  end.N = N_end;
  end.N_sensitivity = dN_end;
  return true;
}

bool ElasticaIntegrator::ensure_sensitivities(int Ns, std::string& error) {
  Impl& d = *impl_;
  if (options_.backend != Backend::kCvodes) return true;
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
