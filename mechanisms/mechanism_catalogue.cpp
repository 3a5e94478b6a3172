#include "flexure/mechanisms/mechanism_catalogue.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/inversion.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

constexpr std::array<std::pair<DesignSet, const char*>, 6> kNames{{
    {DesignSet::kBuiltin, "builtin"},
    {DesignSet::kThesis, "thesis"},
    {DesignSet::kModified, "modified"},
    {DesignSet::kHowell, "howell"},
    {DesignSet::kInversions, "inversions"},
    {DesignSet::kAll, "all"},
}};

}  // namespace

DesignSet design_set_from_string(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) {
    return static_cast<char>(std::tolower(c));
  });
  for (const auto& [set, text] : kNames) {
    if (lower == text) return set;
  }
  throw InvalidInput(fmt::format(
      "design set '{}' is unknown (allowed: builtin, thesis, modified, howell, inversions, all)",
      name));
}

std::string to_string(DesignSet set) {
  for (const auto& [s, text] : kNames) {
    if (s == set) return text;
  }
  return "builtin";
}

std::vector<MechanismDesign> mechanism_designs(DesignSet set) {
  const bool all = set == DesignSet::kAll;
  std::vector<MechanismDesign> out;
  for (const MechanismDesign& d : builtin_mechanisms()) {
    const bool modified = !d.paper_config.empty();
    if (all || set == DesignSet::kBuiltin || (set == DesignSet::kThesis && !modified) ||
        (set == DesignSet::kModified && modified)) {
      out.push_back(d);
    }
  }
  if (all || set == DesignSet::kHowell) {
    out.insert(out.end(), howell_mechanisms().begin(), howell_mechanisms().end());
  }
  if (all || set == DesignSet::kInversions) {
    for (const auto* list : {&builtin_mechanisms(), &howell_mechanisms()}) {
      for (const MechanismDesign& d : *list) {
        // The paper's modified designs are not inverted: paper 004 describes none.
        if (config_has_inversion(d.config) && d.paper_config.empty()) out.push_back(invert(d));
      }
    }
  }
  return out;
}

}  // namespace flexure::mechanism
