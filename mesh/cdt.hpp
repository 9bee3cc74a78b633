#pragma once
// Internal to rheomag_mesh: the CGAL constrained Delaunay triangulation used by the mesher.

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace rheomag::mesh::detail {

/// Face label of faces outside the outermost constraints (never meshed).
inline constexpr int kOutside = -2;
/// Face label before labelling.
inline constexpr int kUnlabelled = -1;

/// What the coarse triangulation knows about a face: its region and its edges' markers.
struct FaceInfo {
  int region = kUnlabelled;                   ///< index into Pslg::regions, or kOutside
  std::array<int, 3> boundary{-1, -1, -1};    ///< Segment::boundary of edge i (opposite vertex i)
  std::array<double, 3> max_length{0, 0, 0};  ///< Segment::max_length of edge i, 0 = none
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<
    Kernel, CGAL::Constrained_triangulation_face_base_2<
                Kernel, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
/// Constrained Delaunay triangulation with exact predicates.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using CgalPoint = Kernel::Point_2;

/// Distance from p to the segment [a, b] (to a when the segment has zero length).
inline double segment_distance(const CgalPoint& p, const CgalPoint& a, const CgalPoint& b) {
  const double dr = b.x() - a.x(), dz = b.y() - a.y();
  const double length_sq = dr * dr + dz * dz;
  double t = length_sq > 0.0 ? ((p.x() - a.x()) * dr + (p.y() - a.y()) * dz) / length_sq : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(a.x() + t * dr - p.x(), a.y() + t * dz - p.y());
}

}  // namespace rheomag::mesh::detail
