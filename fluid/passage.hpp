#pragma once
// Unmagnetised passages of a valve's flow path (ports, channels) and minor losses (entrance,
// exit, turns), in series with the magnetised gaps: the [[valve.passage]] and [[valve.loss]]
// tables of a case (docs/fluid.md).

#include <string>
#include <vector>

#include "case/toml_section.hpp"

namespace rheomag::fluid {

/// Cross-section shape of an unmagnetised passage.
enum class PassageShape {
  pipe,     ///< circular pipe of `diameter`, axial `length`
  annulus,  ///< annulus inner_radius..outer_radius, axial `length`
  slit,     ///< parallel plates: `gap` x `width`, `length`
  radial,   ///< disk gap of axial `gap` between inner_radius and outer_radius (radial flow)
};

/// One unmagnetised passage (Newtonian laminar flow at the fluid's viscosity). Dimensions [m]
/// are given, or taken from the bounding box of the case region `region` (pipe: diameter =
/// 2 r_max, length = z extent; annulus: r_min..r_max, z extent; radial: r_min..r_max, gap = z
/// extent); see SolvedValve.
struct Passage {
  std::string name;
  PassageShape shape = PassageShape::pipe;
  std::string region;  ///< case region whose extent gives the dimensions ("" = given)
  double diameter = 0.0, inner_radius = 0.0, outer_radius = 0.0, gap = 0.0, width = 0.0,
         length = 0.0;
};

/// A minor loss dp = K rho V^2 / 2, V = Q / A of the named section (a gap or passage name) or
/// of the given area; for a radial section A = 2 pi r h at `radius` (required).
struct MinorLoss {
  std::string name;
  double k = 0.0;       ///< loss coefficient K
  std::string section;  ///< gap or passage whose mean velocity is used ("" = `area`)
  double area = 0.0;    ///< flow area [m^2] when no section is named
  double radius = 0.0;  ///< radial sections: radius where V is taken [m]
};

/// The shape's name: "pipe", "annulus", "slit", "radial".
std::string shape_name(PassageShape shape);

/// Reads the [[valve.passage]] tables of [valve]; InputError names the key and what is expected.
std::vector<Passage> read_passages(const cases::TomlSection& valve);

/// Reads the [[valve.loss]] tables of [valve].
std::vector<MinorLoss> read_losses(const cases::TomlSection& valve);

/// Throws InputError unless the passage's dimensions are complete and consistent.
void validate(const Passage& p);

/// Newtonian laminar pressure drop of a passage with its dimensions set [Pa]: pipe
/// 128 mu Q L / (pi D^4) (Hagen-Poiseuille), annulus exact (Bird, Stewart & Lightfoot eq.
/// 2.4-17), slit 12 mu Q L / (b h^3), radial 6 mu Q ln(r2/r1) / (pi h^3).
double passage_dp(const Passage& p, double viscosity, double flow);

/// Flow cross-section of a passage [m^2] (radial: 2 pi r h at `radius`).
double passage_area(const Passage& p, double radius);

/// Hydraulic diameter 4 A / wetted perimeter of a passage [m] (radial: 2 h).
double hydraulic_diameter(const Passage& p);

}  // namespace rheomag::fluid
