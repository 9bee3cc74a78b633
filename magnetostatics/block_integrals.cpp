#include "magnetostatics/block_integrals.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "magnetostatics/stress_tensor.hpp"

namespace rheomag::magnetostatics {
namespace {

/// The region indices named by "A+B+..." (holes excluded); InputError listing the regions.
std::vector<int> named_regions(const cases::Problem& problem, const std::string& names,
                               const std::string& request) {
  std::vector<int> out;
  std::size_t start = 0;
  while (start <= names.size()) {
    const std::size_t plus = std::min(names.find('+', start), names.size());
    const std::string name = names.substr(start, plus - start);
    int found = -1;
    for (int r = 0; r < static_cast<int>(problem.geometry.regions.size()); ++r)
      if (!problem.geometry.regions[r].hole && problem.geometry.regions[r].name == name) found = r;
    if (found < 0) {
      std::string list;
      for (const mesh::RegionSeed& seed : problem.geometry.regions)
        if (!seed.hole) list += (list.empty() ? "" : ", ") + seed.name;
      throw InputError("--integral " + request + ": no region named '" + name +
                       "'; the regions are " + list);
    }
    out.push_back(found);
    start = plus + 1;
  }
  return out;
}

/// Sums over the selected regions' triangles: A J, energies, areas, volumes, B and A.
struct RegionSums {
  double a_dot_j = 0.0, energy = 0.0, b_dot_h = 0.0, area = 0.0, volume = 0.0;
  double b_r = 0.0, b_z = 0.0, a = 0.0;  // integral B dV, integral A dV
};

RegionSums region_sums(const MagnetostaticSolver& solver, const Solution& solution,
                       const std::vector<int>& regions) {
  const mesh::Mesh& m = solver.mesh();
  const cases::Problem& problem = solver.problem();
  const Assembler& assembler = solver.assembler();
  std::vector<char> chosen(problem.regions.size(), 0);
  for (int r : regions) chosen[r] = 1;
  RegionSums sums;
  ElementQuadrature q;
  double a_local[kMaxElementNodes];
  for (int e = 0; e < static_cast<int>(m.triangles.size()); ++e) {
    const int region = m.region[e];
    if (!chosen[region]) continue;
    const cases::RegionData& data = problem.regions[region];
    // [A/m^2]: fixed J plus the circuit's (a coil's N I / area)
    double j = data.current_density;
    if (data.circuit >= 0)
      j += assembler.region_currents()[region].density(solution.currents[data.circuit],
                                                       assembler.centroid_r(e));
    assembler.quadrature(e, q);
    for (int i = 0; i < m.nodes_per_triangle(); ++i) a_local[i] = solution.a[m.triangles[e][i]];
    const Reluctivity& law = assembler.law(e);
    for (int p = 0; p < q.points; ++p) {
      const auto b = element_b(q, p, a_local);
      const auto h = law.h(b[0], b[1]);
      double a = 0.0;
      for (int i = 0; i < m.nodes_per_triangle(); ++i) a += q.n[p][i] * a_local[i];
      sums.a += q.weight[p] * a;
      sums.a_dot_j += q.weight[p] * a * j;
      sums.energy += q.weight[p] * law.energy_density(b[0], b[1]);
      sums.b_dot_h += q.weight[p] * (h[0] * b[0] + h[1] * b[1]);
      sums.area += q.area_weight[p];
      sums.volume += q.weight[p];
      sums.b_r += q.weight[p] * b[0], sums.b_z += q.weight[p] * b[1];
    }
  }
  return sums;
}

BlockIntegral evaluate(const MagnetostaticSolver& solver, const Solution& solution,
                       const std::string& request) {
  const std::size_t colon = request.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == request.size())
    throw InputError("--integral " + request + ": expected REGION:KIND, KIND one of " +
                     kIntegralKindNames.choices());
  const cases::Problem& problem = solver.problem();
  const bool planar = problem.symmetry == cases::Symmetry::planar;
  BlockIntegral out;
  out.kind = kIntegralKindNames.parse(request.substr(colon + 1), "--integral " + request);
  const std::vector<int> regions = named_regions(problem, request.substr(0, colon), request);
  for (int r : regions) out.regions.push_back(problem.geometry.regions[r].name);
  const char* r_name = planar ? "x" : "r";
  const char* z_name = planar ? "y" : "z";
  if (out.kind == IntegralKind::force || out.kind == IntegralKind::torque) {
    if (out.kind == IntegralKind::torque && !planar)
      throw InputError("--integral " + request +
                       ": torque is for planar problems (an axisymmetric body has none)");
    const StressTensorForce f = stress_tensor_force(solver, solution, regions);
    if (out.kind == IntegralKind::torque) {
      out.unit = "N m", out.femm = "mo_blockintegral(22)";
      out.components = {{"torque", f.torque}};
    } else if (planar) {
      out.unit = "N", out.femm = "mo_blockintegral(18), mo_blockintegral(19)";
      out.components = {{"f_x", f.force[0]}, {"f_y", f.force[1]}};
    } else {
      out.unit = "N", out.femm = "mo_blockintegral(19)";
      out.components = {{"f_z", f.force[1]}};
    }
    if (!f.junctions.empty()) {
      out.warning = format_text(
          "the body meets an interface of two media (air, fluids) at %zu point(s), first "
          "at (%.6g, %.6g) m, where the elements are up to %.3g mm: the %s there carries an error "
          "of the order of that size (docs/femm.md); a smaller mesh_size for the regions there "
          "reduces it",
          f.junctions.size(), f.junctions[0].r, f.junctions[0].z, 1e3 * f.junction_size,
          out.kind == IntegralKind::torque ? "torque" : "force");
    }
    return out;
  }
  const RegionSums s = region_sums(solver, solution, regions);
  switch (out.kind) {
    case IntegralKind::a_dot_j:
      out.unit = "Wb A", out.femm = "mo_blockintegral(0)";
      out.components = {{"a_dot_j", s.a_dot_j}};
      break;
    case IntegralKind::energy:
      out.unit = "J", out.femm = "mo_blockintegral(2)";
      out.components = {{"energy", s.energy}};
      break;
    case IntegralKind::coenergy:
      out.unit = "J", out.femm = "mo_blockintegral(17)";
      out.components = {{"coenergy", s.b_dot_h - s.energy}};
      break;
    case IntegralKind::area:
      out.unit = "m^2", out.femm = "mo_blockintegral(5)";
      out.components = {{"area", s.area}};
      break;
    case IntegralKind::volume:
      out.unit = "m^3", out.femm = "mo_blockintegral(10)";
      out.components = {{"volume", s.volume}};
      break;
    case IntegralKind::average_b: {
      out.unit = "T", out.femm = "mo_blockintegral(8) / mo_blockintegral(10), (9) / (10)";
      const double br = s.b_r / s.volume, bz = s.b_z / s.volume;
      out.components = {{std::string("b_") + r_name, br},
                        {std::string("b_") + z_name, bz},
                        {"b", std::hypot(br, bz)}};
      break;
    }
    case IntegralKind::flux:
      out.unit = "Wb", out.femm = "mo_blockintegral(1) / mo_blockintegral(5)";
      out.components = {{"flux", s.a / s.area}};
      break;
    default:
      break;
  }
  return out;
}

}  // namespace

std::vector<BlockIntegral> block_integrals(const MagnetostaticSolver& solver,
                                           const Solution& solution,
                                           const std::vector<std::string>& requests) {
  std::vector<BlockIntegral> out;
  for (const std::string& request : requests) out.push_back(evaluate(solver, solution, request));
  return out;
}

nlohmann::json integrals_json(const std::vector<BlockIntegral>& integrals) {
  nlohmann::json out = nlohmann::json::array();
  for (const BlockIntegral& integral : integrals) {
    nlohmann::json values = nlohmann::json::object();
    for (const IntegralComponent& c : integral.components) values[c.name] = c.value;
    out.push_back({{"regions", integral.regions},
                   {"kind", std::string(kIntegralKindNames.name(integral.kind))},
                   {"unit", integral.unit},
                   {"femm", integral.femm},
                   {"values", values}});
    if (!integral.warning.empty()) out.back()["warning"] = integral.warning;
  }
  return out;
}

std::string integrals_text(const std::vector<BlockIntegral>& integrals) {
  std::string out = integrals.empty() ? "" : "\n";
  for (const BlockIntegral& integral : integrals) {
    std::string regions;
    for (const std::string& r : integral.regions) regions += (regions.empty() ? "" : "+") + r;
    out += std::string(kIntegralKindNames.name(integral.kind)) + " of " + regions + ":";
    for (std::size_t k = 0; k < integral.components.size(); ++k) {
      const IntegralComponent& c = integral.components[k];
      out += format_text("%s %s = %.6g %s", k == 0 ? "" : ",", c.name.c_str(), c.value,
                         integral.unit.c_str());
    }
    out += "  [FEMM " + integral.femm + "]\n";
    if (!integral.warning.empty()) out += "  warning: " + integral.warning + "\n";
  }
  return out;
}

}  // namespace rheomag::magnetostatics
