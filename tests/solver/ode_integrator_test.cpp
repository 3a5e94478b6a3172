// What is checked against what: the general ODE integrator of the beam layer (CVODES behind
// solver/ode/ode_integrator.h) on the harmonic oscillator x'' = -omega^2 x, x(0) = 1, x'(0) = 0,
// against its closed form x = cos(omega t), x' = -omega sin(omega t), with both methods (Adams,
// BDF); the times where x crosses zero (event x = 0) against the analytic crossings
// t = (k + 1/2) pi/omega, upward only (x' > 0: t = (2k + 3/2) pi/omega), downward only and both;
// options refused naming the field; a run out of steps reported with the CVODES function and flag;
// an exception of the right-hand side reaching the caller.
#include "flexure/solver/ode/ode_integrator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

constexpr double kOmega = 3.0;  // rad/s
// rtol 1e-12 over ten periods: the global error stays near 1e-10 on states of size 1 and omega.
constexpr double kStateTolerance = 1e-8;
// An event is located on the interpolated solution: its time error is the state error / |x'|.
constexpr double kEventTolerance = 1e-8;

int oscillator(double, std::span<const double> y, std::span<double> ydot) {
  ydot[0] = y[1];
  ydot[1] = -kOmega * kOmega * y[0];
  return 0;
}

std::vector<double> times(double t_end, int count) {
  std::vector<double> t(count);
  for (int i = 0; i < count; ++i) t[i] = t_end * (i + 1) / count;
  return t;
}

double period() { return 2.0 * std::numbers::pi / kOmega; }

OdeIntegrator::Options tight(OdeIntegrator::Method method) {
  OdeIntegrator::Options options;
  options.rtol = 1e-12;
  options.atol = 1e-14;
  options.method = method;
  return options;
}

TEST(OdeIntegrator, HarmonicOscillatorMatchesClosedForm) {
  const double y0[2] = {1.0, 0.0};
  for (OdeIntegrator::Method method :
       {OdeIntegrator::Method::kAdams, OdeIntegrator::Method::kBdf}) {
    const OdeIntegrator integrator(tight(method));
    const std::vector<double> t = times(10.0 * period(), 97);
    const OdeIntegrator::Solution s = integrator.integrate(oscillator, 0.0, y0, t);
    ASSERT_TRUE(s.status.ok) << s.status.message;
    ASSERT_EQ(s.t.size(), t.size());
    ASSERT_EQ(s.y.size(), t.size());
    EXPECT_GT(s.steps, 0);
    EXPECT_TRUE(s.event_times.empty());
    for (std::size_t i = 0; i < t.size(); ++i) {
      EXPECT_DOUBLE_EQ(s.t[i], t[i]);
      ASSERT_EQ(s.y[i].size(), 2u);
      EXPECT_NEAR(s.y[i][0], std::cos(kOmega * t[i]), kStateTolerance) << "t = " << t[i];
      EXPECT_NEAR(s.y[i][1], -kOmega * std::sin(kOmega * t[i]), kOmega * kStateTolerance)
          << "t = " << t[i];
    }
  }
}

TEST(OdeIntegrator, NonzeroStartTime) {
  // x = cos(omega t) started at t0 = 1 from its value there.
  const double t0 = 1.0;
  const double y0[2] = {std::cos(kOmega * t0), -kOmega * std::sin(kOmega * t0)};
  const OdeIntegrator integrator(tight(OdeIntegrator::Method::kAdams));
  const OdeIntegrator::Solution s = integrator.integrate(oscillator, t0, y0, {t0 + 2.5});
  ASSERT_TRUE(s.status.ok) << s.status.message;
  EXPECT_NEAR(s.y[0][0], std::cos(kOmega * (t0 + 2.5)), kStateTolerance);
}

// Crossings of x = cos(omega t) = 0 in (0, t_end): t = (k + 1/2) pi/omega; x' = -omega sin is
// negative for even k (downward) and positive for odd k (upward).
std::vector<double> analytic_crossings(double t_end, OdeIntegrator::Direction direction) {
  std::vector<double> out;
  for (int k = 0;; ++k) {
    const double t = (k + 0.5) * std::numbers::pi / kOmega;
    if (t >= t_end) break;
    const bool upward = k % 2 == 1;
    if (direction == OdeIntegrator::Direction::kBoth ||
        (direction == OdeIntegrator::Direction::kUpward) == upward) {
      out.push_back(t);
    }
  }
  return out;
}

TEST(OdeIntegrator, EventTimesMatchAnalyticCrossings) {
  const double y0[2] = {1.0, 0.0};
  const double t_end = 5.3 * period();
  const OdeIntegrator integrator(tight(OdeIntegrator::Method::kAdams));
  for (OdeIntegrator::Direction direction : {OdeIntegrator::Direction::kUpward,
                                             OdeIntegrator::Direction::kDownward,
                                             OdeIntegrator::Direction::kBoth}) {
    OdeIntegrator::Event event;
    event.g = [](double, std::span<const double> y) { return y[0]; };
    event.direction = direction;
    const OdeIntegrator::Solution s =
        integrator.integrate(oscillator, 0.0, y0, times(t_end, 7), &event);
    ASSERT_TRUE(s.status.ok) << s.status.message;
    EXPECT_EQ(s.t.size(), 7u);  // the events do not replace outputs
    const std::vector<double> expected = analytic_crossings(t_end, direction);
    ASSERT_EQ(s.event_times.size(), expected.size()) << "direction " << static_cast<int>(direction);
    for (std::size_t i = 0; i < expected.size(); ++i) {
      EXPECT_NEAR(s.event_times[i], expected[i], kEventTolerance) << "crossing " << i;
    }
  }
}

void expect_refused(const OdeIntegrator::Options& options, const std::string& field) {
  try {
    const OdeIntegrator integrator(options);
    ADD_FAILURE() << field << ": options accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(OdeIntegrator, BadOptionsAreRefusedNamingTheField) {
  OdeIntegrator::Options o;
  o.rtol = -1e-8;
  expect_refused(o, "rtol");
  o.rtol = std::nan("");
  expect_refused(o, "rtol");
  o = {};
  o.atol = 0.0;
  expect_refused(o, "atol");
  o = {};
  o.max_steps = 0;
  expect_refused(o, "max_steps");
  EXPECT_NO_THROW(OdeIntegrator(OdeIntegrator::Options{}));
}

TEST(OdeIntegrator, BadArgumentsAreRefused) {
  const OdeIntegrator integrator;
  const double y0[2] = {1.0, 0.0};
  EXPECT_THROW(integrator.integrate(oscillator, 0.0, y0, {1.0, 1.0}), InvalidInput);
  EXPECT_THROW(integrator.integrate(oscillator, 0.0, y0, {0.0}), InvalidInput);
  EXPECT_THROW(integrator.integrate(oscillator, 0.0, y0, {std::nan("")}), InvalidInput);
  EXPECT_THROW(integrator.integrate(nullptr, 0.0, y0, {1.0}), InvalidInput);
  EXPECT_THROW(integrator.integrate(oscillator, 0.0, std::span<const double>(), {1.0}),
               InvalidInput);
  const OdeIntegrator::Event no_function;
  EXPECT_THROW(integrator.integrate(oscillator, 0.0, y0, {1.0}, &no_function), InvalidInput);
  // No output times: nothing to do, and that is a success.
  const OdeIntegrator::Solution s = integrator.integrate(oscillator, 0.0, y0, {});
  EXPECT_TRUE(s.status.ok);
  EXPECT_TRUE(s.t.empty());
}

TEST(OdeIntegrator, RunningOutOfStepsNamesTheCvodesFunctionAndFlag) {
  OdeIntegrator::Options o;
  o.rtol = 1e-6;
  o.atol = 1e-9;
  o.max_steps = 50;  // enough to reach t = 0.01, far too few for a hundred periods
  const OdeIntegrator integrator(o);
  const double y0[2] = {1.0, 0.0};
  const std::vector<double> t = {0.01, 100.0 * period()};
  const OdeIntegrator::Solution s = integrator.integrate(oscillator, 0.0, y0, t);
  EXPECT_FALSE(s.status.ok);
  EXPECT_EQ(s.status.function, "CVode");
  EXPECT_EQ(s.status.flag, -1);
  EXPECT_EQ(s.status.message, "CVODES CVode returned -1 (CV_TOO_MUCH_WORK)");
  EXPECT_EQ(s.status.t_target, t[1]);
  EXPECT_GT(s.status.t_reached, t[0]);
  EXPECT_LT(s.status.t_reached, t[1]);
  EXPECT_EQ(s.t.size(), 1u);  // the first output was reached
  EXPECT_GE(s.steps, o.max_steps);
}

TEST(OdeIntegrator, RightHandSideFailureAndExceptionReachTheCaller) {
  const OdeIntegrator integrator;
  const double y0[1] = {1.0};
  const OdeIntegrator::Solution s = integrator.integrate(
      [](double, std::span<const double>, std::span<double>) { return -1; }, 0.0, y0, {1.0});
  EXPECT_FALSE(s.status.ok);
  EXPECT_NE(s.status.message.find("CV_RHSFUNC_FAIL"), std::string::npos) << s.status.message;
  EXPECT_THROW(integrator.integrate(
                   [](double t, std::span<const double>, std::span<double> ydot) -> int {
                     if (t > 0.5) throw std::domain_error("outside the model");
                     ydot[0] = 1.0;
                     return 0;
                   },
                   0.0,
                   y0,
                   {1.0}),
               std::domain_error);
}

}  // namespace
}  // namespace flexure
