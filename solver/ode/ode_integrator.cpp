#include "flexure/solver/ode/ode_integrator.h"

#include <cvodes/cvodes.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <stdexcept>

#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

// What the C callbacks need; an exception of a user function is parked here and rethrown once
// CVODES has returned (it must not unwind through the C library).
struct CallbackData {
  const OdeIntegrator::Rhs* rhs = nullptr;
  const OdeIntegrator::Event* event = nullptr;
  sunindextype size = 0;
  std::exception_ptr error;
};

int rhs_callback(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  auto& d = *static_cast<CallbackData*>(user);
  const std::span<const double> state(N_VGetArrayPointer(y), static_cast<std::size_t>(d.size));
  const std::span<double> derivative(N_VGetArrayPointer(ydot), static_cast<std::size_t>(d.size));
  try {
    return (*d.rhs)(t, state, derivative);
  } catch (...) {
    d.error = std::current_exception();
    return -1;
  }
}

int root_callback(sunrealtype t, N_Vector y, sunrealtype* gout, void* user) {
  auto& d = *static_cast<CallbackData*>(user);
  const std::span<const double> state(N_VGetArrayPointer(y), static_cast<std::size_t>(d.size));
  try {
    gout[0] = d.event->g(t, state);
    return 0;
  } catch (...) {
    d.error = std::current_exception();
    return -1;
  }
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

int root_direction(OdeIntegrator::Direction direction) {
  switch (direction) {
    case OdeIntegrator::Direction::kUpward:
      return 1;
    case OdeIntegrator::Direction::kDownward:
      return -1;
    case OdeIntegrator::Direction::kBoth:
      break;
  }
  return 0;
}

}  // namespace

void OdeIntegrator::Options::validate() const {
  if (!(rtol > 0.0)) {
    throw InvalidInput(fmt::format("OdeIntegrator::Options: rtol = {} must be > 0", rtol));
  }
  if (!(atol > 0.0)) {
    throw InvalidInput(fmt::format("OdeIntegrator::Options: atol = {} must be > 0", atol));
  }
  if (max_steps < 1) {
    throw InvalidInput(
        fmt::format("OdeIntegrator::Options: max_steps = {} must be >= 1", max_steps));
  }
  if (method != Method::kAdams && method != Method::kBdf) {
    throw InvalidInput("OdeIntegrator::Options: method must be kAdams or kBdf");
  }
}

OdeIntegrator::OdeIntegrator() : OdeIntegrator(Options{}) {}

OdeIntegrator::OdeIntegrator(Options options) : options_(options) { options_.validate(); }

OdeIntegrator::Solution OdeIntegrator::integrate(const Rhs& rhs,
                                                 double t0,
                                                 std::span<const double> y0,
                                                 const std::vector<double>& output_times,
                                                 const Event* event) const {
  if (!rhs) throw InvalidInput("OdeIntegrator::integrate: the right-hand side is empty");
  if (y0.empty()) throw InvalidInput("OdeIntegrator::integrate: the initial state y0 is empty");
  require_finite(t0, "OdeIntegrator::integrate: initial time t0");
  double previous = t0;
  for (double t : output_times) {
    if (!std::isfinite(t) || t <= previous) {
      throw InvalidInput(fmt::format(
          "OdeIntegrator::integrate: output times must be finite, > t0 = {} and increasing (got "
          "{} after {})",
          t0,
          t,
          previous));
    }
    previous = t;
  }
  if (event != nullptr && !event->g) {
    throw InvalidInput("OdeIntegrator::integrate: the event has no function g");
  }

  CallbackData data;
  data.rhs = &rhs;
  data.event = event;
  data.size = static_cast<sunindextype>(y0.size());

  Cvode cv;
  if (SUNContext_Create(nullptr, &cv.context) != 0) {
    throw std::runtime_error("SUNContext_Create failed");
  }
  cv.y = N_VNew_Serial(data.size, cv.context);
  if (cv.y == nullptr) throw std::runtime_error("N_VNew_Serial failed");
  double* y = N_VGetArrayPointer(cv.y);
  for (std::size_t i = 0; i < y0.size(); ++i) y[i] = y0[i];
  cv.mem = CVodeCreate(options_.method == Method::kAdams ? CV_ADAMS : CV_BDF, cv.context);
  if (cv.mem == nullptr) throw std::runtime_error("CVodeCreate failed");
  check(CVodeInit(cv.mem, rhs_callback, t0, cv.y), "CVodeInit");
  check(CVodeSStolerances(cv.mem, options_.rtol, options_.atol), "CVodeSStolerances");
  check(CVodeSetUserData(cv.mem, &data), "CVodeSetUserData");
  check(CVodeSetMaxNumSteps(cv.mem, options_.max_steps), "CVodeSetMaxNumSteps");
  check(CVodeSetErrHandlerFn(cv.mem, silent_error_handler, nullptr), "CVodeSetErrHandlerFn");
  cv.A = SUNDenseMatrix(data.size, data.size, cv.context);
  if (cv.A == nullptr) throw std::runtime_error("SUNDenseMatrix failed");
  cv.LS = SUNLinSol_Dense(cv.y, cv.A, cv.context);
  if (cv.LS == nullptr) throw std::runtime_error("SUNLinSol_Dense failed");
  check(CVodeSetLinearSolver(cv.mem, cv.LS, cv.A), "CVodeSetLinearSolver");
  if (event != nullptr) {
    check(CVodeRootInit(cv.mem, 1, root_callback), "CVodeRootInit");
    int direction = root_direction(event->direction);
    check(CVodeSetRootDirection(cv.mem, &direction), "CVodeSetRootDirection");
  }

  Solution solution;
  solution.t.reserve(output_times.size());
  solution.y.reserve(output_times.size());
  for (double t_out : output_times) {
    double t_reached = 0.0;
    while (true) {
      const int flag = CVode(cv.mem, t_out, cv.y, &t_reached, CV_NORMAL);
      if (data.error) std::rethrow_exception(data.error);
      if (flag == CV_ROOT_RETURN) {
        solution.event_times.push_back(t_reached);
        continue;
      }
      if (flag < 0) {
        long steps = 0;
        CVodeGetNumSteps(cv.mem, &steps);
        solution.steps = steps;
        solution.status.ok = false;
        solution.status.message = flag_text("CVode", flag);
        solution.status.function = "CVode";
        solution.status.flag = flag;
        solution.status.t_reached = t_reached;
        solution.status.t_target = t_out;
        return solution;
      }
      break;
    }
    solution.t.push_back(t_reached);
    solution.y.emplace_back(y, y + y0.size());
  }
  long steps = 0;
  check(CVodeGetNumSteps(cv.mem, &steps), "CVodeGetNumSteps");
  solution.steps = steps;
  solution.status.ok = true;
  solution.status.t_reached = output_times.empty() ? t0 : solution.t.back();
  solution.status.t_target = solution.status.t_reached;
  return solution;
}

}  // namespace flexure
