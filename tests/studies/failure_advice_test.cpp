// What is checked against what: the advice after a failed beam solve (failure_advice.h).
//  * Never in circles: on a grid of problems of every regime (free cantilever with dead loads and
//    moments, guided end, prescribed tips, follower forces; loads inside and beyond the measured
//    reaches), the graph "X failed -> Y suggested" has no cycle, no method is suggested after
//    itself or after auto has tried it, and the PRBM is never suggested.
//  * A method is suggested only within its measured reach; beyond every reach the advice names the
//    load and the reaches and asks for a smaller load.
//  * Whether a suggested method really answers is checked through the tool
//    (tests/cli/cli_failure_advice_test.cpp).
#include "flexure/benchmarks/studies/failure_advice.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace flexure {
namespace {

BeamProblem problem(double alpha2, double n, double mu, EndCondition end, double follower) {
  BeamProblem p;
  p.value = alpha2;
  p.load_ratio_n = n;
  p.mu = mu;
  p.boundary = end;
  p.follower = follower;
  return p;
}

std::vector<BeamProblem> grid() {
  std::vector<BeamProblem> problems;
  for (double alpha2 : {0.0, 5.0, 500.0, 9e3, 2e4, 3.2e4, 5e4, 2e5}) {
    for (double n : {-1.0, 0.0, 2.0}) {
      for (double mu : {0.0, 300.0, 2e4}) {
        for (EndCondition end : {EndCondition::kFree,
                                 EndCondition::kGuided,
                                 EndCondition::kPinned,
                                 EndCondition::kFixed}) {
          for (double follower : {0.0, 50.0, 200.0, 2000.0}) {
            problems.push_back(problem(alpha2, n, mu, end, follower));
          }
        }
      }
    }
  }
  return problems;
}

BeamSolution failed_with(BeamMethod m) {
  BeamSolution s;
  s.method = m;
  s.methods_tried = {m};
  return s;
}

const std::vector<BeamMethod> kMethods = {
    BeamMethod::kElliptic, BeamMethod::kShooting, BeamMethod::kChain, BeamMethod::kPrbm};

TEST(FailureAdvice, NeverLeadsBackToAMethodThatFailed) {
  int problems_with_advice = 0;
  for (const BeamProblem& p : grid()) {
    std::map<BeamMethod, std::vector<BeamMethod>> next;
    for (BeamMethod x : kMethods) {
      const BeamFailureAdvice a = advise_after_failure(p, failed_with(x), {x});
      EXPECT_FALSE(a.text.empty());
      EXPECT_EQ(a.reasons.size(), a.methods.size());
      for (BeamMethod y : a.methods) {
        EXPECT_NE(y, x) << to_string(x);
        EXPECT_NE(y, BeamMethod::kPrbm);
      }
      next[x] = a.methods;
      problems_with_advice += a.methods.empty() ? 0 : 1;
    }
    // No cycle: follow every path of suggestions from every method; none returns to a method on
    // its path (at most four methods, so a depth-first walk is cheap).
    const std::function<void(BeamMethod, std::set<BeamMethod>)> walk =
        [&](BeamMethod m, std::set<BeamMethod> path) {
          ASSERT_EQ(path.count(m), 0u)
              << "circle through " << to_string(m) << " at alpha2 " << p.value << " n "
              << p.load_ratio_n << " mu " << p.mu << " end " << to_string(p.boundary)
              << " follower " << p.follower;
          path.insert(m);
          for (BeamMethod y : next[m]) walk(y, path);
        };
    for (BeamMethod x : kMethods) walk(x, {});
    // auto: after the elliptic solver and the shooting method, neither is suggested again.
    BeamSolution fallback = failed_with(BeamMethod::kShooting);
    fallback.methods_tried = {BeamMethod::kElliptic, BeamMethod::kShooting};
    for (BeamMethod y : advise_after_failure(p, fallback, fallback.methods_tried).methods) {
      EXPECT_EQ(y, BeamMethod::kChain);
    }
  }
  EXPECT_GT(problems_with_advice, 100);
}

TEST(FailureAdvice, BeyondEveryReachAsksForASmallerLoad) {
  // Issue 27: `flexure beam --alpha2 5e4` (auto: elliptic refused, shooting failed).
  BeamSolution s = failed_with(BeamMethod::kShooting);
  s.methods_tried = {BeamMethod::kElliptic, BeamMethod::kShooting};
  BeamFailureAdvice a = advise_after_failure(problem(5e4, 0, 0, EndCondition::kFree, 0), s, {});
  EXPECT_TRUE(a.methods.empty());
  EXPECT_NE(a.text.find("No method of flexure is measured to solve |F| l^2/EI = 5e4"),
            std::string::npos)
      << a.text;
  EXPECT_NE(a.text.find("smaller load"), std::string::npos) << a.text;
  // The chain algorithm at the same load: the shooting method is not sent back to.
  a = advise_after_failure(problem(5e4, 0, 0, EndCondition::kFree, 0),
                           failed_with(BeamMethod::kChain),
                           {BeamMethod::kChain});
  EXPECT_TRUE(a.methods.empty()) << a.text;
  // Within the shooting method's reach the chain algorithm's failure is sent to it.
  a = advise_after_failure(problem(2e4, 0, 0, EndCondition::kGuided, 0),
                           failed_with(BeamMethod::kChain),
                           {BeamMethod::kChain});
  EXPECT_EQ(a.methods, std::vector<BeamMethod>{BeamMethod::kShooting});
  // A follower force beyond the shooting continuation's reach: the chain algorithm, and after it
  // nothing but a smaller follower force.
  a = advise_after_failure(problem(0, 0, 0, EndCondition::kFree, 200),
                           failed_with(BeamMethod::kShooting),
                           {BeamMethod::kShooting});
  EXPECT_EQ(a.methods, std::vector<BeamMethod>{BeamMethod::kChain});
  a = advise_after_failure(problem(0, 0, 0, EndCondition::kFree, 200),
                           failed_with(BeamMethod::kChain),
                           {BeamMethod::kChain});
  EXPECT_TRUE(a.methods.empty());
  EXPECT_NE(a.text.find("smaller follower force"), std::string::npos) << a.text;
  // A prescribed tip: after the shooting method, what to change in the tip.
  a = advise_after_failure(problem(0, 0, 0, EndCondition::kFixed, 0),
                           failed_with(BeamMethod::kShooting),
                           {BeamMethod::kShooting});
  EXPECT_TRUE(a.methods.empty());
  EXPECT_NE(a.text.find("a tip nearer the unloaded one"), std::string::npos) << a.text;
}

TEST(FailureAdvice, LoadText) {
  EXPECT_EQ(load_text(35000.0), "3.5e4");
  EXPECT_EQ(load_text(1e4), "1e4");
  EXPECT_EQ(load_text(500.0), "500");
  EXPECT_EQ(load_text(123456.0), "1.235e5");
}

}  // namespace
}  // namespace flexure
