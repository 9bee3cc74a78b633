#include "magnetostatics/field_probe.hpp"

#include <array>
#include <cmath>

#include "core/error.hpp"
#include "core/format_text.hpp"

namespace rheomag::magnetostatics {

std::vector<FieldProbe> probe_field(const MagnetostaticSolver& solver, const Solution& solution,
                                    const std::vector<double>& points) {
  if (points.size() % 2 != 0)
    throw InputError("--point: expected pairs r,z [m], got " + std::to_string(points.size()) +
                     " numbers");
  std::vector<FieldProbe> probes;
  for (std::size_t k = 0; k + 1 < points.size(); k += 2) {
    std::array<double, 2> b{};
    if (!flux_density_at(solver, solution, {points[k], points[k + 1]}, -1, b))
      throw InputError("--point " + std::to_string(points[k]) + "," +
                       std::to_string(points[k + 1]) + ": not inside the mesh");
    probes.push_back({points[k], points[k + 1], b[0], b[1], std::hypot(b[0], b[1])});
  }
  return probes;
}

nlohmann::json probes_json(const std::vector<FieldProbe>& probes) {
  nlohmann::json out = nlohmann::json::array();
  for (const FieldProbe& p : probes)
    out.push_back({{"r", p.r}, {"z", p.z}, {"b_r", p.b_r}, {"b_z", p.b_z}, {"b", p.b}});
  return out;
}

std::string probes_text(const std::vector<FieldProbe>& probes) {
  std::string out = probes.empty() ? "" : "\n";
  for (const FieldProbe& p : probes)
    out += format_text("B at (%.6g, %.6g) m: B_r %.6g T, B_z %.6g T, |B| %.6g T\n", p.r, p.z, p.b_r,
                       p.b_z, p.b);
  return out;
}

}  // namespace rheomag::magnetostatics
