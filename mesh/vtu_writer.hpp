#pragma once
// Mesh and fields to a VTK XML unstructured grid (.vtu) that ParaView opens.

#include <array>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace rheomag::mesh {

/// Named fields to write with a mesh: per cell (triangle) or per point (node), scalar or
/// 3-vector (r, z, phi components for axisymmetric problems; x, y, z for planar ones).
class VtuFields {
 public:
  /// Where a field lives.
  enum class Location { cell, point };

  /// One field: `components` values per cell or point, stored contiguously.
  struct Field {
    std::string name;
    Location location = Location::cell;
    int components = 1;
    bool integer = false;
    std::vector<double> values;
  };

  /// A scalar per triangle.
  void add_cell_scalar(std::string name, std::vector<double> values);
  /// A 3-vector per triangle.
  void add_cell_vector(std::string name, const std::vector<std::array<double, 3>>& values);
  /// An integer per triangle (e.g. a material index).
  void add_cell_int(std::string name, const std::vector<int>& values);
  /// A scalar per node.
  void add_point_scalar(std::string name, std::vector<double> values);
  /// A 3-vector per node.
  void add_point_vector(std::string name, const std::vector<std::array<double, 3>>& values);

  /// The fields in the order they were added.
  const std::vector<Field>& fields() const { return fields_; }

 private:
  void add(Field field);
  std::vector<Field> fields_;
};

/// A general unstructured grid of one cell type (e.g. tetrahedra of a 3D mesh).
struct VtuGrid {
  std::vector<std::array<double, 3>> points;  ///< [m]
  int cell_type = 0;                          ///< VTK cell type (10 = VTK_TETRA)
  int nodes_per_cell = 0;
  std::vector<int> connectivity;  ///< nodes_per_cell point indices per cell
  std::vector<int> region;        ///< region index per cell
  /// Number of cells.
  std::size_t cells() const {
    return nodes_per_cell > 0 ? connectivity.size() / static_cast<std::size_t>(nodes_per_cell) : 0;
  }
};

/// Writes `grid` with cell data "region" plus `fields` (cell fields per cell, point fields per
/// point) and field data "region_names", atomically, like the triangle-mesh overload below.
void write_vtu(const std::string& path, const VtuGrid& grid, const VtuFields& fields = {},
               const std::vector<std::string>& region_names = {});

/// Writes `mesh` with points (r, z, 0), triangles (VTK_TRIANGLE, or VTK_QUADRATIC_TRIANGLE for
/// order 2, whose node order is the one of mesh.hpp), cell data "region" (region index) plus
/// `fields`, and field data "region_names". Binary appended XML, written to PATH.tmp and then
/// renamed, so PATH is never partial. Throws InputError when PATH cannot be written and
/// std::invalid_argument when a field's length does not match the mesh.
void write_vtu(const std::string& path, const Mesh& mesh, const VtuFields& fields = {},
               const std::vector<std::string>& region_names = {});

}  // namespace rheomag::mesh
