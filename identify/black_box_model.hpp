#pragma once
// The common face of every identified black-box model: free-run simulation and one-step
// prediction on new data, its parameters by name, and how much measured history it needs.

#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "identify/io_data.hpp"

namespace rheomag::identify {

/// How a model is compared with a measurement.
enum class EvalMode {
  simulation,  ///< free run: past model outputs feed back (MATLAB compare, horizon inf)
  prediction   ///< one step ahead: past measured outputs feed back (horizon 1)
};

/// A named scalar parameter of a fitted model.
using NamedValue = std::pair<std::string, double>;

/// prefix followed by the decimal index, e.g. numbered("a", 2) == "a2".
inline std::string numbered(std::string prefix, long index) {
  prefix.append(std::to_string(index));
  return prefix;
}

/// An identified model that can be run on any data with the same drives.
class IdentModel {
 public:
  virtual ~IdentModel() = default;
  /// Canonical name with the orders used, e.g. "arx:2,4,1".
  virtual std::string name() const = 0;
  /// Fitted parameters (and chosen structure numbers) by name.
  virtual std::vector<NamedValue> params() const = 0;
  /// Number of leading samples taken from the measurement as initial conditions; metrics skip them.
  virtual std::ptrdiff_t warmup() const = 0;
  /// Model output on `data` in the given mode (same length as data.y).
  virtual Eigen::VectorXd run(const IoData& data, EvalMode mode) const = 0;
};

}  // namespace rheomag::identify
