#include "flexure/mechanisms/inversion.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "flexure/mechanisms/prbm_virtual_work.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

bool config_has_inversion(const std::string& config) {
  // plp reads the same reversed but its beam replaces link 2; the mirror has it on link 3 (the
  // thesis writes that form "pl3p", §7.4).
  return config == "spp" || config == "lpp" || config == "plp" || config == "ssp" ||
         config == "slp" || config == "lps";
}

std::string mirrored_config(const std::string& config) {
  if (config == "plp") return "pl3p";
  return std::string(config.rbegin(), config.rend());
}

MechanismDesign invert(const MechanismDesign& design) {
  if (!config_has_inversion(design.config)) {
    throw InvalidInput(fmt::format(
        "'{}' ({}) has no distinct inversion: {} reads the same mirrored (thesis §3.2.4); its "
        "inversion is a {} design with R' = 1/R, K1' = K1/K2, K2' = 1/K2. Inversions exist for "
        "spp, lpp, plp, ssp, slp, lps",
        design.name,
        design.config,
        design.config,
        design.config));
  }
  MechanismDesign d = design;
  if (design.inverted) {
    d.inverted = false;
    if (!d.name.empty() && d.name.back() == '\'') d.name.pop_back();
    const std::string prefix = "inversion of ";
    if (const auto at = d.note.find(": ");
        d.note.rfind(prefix, 0) == 0 && at != std::string::npos) {
      d.note = d.note.substr(at + 2);
    }
    return d;
  }
  d.inverted = true;
  d.note = fmt::format(
      "inversion of {} ({} read from the slider block, which is fixed; the ground "
      "block slides): {}",
      design.name,
      mirrored_config(design.config),
      design.note);
  d.name = design.name + "'";
  return d;
}

std::optional<std::string> inversion_base_name(const std::string& name) {
  if (name.size() > 1 && name.back() == '\'') return name.substr(0, name.size() - 1);
  const std::string lower = to_lower(name);
  const std::string suffix = "-inv";
  if (lower.size() > suffix.size() &&
      lower.compare(lower.size() - suffix.size(), suffix.size(), suffix) == 0) {
    return name.substr(0, name.size() - suffix.size());
  }
  return std::nullopt;
}

DescribedDesign described_form(const MechanismDesign& design) {
  DescribedDesign out;
  if (!design.inverted) {
    out.config = design.config;
    out.r2 = design.r2;
    out.r3 = design.r3;
    out.joints = design.joints;
    out.fixed_body = "ground";
    return out;
  }
  out.config = mirrored_config(design.config);
  out.r2 = design.r3;  // Howell §10.1.2: "r2 for r3, r3 for r2"
  out.r3 = design.r2;
  out.joints = {design.joints[2], design.joints[1], design.joints[0]};
  out.fixed_body = "slider block";
  return out;
}

int described_pivot(const MechanismDesign& design, int pivot) {
  return design.inverted ? 4 - pivot : pivot;
}

std::array<double, 3> to_described(const MechanismDesign& design, const std::array<double, 3>& v) {
  return design.inverted ? std::array<double, 3>{v[2], v[1], v[0]} : v;
}

double inverted_prbm_force(const MechanismDesign& design, double displacement) {
  const DescribedDesign m = described_form(design);
  // k1 <-> k3 (Howell §10.1.2); the spring constants belong to the pivots, whose stored order is
  // the original one.
  const std::array<double, 3> k_described = to_described(
      design, {design.spring_constant(1), design.spring_constant(2), design.spring_constant(3)});
  return virtual_work_state(m.r2, m.r3, k_described, displacement).force;
}

}  // namespace flexure::mechanism
