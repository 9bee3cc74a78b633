#pragma once
// A region given by its closed outline in the meridian plane, before conversion to a PSLG:
// the common form of TOML [[region]] tables and parametric templates.

#include <string>
#include <vector>

#include "mesh/pslg.hpp"

namespace rheomag::cases {

/// One closed region outline with its material, coil and gap data (lengths in metres).
struct RegionOutline {
  std::string name;                  ///< region name, reported in outputs
  std::string material;              ///< material name (resolved against the library)
  std::vector<mesh::Point> outline;  ///< closed polygon, straight edges, first point not repeated
  std::string circuit;               ///< circuit name driving this coil, empty = no coil
  double turns = 0.0;                ///< coil turns (> 0 when `circuit` is set)
  mesh::GapKind gap = mesh::GapKind::none;  ///< fluid gap kind, for flux-density reports
  double mesh_size = 0.0;                   ///< target element size [m], 0 = automatic
  std::string where;                        ///< "file:line: region[i]" for error messages
  std::string material_where;               ///< "file:line: region[i].material" ("" = where)
};

/// Appends the points of a circular arc from `from` to `to` to `out` (excluding `from`, including
/// `to`). `degrees` is the signed included angle: positive runs counter-clockwise about the arc's
/// centre (as FEMM arc segments), negative clockwise; |degrees| in (0, 360). The arc is split into
/// ceil(|degrees| / max_segment_degrees) equal straight segments.
void append_arc(std::vector<mesh::Point>& out, mesh::Point from, mesh::Point to, double degrees,
                double max_segment_degrees);

}  // namespace rheomag::cases
