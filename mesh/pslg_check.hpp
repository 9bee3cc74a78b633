#pragma once
// Validation and clean-up of a PSLG before triangulation.

#include <string>
#include <vector>

#include "mesh/pslg.hpp"

namespace rheomag::mesh {

/// A segment of a prepared PSLG: a piece of one input segment.
struct PreparedSegment {
  int a = 0;
  int b = 0;
  int boundary = -1;
  double max_length = 0.0;
  int source_segment = 0;  ///< index of the input segment it comes from (for messages)
};

/// A PSLG that can be triangulated as is: points are distinct, segments meet only at their end
/// points. Input segments are split where an input point lies on them (a "T-junction", as
/// FEMM's editor does) and a segment given twice is kept once.
struct PreparedPslg {
  std::vector<Point> points;  ///< the input points, unchanged and in the same order
  std::vector<PreparedSegment> segments;
  double tolerance = 0.0;  ///< distance below which two points are the same [m]
};

/// Most pieces the segments' maximum lengths may cut them into, in all: more is an InputError
/// (a maximum length orders of magnitude below its segment's, such as a unit mistake, would
/// otherwise triangulate for hours).
inline constexpr double kMaxSegmentPieces = 5e6;

/// Checks the PSLG and returns its prepared form. Throws InputError naming Pslg::source and the
/// offending indices and coordinates for: non-finite coordinates, coincident points (closer
/// than 1e-9 of the bounding box), segments with a bad index or zero length, segments that
/// cross, the same segment given twice with different boundary markers, region seeds that are
/// non-finite or lie on a segment, a default region index out of range, and maximum lengths that
/// cut the segments into more than kMaxSegmentPieces pieces.
PreparedPslg prepare_pslg(const Pslg& pslg);

/// A number with up to 9 significant digits (no trailing zeros), for messages.
std::string format_number(double value);

/// "(r, z)" with enough digits to find the place in the input.
std::string format_point(const Point& p);

/// The name used for the PSLG in messages: its source file, or "geometry".
std::string pslg_name(const Pslg& pslg);

}  // namespace rheomag::mesh
