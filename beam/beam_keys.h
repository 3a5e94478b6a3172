#pragma once
// The keys of a beam answer, written once for every front end: the JSON object of
// `flexure beam --json` (docs/cli.md "flexure beam") and the dict of the Python module's
// flexure.beam, including the keys of a physical beam, the plate modulus, the deflected shape and
// the `reached` object of a failed solve. Internal header (not installed).
//
// J is the caller's JSON value type with nlohmann::json's interface: J(value) from a double, int,
// bool, string or nullptr; J::array(), push_back, operator[] by key and by index; keys kept in
// the order written (nlohmann::ordered_json). The beam layer itself links no JSON library.
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/beam_request.h"
#include "flexure/beam/physical_beam.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::beam_keys {

// NaN (a quantity the problem does not have) as null; -0 written as 0.
template <class J>
J number_or_null(double value) {
  return std::isfinite(value) ? J(value + 0.0) : J(nullptr);
}

template <class J>
J optional_number(const std::optional<double>& value) {
  return value ? J(*value) : J(nullptr);
}

template <class J>
J reaction(const Reaction& r) {
  J out;
  out["Fx"] = number_or_null<J>(r.Fx);
  out["Fy"] = number_or_null<J>(r.Fy);
  out["M"] = number_or_null<J>(r.M);
  return out;
}

// The stability keys (docs/cli.md): index and margin null unless the energy judged it.
template <class J>
void add_stability(J& out, const Stability& s) {
  out["stability"] = std::string(stability_name(s.kind));
  out["stability_index"] = s.judged() ? J(s.index) : J(nullptr);
  out["stability_margin"] = s.judged() ? number_or_null<J>(s.margin) : J(nullptr);
  out["stability_message"] = s.message;
}

// One modulus choice (docs/plate-modulus.md): rule, modulus_rule, plate, E, nu, effective_E, and
// for auto the Searle parameter, its threshold, the share of the plate stiffening and the
// curvature.
template <class J>
J modulus_choice(const ModulusChoice& c) {
  J out;
  out["rule"] = to_string(c.rule);
  out["modulus_rule"] = c.modulus_rule();
  out["plate"] = c.plate;
  out["E"] = c.E;
  out["nu"] = optional_number<J>(c.nu);
  out["effective_E"] = c.effective_E;
  out["searle_beta"] = optional_number<J>(c.beta);
  out["searle_threshold"] = optional_number<J>(c.threshold);
  out["plate_fraction"] = optional_number<J>(c.fraction);
  out["curvature"] = optional_number<J>(c.curvature);
  out["reason"] = c.reason();
  return out;
}

// `modulus_rule`, `effective_E` (the first choice's, or null when the segments differ or none has
// a section) and `modulus` (the list).
template <class J>
void add_modulus(J& out, const std::vector<ModulusChoice>& choices) {
  J list = J::array();
  bool same = !choices.empty();
  for (const ModulusChoice& c : choices) {
    list.push_back(modulus_choice<J>(c));
    same = same && c.plate == choices.front().plate && c.effective_E == choices.front().effective_E;
  }
  out["modulus_rule"] = same ? J(choices.front().modulus_rule()) : J(nullptr);
  out["effective_E"] = same ? J(choices.front().effective_E) : J(nullptr);
  out["modulus"] = std::move(list);
}

// The limit and bifurcation points the shooting method's continuation passed (null for the other
// methods): the load factor (stage 2 of a pinned or fixed straight beam: the fraction of the
// released coordinate's travel), the tip per unit length as a_over_l, b_over_l are, and where.
template <class J>
J special_points(const BeamProblem& problem, const BeamSolution& solution) {
  if (!solution.special_points_known) return J(nullptr);
  const double length = problem.chain ? problem.chain->total_length() : 1.0;
  J list = J::array();
  for (const SpecialPoint& sp : solution.special_points) {
    J p;
    p["kind"] = to_string(sp.kind);
    p["load_factor"] = sp.lambda;
    p["a_over_l"] = sp.tip.x / length;
    p["b_over_l"] = sp.tip.y / length;
    p["theta0"] = sp.tip.theta;
    p["stage"] = sp.stage;
    p["located"] = sp.located;
    list.push_back(std::move(p));
  }
  return list;
}

// The physical keys (docs/cli.md, "Physical beams"): SI units, named with their unit where the
// nondimensional output already uses the bare name.
template <class J>
void add_physical(J& out, const BeamInput& input, const PhysicalResults& r) {
  out["units"] = "SI";
  out["length_m"] = r.length;
  if (input.physical) {
    const PhysicalCantilever& b = *input.physical;
    out["E_Pa"] = b.material.E;
    out["I_m4"] = b.second_moment();
    // The rigidity solved with: E I, or E I/(1 - nu^2) with the plate modulus.
    out["EI_Nm2"] = r.modulus.empty() ? b.flexural_rigidity()
                                      : r.modulus.front().effective_E * b.second_moment();
    out["Fx_N"] = b.Fx;
    out["Fy_N"] = b.Fy;
    out["M_Nm"] = b.M;
    if (b.shaped()) {
      // A curved or tapered beam (EI_Nm2 and I_m4 above are the clamp's).
      out["curvature_per_m"] = b.curvature;
      out["width_tip_m"] = optional_number<J>(b.width_tip);
      out["thickness_tip_m"] = optional_number<J>(b.thickness_tip);
    }
    if (b.beyond_elastica()) {
      out["qx_N_per_m"] = b.qx;
      out["qy_N_per_m"] = b.total_qy();  // including the self-weight
      out["q_follower_N_per_m"] = b.q_follower;
      if (b.extensible) {
        // An extensible beam has nu (validate()); the product in PhysicalCantilever::to_chain's
        // order.
        out["EA_N"] = b.material.E * b.area().value_or(0.0);
        out["GAs_N"] = b.shear_coefficient * b.material.E / (2.0 * (1.0 + b.material.nu)) *
                       b.area().value_or(0.0);
      }
    }
  }
  add_modulus(out, r.modulus);
  out["max_axial_force_N"] = r.max_axial_force;
  out["max_axial_strain"] = optional_number<J>(r.max_axial_strain);
  out["tip_x"] = r.tip_x;
  out["tip_y"] = r.tip_y;
  out["root_moment_Nm"] = r.root_moment;
  out["max_moment_Nm"] = r.max_moment;
  out["max_moment_at_m"] = r.max_moment_at;
  out["max_moment_from"] = r.max_from;
  out["max_stress"] = optional_number<J>(r.max_stress);
  out["max_stress_at_m"] = optional_number<J>(r.max_stress_at);
  if (r.yield_strength) {
    out["yield_strength"] = *r.yield_strength;
    out["safety_factor"] = optional_number<J>(r.safety_factor);
  }
}

// The answer's object, in the order of docs/cli.md; `warnings` as beam_answer_warnings gives them
// with `names`.
template <class J>
J answer(const BeamInput& input,
         const BeamSolution& solution,
         const PhysicalResults* physical,
         const BeamRequestNames& names) {
  const BeamProblem& problem = input.problem;
  J out;
  out["method"] = to_string(solution.method);
  out["method_reason"] = solution.method_reason;
  // The relative tip error the method is known to stay within (null where none is known: the chain
  // algorithm, the PRBM off its measured map).
  out["expected_error"] =
      std::isfinite(solution.expected_error) ? J(solution.expected_error) : J(nullptr);
  out["expected_error_per_length"] = std::isfinite(solution.expected_error_per_length)
                                         ? J(solution.expected_error_per_length)
                                         : J(nullptr);
  // Howell's parameters; null for a chain that has none (not one uniform straight beam).
  out["n"] = number_or_null<J>(solution.load_ratio_n);
  out["alpha2"] = number_or_null<J>(solution.alpha2);
  out["mu"] = number_or_null<J>(solution.mu);
  out["a_over_l"] = solution.tip.a_over_l;
  out["b_over_l"] = solution.tip.b_over_l;
  out["theta0"] = solution.tip.theta0;
  out["iterations"] = solution.iterations;
  out["converged"] = solution.converged();
  out["branch"] = solution.branch;
  out["inflection_points"] = solution.inflection_points;
  out["root_moment"] = number_or_null<J>(solution.root_moment);
  out["limit_points"] = solution.limit_points;
  out["target_residual"] =
      std::isfinite(solution.target_residual) ? J(solution.target_residual) : J(nullptr);
  out["first_limit_load_factor"] =
      solution.limit_points > 0 ? J(solution.first_limit_load_factor) : J(nullptr);
  out["special_points"] = special_points<J>(problem, solution);
  out["family"] = solution.family;
  out["message"] = solution.message;
  out["termination"] = std::string(termination_name(solution.termination));
  out["boundary"] = to_string(problem.boundary);
  out["reactions"] = reaction<J>(solution.reactions);
  add_stability(out, solution.stability);
  out["stable_search"] = problem.stable ? J(solution.stable_search) : J(nullptr);
  if (input.chain) {
    // The chain's loads in the file's own units, whether or not it has Howell's parameters.
    out["tip_load_chain_units"] = reaction<J>(solution.chain_tip_load);
    out["root_moment_chain_units"] = solution.chain_root_moment;
    out["reactions_chain_units"] = reaction<J>(solution.chain_reactions);
  }
  if (solution.method == BeamMethod::kPrbm) {
    // PRBM validity as a result, not a phrase: the PRB angle, the limit and the verdict.
    out["within_validity"] = solution.prbm_inside_validity;
    out["Theta"] = solution.prbm_Theta;
    out["theta_max"] = solution.prbm_theta_max;
    out["validity_source"] = solution.prbm_limits_source;
  }
  if (solution.method == BeamMethod::kChain) {
    out["elements"] = solution.elements;
    out["increments"] = solution.increments;
  }
  if (solution.method == BeamMethod::kPrbm3r) out["constants"] = solution.model_constants;
  if (solution.method == BeamMethod::kBcm || solution.method == BeamMethod::kCbcm) {
    // The BCM's validity as a result: the largest element deflection against its stated 0.1.
    out["elements"] = solution.elements;
    out["max_element_deflection"] = solution.max_element_deflection;
    out["within_validity"] = solution.model_inside_validity;
    out["slenderness"] = solution.slenderness > 0.0 ? J(solution.slenderness) : J(nullptr);
    // d = EA L^2/EI solved with (a chain segment's EA or the slenderness); null: inextensible.
    out["axial_stiffness_d"] =
        std::isfinite(solution.axial_stiffness_d) ? J(solution.axial_stiffness_d) : J(nullptr);
  }
  if (problem.shape_points > 0) {
    J shape = J::array();
    for (const ShapePoint& p : solution.shape) {
      J point;
      point["s"] = p.s;
      point["x"] = p.x;
      point["y"] = p.y;
      point["theta"] = p.theta;
      shape.push_back(std::move(point));
    }
    if (!physical && !problem.chain && solution.shape.size() >= 2) {
      // Howell's beam: the internal forces per unit EI/l^2 (N, V) and EI/l (m) from the statics
      // of the part before each point (the clamp's reaction), as for a physical beam.
      const ShapeInternalForces f = shape_internal_forces(
          uniform_cantilever(EndLoad{0.0, 0.0, 0.0}), solution.shape, solution.reactions);
      for (std::size_t i = 0; i < f.moment.size() && i < solution.shape.size(); ++i) {
        shape[i]["N"] = f.axial[i];
        shape[i]["V"] = f.shear[i];
        shape[i]["m"] = f.moment[i];
      }
    }
    if (physical) {
      // The same points in SI: s, x, y in metres, the bending moment and stress.
      for (std::size_t i = 0; i < physical->shape.size() && i < solution.shape.size(); ++i) {
        const PhysicalShapePoint& p = physical->shape[i];
        shape[i]["s_m"] = p.s;
        shape[i]["x_m"] = p.x;
        shape[i]["y_m"] = p.y;
        shape[i]["moment_Nm"] = p.moment;
        shape[i]["stress_Pa"] = optional_number<J>(p.stress);
        shape[i]["axial_force_N"] = p.axial_force;
        // Internal forces (docs/units.md "Internal forces"): N, V, m and the fibre stresses
        // N/A -+ m c/I (null where the section's area or thickness is not given).
        shape[i]["N_N"] = p.axial_force;
        shape[i]["V_N"] = p.shear_force;
        shape[i]["m_Nm"] = p.moment;
        shape[i]["stress_pos_fibre_Pa"] = optional_number<J>(p.stress_pos_fibre);
        shape[i]["stress_neg_fibre_Pa"] = optional_number<J>(p.stress_neg_fibre);
        if (!p.stress_pos_fibre) {
          shape[i]["stress_note"] =
              "stress unavailable: the section's area and thickness are not given (EI or I alone)";
        }
      }
    }
    out["shape"] = std::move(shape);
  }
  if (physical) add_physical(out, input, *physical);
  J warnings = J::array();
  for (const Warning& w : beam_answer_warnings(problem, solution, names)) {
    warnings.push_back(w.text);
  }
  out["warnings"] = std::move(warnings);
  return out;
}

// What a failed solve reached (the `reached` object of the JSON error, NoConvergence.reached in
// Python), null where not a number: method, method_reason, termination, iterations, load_factor,
// alpha2, target_residual (when finite), the stability keys (when judged or failed to judge),
// stable_search (with --stable), suggested_methods (the caller's advice, most capable first).
template <class J>
J failure(const BeamProblem& problem,
          const BeamSolution& solution,
          const std::vector<BeamMethod>& suggested_methods) {
  J reached;
  reached["method"] = to_string(solution.method);
  reached["method_reason"] = solution.method_reason;
  reached["termination"] = std::string(termination_name(solution.termination));
  reached["iterations"] = solution.iterations;
  reached["load_factor"] =
      std::isfinite(solution.load_factor) ? J(solution.load_factor) : J(nullptr);
  reached["alpha2"] = std::isfinite(solution.alpha2) ? J(solution.alpha2) : J(nullptr);
  if (std::isfinite(solution.target_residual))
    reached["target_residual"] = solution.target_residual;
  if (solution.stability.kind != StabilityKind::kNotChecked) {
    add_stability(reached, solution.stability);
  }
  if (problem.stable) reached["stable_search"] = solution.stable_search;
  J suggested = J::array();
  for (BeamMethod m : suggested_methods) suggested.push_back(to_string(m));
  reached["suggested_methods"] = std::move(suggested);
  return reached;
}

}  // namespace flexure::beam_keys
