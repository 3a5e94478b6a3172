#pragma once
// Error channels shared by every solver and the command-line tool.
//
// Bad input (NaN, negative length, unknown name, a load outside a method's domain) is reported by
// throwing InvalidInput; the CLI maps it to exit code 2. A method that cannot produce a converged
// solution returns a result with converged == false and a message; the CLI maps that to exit
// code 3. Programmer errors are not caught.
#include <cmath>
#include <stdexcept>
#include <string>

namespace flexure {

class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Input that is valid but outside one method's domain (e.g. a load beyond the elliptic solver's
// range): another method may solve it, so `--method auto` can fall back. Still exit code 2 when
// the user named the method.
class OutsideMethodDomain : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

class NoConvergence : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws InvalidInput naming `what` unless `value` is a finite number.
void require_finite(double value, const std::string& what);

}  // namespace flexure
