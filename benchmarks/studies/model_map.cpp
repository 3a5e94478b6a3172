#include "flexure/benchmarks/studies/model_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "flexure/beam/beam_problem.h"
#include "flexure/solver/common/status.h"

namespace flexure::studies {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void require_axis(const std::vector<double>& axis, const char* name) {
  if (axis.empty()) throw InvalidInput(fmt::format("the model map's {} axis is empty", name));
  for (double v : axis) {
    if (!std::isfinite(v)) {
      throw InvalidInput(
          fmt::format("the model map's {} axis holds {} (finite values only)", name, v));
    }
  }
}

double median(std::vector<double> v) {
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// The beam problem of one grid point.
BeamProblem problem_at(const ModelMapSpec& spec, double n, double alpha2, double third) {
  BeamProblem p;
  p.given = BeamProblem::Given::kAlpha2;
  p.value = alpha2;
  p.load_ratio_n = n;
  p.boundary = spec.boundary;
  if (spec.boundary == EndCondition::kGuided) {
    // 0 is the guided end's stress-free angle: left unset, so that the 1R model (which has no
    // prescribed angle) can answer there.
    if (third != 0.0) p.prescribed.theta = third;
  } else {
    p.mu = third;
  }
  p.elements = spec.chain_elements;
  p.cbcm_elements = spec.cbcm_elements;
  p.prbm3r_constants = spec.prbm3r_constants;
  return p;
}

struct Timed {
  BeamSolution solution;
  ModelPointStatus status = ModelPointStatus::kConverged;
  double seconds = kNaN;
};

// One model at one point: the first solve's answer, timed as the mean of repeats until
// `min_seconds` have passed.
Timed timed_solve(BeamMethod method, const BeamProblem& problem, double min_seconds) {
  Timed t;
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  try {
    t.solution = solve_beam(method, problem);
  } catch (const InvalidInput&) {
    t.status = ModelPointStatus::kNotRepresented;  // includes OutsideMethodDomain
    return t;
  } catch (const NoConvergence&) {
    t.status = ModelPointStatus::kNotConverged;
    return t;
  }
  double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  if (!t.solution.converged()) {
    t.status = ModelPointStatus::kNotConverged;
    return t;
  }
  int solves = 1;
  while (elapsed < min_seconds) {
    (void)solve_beam(method, problem);
    ++solves;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  }
  t.seconds = elapsed / solves;
  return t;
}

void summarise(ModelMapModel& m) {
  std::vector<double> errors, times;
  for (std::size_t i = 0; i < m.values.status.size(); ++i) {
    if (m.values.status[i] != static_cast<int>(ModelPointStatus::kConverged)) continue;
    errors.push_back(m.values.position_error[i]);
    times.push_back(m.values.seconds[i]);
  }
  m.converged = static_cast<long>(errors.size());
  m.max_position_error = errors.empty() ? kNaN : *std::max_element(errors.begin(), errors.end());
  m.median_position_error = median(errors);
  m.median_seconds = median(times);
}

}  // namespace

std::vector<BeamMethod> ModelMapSpec::model_list() const {
  if (!models.empty()) return models;
  std::vector<BeamMethod> list = {BeamMethod::kLinear,
                                  BeamMethod::kPrbm,
                                  BeamMethod::kPrbm3r,
                                  BeamMethod::kBcm,
                                  BeamMethod::kCbcm,
                                  BeamMethod::kChain};
  // The shooting method is checked against the elliptic solution on a free end; on a guided one
  // it is the reference itself.
  if (boundary != EndCondition::kGuided) list.push_back(BeamMethod::kShooting);
  return list;
}

BeamMethod ModelMapSpec::reference() const {
  return boundary == EndCondition::kGuided ? BeamMethod::kShooting : BeamMethod::kElliptic;
}

const std::vector<double>& ModelMapSpec::third_axis() const {
  return boundary == EndCondition::kGuided ? tip_angle : mu;
}

const char* ModelMapSpec::third_axis_name() const {
  return boundary == EndCondition::kGuided ? "tip_angle" : "mu";
}

std::size_t ModelMapSpec::point_count() const {
  return n.size() * alpha2.size() * third_axis().size();
}

void ModelMapSpec::validate() const {
  if (boundary != EndCondition::kFree && boundary != EndCondition::kGuided) {
    throw InvalidInput(fmt::format(
        "the model map covers a free or a guided end (got {}): the ladder's models that solve "
        "other ends (bcm, cbcm) are compared on chains with `flexure beam --chain`",
        to_string(boundary)));
  }
  require_axis(n, "n");
  require_axis(alpha2, "alpha2");
  require_axis(mu, "mu");
  require_axis(tip_angle, "tip_angle");
  const auto only_zero = [](const std::vector<double>& v) { return v.size() == 1 && v[0] == 0.0; };
  if (boundary == EndCondition::kGuided && !only_zero(mu)) {
    throw InvalidInput(
        "a guided end takes its tip moment as the guide's reaction: the map's third axis is the "
        "prescribed tip angle (--tip-angle), not mu");
  }
  if (boundary == EndCondition::kFree && !only_zero(tip_angle)) {
    throw InvalidInput("a tip angle is prescribed on a guided end only (--boundary guided)");
  }
  const std::vector<BeamMethod> list = model_list();
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i] == BeamMethod::kAuto) {
      throw InvalidInput("the model map compares named models; 'auto' is not one");
    }
    if (list[i] == reference()) {
      throw InvalidInput(fmt::format(
          "'{}' is the map's reference for a {} end (every error is measured against it)",
          to_string(list[i]),
          to_string(boundary)));
    }
    if (boundary == EndCondition::kGuided && list[i] == BeamMethod::kElliptic) {
      throw InvalidInput("the elliptic solver solves a free end only; drop it for a guided map");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (list[j] == list[i]) {
        throw InvalidInput(fmt::format("model '{}' is listed twice", to_string(list[i])));
      }
    }
  }
  if (cbcm_elements < 1 || cbcm_elements > 2000) {
    throw InvalidInput(
        fmt::format("--elements (chained BCM) must be 1 to 2000 (got {})", cbcm_elements));
  }
  if (chain_elements < 2 || chain_elements > 100000) {
    throw InvalidInput(fmt::format(
        "--chain-elements (chain algorithm) must be 2 to 100000 (got {})", chain_elements));
  }
  if (!(min_seconds >= 0.0) || !std::isfinite(min_seconds) || min_seconds > 10.0) {
    throw InvalidInput(fmt::format("the timing per point must be 0 to 10 s (got {})", min_seconds));
  }
}

void ModelMapColumns::resize(std::size_t count) {
  a_over_l.assign(count, kNaN);
  b_over_l.assign(count, kNaN);
  theta0.assign(count, kNaN);
  position_error.assign(count, kNaN);
  angle_error.assign(count, kNaN);
  relative_error.assign(count, kNaN);
  seconds.assign(count, kNaN);
  status.assign(count, static_cast<int>(ModelPointStatus::kNotConverged));
}

ModelMap compute_model_map(const ModelMapSpec& spec,
                           const std::function<void(std::size_t, std::size_t)>& progress) {
  spec.validate();
  ModelMap map;
  map.spec = spec;
  const std::size_t count = spec.point_count();
  map.reference.resize(count);
  map.reference_limit_points.assign(count, 0);
  for (BeamMethod method : spec.model_list()) {
    ModelMapModel m;
    m.method = method;
    if (method == BeamMethod::kCbcm) m.settings = fmt::format("elements {}", spec.cbcm_elements);
    if (method == BeamMethod::kChain) m.settings = fmt::format("elements {}", spec.chain_elements);
    if (method == BeamMethod::kPrbm3r)
      m.settings = std::string("constants ") + to_string(spec.prbm3r_constants);
    m.values.resize(count);
    map.models.push_back(std::move(m));
  }
  const std::vector<double>& third = spec.third_axis();
  std::size_t k = 0;
  for (double n : spec.n) {
    for (double alpha2 : spec.alpha2) {
      for (double t : third) {
        const BeamProblem problem = problem_at(spec, n, alpha2, t);
        const Timed ref = timed_solve(spec.reference(), problem, spec.min_seconds);
        ModelMapColumns& r = map.reference;
        r.status[k] = static_cast<int>(ref.status);
        const bool have_reference = ref.status == ModelPointStatus::kConverged;
        if (have_reference) {
          r.a_over_l[k] = ref.solution.tip.a_over_l;
          r.b_over_l[k] = ref.solution.tip.b_over_l;
          r.theta0[k] = ref.solution.tip.theta0;
          r.position_error[k] = r.angle_error[k] = r.relative_error[k] = 0.0;
          r.seconds[k] = ref.seconds;
          map.reference_limit_points[k] = ref.solution.limit_points;
        }
        const double displacement = std::hypot(r.a_over_l[k] - 1.0, r.b_over_l[k]);
        for (ModelMapModel& m : map.models) {
          const Timed got = timed_solve(m.method, problem, spec.min_seconds);
          ModelMapColumns& v = m.values;
          v.status[k] = static_cast<int>(got.status);
          if (got.status != ModelPointStatus::kConverged) continue;
          v.a_over_l[k] = got.solution.tip.a_over_l;
          v.b_over_l[k] = got.solution.tip.b_over_l;
          v.theta0[k] = got.solution.tip.theta0;
          v.seconds[k] = got.seconds;
          if (!have_reference) {
            v.status[k] = static_cast<int>(ModelPointStatus::kNoReference);
            continue;
          }
          v.position_error[k] =
              std::hypot(v.a_over_l[k] - r.a_over_l[k], v.b_over_l[k] - r.b_over_l[k]);
          v.angle_error[k] = std::fabs(v.theta0[k] - r.theta0[k]);
          v.relative_error[k] = displacement > 0.0 ? v.position_error[k] / displacement : kNaN;
        }
        ++k;
        if (progress) progress(k, count);
      }
    }
  }
  for (ModelMapModel& m : map.models) summarise(m);
  return map;
}

}  // namespace flexure::studies
