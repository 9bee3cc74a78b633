#pragma once
// The field along a straight line of the model (`rheomag solve --line x1,y1:x2,y2`): B normal and
// tangential, |B| and H at evenly spaced points, and the flux through the line (FEMM's line plot
// and mo_lineintegral(0)), as values, JSON and text.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"

namespace rheomag::magnetostatics {

/// The field at one point of a line. Tangent t = (end - start) / length, normal n = t turned
/// counter-clockwise by 90 degrees in the (r, z) or (x, y) plane.
struct LineSample {
  double s = 0.0;               ///< distance from the start [m]
  double r = 0.0, z = 0.0;      ///< the point [m]
  double b_n = 0.0, b_t = 0.0;  ///< B . n, B . t [T]
  double b = 0.0;               ///< |B| [T]
  double h_n = 0.0, h_t = 0.0;  ///< H . n, H . t [A/m]
  double h = 0.0;               ///< |H| [A/m]
};

/// One line's samples and the flux through it.
struct LineField {
  mesh::Point start, end;  ///< [m]
  double length = 0.0;     ///< [m]
  std::vector<LineSample> samples;
  /// Flux of B . n through the surface the line sweeps: axisymmetric integral B . n 2 pi r ds
  /// = 2 pi (r2 A2 - r1 A1), planar depth integral B . n ds = depth (A1 - A2) [Wb] (exact for
  /// the finite-element field, from A at the ends).
  double normal_flux = 0.0;
};

/// The field along the line "x1,y1:x2,y2" [m] at `points` (>= 2) evenly spaced points, ends
/// included. InputError for a malformed line, fewer than 2 points, or a point of it outside the
/// mesh (giving the model's extent).
LineField line_field(const MagnetostaticSolver& solver, const Solution& solution,
                     const std::string& line, int points);

/// The lines as a JSON array of {start, end, length, normal_flux, samples: [{s, r, z, b_n, b_t, b,
/// h_n, h_t, h}]}.
nlohmann::json lines_json(const std::vector<LineField>& lines);

/// The lines as text: per line a heading with the flux, then a table with units.
std::string lines_text(const std::vector<LineField>& lines, cases::Symmetry symmetry);

}  // namespace rheomag::magnetostatics
