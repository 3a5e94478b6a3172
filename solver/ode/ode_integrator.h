#pragma once
// A general initial-value integrator for small systems y' = f(t, y), on SUNDIALS CVODES (variable
// order, variable step: Adams-Moulton orders 1-12 for non-stiff problems, BDF orders 1-5 for stiff
// ones, Newton iteration with a dense linear solver; CVODES user guide, "Mathematical
// considerations"). It reports the state at given output times and, optionally, the times where an
// event function g(t, y) crosses zero in a chosen direction (CVODES root finding).
//
// The beam layer is the only one that links SUNDIALS (solver/CMakeLists.txt): the layers above
// integrate through this class, and no SUNDIALS type appears here.
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace flexure {

class OdeIntegrator {
 public:
  enum class Method { kAdams, kBdf };

  struct Options {
    double rtol = 1e-10;       // relative tolerance (> 0)
    double atol = 1e-14;       // absolute tolerance on every component (> 0)
    long max_steps = 1000000;  // steps allowed between two output times (>= 1)
    Method method = Method::kAdams;
    // Throws InvalidInput naming the field and its allowed range unless rtol > 0, atol > 0 and
    // max_steps >= 1 (NaN is refused).
    void validate() const;
  };

  // Writes f(t, y) into ydot (same size as y). Returns 0 on success, > 0 for a recoverable failure
  // (e.g. y outside the domain of f: the integrator retries with a smaller step), < 0 to stop the
  // integration (status CV_RHSFUNC_FAIL). An exception thrown here stops the integration and
  // reaches the caller of integrate().
  using Rhs = std::function<int(double t, std::span<const double> y, std::span<double> ydot)>;

  enum class Direction { kBoth, kUpward, kDownward };
  // Zeros of g(t, y) crossed in `direction` (kUpward: g increasing) are located and recorded.
  struct Event {
    std::function<double(double t, std::span<const double> y)> g;
    Direction direction = Direction::kBoth;
  };

  struct Status {
    bool ok = false;
    // On failure: the CVODES function, its flag and the flag's name, "CVODES CVode returned -1
    // (CV_TOO_MUCH_WORK)".
    std::string message;
    std::string function;    // CVODES function that failed ("CVode"), empty when ok
    int flag = 0;            // its return flag (< 0 on failure)
    double t_reached = 0.0;  // time reached (the last output time when ok)
    double t_target = 0.0;   // output time being integrated to when the integration stopped
  };

  struct Solution {
    std::vector<double> t;               // output times reached, in order
    std::vector<std::vector<double>> y;  // state at each of them
    std::vector<double> event_times;     // times of the event's zeros, in order
    long steps = 0;                      // internal steps taken
    Status status;
  };

  OdeIntegrator();  // default Options
  // Throws InvalidInput (Options::validate) for bad options.
  explicit OdeIntegrator(Options options);

  // Integrates from y(t0) = y0 and reports the state at each of `output_times` (finite, > t0,
  // increasing; may be empty). Stops at the first failure with the outputs done so far and
  // status.ok = false. Throws InvalidInput for an empty rhs or y0, a non-finite t0, bad output
  // times or an event without a function; std::runtime_error naming the CVODES function if CVODES
  // cannot be set up. The components of y0 are passed to CVODES as given.
  Solution integrate(const Rhs& rhs,
                     double t0,
                     std::span<const double> y0,
                     const std::vector<double>& output_times,
                     const Event* event = nullptr) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace flexure
