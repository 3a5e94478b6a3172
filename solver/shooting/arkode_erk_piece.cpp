#include "flexure/solver/shooting/arkode_erk_piece.h"

#include <arkode/arkode_erkstep.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace flexure {

namespace {

struct UserData {
  const ElasticaPieceData* piece = nullptr;
  int Ns = 0;
};

int arkode_rhs(realtype s, N_Vector y, N_Vector ydot, void* user_data) {
  const auto* d = static_cast<const UserData*>(user_data);
  elastica_rhs(*d->piece, s, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), d->Ns);
  return 0;
}

void silent_error_handler(int, const char*, const char*, char*, void*) {}

std::string flag_message(const char* function, int flag) {
  char* name = ERKStepGetReturnFlagName(flag);
  std::string text = fmt::format("ARKODE {} failed with flag {} ({})", function, flag, name);
  free(name);  // allocated with malloc by ARKODE
  return text;
}

}  // namespace

struct ArkodeErkPiece::Impl {
  SUNContext context = nullptr;
  // ERKStep's vectors have a fixed length, which changes with the sensitivity columns: one
  // stepper per Ns.
  struct Stepper {
    N_Vector y = nullptr;
    void* mem = nullptr;
  };
  std::vector<Stepper> by_columns;
  UserData data;

  ~Impl() {
    for (Stepper& s : by_columns) {
      if (s.mem != nullptr) ERKStepFree(&s.mem);
      if (s.y != nullptr) N_VDestroy(s.y);
    }
    if (context != nullptr) SUNContext_Free(&context);
  }
};

ArkodeErkPiece::ArkodeErkPiece(const ExplicitRkSettings& settings)
    : settings_(settings), impl_(std::make_unique<Impl>()) {
  if (SUNContext_Create(nullptr, &impl_->context) != 0) {
    throw std::runtime_error("SUNContext_Create failed");
  }
}

ArkodeErkPiece::~ArkodeErkPiece() = default;

bool ArkodeErkPiece::integrate(const PieceRun& run) {
  Impl& d = *impl_;
  d.data = UserData{&run.piece, run.Ns};
  if (static_cast<int>(d.by_columns.size()) <= run.Ns) d.by_columns.resize(run.Ns + 1);
  Impl::Stepper& st = d.by_columns[run.Ns];
  const auto dim = static_cast<sunindextype>(run.y.size());
  int flag = 0;
  if (st.mem == nullptr) {
    st.y = N_VNew_Serial(dim, d.context);
    if (st.y == nullptr) {
      run.error = "ARKODE: N_VNew_Serial failed";
      return false;
    }
    std::copy(run.y.begin(), run.y.end(), N_VGetArrayPointer(st.y));
    st.mem = ERKStepCreate(arkode_rhs, run.s_a, st.y, d.context);
    if (st.mem == nullptr) {
      run.error = "ARKODE: ERKStepCreate failed";
      return false;
    }
    for (auto [f, name] :
         {std::pair{ERKStepSetTableNum(st.mem, ARKODE_FEHLBERG_13_7_8), "ERKStepSetTableNum"},
          std::pair{ERKStepSStolerances(st.mem, settings_.rtol, settings_.atol),
                    "ERKStepSStolerances"},
          std::pair{ERKStepSetMaxNumSteps(st.mem, settings_.max_steps), "ERKStepSetMaxNumSteps"},
          std::pair{ERKStepSetUserData(st.mem, &d.data), "ERKStepSetUserData"},
          std::pair{ERKStepSetErrHandlerFn(st.mem, silent_error_handler, nullptr),
                    "ERKStepSetErrHandlerFn"}}) {
      if (f != ARK_SUCCESS) {
        run.error = flag_message(name, f);
        return false;
      }
    }
  } else {
    std::copy(run.y.begin(), run.y.end(), N_VGetArrayPointer(st.y));
    flag = ERKStepReInit(st.mem, arkode_rhs, run.s_a, st.y);
    if (flag != ARK_SUCCESS) {
      run.error = flag_message("ERKStepReInit", flag);
      return false;
    }
  }
  realtype s = run.s_a;
  const double* v = N_VGetArrayPointer(st.y);
  for (;;) {
    const bool to_shape_point = run.shape.pending_before(run.s_b);
    const double target =
        to_shape_point ? std::max((*run.shape.shape_s)[run.shape.next], s) : run.s_b;
    // Land exactly on the target (no interpolation): the same stops as the other backends.
    if (target - s > 1e-14 * std::max(1.0, std::abs(s))) {
      flag = ERKStepSetStopTime(st.mem, target);
      if (flag == ARK_SUCCESS) flag = ERKStepEvolve(st.mem, target, st.y, &s, ARK_NORMAL);
      if (flag < 0) {
        run.error = flag_message("ERKStepEvolve", flag) + fmt::format(" at s = {}", s);
        return false;
      }
    }
    if (!to_shape_point) break;
    run.shape.emit(v);
  }
  long taken = 0;
  ERKStepGetNumSteps(st.mem, &taken);
  run.steps += taken;
  std::copy(v, v + dim, run.y.begin());
  if (!std::all_of(run.y.begin(), run.y.end(), [](double c) { return std::isfinite(c); })) {
    run.error = fmt::format("ARKODE: non-finite state at s = {}", run.s_b);
    return false;
  }
  return true;
}

}  // namespace flexure
