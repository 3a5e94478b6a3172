// What is checked against what: flexure's own Carlson integrals R_F and R_D against values
// computed independently with mpmath (elliprf, elliprd at 40 significant digits), over the
// arguments the elastica produces: one argument zero (complete integrals), two arguments near zero
// (the logarithmic singularity at the separatrix, down to 1e-30), very unequal arguments and equal
// ones; R_F and R_D from one shared duplication sequence likewise. Tolerance: 1e-15 relative (a few
// units in the last place; GSL's implementation of the same method is as close). Arguments outside
// the domain (negative, two zeros, NaN) are refused.
#include "flexure/solver/elliptic/carlson_integrals.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexure/solver/common/status.h"

namespace flexure::elliptic {
namespace {

constexpr double kRelTol = 1e-15;

struct Case {
  double x, y, z, value;
};

TEST(CarlsonIntegrals, RfMatchesMpmath) {
  const Case cases[] = {
      {0, 1e-30, 1, 35.92507075603057583744},
      {0, 1e-08, 1, 10.59663475708766030979},
      {0, 0.5, 1, 1.854074677301371918434},
      {0, 1, 1, 1.570796326794896619231},
      {1, 2, 3, 0.7269459354689081985396},
      {0.3, 1e-20, 0.9, 2.138710681146835517614},
      {2.5e-17, 0.25, 1, 2.156515637499643295991},
      {1e-300, 1, 1, 1.570796326794896619231},
      {0.7, 0.7, 0.7, 1.195228609334393677882},
      {1e-05, 1e-05, 1, 6.44963966131461189841},
      {4, 0, 9, 0.6347471389816664949232},
  };
  for (const Case& c : cases) {
    EXPECT_NEAR(carlson_rf(c.x, c.y, c.z), c.value, kRelTol * c.value)
        << "R_F(" << c.x << ", " << c.y << ", " << c.z << ")";
  }
}

TEST(CarlsonIntegrals, RdMatchesMpmath) {
  const Case cases[] = {
      {0, 1e-30, 1, 104.7752122680917275123},
      {0, 1e-08, 1, 28.78990440771250347494},
      {0, 0.5, 1, 3.020584777522178495482},
      {0, 2, 1, 1.79721035210338831116},
      {1, 2, 3, 0.2904602810289906442327},
      {0.3, 1e-20, 0.9, 4.046519815739458535344},
      {2.5e-17, 0.25, 1, 3.781838449724735071472},
      {0.7, 0.7, 0.7, 1.707469441906276791013},
      {1e-05, 1e-05, 1, 16.34908247476858338108},
      {1, 1e-10, 1e-10, 14999999983.19089048266},
  };
  for (const Case& c : cases) {
    EXPECT_NEAR(carlson_rd(c.x, c.y, c.z), c.value, kRelTol * c.value)
        << "R_D(" << c.x << ", " << c.y << ", " << c.z << ")";
  }
}

TEST(CarlsonIntegrals, BothFromOneDuplicationMatchMpmath) {
  struct Pair {
    double x, y, z, rf, rd;
  };
  const Pair cases[] = {
      {0, 1e-30, 1, 35.92507075603057583744, 104.7752122680917275123},
      {0, 0.5, 1, 1.854074677301371918434, 3.020584777522178495482},
      {1, 2, 3, 0.7269459354689081985396, 0.2904602810289906442327},
      {0.3, 1e-20, 0.9, 2.138710681146835517614, 4.046519815739458535344},
      {2.5e-17, 0.25, 1, 2.156515637499643295991, 3.781838449724735071472},
      {1e-05, 1e-05, 1, 6.44963966131461189841, 16.34908247476858338108},
  };
  for (const Pair& c : cases) {
    const CarlsonPair both = carlson_rf_rd(c.x, c.y, c.z);
    EXPECT_NEAR(both.rf, c.rf, kRelTol * c.rf)
        << "R_F(" << c.x << ", " << c.y << ", " << c.z << ")";
    EXPECT_NEAR(both.rd, c.rd, kRelTol * c.rd)
        << "R_D(" << c.x << ", " << c.y << ", " << c.z << ")";
  }
}

TEST(CarlsonIntegrals, RefuseArgumentsOutsideTheDomain) {
  EXPECT_THROW(carlson_rf(0.0, -0.0, 1.0), NoConvergence);  // two zeros
  EXPECT_THROW(carlson_rf(-1e-3, 1.0, 1.0), NoConvergence);
  EXPECT_THROW(carlson_rd(0.0, 0.0, 1.0), NoConvergence);
  EXPECT_THROW(carlson_rd(1.0, 1.0, 0.0), NoConvergence);
  EXPECT_THROW(carlson_rf(std::nan(""), 1.0, 1.0), NoConvergence);
}

}  // namespace
}  // namespace flexure::elliptic
