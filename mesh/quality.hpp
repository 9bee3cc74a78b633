#pragma once
// Quality statistics of a mesh: sizes, angles, and how well each fluid gap is resolved.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/pslg.hpp"

namespace rheomag::mesh {

/// Statistics of the triangles of one region.
struct RegionQuality {
  std::string name;
  GapKind gap = GapKind::none;
  int elements = 0;
  double area = 0.0;       ///< [m^2]
  double max_edge = 0.0;   ///< longest triangle edge [m]
  double thickness = 0.0;  ///< band_thickness(area, perimeter) [m]
  /// thickness / max_edge: a lower bound on the number of triangles any straight line across
  /// the region crosses (each triangle covers at most its longest edge of the line).
  double elements_across = 0.0;
};

/// Statistics of a whole mesh.
struct MeshQuality {
  int elements = 0;
  int nodes = 0;
  int order = 1;
  double min_angle = 0.0;         ///< smallest triangle angle [deg]
  double max_aspect_ratio = 0.0;  ///< max of longest edge / (2 sqrt(3) inradius); 1 = equilateral
  std::vector<RegionQuality> regions;  ///< index = region index of the PSLG
};

/// Measures a mesh generated from `pslg` (which gives the region names and gap kinds).
MeshQuality measure_quality(const Mesh& mesh, const Pslg& pslg);

/// The JSON document of `rheomag mesh --json`: counts, order, min angle, max aspect ratio and
/// per-region statistics (gap thickness and elements across for gap regions).
nlohmann::json quality_json(const MeshQuality& quality);

/// A human-readable table of the statistics, one line per region.
std::string format_quality(const MeshQuality& quality);

/// Thickness t of a region of area A and perimeter P taken as a thin band: the smaller root of
/// t^2 - (P/2) t + A = 0 (the short side of the rectangle with that A and P; exact for
/// rectangles and for bands of constant thickness), or 4A/P when there is no real root.
double band_thickness(double area, double perimeter);

}  // namespace rheomag::mesh
