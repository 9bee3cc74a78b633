// The coil and gap regions of a device and the spreading of its heat over them.

#include "thermal/device_regions.hpp"

#include "core/error.hpp"
#include "core/format_text.hpp"

namespace rheomag::thermal {

std::vector<int> coil_regions(const cases::Problem& problem) {
  std::vector<int> out;
  for (std::size_t r = 0; r < problem.regions.size(); ++r) {
    const cases::RegionData& data = problem.regions[r];
    if (data.circuit >= 0 || data.turns != 0.0 || data.current_density != 0.0)
      out.push_back(static_cast<int>(r));
  }
  return out;
}

std::vector<int> gap_regions(const cases::Problem& problem) {
  std::vector<int> out;
  for (std::size_t r = 0; r < problem.regions.size(); ++r)
    if (problem.geometry.regions[r].gap != mesh::GapKind::none) out.push_back(static_cast<int>(r));
  return out;
}

void spread_power(double power, const std::vector<int>& regions, const std::vector<double>& volume,
                  std::vector<double>& out) {
  double total = 0.0;
  for (int r : regions) total += volume[r];
  if (regions.empty() || !(total > 0.0)) {
    if (power != 0.0)
      throw InputError(format_text("thermal: %.6g W of heat but no region to place it in", power));
    return;
  }
  for (int r : regions) out[r] += power * volume[r] / total;
}

std::vector<double> source_densities(const std::vector<double>& power,
                                     const std::vector<double>& volume) {
  std::vector<double> q(power.size(), 0.0);
  for (std::size_t r = 0; r < q.size(); ++r)
    if (power[r] != 0.0 && volume[r] > 0.0) q[r] = power[r] / volume[r];
  return q;
}

}  // namespace rheomag::thermal
