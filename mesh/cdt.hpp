#pragma once
// Internal to rheomag_mesh: the CGAL constrained Delaunay triangulation used by the mesher.

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <array>

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

}  // namespace rheomag::mesh::detail
