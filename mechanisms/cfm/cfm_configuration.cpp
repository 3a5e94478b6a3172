#include <fmt/format.h>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure::cfm {

SegmentConstants segment_constants(PivotType type) {
  switch (type) {
    case PivotType::kSmall:  // App. A.2: K = EI/l, l = 0.1 r (thesis eq. 4.5)
      return {1.0, SmallLengthFlexuralPivot::kStiffnessCoefficient, 0.1};
    case PivotType::kLong: {  // App. A.3: gamma_ave, K_theta, l = r/gamma (eq. 4.4)
      const FixedPinnedConstants& c = howell_average_fixed_pinned().constants();
      return {c.gamma, c.K_theta, 1.0 / c.gamma};
    }
    case PivotType::kPin:
      break;
  }
  return {0.0, 0.0, 1.0};
}

const std::vector<CfmConfiguration>& cfm_configurations() {
  using P = PivotType;
  static const std::vector<CfmConfiguration> kConfigurations = {
      {"spp", "1A", {P::kSmall, P::kPin, P::kPin}, false},
      {"lpp", "1A", {P::kLong, P::kPin, P::kPin}, false},
      {"psp", "1B", {P::kPin, P::kSmall, P::kPin}, false},
      {"plp", "1B", {P::kPin, P::kLong, P::kPin}, true},  // tabulated rows use link 2 (pl2p)
      {"ssp", "2A", {P::kSmall, P::kSmall, P::kPin}, false},
      {"slp", "2A", {P::kSmall, P::kLong, P::kPin}, false},  // the beam is link 3
      {"sps", "2B", {P::kSmall, P::kPin, P::kSmall}, false},
      {"lps", "2B", {P::kLong, P::kPin, P::kSmall}, false},
      {"sss", "3A", {P::kSmall, P::kSmall, P::kSmall}, false},
  };
  return kConfigurations;
}

const CfmConfiguration& find_cfm_configuration(const std::string& name) {
  // The exact name first: a synthesis looks its configuration up once per model evaluation.
  for (const CfmConfiguration& c : cfm_configurations()) {
    if (name == c.name) return c;
  }
  for (const CfmConfiguration& c : cfm_configurations()) {
    if (same_name(c.name, name)) return c;
  }
  throw InvalidInput(fmt::format(
      "configuration '{}' is unknown; allowed: spp, lpp, psp, plp, ssp, slp, sps, lps, sss", name));
}

}  // namespace flexure::cfm
