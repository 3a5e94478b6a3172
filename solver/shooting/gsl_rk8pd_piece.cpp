#include "flexure/solver/shooting/gsl_rk8pd_piece.h"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>

#include "flexure/solver/common/gsl_guard.h"

namespace flexure {

namespace {

struct Parameters {
  const ElasticaPieceData* piece = nullptr;
  int Ns = 0;
};

int gsl_rhs(double s, const double y[], double dydt[], void* params) {
  const auto* p = static_cast<const Parameters*>(params);
  elastica_rhs(*p->piece, s, y, dydt, p->Ns);
  return GSL_SUCCESS;
}

}  // namespace

struct GslRk8pdPiece::Impl {
  // GSL's stepper and evolution objects are sized for one dimension; the dimension changes with
  // the number of sensitivity columns, so there is one pair per Ns.
  struct Stepper {
    gsl_odeiv2_step* step = nullptr;
    std::vector<double> y0, error, dydt_in, dydt_out;  // step start, error estimate, derivatives
  };
  std::vector<Stepper> by_columns;
  gsl_odeiv2_control* control = nullptr;
  // First step size per piece (segment and start), from the previous integration of that piece:
  // Newton and continuation integrate the same pieces again and again, and a step size guessed
  // from the tolerance alone costs one or two short steps every time (docs/theory-shooting.md §4).
  struct FirstStep {
    const FlexibleSegment* segment;
    double s_a;
    double h;
  };
  std::vector<FirstStep> first_step;

  double* first_step_of(const FlexibleSegment* segment, double s_a) {
    for (FirstStep& f : first_step) {
      if (f.segment == segment && f.s_a == s_a) return &f.h;
    }
    return nullptr;
  }

  ~Impl() {
    for (Stepper& s : by_columns) {
      if (s.step != nullptr) gsl_odeiv2_step_free(s.step);
    }
    if (control != nullptr) gsl_odeiv2_control_free(control);
  }

  Stepper* stepper(int Ns) {
    if (static_cast<int>(by_columns.size()) <= Ns) by_columns.resize(Ns + 1);
    Stepper& s = by_columns[Ns];
    if (s.step == nullptr) {
      const std::size_t dim = kElasticaStates * (Ns + 1);
      s.step = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, dim);
      if (s.step == nullptr) return nullptr;
      s.y0.resize(dim);
      s.error.resize(dim);
      s.dydt_in.resize(dim);
      s.dydt_out.resize(dim);
    }
    return &s;
  }
};

GslRk8pdPiece::GslRk8pdPiece(const ExplicitRkSettings& settings)
    : settings_(settings), impl_(std::make_unique<Impl>()) {
  disable_gsl_abort();
  // Standard control (GSL manual, "Adaptive Step-size Control"): the local error of component i
  // must stay below atol + rtol |y_i| (a_y = 1, a_dydt = 0), the test of the other backends.
  impl_->control = gsl_odeiv2_control_y_new(settings_.atol, settings_.rtol);
}

GslRk8pdPiece::~GslRk8pdPiece() = default;

bool GslRk8pdPiece::integrate(const PieceRun& run) {
  Impl::Stepper* st = impl_->stepper(run.Ns);
  if (st == nullptr || impl_->control == nullptr) {
    run.error = "GSL rk8pd: allocation failed";
    return false;
  }
  Parameters parameters{&run.piece, run.Ns};
  const std::size_t dim = kElasticaStates * (run.Ns + 1);
  const gsl_odeiv2_system system{gsl_rhs, nullptr, dim, &parameters};
  gsl_odeiv2_step_reset(st->step);
  // The loop of gsl_odeiv2_evolve_apply (GSL 2.7, ode-initval2/evolve.c) with GSL's stepper and
  // step-size control, except that the derivative at the end of an accepted step is kept as the
  // first stage of the next one: evolve_apply evaluates it again at every call (13 instead of 14
  // right-hand sides per rk8pd step).
  double s = run.s_a;
  elastica_rhs(run.piece, s, run.y.data(), st->dydt_in.data(), run.Ns);
  // First step: the controller's proposal after the first step of the previous integration of
  // this piece; else from the tolerance (the local error of an eighth-order step is ~ h^9; the
  // control grows the step by up to 5x per step from there).
  const double* remembered = impl_->first_step_of(run.piece.segment, run.s_a);
  double h =
      std::min(run.s_b - run.s_a,
               remembered != nullptr ? *remembered : 0.5 * std::pow(settings_.rtol, 1.0 / 8.0));
  bool first_accepted = false;
  long taken = 0;
  for (;;) {
    const bool to_shape_point = run.shape.pending_before(run.s_b);
    const double target =
        to_shape_point ? std::max((*run.shape.shape_s)[run.shape.next], s) : run.s_b;
    while (s < target) {
      if (++taken > run.max_steps) {
        run.error = fmt::format("GSL rk8pd: more than {} steps at s = {}", run.max_steps, s);
        return false;
      }
      const bool final_step = h >= target - s;
      const double h_try = final_step ? target - s : h;
      std::copy(run.y.begin(), run.y.end(), st->y0.begin());
      const int status = gsl_odeiv2_step_apply(st->step,
                                               s,
                                               h_try,
                                               run.y.data(),
                                               st->error.data(),
                                               st->dydt_in.data(),
                                               st->dydt_out.data(),
                                               &system);
      if (status != GSL_SUCCESS) {
        run.error = fmt::format("GSL rk8pd: gsl_odeiv2_step_apply returned {} ({}) at s = {}",
                                status,
                                gsl_strerror(status),
                                s);
        return false;
      }
      double h_next = h_try;
      const int adjust = gsl_odeiv2_control_hadjust(
          impl_->control, st->step, run.y.data(), st->error.data(), st->dydt_out.data(), &h_next);
      if (!std::all_of(run.y.begin(), run.y.end(), [](double v) { return std::isfinite(v); })) {
        run.error = fmt::format("GSL rk8pd: non-finite state at s = {}", s);
        return false;
      }
      if (adjust == GSL_ODEIV_HADJ_DEC) {
        // Rejected (GSL decreases h only when the error exceeds 1.1 times the tolerance): undo.
        std::copy(st->y0.begin(), st->y0.end(), run.y.begin());
        h = h_next;
        --taken;
        continue;
      }
      const double s_end = final_step ? target : s + h_try;
      if (run.observer != nullptr) {
        run.observer->accepted_step(run.piece,
                                    s,
                                    st->y0.data(),
                                    st->dydt_in.data(),
                                    s_end,
                                    run.y.data(),
                                    st->dydt_out.data());
      }
      s = s_end;
      st->dydt_in.swap(st->dydt_out);
      // A step shortened to land on the target says nothing against the step before it.
      h = final_step && adjust != GSL_ODEIV_HADJ_INC ? std::max(h, h_next) : h_next;
      if (!first_accepted) {
        first_accepted = true;
        if (double* slot = impl_->first_step_of(run.piece.segment, run.s_a)) {
          *slot = h;
        } else {
          impl_->first_step.push_back({run.piece.segment, run.s_a, h});
        }
      }
    }
    if (!to_shape_point) break;
    run.shape.emit(run.y.data());
  }
  run.steps += taken;
  return true;
}

}  // namespace flexure
