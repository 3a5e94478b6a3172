#include "flexure/mechanisms/dynamics/forward_dynamics.h"

#include <cvodes/cvodes.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>

#include "flexure/solver/common/errors.h"

namespace flexure::dynamics {
namespace {

struct RhsData {
  const SliderCrankDynamics* model = nullptr;
  const InputForce* force = nullptr;
  double sign_velocity = 1e-3;
  double crossing_level = 0.0;
};

// y = (theta2 - crossing_level, theta2'): the offset keeps the root function y0 at full relative
// precision near the crossing (with theta2 itself, theta2 - level is exactly 0 over a short
// interval after a root and CVODES stops with CV_ILL_INPUT, "root found at and very near t").
// Returns 1 (recoverable) past the toggle position so CVODES cuts the step.
int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  const auto& d = *static_cast<RhsData*>(user);
  const double th = NV_Ith_S(y, 0) + d.crossing_level, w = NV_Ith_S(y, 1);
  ConfigurationTerms c;
  if (!d.model->try_terms(th, c)) return 1;
  const double F = (d.force != nullptr && *d.force) ? (*d.force)(t, th, w) : 0.0;
  if (!std::isfinite(F)) return -1;
  const double Q = -F * c.dr1 + d.model->friction_moment(c, std::tanh(w / d.sign_velocity));
  NV_Ith_S(ydot, 0) = w;
  NV_Ith_S(ydot, 1) = (Q - 0.5 * c.dM * w * w - c.dV) / c.M;
  return 0;
}

int root(sunrealtype, N_Vector y, sunrealtype* gout, void*) {
  gout[0] = NV_Ith_S(y, 0);
  return 0;
}

std::string flag_text(const char* function, int flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string text = fmt::format("CVODES {} returned {} ({})", function, flag, name);
  free(name);  // allocated with malloc by CVODES
  return text;
}

void silent_error_handler(int, const char*, const char*, char*, void*) {}

// Owns the SUNDIALS objects of one integration.
struct Cvode {
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  void* mem = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  ~Cvode() {
    if (mem != nullptr) CVodeFree(&mem);
    if (LS != nullptr) SUNLinSolFree(LS);
    if (A != nullptr) SUNMatDestroy(A);
    if (y != nullptr) N_VDestroy(y);
    if (context != nullptr) SUNContext_Free(&context);
  }
};

void check(int flag, const char* function) {
  if (flag < 0) throw std::runtime_error(flag_text(function, flag));
}

}  // namespace

InputForce driving_spring(const SliderCrankDynamics& model,
                          double k_drive,
                          std::function<double(double t)> actuator) {
  require_finite(k_drive, "driving spring stiffness k_drive");
  if (k_drive <= 0.0) throw InvalidInput(fmt::format("k_drive = {} N/m must be > 0", k_drive));
  if (!actuator) throw InvalidInput("driving_spring: actuator position function is empty");
  // Copies of the model and the function: the returned closure may outlive the arguments.
  return [model, k_drive, actuator = std::move(actuator)](double t, double theta2, double) {
    ConfigurationTerms c;
    if (!model.try_terms(theta2, c)) return std::numeric_limits<double>::quiet_NaN();
    return k_drive * (actuator(t) - (model.r_tot() - c.r1));
  };
}

Linearisation linearise(const SliderCrankDynamics& model,
                        double F0,
                        double theta_lo,
                        double theta_hi) {
  require_finite(F0, "F0");
  if (F0 < 0.0) throw InvalidInput(fmt::format("F0 = {} N must be >= 0", F0));
  Linearisation lin;
  double theta = 0.0;
  if (F0 > 0.0) {
    // Residual V' + F0 r1' = (F_static - F0)(-r1'): its sign is that of F_static - F0 for
    // theta2 > 0. Bisection on the crank angle up to just before the toggle position.
    const DynamicsParameters& p = model.parameters();
    // Stay 1e-6 inside the toggle angle, where cos theta3 -> 0 and r1' has a 1/cos singularity.
    const double theta_max = p.r2 > p.r3 ? std::asin(p.r3 / p.r2) * (1.0 - 1e-6)
                                         : 0.5 * 3.141592653589793 * (1.0 - 1e-6);
    auto residual = [&](double th) {
      const ConfigurationTerms c = model.terms(th);
      return c.dV + F0 * c.dr1;
    };
    double lo = theta_lo > 0.0 ? theta_lo : 1e-9 * theta_max;
    double hi = theta_hi > 0.0 ? std::min(theta_hi, theta_max) : theta_max;
    if (!(lo < hi)) {
      throw InvalidInput(fmt::format("bracket [{}, {}] rad is empty", theta_lo, theta_hi));
    }
    const double f_lo = residual(lo), f_hi = residual(hi);
    if (f_lo * f_hi > 0.0) {
      throw InvalidInput(fmt::format(
          "F0 = {} N: no equilibrium with 0 < theta2 < {} rad (static force does not cross F0)",
          F0,
          theta_max));
    }
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (residual(mid) * f_lo > 0.0) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    theta = 0.5 * (lo + hi);
  }
  const ConfigurationTerms c = model.terms(theta);
  lin.theta2_eq = theta;
  lin.stiffness = c.d2V + F0 * c.d2r1;
  lin.inertia = c.M;
  lin.stable = lin.stiffness > 0.0 && c.M > 0.0;
  lin.omega_n = lin.stable ? std::sqrt(lin.stiffness / c.M) : 0.0;
  return lin;
}

ForwardDynamics::ForwardDynamics(SliderCrankDynamics model, ForwardOptions options)
    : model_(std::move(model)), options_(options) {
  if (!(options_.rtol > 0.0) || !(options_.atol > 0.0)) {
    throw InvalidInput("ForwardOptions: rtol and atol must be > 0");
  }
  if (!(options_.friction_sign_velocity > 0.0)) {
    throw InvalidInput("ForwardOptions: friction_sign_velocity must be > 0");
  }
  if (options_.max_steps < 1) throw InvalidInput("ForwardOptions: max_steps must be >= 1");
}

ForwardResult ForwardDynamics::integrate(double theta2_0,
                                         double theta2_dot_0,
                                         const std::vector<double>& output_times,
                                         const InputForce& force) const {
  require_finite(theta2_0, "theta2_0");
  require_finite(theta2_dot_0, "theta2_dot_0");
  model_.terms(theta2_0);  // throws past the toggle position
  double previous = 0.0;
  for (double t : output_times) {
    if (!std::isfinite(t) || t <= previous) {
      throw InvalidInput("output_times must be finite, > 0 and increasing");
    }
    previous = t;
  }
  if (model_.terms(theta2_0).M <= 0.0) {
    throw InvalidInput("generalized inertia M is zero (all masses zero): no forward dynamics");
  }

  RhsData data;
  data.model = &model_;
  data.force = &force;
  data.sign_velocity = options_.friction_sign_velocity;
  data.crossing_level = options_.crossing_level;

  Cvode cv;
  if (SUNContext_Create(nullptr, &cv.context) != 0) {
    throw std::runtime_error("SUNContext_Create failed");
  }
  cv.y = N_VNew_Serial(2, cv.context);
  if (cv.y == nullptr) throw std::runtime_error("N_VNew_Serial failed");
  NV_Ith_S(cv.y, 0) = theta2_0 - data.crossing_level;
  NV_Ith_S(cv.y, 1) = theta2_dot_0;
  cv.mem = CVodeCreate(options_.adams ? CV_ADAMS : CV_BDF, cv.context);
  if (cv.mem == nullptr) throw std::runtime_error("CVodeCreate failed");
  check(CVodeInit(cv.mem, rhs, 0.0, cv.y), "CVodeInit");
  check(CVodeSStolerances(cv.mem, options_.rtol, options_.atol), "CVodeSStolerances");
  check(CVodeSetUserData(cv.mem, &data), "CVodeSetUserData");
  check(CVodeSetMaxNumSteps(cv.mem, options_.max_steps), "CVodeSetMaxNumSteps");
  check(CVodeSetErrHandlerFn(cv.mem, silent_error_handler, nullptr), "CVodeSetErrHandlerFn");
  cv.A = SUNDenseMatrix(2, 2, cv.context);
  if (cv.A == nullptr) throw std::runtime_error("SUNDenseMatrix failed");
  cv.LS = SUNLinSol_Dense(cv.y, cv.A, cv.context);
  if (cv.LS == nullptr) throw std::runtime_error("SUNLinSol_Dense failed");
  check(CVodeSetLinearSolver(cv.mem, cv.LS, cv.A), "CVodeSetLinearSolver");
  if (options_.record_crossings) {
    check(CVodeRootInit(cv.mem, 1, root), "CVodeRootInit");
    int direction = 1;  // upward crossings only
    check(CVodeSetRootDirection(cv.mem, &direction), "CVodeSetRootDirection");
  }

  ForwardResult result;
  const double E0 = model_.energy(theta2_0, theta2_dot_0);
  const bool conservative = !force;
  auto record = [&](double t) {
    const double th = NV_Ith_S(cv.y, 0) + data.crossing_level, w = NV_Ith_S(cv.y, 1);
    result.t.push_back(t);
    result.theta2.push_back(th);
    result.theta2_dot.push_back(w);
    result.delta_x.push_back(model_.delta_x_at(th));
    const double E = model_.energy(th, w);
    result.energy.push_back(E);
    if (conservative && E0 != 0.0) {
      result.residual = std::max(result.residual, std::abs(E - E0) / std::abs(E0));
    }
  };
  for (double t_out : output_times) {
    double t_reached = 0.0;
    while (true) {
      const int flag = CVode(cv.mem, t_out, cv.y, &t_reached, CV_NORMAL);
      if (flag == CV_ROOT_RETURN) {
        result.upward_crossings.push_back(t_reached);
        continue;
      }
      if (flag < 0) {
        long steps = 0;
        CVodeGetNumSteps(cv.mem, &steps);
        result.iterations = steps;
        result.message = fmt::format("{} at t = {} s (target {} s, {} outputs done)",
                                     flag_text("CVode", flag),
                                     t_reached,
                                     t_out,
                                     result.t.size());
        return result;
      }
      break;
    }
    record(t_reached);
  }
  long steps = 0;
  check(CVodeGetNumSteps(cv.mem, &steps), "CVodeGetNumSteps");
  result.iterations = steps;
  result.converged = true;
  result.message = "integrated to the last output time";
  return result;
}

}  // namespace flexure::dynamics
