#pragma once
// Input/output data for black-box identification: sampled drives u (one column per input) and
// the output y, on a uniform sample time.

#include <Eigen/Dense>
#include <cstddef>

namespace rheomag::identify {

/// Uniformly sampled input/output data: u is N x nu (one column per drive), y has N samples.
struct IoData {
  Eigen::MatrixXd u;         ///< drives, SI units of the recording columns
  Eigen::VectorXd y;         ///< measured output
  double sample_time = 1.0;  ///< [s]

  /// Number of samples.
  std::ptrdiff_t size() const { return y.size(); }
  /// Number of drive columns.
  std::ptrdiff_t inputs() const { return u.cols(); }
};

/// The samples [begin, end) of `data` (half-open sample-index range); throws InputError if the
/// range is empty or outside the data.
IoData slice(const IoData& data, std::ptrdiff_t begin, std::ptrdiff_t end);

/// Single-input data from plain vectors (same length, else InputError).
IoData make_io_data(const Eigen::VectorXd& u, const Eigen::VectorXd& y, double sample_time);

}  // namespace rheomag::identify
