// Howell's chain algorithm as the model of a flexure of a general mechanism (`--model mixed`,
// model = "chain" with `elements`; solve_general_mixed, general_analysis.h; docs/mechanisms.md "A
// model per flexure"): the shipped parallel guide with both flexures `chain` against the same
// mechanism with both exact, the error falling with the chain's N at its measured order, and an
// invalid `elements` refused naming the flexure and the file line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

std::string example_path(const std::string& file = "parallel_guide.toml") {
  return std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/" + file;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The parallel guide (two fixed-guided Delrin flexures, stage x over +-4 mm = +-0.18 l) with
// every flexure under `model` (`elements`: 0, the model's default).
GeneralMechanism guide(FlexureModel model,
                       int elements = 0,
                       const std::string& file = "parallel_guide.toml") {
  GeneralMechanism m = load_general_mechanism_toml(example_path(file));
  set_flexure_model(m, "", model, 0.0, elements);
  return m;
}

// The largest |input load - exact's| over the points, per the exact's largest |input load|.
double load_error(const GeneralPrbmResult& r, const GeneralPrbmResult& exact) {
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < exact.points.size(); ++i) {
    worst = std::max(worst, std::fabs(r.points[i].input_load - exact.points[i].input_load));
    scale = std::max(scale, std::fabs(exact.points[i].input_load));
  }
  return worst / scale;
}

TEST(GeneralChainFlexure, NamesAndDefaults) {
  EXPECT_EQ(parse_flexure_model("chain"), FlexureModel::kChain);
  EXPECT_EQ(flexure_model_name(FlexureModel::kChain), "chain");
  Flexure f;
  f.model = FlexureModel::kChain;
  EXPECT_EQ(f.model_elements(), 100);  // as `flexure beam --method chain`
  f.model = FlexureModel::kCbcm;
  EXPECT_EQ(f.model_elements(), 6);  // the error map's CBCM
  // The chain is not on the model ladder's error maps: no mapped error, so auto never picks it.
  EXPECT_TRUE(std::isnan(mapped_flexure_error(FlexureModel::kChain, 100, {0.0, 1.0, 0.0})));
  EXPECT_EQ(std::count(auto_ladder().begin(), auto_ladder().end(), FlexureModel::kChain), 0);
}

// One cantilever under tip loads: the chain's tip converges on the elliptic solution's at its own
// order (docs/theory-chain.md: the corrected variant's error is third order in 1/N; measured
// here on the mixed model's path, with the element count fixed).
TEST(GeneralChainFlexure, ModelTipConvergesOnTheElastica) {
  const FlexureTipLoad load{-0.8, 2.5, -0.6};  // compression, a transverse force, a counter moment
  FlexureTip exact;
  ASSERT_TRUE(exact_flexure_tip(load, exact));
  double previous = 0.0;
  for (int n : {25, 50, 100}) {
    FlexureTip tip;
    std::string why;
    ASSERT_TRUE(model_tip(FlexureModel::kChain, PrbmKind::kSmallLengthPivot, n, load, tip, &why))
        << why;
    const double e = std::hypot(tip.x - exact.x, tip.y - exact.y);
    std::cout << "chain N = " << n << ": tip error " << e << " l";
    if (previous > 0.0) std::cout << ", order " << std::log2(previous / e);
    std::cout << "\n";
    if (previous > 0.0) EXPECT_GT(std::log2(previous / e), 2.7) << "N = " << n;
    previous = e;
  }
  EXPECT_LT(previous, 1e-4);
}

// Every flexure `chain`: the input load at every point against the same mechanism with every
// flexure exact, the error falling with N at the chain's order, and the Richardson extrapolation
// of N = 50, 100 closer to the exact than N = 100 (an independent check that the limit is the
// exact model's). The parallel guide (two S-shaped guided strips) and Howell's fully compliant
// four-bar (three flexures, a crank over 50 deg).
void expect_converges_on_exact(const std::string& file, double lowest_order) {
  const GeneralPrbmResult exact = solve_general_mixed(guide(FlexureModel::kExact, 0, file));
  ASSERT_TRUE(exact.converged()) << exact.message;
  std::vector<GeneralPrbmResult> chain;
  std::vector<double> error;
  const int ns[] = {25, 50, 100};
  GeneralExactOptions measured;
  measured.measure_flexure_errors = true;
  for (int n : ns) {
    chain.push_back(solve_general_mixed(guide(FlexureModel::kChain, n, file), measured));
    const GeneralPrbmResult& r = chain.back();
    ASSERT_TRUE(r.converged()) << file << " N = " << n << ": " << r.message;
    ASSERT_EQ(r.points.size(), exact.points.size());
    double tip_error = 0.0;
    for (const FlexureModelReport& f : r.flexure_models) {
      EXPECT_EQ(f.model, FlexureModel::kChain);
      EXPECT_EQ(f.elements, n);
      EXPECT_NE(f.reason.find("chain algorithm"), std::string::npos) << f.reason;
      EXPECT_TRUE(std::isnan(f.expected_error_per_length));  // not on the error maps
      tip_error = std::max(tip_error, f.measured_error_per_length);
    }
    error.push_back(load_error(r, exact));
    std::cout << file << ", chain N = " << n << ": input load error " << error.back()
              << " of the largest; largest flexure tip error " << tip_error << " l\n";
    // Within the chain's own discretisation error: the relative load error no larger than the
    // largest tip error per length its flexures measure against the elastica under their loads.
    EXPECT_LE(error.back(), tip_error) << file << " N = " << n;
  }
  for (std::size_t k = 1; k < error.size(); ++k) {
    const double order = std::log2(error[k - 1] / error[k]);
    std::cout << "  order N = " << ns[k - 1] << " -> " << ns[k] << ": " << order << "\n";
    EXPECT_GT(order, lowest_order) << file << " N = " << ns[k];
  }
  // Richardson with the measured order between N = 50 and 100.
  const double w = error[1] / error[2];
  double extrapolated = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < exact.points.size(); ++i) {
    const double f = (w * chain[2].points[i].input_load - chain[1].points[i].input_load) / (w - 1);
    extrapolated = std::max(extrapolated, std::fabs(f - exact.points[i].input_load));
    scale = std::max(scale, std::fabs(exact.points[i].input_load));
  }
  std::cout << "  extrapolated error " << extrapolated / scale << "\n";
  EXPECT_LT(extrapolated / scale, 0.2 * error[2]) << file;
}

TEST(GeneralChainFlexure, ParallelGuideConvergesOnTheExactModel) {
  expect_converges_on_exact("parallel_guide.toml", 3.5);
}

TEST(GeneralChainFlexure, FullyCompliantFourbarConvergesOnTheExactModel) {
  expect_converges_on_exact("howell_fully_compliant_fourbar.toml", 2.7);
}

// An invalid element count in the file: refused with the file, the line and the flexure.
TEST(GeneralChainFlexure, InvalidElementsNameTheFlexureAndLine) {
  const std::string text = read_text(example_path());
  const std::string anchor = "prbm = \"fixed-guided\"";
  const std::size_t at = text.find(anchor);  // the first flexure, "left"
  ASSERT_NE(at, std::string::npos);
  const int line =
      static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n')) + 2;
  for (const char* bad : {"0", "-3", "2.5"}) {
    std::string edited = text;
    edited.insert(at + anchor.size(), std::string("\nmodel = \"chain\"\nelements = ") + bad);
    try {
      parse_general_mechanism_toml(edited, "guide.toml");
      ADD_FAILURE() << "elements = " << bad << " accepted";
    } catch (const InvalidInput& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("guide.toml:" + std::to_string(line + 1) + ":"), std::string::npos)
          << what;
      EXPECT_NE(what.find("flexure 'left'"), std::string::npos) << what;
      EXPECT_NE(what.find("elements"), std::string::npos) << what;
    }
  }
  // elements with a model that has none is refused too; a valid count is kept.
  std::string prbm = text;
  prbm.insert(at + anchor.size(), "\nelements = 40");
  EXPECT_THROW(parse_general_mechanism_toml(prbm, "guide.toml"), InvalidInput);
  std::string good = text;
  good.insert(at + anchor.size(), "\nmodel = \"chain\"\nelements = 40");
  const GeneralMechanism m = parse_general_mechanism_toml(good, "guide.toml");
  EXPECT_EQ(m.flexures[0].model, FlexureModel::kChain);
  EXPECT_EQ(m.flexures[0].model_elements(), 40);
  EXPECT_EQ(m.flexures[1].model, FlexureModel::kPrbm);
  // Built in C++: a negative count is refused by validate, naming the flexure.
  GeneralMechanism c = guide(FlexureModel::kChain);
  c.flexures[1].elements = -5;
  try {
    c.validate();
    ADD_FAILURE() << "elements = -5 accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("flexure 'right'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace flexure::mechanism::general
