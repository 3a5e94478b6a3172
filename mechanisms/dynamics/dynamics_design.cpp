#include <fmt/format.h>
#include <fmt/ranges.h>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/solver/common/enum_names.h"
#include "flexure/solver/common/status.h"

namespace flexure::dynamics {
namespace {

using mechanism::MechanismDesign;
using mechanism::PivotType;
using mechanism::SpringRule;

std::array<double, 3> spring_constants(const MechanismDesign& d) {
  return {d.spring_constant(1), d.spring_constant(2), d.spring_constant(3)};
}

std::optional<DynamicsSpringRule> design_rule(const MechanismDesign& d) {
  if (!mechanism::has_fixed_fixed(d)) return std::nullopt;
  return dynamics_spring_rule(d.spring_rule);
}

constexpr std::array<const char*, 5> kDynamicsSpringRuleNames = {
    "table5-printed", "pure-bending", "table2", "table5", "given"};

}  // namespace

const char* to_string(DynamicsSpringRule rule) { return enum_name(kDynamicsSpringRuleNames, rule); }

DynamicsSpringRule dynamics_spring_rule_from_string(std::string_view name) {
  return enum_from_name<DynamicsSpringRule>(kDynamicsSpringRuleNames, name, "dynamics spring rule");
}

DynamicsSpringRule dynamics_spring_rule(SpringRule rule) {
  switch (rule) {
    case SpringRule::kPureBending:
      return DynamicsSpringRule::kPureBending;
    case SpringRule::kTable2:
      return DynamicsSpringRule::kTable2;
    case SpringRule::kTable5:
      return DynamicsSpringRule::kTable5;
  }
  throw InvalidInput("unknown spring rule");
}

DynamicsDesign builtin_dynamics_design(const std::string& name,
                                       std::optional<SpringRule> rule,
                                       const MaterialGrade* material) {
  const CfsmDesign& t = find_cfsm_design(name);
  if (material != nullptr && !rule) {
    throw InvalidInput(fmt::format(
        "{}: material '{}' sets the modulus of springs computed from the strips, but the printed "
        "Table 5 springs of {} are constants; give --spring-rule pure-bending, table2 or table5 "
        "to compute them from the strips with the material's E",
        t.name,
        material->id,
        t.name));
  }
  DynamicsDesign d;
  d.name = t.name;
  d.r2 = t.r2;
  d.r3 = t.r3;
  d.m2 = t.m2;
  d.m3 = t.m3;
  d.m_slider = t.m_slider;
  d.F_nom_paper = t.F_nom_paper;
  if (rule) {
    // The same strips as `mechanism analyze NAME` (its Table 5 column), springs by `rule`.
    MechanismDesign m =
        mechanism::modified_design(mechanism::find_modified_configuration(t.name), *rule);
    if (material != nullptr) {
      m.material.E = material->E;  // k = EI/L and its factors (modified_springs.h) scale with E
      d.material = material->material();
      d.material_id = material->id;
    }
    d.k = spring_constants(m);
    d.spring_rule = dynamics_spring_rule(*rule);
  } else {
    d.k = t.k;
    d.spring_rule = DynamicsSpringRule::kTable5Printed;
  }
  return d;
}

DynamicsDesign dynamics_design(MechanismDesign design,
                               const DynamicsData& data,
                               MassesNeeded needed,
                               std::optional<SpringRule> rule,
                               const MaterialGrade* material) {
  const std::string where =
      data.line > 0 ? fmt::format("{}:{}", data.source, data.line) : data.source;
  if (design.inverted) {
    throw InvalidInput(fmt::format(
        "{}: an inversion (fixed slider block) has no dynamics model: the slider-crank of "
        "docs/dynamics.md moves the slider",
        design.name));
  }
  DynamicsDesign d;
  d.name = design.name;
  d.r2 = design.r2;
  d.r3 = design.r3;
  d.stroke = design.stroke;
  // A missing mass is an error only where the run needs it (--zero-inertia needs none).
  auto mass = [&](const std::optional<double>& m, const char* key, const char* what, bool used) {
    if (m || !used) return m.value_or(0.0);
    const std::string alternative =
        std::string(key) == "m_slider" ? "--zero-slider-mass or --zero-inertia" : "--zero-inertia";
    if (data.line > 0) {
      throw InvalidInput(fmt::format(
          "{}: [dynamics] lacks {} ({}, kg), which flexure dynamics needs; add it or run with {}",
          where,
          key,
          what,
          alternative));
    }
    throw InvalidInput(fmt::format(
        "{}: flexure dynamics needs [dynamics] {} ({}, kg), and the file has no [dynamics] "
        "table; add one with m2, m3 and m_slider (docs/mechanisms.md \"TOML\") or run with {}",
        where,
        key,
        what,
        alternative));
  };
  d.m2 = mass(data.m2, "m2", "mass of link 2 of one half", needed != MassesNeeded::kNone);
  d.m3 = mass(data.m3, "m3", "mass of link 3 of one half", needed != MassesNeeded::kNone);
  d.m_slider = mass(data.m_slider,
                    "m_slider",
                    "mass of the slider both halves share",
                    needed == MassesNeeded::kAll);
  if (material != nullptr) {
    if (data.spring_constants) {
      throw InvalidInput(fmt::format(
          "{}: material '{}' sets the modulus of springs computed from the strips, but [dynamics] "
          "spring_constants give the springs; remove one",
          where,
          material->id));
    }
    design.material.E = material->E;
    design.material_id = material->id;
    d.material = material->material();
    d.material_id = material->id;
  }
  if (data.spring_constants) {
    if (rule) {
      throw InvalidInput(fmt::format(
          "{}: --spring-rule contradicts [dynamics] spring_constants, which replace the rule in "
          "flexure dynamics; remove one",
          where));
    }
    const std::array<double, 3>& k = *data.spring_constants;
    for (int p = 1; p <= 3; ++p) {
      const bool pin = design.joints[p - 1].type == PivotType::kPin;
      if (pin != (k[p - 1] == 0.0)) {
        throw InvalidInput(
            fmt::format("{}: [dynamics] spring_constants[{}] = {} for pivot {}, {}: it must be {}",
                        where,
                        p - 1,
                        k[p - 1],
                        p,
                        pin ? "a pin" : "a flexure",
                        pin ? "0" : "> 0"));
      }
    }
    d.k = k;
    d.spring_rule = DynamicsSpringRule::kGiven;
    return d;
  }
  if (rule) mechanism::apply_spring_rule(design, *rule);
  d.k = spring_constants(design);
  d.spring_rule = design_rule(design);
  return d;
}

}  // namespace flexure::dynamics
