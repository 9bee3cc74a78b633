#include "identify/io_data.hpp"

#include <string>

#include "core/error.hpp"

namespace rheomag::identify {

IoData slice(const IoData& data, std::ptrdiff_t begin, std::ptrdiff_t end) {
  if (begin < 0 || end > data.size() || begin >= end)
    throw InputError("sample range " + std::to_string(begin) + ":" + std::to_string(end) +
                     " is empty or outside the data (0:" + std::to_string(data.size()) + ")");
  IoData part;
  part.u = data.u.middleRows(begin, end - begin);
  part.y = data.y.segment(begin, end - begin);
  part.sample_time = data.sample_time;
  return part;
}

IoData make_io_data(const Eigen::VectorXd& u, const Eigen::VectorXd& y, double sample_time) {
  if (u.size() != y.size())
    throw InputError("input has " + std::to_string(u.size()) + " samples but output has " +
                     std::to_string(y.size()));
  if (!(sample_time > 0.0)) throw InputError("sample time must be positive");
  IoData data;
  data.u = u;
  data.y = y;
  data.sample_time = sample_time;
  return data;
}

}  // namespace rheomag::identify
