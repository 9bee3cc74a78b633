#pragma once
// The field map of a magnetostatic solution: |B| density, flux lines, region outlines, gaps.

#include <string>

#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "plot/axes.hpp"
#include "plot/colour_map.hpp"
#include "plot/figure.hpp"

namespace rheomag::figures {

/// How a field map is drawn.
struct FieldMapOptions {
  int width = 1000, height = 800;  ///< pixels
  int flux_lines = 21;             ///< contour levels of r A_phi (axisymmetric) / A_z (planar)
  int bins = 20;                   ///< colour bins of |B|
  double margin = 0.1;             ///< around the non-air regions, as a fraction of their size
  bool gap_labels = true;          ///< name each fluid gap
  std::string title;
};

/// A drawn field map and how it maps the model (in mm) onto its pixels.
struct FieldMap {
  plot::Figure figure;
  plot::Axes axes;          ///< data in mm: (r, z) or (x, y)
  plot::ColourMap colours;  ///< |B| [T]
};

/// The |B| density of `solution` on the mesh (each P2 triangle split in four, each piece in the
/// colour of |B| at its centre), zoomed to the regions that are not air (steel, magnets, coils,
/// fluid) plus a margin, at true aspect ratio; the region outlines, the flux lines, the gaps'
/// names and a colour bar in T.
FieldMap draw_field_map(const magnetostatics::MagnetostaticSolver& solver,
                        const magnetostatics::Solution& solution,
                        const magnetostatics::Results& results, const FieldMapOptions& options);

}  // namespace rheomag::figures
