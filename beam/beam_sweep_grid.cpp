#include "flexure/beam/beam_sweep_grid.h"

#include <fmt/format.h>

#include <cmath>

#include "flexure/solver/common/evenly_spaced.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

BeamProblem::Given given_of(SweepParameter p) {
  switch (p) {
    case SweepParameter::kTheta0:
      return BeamProblem::Given::kTheta0;
    case SweepParameter::kBOverL:
      return BeamProblem::Given::kBOverL;
    default:
      return BeamProblem::Given::kAlpha2;
  }
}

bool is_given(SweepParameter p) {
  return p == SweepParameter::kAlpha2 || p == SweepParameter::kTheta0 ||
         p == SweepParameter::kBOverL;
}

void set(BeamProblem& problem, SweepParameter p, double value) {
  switch (p) {
    case SweepParameter::kLoadRatioN:
      problem.load_ratio_n = value;
      break;
    case SweepParameter::kMu:
      problem.mu = value;
      break;
    default:
      problem.value = value;  // alpha2, theta0 or b/l: the problem's `given`
      break;
  }
}

}  // namespace

const char* dataset_name(SweepParameter p) {
  constexpr const char* kNames[] = {
      "alpha2", "load_ratio_n", "mu", "theta0", "b_over_l", "Fx", "Fy", "M"};
  return kNames[static_cast<int>(p)];
}

const char* flag_name(SweepParameter p) {
  constexpr const char* kFlags[] = {
      "--alpha2", "--n", "--mu", "--theta0", "--b-over-l", "--Fx", "--Fy", "--M"};
  return kFlags[static_cast<int>(p)];
}

const char* units_of(SweepParameter p) {
  switch (p) {
    case SweepParameter::kTheta0:
      return "rad";
    case SweepParameter::kFx:
    case SweepParameter::kFy:
      return "N";
    case SweepParameter::kM:
      return "N m";
    default:
      return "1";
  }
}

bool is_physical(SweepParameter p) {
  return p == SweepParameter::kFx || p == SweepParameter::kFy || p == SweepParameter::kM;
}

double SweepAxis::at(long i) const { return evenly_spaced(start, stop, count, i); }

void BeamSweepGrid::validate(long max_points) const {
  if (axes.empty() || axes.size() > 2) {
    throw InvalidInput(
        fmt::format("sweep beam sweeps one or two of {} as START:STOP:COUNT (got {} ranges)",
                    physical || chain ? "the tip loads --Fx, --Fy, --M"
                                      : "--alpha2, --n, --mu, --theta0, --b-over-l",
                    axes.size()));
  }
  if (axes.size() == 2 && axes[0].parameter == axes[1].parameter) {
    throw InvalidInput(fmt::format("{} is given as a range twice", flag_name(axes[0].parameter)));
  }
  for (const SweepAxis& axis : axes) {
    if (is_physical(axis.parameter) != (physical.has_value() || chain.has_value())) {
      throw InvalidInput(fmt::format(
          "{} is a range of {}: a physical sweep (--length, --E, the section) sweeps --Fx, --Fy, "
          "--M, Howell's sweep --alpha2, --n, --mu, --theta0, --b-over-l",
          flag_name(axis.parameter),
          is_physical(axis.parameter) ? "a tip load in newtons without a physical beam"
                                      : "Howell's parameters with a physical beam"));
    }
    if (!(std::isfinite(axis.start) && std::isfinite(axis.stop)) || axis.count < 1) {
      throw InvalidInput(fmt::format("{}: START and STOP must be finite and COUNT >= 1",
                                     flag_name(axis.parameter)));
    }
    if (is_given(axis.parameter) && given_of(axis.parameter) != base.given) {
      throw InvalidInput(fmt::format(
          "{} is a range but the sweep's given quantity is another one: give exactly one of "
          "--alpha2, --theta0, --b-over-l",
          flag_name(axis.parameter)));
    }
    if (axis.parameter == SweepParameter::kBOverL &&
        (std::fabs(axis.start) > 1.0 || std::fabs(axis.stop) > 1.0)) {
      throw InvalidInput("--b-over-l: the tip deflection b/l lies in [-1, 1]");
    }
  }
  // Counts are positive: the product overflows only past max_points, checked step by step.
  long points = 1;
  for (const SweepAxis& axis : axes) {
    if (axis.count > max_points / points) {
      throw InvalidInput(fmt::format(
          "the sweep has more than {} points ({}); split it", max_points, axis_names()));
    }
    points *= axis.count;
  }
}

long BeamSweepGrid::size() const {
  long n = 1;
  for (const SweepAxis& axis : axes) n *= axis.count;
  return n;
}

std::vector<long> BeamSweepGrid::shape() const {
  std::vector<long> s;
  for (const SweepAxis& axis : axes) s.push_back(axis.count);
  return s;
}

std::vector<double> BeamSweepGrid::coordinates(long index) const {
  std::vector<double> c(axes.size());
  for (std::size_t k = axes.size(); k-- > 0;) {
    c[k] = axes[k].at(index % axes[k].count);
    index /= axes[k].count;
  }
  return c;
}

BeamProblem BeamSweepGrid::at(long index) const {
  BeamProblem problem = base;
  const std::vector<double> c = coordinates(index);
  if (chain) {
    problem.chain = *chain;
    TipLoad& load = problem.chain->tip_load;
    for (std::size_t k = 0; k < axes.size(); ++k) {
      (axes[k].parameter == SweepParameter::kFx   ? load.Fx
       : axes[k].parameter == SweepParameter::kFy ? load.Fy
                                                  : load.M) = c[k];
    }
    problem.boundary = chain->end;
    return problem;
  }
  if (physical) {
    PhysicalCantilever beam = *physical;
    for (std::size_t k = 0; k < axes.size(); ++k) {
      (axes[k].parameter == SweepParameter::kFx   ? beam.Fx
       : axes[k].parameter == SweepParameter::kFy ? beam.Fy
                                                  : beam.M) = c[k];
    }
    return beam.to_problem(base);
  }
  for (std::size_t k = 0; k < axes.size(); ++k) set(problem, axes[k].parameter, c[k]);
  return problem;
}

bool BeamSweepGrid::needs_shooting() const {
  if (base.boundary != EndCondition::kFree || base.follower != 0.0 || chain) return true;
  if (!physical) return false;
  const PhysicalCantilever& b = *physical;
  if (b.beyond_elastica() || b.shaped() || b.end != EndCondition::kFree) return true;
  // An axial force alone (Fy = 0, Fx != 0) has no Howell's n: a chain.
  const SweepAxis* fx = nullptr;
  const SweepAxis* fy = nullptr;
  for (const SweepAxis& axis : axes) {
    if (axis.parameter == SweepParameter::kFx) fx = &axis;
    if (axis.parameter == SweepParameter::kFy) fy = &axis;
  }
  bool fy_zero = fy == nullptr && b.Fy == 0.0;
  for (long i = 0; fy != nullptr && i < fy->count && !fy_zero; ++i) fy_zero = fy->at(i) == 0.0;
  const bool fx_nonzero = fx != nullptr ? fx->start != 0.0 || fx->stop != 0.0 : b.Fx != 0.0;
  return fy_zero && fx_nonzero;
}

std::string BeamSweepGrid::axis_names() const {
  std::string names;
  for (const SweepAxis& axis : axes) {
    if (!names.empty()) names += ",";
    names += dataset_name(axis.parameter);
  }
  return names;
}

}  // namespace flexure
