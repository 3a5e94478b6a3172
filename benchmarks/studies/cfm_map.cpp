#include "flexure/benchmarks/studies/cfm_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::studies {
namespace {

void check_axis(const std::vector<double>& axis, const char* name) {
  for (double v : axis) {
    if (!(std::isfinite(v) && v > 0.0)) {
      throw InvalidInput(fmt::format("{} = {} must be a finite number > 0", name, v));
    }
  }
}

}  // namespace

void CfmMapSpec::validate() const {
  const cfm::CfmConfiguration& c = cfm::find_cfm_configuration(config);
  if (R.empty() || d.empty()) throw InvalidInput("the map needs at least one R and one d");
  check_axis(R, "R");
  check_axis(d, "d");
  check_axis(K1, "K1");
  check_axis(K2, "K2");
  for (double v : d) {
    if (v > 100.0) throw InvalidInput(fmt::format("d = {} % must not exceed 100", v));
  }
  const bool takes_K1 = c.has_spring(2) && !c.is_class_1B();
  if (takes_K1 != !K1.empty()) {
    throw InvalidInput(takes_K1 ? fmt::format("configuration {} needs --K1 (k2/k1)", config)
                                : fmt::format("configuration {} takes no --K1 ({})",
                                              config,
                                              c.is_class_1B() ? "class 1B: K1 = 1 by definition"
                                                              : "no spring at pivot 2"));
  }
  if (c.has_spring(3) != !K2.empty()) {
    throw InvalidInput(
        c.has_spring(3)
            ? fmt::format("configuration {} needs --K2 (k3/k1)", config)
            : fmt::format("configuration {} takes no --K2 (no spring at pivot 3)", config));
  }
  // The grid's size, checked before any allocation: a product that overflows or a grid beyond
  // 10^8 points (800 MB per quantity) is refused.
  double total = 1.0;
  for (std::size_t n : dims()) total *= static_cast<double>(n);
  if (total > 1e8) {
    throw InvalidInput(fmt::format(
        "the map has {:.4g} points; at most 1e8 (800 MB per quantity) are allowed", total));
  }
  if (points < 2 || points > 100000) {
    throw InvalidInput(fmt::format("points = {} must lie in [2, 100000]", points));
  }
  prbm.validate();
}

std::vector<std::size_t> CfmMapSpec::dims() const {
  return {
      R.size(), d.size(), std::max<std::size_t>(1, K1.size()), std::max<std::size_t>(1, K2.size())};
}

CfmMapPoint cfm_map_point(const CfmMapSpec& spec, std::size_t index) {
  const std::vector<std::size_t> dims = spec.dims();
  // Row-major: K2 fastest.
  const std::size_t b = index % dims[3];
  const std::size_t a = (index / dims[3]) % dims[2];
  const std::size_t j = (index / (dims[3] * dims[2])) % dims[1];
  const std::size_t i = index / (dims[3] * dims[2] * dims[1]);
  cfm::CfmParameters p;
  p.config = spec.config;
  p.R = spec.R.at(i);
  p.stroke_percent = spec.d[j];
  if (!spec.K1.empty()) p.K1 = spec.K1[a];
  if (!spec.K2.empty()) p.K2 = spec.K2[b];
  CfmMapPoint m;
  try {
    const cfm::CfmResult r = cfm::CfmModel(spec.prbm).evaluate(p);
    if (!r.converged()) throw InvalidInput(r.message);
    m.Phi = r.Phi;
    m.percent_constant_force = r.percent_constant_force;
    m.Psi_raw = r.Psi_raw;
    m.toggle_stroke_percent = r.toggle_stroke_percent;
    m.effective_stroke_percent = r.stroke_percent;
    m.stroke_clamped = r.stroke_clamped ? 1 : 0;
    if (spec.exact) {
      // The exact model may refuse a point the PRBM takes (its equivalent design leaves the
      // slender-beam limits at extreme K): the PRBM values stay, status 1.
      cfm::CfmExactOptions exact_options;
      exact_options.points = spec.points;
      try {
        const cfm::CfmExactResult e = cfm::solve_cfm_exact(r, exact_options);
        if (e.converged()) {
          m.percent_constant_force_exact = e.percent_constant_force_exact;
          m.Phi_exact = e.Phi_exact;
          m.max_force_error = e.max_force_error;
        } else {
          m.status = kMapExactNotConverged;
        }
      } catch (const InvalidInput&) {
        m.status = kMapExactNotConverged;
      }
    }
  } catch (const InvalidInput&) {
    m = CfmMapPoint{};
    m.status = kMapInvalid;
  }
  return m;
}

}  // namespace flexure::studies
