#pragma once
// Magnetisation direction of a permanent-magnet region: a constant angle or an expression of
// the position (FEMM's "direction expressions", e.g. "theta+180"), evaluated with muparser.

#include <memory>
#include <string>

#include "case/problem.hpp"
#include "mesh/pslg.hpp"

namespace rheomag::cases {

/// Evaluator of one MagnetDirection (the expression is compiled once).
class MagnetDirectionField {
 public:
  /// Compiles the expression; InputError "`where`: ..." when it does not parse or uses an unknown
  /// variable or function. Variables: x, y, r, z (coordinates), theta (polar angle of (x, y)
  /// [deg]), R (distance from the origin), in the direction's length unit; constant pi;
  /// muparser's functions plus those of FEMM's Lua (atan2, mod, floor, ceil, deg, rad; radians).
  MagnetDirectionField(const MagnetDirection& direction, const std::string& where);
  ~MagnetDirectionField();
  MagnetDirectionField(MagnetDirectionField&&) noexcept;
  MagnetDirectionField& operator=(MagnetDirectionField&&) noexcept;

  /// Angle of m from the r (x) axis [deg] at the point `p` [m]; InputError on a non-finite value.
  double degrees_at(mesh::Point p) const;

 private:
  struct Parser;
  std::unique_ptr<Parser> parser_;  // null for a constant direction
  MagnetDirection direction_;
  std::string where_;
};

}  // namespace rheomag::cases
