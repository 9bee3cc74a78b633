#pragma once
// Export of a closed magnetostatic Problem as a FEMM 4.2 .fem model (the inverse of
// femm_import): points, segments with boundary markers and maximum lengths, holes, one block
// label per area with its material, circuit, turns, magnet direction and mesh size.

#include <string>
#include <vector>

#include "case/problem.hpp"
#include "mesh/mesher.hpp"

namespace rheomag::cases {

/// The .fem text of `problem`, whose PSLG must already contain its outer boundary
/// (Problem::outer == none, e.g. after magnetostatics::close_domain). Lengths are written in
/// metres, or in the length unit of the magnet direction expressions (FEMM evaluates them in
/// the file's unit). Every area gets a block label: the seeds, plus one label per further connected
/// area of the default region (FEMM has no default region). A region without a mesh size gets the
/// FEMM size of the mean edge of the mesh that `mesh_options` give it, so FEMM meshes as finely
/// as rheomag (fluid gaps included). InputError for what a .fem cannot hold (non-integer turns)
/// and for a problem whose outer boundary is not closed yet.
std::string write_femm(const Problem& problem, const mesh::MeshOptions& mesh_options);

/// A .fem text with what a solution file needs to refer to it.
struct FemmModel {
  std::string text;                 ///< the .fem text
  double length_unit = 1.0;         ///< the file's length unit [m]
  std::vector<int> label_region;    ///< region (index into Problem::regions) of each block label
  std::vector<int> triangle_label;  ///< written block label of each triangle of the mesh given
};

/// write_femm with the labels found on `mesh` (a mesh of the closed `problem`, order 1 or 2),
/// returning also the block label of every triangle of `mesh` (FEMM's element `lbl`).
FemmModel write_femm_for_mesh(const Problem& problem, const mesh::Mesh& mesh);

/// Inverse of femm_mesh_size_to_edge: the FEMM block-label size for a target edge length.
double edge_to_femm_mesh_size(double edge);

}  // namespace rheomag::cases
