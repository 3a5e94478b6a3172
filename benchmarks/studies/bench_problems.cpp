#include "flexure/benchmarks/studies/bench_problems.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::bench {
namespace {

std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

std::vector<double> linspace(double first, double last, int count) {
  std::vector<double> v;
  for (int i = 0; i < count; ++i) v.push_back(first + (last - first) * i / (count - 1));
  return v;
}

}  // namespace

const char* to_string(MethodFamily family) {
  switch (family) {
    case MethodFamily::kElliptic:
      return "elliptic";
    case MethodFamily::kShooting:
      return "shooting";
    case MethodFamily::kChain:
      return "chain";
    case MethodFamily::kPrbm:
      return "prbm";
    case MethodFamily::kMechanismExact:
      return "exact";
  }
  return "unknown";
}

std::vector<BenchProblem> standard_problems(bool quick) {
  std::vector<BenchProblem> problems;
  {
    // Howell's load plane (eq. 2.83): the stability maps are drawn over (n, alpha2).
    BenchProblem p{"cantilever_force",
                   "Cantilever, tip force Fx = -n alpha2, Fy = alpha2 (Howell eq. 2.83)",
                   EndCondition::kFree,
                   {},
                   ""};
    const std::vector<double> alpha2s =
        quick ? std::vector<double>{1.0, 5.0, 20.0}
              : std::vector<double>{0.5, 1, 2, 3, 4, 5, 7.5, 10, 12.5, 15, 17.5, 20};
    for (double n : {-2.0, -1.0, 0.0, 1.0, 3.0}) {
      for (double a : alpha2s) p.points.push_back({n, a, 0.0});
    }
    problems.push_back(p);
  }
  {
    // mu = 2 pi rolls the beam into a full circle (Howell eq. 2.59).
    BenchProblem p{"tip_moment",
                   "Cantilever, pure tip moment mu = M l/EI up to 2 pi (circular arc, Howell eq. "
                   "2.59)",
                   EndCondition::kFree,
                   {},
                   ""};
    for (double mu : linspace(
             2.0 * std::numbers::pi / (quick ? 3 : 12), 2.0 * std::numbers::pi, quick ? 3 : 12)) {
      p.points.push_back({0.0, 0.0, mu});
    }
    problems.push_back(p);
  }
  {
    BenchProblem p{"force_and_moment",
                   "Cantilever, transverse tip force alpha2 with a tip moment mu = -alpha2/4 "
                   "(n = 0): the moment opposes the force, the shape has an inflection point",
                   EndCondition::kFree,
                   {},
                   ""};
    for (double a : quick ? linspace(2.0, 10.0, 2) : linspace(1.0, 12.0, 12)) {
      p.points.push_back({0.0, a, -0.25 * a});
    }
    problems.push_back(p);
  }
  {
    BenchProblem p{"fixed_guided",
                   "Fixed-guided beam: tip held at theta = 0, transverse force alpha2 (Howell "
                   "§5.3)",
                   EndCondition::kGuided,
                   {},
                   ""};
    for (double a : quick ? linspace(5.0, 20.0, 2) : linspace(2.0, 40.0, 12)) {
      p.points.push_back({0.0, a, 0.0});
    }
    problems.push_back(p);
  }
  {
    // n = 50: a compressive load n alpha2 from 1 to 20 (Euler load pi^2/4 = 2.47) with a
    // 2 % lateral imperfection force; past 2.47 the column deflects far sideways.
    BenchProblem p{"post_buckled_column",
                   "Cantilever column, axial compression P = 50 alpha2 from 0.4 to 8 Euler "
                   "loads (pi^2/4) with a lateral force alpha2 = P/50",
                   EndCondition::kFree,
                   {},
                   ""};
    for (double P : quick ? linspace(2.0, 15.0, 2) : linspace(1.0, 20.0, 12)) {
      p.points.push_back({50.0, P / 50.0, 0.0});
    }
    problems.push_back(p);
  }
  {
    // Thesis design example 1 (Weight 2001, Table 8.4): the slider travels its whole stroke.
    BenchProblem p{"cfm_stroke",
                   "Constant-force mechanism 1A-lpp (thesis design example 1), slider input "
                   "force over the stroke Delta x = k stroke/K, k = 1..K",
                   EndCondition::kFree,
                   {},
                   "1A-lpp"};
    const mechanism::MechanismDesign design = mechanism::find_builtin_mechanism(p.mechanism);
    for (double dx :
         mechanism::stroke_displacements(design, quick ? kCfmQuickPoints : kCfmPoints)) {
      LoadPoint load;
      load.displacement = dx;
      p.points.push_back(load);
    }
    problems.push_back(p);
  }
  return problems;
}

std::vector<BenchMethod> standard_methods(bool quick) {
  using Backend = ElasticaIntegrator::Backend;
  std::vector<BenchMethod> methods;
  methods.push_back({"elliptic", MethodFamily::kElliptic});
  const std::vector<double> rtols =
      quick ? std::vector<double>{1e-8} : std::vector<double>{1e-6, 1e-9, 1e-12};
  // rk8pd is the default integrator; CVODES the reference; Dormand-Prince the former built-in.
  const std::pair<Backend, const char*> backends[] = {
      {Backend::kRk8pd, "rk8pd"}, {Backend::kCvodes, "cvodes"}, {Backend::kDormandPrince, "dopri"}};
  for (const auto& [backend, backend_name] : backends) {
    for (double rtol : rtols) {
      BenchMethod m;
      m.family = MethodFamily::kShooting;
      m.backend = backend;
      m.rtol = rtol;
      m.name = fmt::format("shooting_{}_rtol{:.0e}", backend_name, rtol);
      methods.push_back(m);
    }
  }
  const std::vector<int> Ns =
      quick ? std::vector<int>{10, 50} : std::vector<int>{10, 20, 50, 100, 200};
  const std::vector<int> incs = quick ? std::vector<int>{5} : std::vector<int>{1, 5, 20};
  for (int N : Ns) {
    for (int inc : incs) {
      BenchMethod m;
      m.family = MethodFamily::kChain;
      m.elements = N;
      m.increments = inc;
      m.name = fmt::format("chain_N{:03d}_inc{:02d}", N, inc);
      methods.push_back(m);
    }
  }
  methods.push_back({"prbm", MethodFamily::kPrbm});
  methods.push_back({"exact", MethodFamily::kMechanismExact});
  return methods;
}

bool method_applies(const BenchMethod& method, const BenchProblem& problem) {
  // The mechanism assembler has a PRBM and an exact (shooting) model of a whole mechanism; the
  // beam solvers take one beam and are not run on it.
  if (problem.is_mechanism()) {
    return method.family == MethodFamily::kPrbm || method.family == MethodFamily::kMechanismExact;
  }
  switch (method.family) {
    case MethodFamily::kMechanismExact:
      return false;
    case MethodFamily::kElliptic:
      return problem.elliptic_applies();
    case MethodFamily::kPrbm:
      // Howell's elements: fixed-pinned (tip force), end-moment, fixed-guided. No element takes a
      // tip force and moment together.
      return problem.name != "force_and_moment";
    default:
      return true;
  }
}

std::vector<BenchProblem> select_problems(const std::vector<BenchProblem>& all,
                                          const std::string& list) {
  if (list.empty() || list == "all") return all;
  std::vector<BenchProblem> out;
  std::vector<std::string> names;
  for (const auto& p : all) names.push_back(p.name);
  for (const std::string& want : split_list(list)) {
    auto it = std::find_if(all.begin(), all.end(), [&](const auto& p) { return p.name == want; });
    if (it == all.end()) {
      throw InvalidInput(fmt::format(
          "--problems: unknown problem '{}' (allowed: {})", want, fmt::join(names, ", ")));
    }
    out.push_back(*it);
  }
  return out;
}

std::vector<BenchMethod> select_methods(const std::vector<BenchMethod>& all,
                                        const std::string& list) {
  if (list.empty() || list == "all") return all;
  std::set<std::string> wanted;
  for (const std::string& w : split_list(list)) wanted.insert(w);
  std::vector<BenchMethod> out;
  for (const BenchMethod& m : all) {
    if (wanted.count(m.name) || wanted.count(to_string(m.family))) out.push_back(m);
  }
  for (const std::string& w : wanted) {
    const bool known = std::any_of(all.begin(), all.end(), [&](const BenchMethod& m) {
      return m.name == w || w == to_string(m.family);
    });
    if (!known) {
      std::vector<std::string> names{"elliptic", "shooting", "chain", "prbm", "exact"};
      for (const auto& m : all) {
        if (m.family == MethodFamily::kShooting || m.family == MethodFamily::kChain) {
          names.push_back(m.name);
        }
      }
      throw InvalidInput(
          fmt::format("--methods: unknown method '{}' (allowed: {})", w, fmt::join(names, ", ")));
    }
  }
  return out;
}

}  // namespace flexure::bench
