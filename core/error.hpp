#pragma once
// Error types shared by every layer (core is the root library).

#include <stdexcept>
#include <string>

namespace rheomag {

/// Bad input (file, line or key, and what was expected). The CLI exits with code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An iterative solver that did not converge (says the residual reached). CLI exit code 3.
class ConvergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rheomag
