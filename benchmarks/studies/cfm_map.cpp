#include "flexure/benchmarks/studies/cfm_map.h"

#include <fmt/format.h>

#include <cmath>

#include "flexure/mechanisms/cfm/cfm_configuration.h"
#include "flexure/mechanisms/cfm/cfm_exact.h"
#include "flexure/solver/common/errors.h"

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

CfmMap cfm_map(const CfmMapSpec& spec,
               const std::function<void(std::size_t, std::size_t)>& progress) {
  spec.validate();
  CfmMap m;
  m.dims = spec.dims();
  const std::size_t total = m.dims[0] * m.dims[1] * m.dims[2] * m.dims[3];
  for (auto* v : {&m.Phi,
                  &m.percent_constant_force,
                  &m.Psi_raw,
                  &m.toggle_stroke_percent,
                  &m.effective_stroke_percent}) {
    v->assign(total, 0.0);
  }
  m.stroke_clamped.assign(total, 0);
  m.status.assign(total, kMapOk);
  if (spec.exact) {
    for (auto* v : {&m.percent_constant_force_exact, &m.Phi_exact, &m.max_force_error}) {
      v->assign(total, 0.0);
    }
  }
  const cfm::CfmModel model(spec.prbm);
  cfm::CfmExactOptions exact_options;
  exact_options.points = spec.points;
  std::size_t k = 0;
  for (std::size_t i = 0; i < m.dims[0]; ++i) {
    for (std::size_t j = 0; j < m.dims[1]; ++j) {
      for (std::size_t a = 0; a < m.dims[2]; ++a) {
        for (std::size_t b = 0; b < m.dims[3]; ++b, ++k) {
          cfm::CfmParameters p;
          p.config = spec.config;
          p.R = spec.R[i];
          p.stroke_percent = spec.d[j];
          if (!spec.K1.empty()) p.K1 = spec.K1[a];
          if (!spec.K2.empty()) p.K2 = spec.K2[b];
          try {
            const cfm::CfmResult r = model.evaluate(p);
            if (!r.converged()) throw InvalidInput(r.message);
            m.Phi[k] = r.Phi;
            m.percent_constant_force[k] = r.percent_constant_force;
            m.Psi_raw[k] = r.Psi_raw;
            m.toggle_stroke_percent[k] = r.toggle_stroke_percent;
            m.effective_stroke_percent[k] = r.stroke_percent;
            m.stroke_clamped[k] = r.stroke_clamped ? 1 : 0;
            if (spec.exact) {
              // The exact model may refuse a point the PRBM takes (its equivalent design leaves
              // the slender-beam limits at extreme K): the PRBM values stay, status 1.
              try {
                const cfm::CfmExactResult e = cfm::solve_cfm_exact(r, exact_options);
                if (e.converged()) {
                  m.percent_constant_force_exact[k] = e.percent_constant_force_exact;
                  m.Phi_exact[k] = e.Phi_exact;
                  m.max_force_error[k] = e.max_force_error;
                } else {
                  m.status[k] = kMapExactNotConverged;
                }
              } catch (const InvalidInput&) {
                m.status[k] = kMapExactNotConverged;
              }
            }
          } catch (const InvalidInput&) {
            m.status[k] = kMapInvalid;
            m.Phi[k] = m.percent_constant_force[k] = m.Psi_raw[k] = 0.0;
            m.toggle_stroke_percent[k] = m.effective_stroke_percent[k] = 0.0;
            m.stroke_clamped[k] = 0;
          }
          if (progress) progress(k + 1, total);
        }
      }
    }
  }
  return m;
}

}  // namespace flexure::studies
