#pragma once
// Planar straight-line graph: the input of the mesher, in the (r, z) or (x, y) plane.

#include <string>
#include <vector>

namespace rheomag::mesh {

/// A point of the meridian plane (r, z) for axisymmetric problems, (x, y) for planar ones [m].
struct Point {
  double r = 0.0;
  double z = 0.0;
};

/// What a fluid gap region is, for flux-density reporting.
enum class GapKind { none, annular, radial };

/// A constrained straight segment between two PSLG points.
struct Segment {
  int a = 0;
  int b = 0;
  int boundary = -1;        ///< index into the problem's boundary conditions, -1 if none
  double max_length = 0.0;  ///< requested maximum element edge length on it [m], 0 = none
};

/// One region (block) of the domain: the face of the PSLG that contains `seed`.
struct RegionSeed {
  Point seed;              ///< a point strictly inside the region
  std::string name;        ///< region name, reported in outputs
  double mesh_size = 0.0;  ///< target element edge length [m], 0 = automatic
  GapKind gap = GapKind::none;
  bool hole = false;    ///< true: not meshed (FEMM "<No Mesh>")
  std::string where{};  ///< where the seed is defined ("model.fem:12"), for messages
};

/// The whole mesher input.
struct Pslg {
  std::vector<Point> points;
  std::vector<Segment> segments;
  std::vector<RegionSeed> regions;  ///< region index = position in this list
  int default_region = -1;  ///< region of faces reached by no seed; -1 = such faces are an error
  std::string source;       ///< file name used in error messages
};

}  // namespace rheomag::mesh
