#include "flexure/mechanisms/design/subclass_rederivation.h"

#include <chrono>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"
#include "flexure/mechanisms/design/subclass_problem.h"

namespace flexure::design {

std::vector<const cfm::CfmSubclass*> thesis_rows(const std::string& config) {
  if (!config.empty()) cfm::find_cfm_configuration(config);  // throws
  std::vector<const cfm::CfmSubclass*> rows;
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    if (config.empty() || config == row.config) rows.push_back(&row);
  }
  return rows;
}

SubclassRederivation rederive_subclass(const cfm::CfmSubclass& row,
                                       const RederivationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const SubclassProblem sp = subclass_problem(row);
  const CfmDesignProblem& p = sp.problem;
  SubclassRederivation r;
  r.name = row.name;
  r.config = row.config;
  r.stroke_percent = p.stroke_percent;
  r.objective = p.objective;
  r.printed_objective =
      objective_value(p, cfm::CfmModel(p.model).evaluate(parameters_at(p, sp.printed)));
  r.prbm = synthesize_cfm(p, options.synthesis);
  if (options.exact) {
    std::vector<std::vector<double>> starts;
    if (!r.prbm.x.empty()) starts.push_back(r.prbm.x);
    const auto [R_lo, R_hi] = toggle_R_interval(p.stroke_percent);
    if (row.R >= R_lo && row.R <= R_hi) starts.push_back(sp.printed);
    ExactRefinementOptions o;
    o.sequence_starts =
        options.exact_starts >= 0 ? options.exact_starts : static_cast<int>(2 * sp.printed.size());
    r.printed_percent_constant_force_exact =
        exact_percent_constant_force(p, sp.printed, o.confirm_points, o.work_budget);
    if (!starts.empty()) {
      const CfmExactRefinement e = refine_cfm_exact(p, starts, o);
      r.exact_evaluations = e.evaluations;
      r.exact_message = e.message;
      if (e.converged()) {
        r.percent_constant_force_exact = e.percent_constant_force_exact;
        r.exact_R = e.prbm.result.R;
        r.exact_K1 = e.prbm.result.K1;
        r.exact_K2 = e.prbm.result.K2;
      }
    } else {
      r.exact_message = "no start inside the bounds";
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::vector<SubclassRederivation> rederive_subclasses(
    const RederivationOptions& options,
    const std::function<void(std::size_t, std::size_t)>& progress) {
  options.synthesis.validate();
  const std::vector<const cfm::CfmSubclass*> rows = thesis_rows(options.config);
  std::vector<SubclassRederivation> out;
  out.reserve(rows.size());
  for (const cfm::CfmSubclass* row : rows) {
    out.push_back(rederive_subclass(*row, options));
    if (progress) progress(out.size(), rows.size());
  }
  return out;
}

}  // namespace flexure::design
