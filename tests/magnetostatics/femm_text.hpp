#pragma once
// Small FEMM 4.2 .fem texts written by the tests themselves: rectangles of blocks with the
// property sections the reader needs.

#include <sstream>
#include <string>
#include <vector>

namespace rheomag::testing {

/// The sections of one .fem file; the lists hold raw lines or property blocks.
struct FemText {
  std::string problem = "planar";
  double depth = 1.0;
  std::vector<std::string> point_props, boundaries, blocks, circuits;
  std::vector<std::string> points, segments, arcs, labels;
  std::string header;  ///< extra "[Key] = value" lines after [ProblemType]

  std::string str() const {
    std::ostringstream out;
    out << "[Format] = 4.0\n[Frequency] = 0\n[Precision] = 1e-08\n[Depth] = " << depth
        << "\n[LengthUnits] = meters\n[ProblemType] = " << problem << "\n"
        << header;
    auto section = [&](const char* key, const std::vector<std::string>& items) {
      out << key << " = " << items.size() << "\n";
      for (const std::string& item : items) out << item << "\n";
    };
    section("[PointProps]", point_props);
    section("[BdryProps]", boundaries);
    section("[BlockProps]", blocks);
    section("[CircuitProps]", circuits);
    section("[NumPoints]", points);
    section("[NumSegments]", segments);
    section("[NumArcSegments]", arcs);
    out << "[NumHoles] = 0\n";
    section("[NumBlockLabels]", labels);
    return out.str();
  }
};

/// A linear block property (mu_r, H_c [A/m], J [MA/m^2], lamination type and fill, electrical
/// conductivity [MS/m]).
inline std::string fem_block(const std::string& name, double mu, double h_c = 0.0, double j = 0.0,
                             int lam_type = 0, double fill = 1.0, double sigma = 0.0) {
  std::ostringstream out;
  out << "<BeginBlock>\n<BlockName> = \"" << name << "\"\n<Mu_x> = " << mu << "\n<Mu_y> = " << mu
      << "\n<H_c> = " << h_c << "\n<J_re> = " << j << "\n<Sigma> = " << sigma
      << "\n<LamType> = " << lam_type << "\n<LamFill> = " << fill << "\n<BHPoints> = 0\n<EndBlock>";
  return out.str();
}

/// A circuit: series (type 1, the default) or parallel (type 0).
inline std::string fem_circuit(const std::string& name, double amps, int type = 1) {
  return "<BeginCircuit>\n<CircuitName> = \"" + name +
         "\"\n<TotalAmps_re> = " + std::to_string(amps) +
         "\n<CircuitType> = " + std::to_string(type) + "\n<EndCircuit>";
}

/// A boundary property: type 0 (A = a0) or 2 (mixed, c0, c1).
inline std::string fem_boundary(const std::string& name, int type, double a0, double c0 = 0.0,
                                double c1 = 0.0) {
  std::ostringstream out;
  out.precision(17);
  out << "<BeginBdry>\n<BdryName> = \"" << name << "\"\n<BdryType> = " << type << "\n<A_0> = " << a0
      << "\n<c0> = " << c0 << "\n<c1> = " << c1 << "\n<EndBdry>";
  return out.str();
}

}  // namespace rheomag::testing
