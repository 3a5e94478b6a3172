#include "flexure/mechanisms/design/subclass_problem.h"

#include <cctype>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm_comparison.h"

namespace flexure::design {

std::string subclass_flags(const std::string& name) {
  std::size_t k = name.size();
  while (k > 0 && (name[k - 1] == 'I' || name[k - 1] == 'O' || name[k - 1] == 'o')) --k;
  return name.substr(k);
}

SubclassProblem subclass_problem(const cfm::CfmSubclass& row) {
  SubclassProblem s;
  CfmDesignProblem& p = s.problem;
  p.config = row.config;
  // The effective stroke: the toggle-clamped rows were optimised over their clamped stroke.
  p.stroke_percent = cfm::CfmModel().evaluate(cfm::parameters_of(row)).stroke_percent;
  const std::string name = row.name;
  std::string digits;
  for (std::size_t k = name.find('-') + 2; k < name.size(); ++k) {
    if (std::isdigit(static_cast<unsigned char>(name[k]))) digits += name[k];
  }
  if (digits.empty()) {
    p.objective = DesignObjective::kMaxPcf;
  } else {
    p.objective = DesignObjective::kMaxPsi;
    p.pcf_min = std::stod(digits);
    p.orientation = orientation_rules_from_string(subclass_flags(name));
  }
  p.model = default_model_options(p.objective);
  for (const std::string& v : p.variables()) {
    s.printed.push_back(v == "R" ? row.R : (v == "K1" ? row.K1 : row.K2));
  }
  return s;
}

}  // namespace flexure::design
