// .ans writer. Format facts from xfemm (Reoptimize-Systems/xfemm 35baec4c): the solver's
// WriteStatic2D (fsolver/static2d.cpp) and the post-processor's reader (FPProc::OpenDocument,
// fpproc/fpproc.cpp), which reads A as 2 pi r A in axisymmetric files (GetJA, GetElementB).

#include "magnetostatics/femm_ans.hpp"

#include <array>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <vector>

#include "case/femm_export.hpp"

namespace rheomag::magnetostatics {

namespace {

/// Full-precision number as FEMM writes it (%.17g).
std::string ans_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

/// The linear triangles FEMM gets of triangle `t`: itself (P1) or its four children (P2, node
/// order v0 v1 v2 m01 m12 m20), all counter-clockwise.
std::vector<std::array<int, 3>> linear_pieces(const std::array<int, 6>& t, int order) {
  if (order == 1) return {{t[0], t[1], t[2]}};
  return {{t[0], t[3], t[5]}, {t[3], t[1], t[4]}, {t[5], t[4], t[2]}, {t[3], t[4], t[5]}};
}

}  // namespace

std::string femm_ans_text(const MagnetostaticSolver& solver, const Solution& solution) {
  cases::Problem problem = solver.problem();
  for (std::size_t c = 0; c < problem.circuits.size() && c < solution.currents.size(); ++c)
    problem.circuits[c].current = solution.currents[c];
  const mesh::Mesh& m = solver.mesh();
  const cases::FemmModel model = cases::write_femm_for_mesh(problem, m);
  const bool axisymmetric = problem.symmetry == cases::Symmetry::axisymmetric;

  std::ostringstream out;
  out << model.text << "[Solution]\n" << m.nodes.size() << "\n";
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const mesh::Point p = m.nodes[i];
    const double a = solution.a[static_cast<Eigen::Index>(i)];
    const double value = axisymmetric ? 2.0 * std::numbers::pi * p.r * a : a;
    // -1: no point-property marker (read only by FEMM's incremental re-solve).
    out << ans_number(p.r / model.length_unit) << "\t" << ans_number(p.z / model.length_unit)
        << "\t" << ans_number(value) << "\t-1\n";
  }
  std::size_t elements = 0;
  std::ostringstream element_lines;
  for (std::size_t e = 0; e < m.triangles.size(); ++e) {
    for (const auto& piece : linear_pieces(m.triangles[e], m.order)) {
      element_lines << piece[0] << "\t" << piece[1] << "\t" << piece[2] << "\t"
                    << model.triangle_label[e] << "\n";
      ++elements;
    }
  }
  out << elements << "\n" << element_lines.str();

  // Per block label: "1 J", a circuit current density [MA/m^2] added to the block's J, or for a
  // solid conductor of an axisymmetric model "0 dV", a voltage per radian FEMM's post-processor
  // turns into J = -sigma dV / r: the circuit's current as rheomag's assembly spreads it.
  const std::vector<RegionCurrent>& currents = solver.assembler().region_currents();
  out << model.label_region.size() << "\n";
  for (int region : model.label_region) {
    const cases::RegionData& d = problem.regions[region];
    const RegionCurrent& c = currents[region];
    const double drive =
        d.circuit >= 0 ? c.per_amp * problem.circuits[d.circuit].current + c.offset : 0.0;
    const double sigma = problem.materials[d.material].conductivity.value_or(0.0);
    if (c.radial && sigma > 0.0)
      out << "0\t" << ans_number(-drive / sigma) << "\n";
    else
      out << "1\t" << ans_number(c.radial ? 0.0 : drive * 1e-6) << "\n";
  }
  out << "0\n0\n";  // no periodic pairs (export refuses them), no air-gap elements
  return out.str();
}

}  // namespace rheomag::magnetostatics
