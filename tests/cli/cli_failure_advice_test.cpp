// What is checked against what: the failure messages of `flexure beam` and `flexure sweep beam`
// (issue 27, "failures that help") through the built tool.
//  * The reproducer `beam --alpha2 5e4` (and the same load by the chain algorithm) says
//    that no method is measured to reach it and asks for a smaller load: no "--method" hint, and
//    the refusal of the elliptic solver no longer promises that the shooting method "has no fixed
//    range".
//  * Where a method is suggested, the suggested method is run on the same problem and must answer
//    (exit 0): the advice is tested, not only printed. Each case asserts the key words and the
//    exit code.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

bool has(const std::string& text, const std::string& words) {
  return text.find(words) != std::string::npos;
}

TEST(FailureAdviceCli, LoadBeyondEveryMethodAsksForASmallerLoad) {
  const CommandResult auto_run = run_flexure("beam --alpha2 5e4");
  EXPECT_EQ(auto_run.exit_code, 3) << auto_run.err;
  EXPECT_TRUE(has(auto_run.err, "No method of flexure is measured to solve |F| l^2/EI = 5e4"))
      << auto_run.err;
  EXPECT_TRUE(has(auto_run.err, "Try a smaller load")) << auto_run.err;
  EXPECT_FALSE(has(auto_run.err, "--method")) << auto_run.err;
  const CommandResult chain = run_flexure("beam --alpha2 5e4 --method chain");
  EXPECT_EQ(chain.exit_code, 3) << chain.err;
  EXPECT_TRUE(has(chain.err, "Try a smaller load")) << chain.err;
  EXPECT_FALSE(has(chain.err, "--method shooting")) << chain.err;
  // The elliptic solver refuses (exit 2) and says what the others are measured to do.
  const CommandResult elliptic = run_flexure("beam --alpha2 5e4 --method elliptic");
  EXPECT_EQ(elliptic.exit_code, 2) << elliptic.err;
  EXPECT_TRUE(has(elliptic.err, "no method of flexure is measured to reach it")) << elliptic.err;
  EXPECT_FALSE(has(elliptic.err, "no fixed range")) << elliptic.err;
  // Within the shooting method's reach the refusal names it, and it answers.
  const CommandResult near = run_flexure("beam --alpha2 2e4 --method elliptic");
  EXPECT_EQ(near.exit_code, 2) << near.err;
  EXPECT_TRUE(has(near.err, "the shooting method is measured to converge up to")) << near.err;
  EXPECT_EQ(run_flexure("beam --alpha2 2e4 --method shooting").exit_code, 0);
}

// A suggestion, then the suggested method on the same problem: it must answer.
void expect_suggestion_answers(const std::string& problem,
                               const std::string& failing,
                               const std::string& suggested) {
  const CommandResult failed = run_flexure("beam " + problem + " --method " + failing + " --json");
  ASSERT_EQ(failed.exit_code, 3) << problem << " " << failing << ": " << failed.out;
  const nlohmann::json e = nlohmann::json::parse(failed.out);
  const std::string message = e.value("error", "");
  EXPECT_TRUE(has(message, "(--method " + suggested + ")")) << message;
  ASSERT_TRUE(e.contains("suggested_methods")) << failed.out;
  EXPECT_EQ(e["suggested_methods"].at(0), suggested) << failed.out;
  const CommandResult answered = run_flexure("beam " + problem + " --method " + suggested);
  EXPECT_EQ(answered.exit_code, 0) << problem << " by " << suggested << ": " << answered.err;
}

TEST(FailureAdviceCli, SuggestedMethodsAnswer) {
  // A large end moment with a tip force: the continuation loses the path, the closed form does not.
  expect_suggestion_answers("--alpha2 100 --mu -500", "shooting", "elliptic");
  // A follower force of 200: the shooting continuation runs out of steps, the chain algorithm
  // takes its own increments.
  expect_suggestion_answers("--alpha2 0 --follower 200", "shooting", "chain");
  // A pinned tip the chain algorithm does not reach from the straight beam: the shooting method.
  expect_suggestion_answers(
      "--alpha2 0 --boundary pinned --tip-x 0 --tip-y 0.5", "chain", "shooting");
}

TEST(FailureAdviceCli, WithoutAMethodToTrySaysWhatToChange) {
  // A follower force of 2000 is beyond what either method is measured to follow (shooting about
  // 100, the chain algorithm about 500): neither is suggested.
  const CommandResult follower = run_flexure("beam --alpha2 0 --follower 2000 --method shooting");
  EXPECT_EQ(follower.exit_code, 3) << follower.err;
  EXPECT_TRUE(has(follower.err, "Try a smaller follower force")) << follower.err;
  EXPECT_FALSE(has(follower.err, "--method")) << follower.err;
  // A straight clamped-clamped beam pushed to half its length: no method reaches it from the
  // straight state; the message says what to change in the prescribed tip.
  const CommandResult tip =
      run_flexure("beam --alpha2 0 --boundary fixed --tip-x 0.5 --tip-y 0.001 --method shooting");
  EXPECT_EQ(tip.exit_code, 3) << tip.err;
  EXPECT_TRUE(has(tip.err, "Try a tip nearer the unloaded one")) << tip.err;
  EXPECT_TRUE(has(tip.err, "a tip offset across the beam (tip y)")) << tip.err;
  EXPECT_FALSE(has(tip.err, "--method")) << tip.err;
}

TEST(FailureAdviceCli, SweepNamesTheFirstFailureAndWhatToTry) {
  ScratchDir dir;
  const CommandResult r =
      run_flexure("sweep beam --method shooting --alpha2 4e4:5e4:2 --out s.h5", dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(has(r.err, "the first is")) << r.err;
  EXPECT_TRUE(has(r.err, "Try a smaller load")) << r.err;
  EXPECT_FALSE(has(r.err, "--method chain")) << r.err;
}

}  // namespace
}  // namespace flexure::test
