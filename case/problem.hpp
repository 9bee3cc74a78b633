#pragma once
// A magnetostatic problem: geometry, materials per region, coils and boundary conditions.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mesh/pslg.hpp"

namespace rheomag::cases {

/// Planar (A_z, per unit depth scaled by `depth`) or axisymmetric (A_phi about the z axis).
enum class Symmetry { planar, axisymmetric };

/// One (B, H) sample of a magnetisation curve [T, A/m].
struct BhPoint {
  double b = 0.0;
  double h = 0.0;
};

/// Heat conduction and storage of a material (the [thermal] table of a material file).
struct ThermalProperties {
  double conductivity = 0.0;   ///< thermal conductivity k [W/(m K)]
  double density = 0.0;        ///< [kg/m^3]
  double specific_heat = 0.0;  ///< c_p [J/(kg K)]
  std::string source;          ///< where the data come from
  /// Volumetric heat capacity rho c_p [J/(m^3 K)].
  double heat_capacity() const { return density * specific_heat; }
};

/// A magnetic material: linear (relative permeability) or nonlinear (B-H table).
/// How H(B) is interpolated between the points of a B-H table.
enum class BhInterpolation {
  /// Monotone piecewise cubic (PCHIP slopes; magnetostatics/bh_curve.hpp): rheomag's default.
  monotone_cubic,
  /// FEMM's natural cubic spline of H(B) (zero second derivative at both ends), for tables read
  /// from a .fem file: the curve FEMM's solver uses.
  femm_natural_spline,
};

struct Material {
  std::string name;
  double mu_r = 1.0;                   ///< relative permeability when `bh` is empty
  std::vector<BhPoint> bh;             ///< B-H table, B ascending from (0, 0); empty = linear
  std::optional<double> conductivity;  ///< electrical conductivity [S/m]; empty: not stated
  std::string source;                  ///< where the data come from
  /// Permanent magnet: H_c [A/m], B = mu0 mu_r (H + H_c m); with a B-H table (its curve shifted
  /// by H_c to start at (0, 0), as FEMM gives it) H = H_table(|B|) B/|B| - H_c m.
  double coercivity = 0.0;
  bool fluid = false;  ///< an MR fluid of the materials library: a medium a body moves through
  /// Thermal data; empty: the material is outside the thermal model (surroundings, e.g. air).
  std::optional<ThermalProperties> thermal{};
  /// How H is interpolated between the `bh` points (FEMM's spline for tables from a .fem).
  BhInterpolation bh_interpolation = BhInterpolation::monotone_cubic;
  /// A linear anisotropic material (FEMM's Mu_x != Mu_y, or laminations along x or y): the
  /// relative permeabilities along r (x) and z (y), mu_r being the first; empty: isotropic.
  std::optional<std::array<double, 2>> mu_r_axes{};
};

/// A circuit driving one or more coil regions: in series (each region carries turns x current)
/// or, as FEMM's parallel circuit, sharing one current among its regions.
struct Circuit {
  std::string name;
  double current = 0.0;  ///< [A]
  /// FEMM's parallel circuit (CircuitType 0): `current` is split among its regions, whatever
  /// their turns, as FEMM's solver splits it (magnetostatics/circuit_currents.hpp).
  bool parallel = false;
};

/// Kinds of boundary condition on marked PSLG segments.
enum class BoundaryKind {
  prescribed_a,  ///< Dirichlet A = value
  mixed,         ///< Robin: nu0 dA/dn + c0 A = c1 (FEMM "mixed")
  periodic,      ///< A on this edge equals A on the partner edge (FEMM BdryType 4)
  antiperiodic,  ///< A on this edge equals -A on the partner edge (FEMM BdryType 5)
};

/// A boundary condition referenced by Segment::boundary.
struct BoundaryCondition {
  std::string name;
  BoundaryKind kind = BoundaryKind::prescribed_a;
  double a_value = 0.0;  ///< prescribed A [Wb/m] (at r = z = 0 when it varies)
  double c0 = 0.0;       ///< mixed: coefficient [1/(H)] as in FEMM (A/(Wb) per m^2)
  double c1 = 0.0;       ///< mixed: constant term
  /// (Anti)periodic: index of the paired boundary condition (the other edge), -1 otherwise.
  /// Each edge of a pair has its own condition; the one with the lower index is the master.
  /// As in FEMM, both edges are followed with the meshed domain on their left, and the start of
  /// the first pairs with the end of the second (a translation or a rotation of the domain).
  int partner = -1;
  /// (Anti)periodic arcs of one angle: paired by the fraction of their angle, so their radii
  /// (and lengths) may differ, as FEMM's Kelvin open boundary joins a circle to a smaller disk.
  bool pairs_by_angle = false;
  /// Prescribed A varying in space as FEMM's A_0 + A_1 x + A_2 y: A = a_value + a_per_r r +
  /// a_per_z z [Wb/m per m] (r, z the planar x, y); e.g. a_per_r = -B0 (planar) or B0 / 2
  /// (axisymmetric) puts the model in a uniform field B0 along y or z. (Last: aggregate
  /// initialisations list the fields above in order.)
  double a_per_r = 0.0;
  double a_per_z = 0.0;  ///< see a_per_r
  /// The prescribed A at point p [Wb/m].
  double a_at(const mesh::Point& p) const { return a_value + a_per_r * p.r + a_per_z * p.z; }
};

/// Direction of magnetisation m of a permanent-magnet region, measured from the r (x) axis:
/// a constant angle, or an expression of the element centroid (FEMM's variables x, y, r, z,
/// theta [deg], R in the length unit `length_unit` [m]) giving the angle in degrees.
struct MagnetDirection {
  double degrees = 0.0;      ///< constant angle [deg] (used when `expression` is empty)
  std::string expression;    ///< e.g. "theta+180"; empty = constant
  double length_unit = 1.0;  ///< metres per unit of the expression's coordinates
};

/// Material, coil and gap data of one region (index matches Pslg::regions).
struct RegionData {
  int material = -1;             ///< index into Problem::materials
  int circuit = -1;              ///< index into Problem::circuits, -1 = no coil
  double turns = 0.0;            ///< coil turns in this region (sign gives the winding direction)
  double current_density = 0.0;  ///< fixed source current density J [A/m^2] (FEMM block J)
  MagnetDirection magnetisation{};  ///< direction of H_c when the material is a magnet
  /// A region of FEMM's axisymmetric external disk: its permeability scaled by Problem::kelvin.
  bool kelvin_exterior = false;
  /// A solid conductor, not a winding (FEMM: a label of at most one turn that is not litz or
  /// wire): its circuit's current flows as sigma E, and E ~ 1/r in an axisymmetric model.
  bool solid_conductor = false;
};

/// FEMM's axisymmetric open boundary (Kelvin transformation, [extRo], [extRi], [extZo]): the
/// space outside the sphere of radius `domain_radius` (extRi) about the origin is mapped into a
/// disk of radius `disk_radius` (extRo) centred on the axis at z = `disk_centre_z` (extZo),
/// joined to the sphere's boundary by a periodic pair of arcs. In the disk's regions mu is
/// divided by (r^2 + (z - z_c)^2) R_i / R_o^3 at each triangle's centroid, as in FEMM.
struct KelvinExterior {
  double domain_radius = 0.0;  ///< R_i [m], FEMM's extRi
  double disk_radius = 0.0;    ///< R_o [m], FEMM's extRo
  double disk_centre_z = 0.0;  ///< z_c [m], FEMM's extZo
  /// The factor nu is multiplied by at (r, z) in the disk.
  double reluctivity_factor(double r, double z) const {
    const double dz = z - disk_centre_z;
    return (r * r + dz * dz) * domain_radius / (disk_radius * disk_radius * disk_radius);
  }
};

/// A prescribed value of A or a concentrated current at one geometry point (FEMM point
/// property): a line current (planar) or a ring current (axisymmetric).
struct PointCondition {
  std::string name;
  int point = -1;           ///< index into geometry.points
  bool prescribed = false;  ///< true: A = a_value at the point; false: current source
  double a_value = 0.0;     ///< [Wb/m]
  double current = 0.0;     ///< [A]
};

/// The outer boundary of the computational domain.
enum class OuterBoundary {
  none,       ///< the PSLG already contains the outer boundary (e.g. FEMM import)
  open,       ///< automatic semicircle (axisymmetric) / circle (planar) with an asymptotic
              ///< (dipole-decay) Robin condition: an open boundary
  dirichlet,  ///< automatic semicircle/circle with A = 0
};

/// Everything needed to mesh and solve one magnetostatic problem.
struct Problem {
  Symmetry symmetry = Symmetry::axisymmetric;
  double depth = 1.0;  ///< planar only: length in the third direction [m]
  mesh::Pslg geometry;
  std::vector<RegionData> regions;  ///< parallel to geometry.regions
  std::vector<Material> materials;
  std::vector<Circuit> circuits;
  std::vector<BoundaryCondition> boundaries;
  std::vector<PointCondition> point_conditions;  ///< FEMM point properties
  OuterBoundary outer = OuterBoundary::open;
  double outer_radius_factor = 5.0;  ///< automatic outer radius = factor * bounding radius
  int min_gap_elements = 4;          ///< elements across every fluid gap
  int order = 2;                     ///< Lagrange order, 1 or 2
  /// FEMM's axisymmetric external region, when a region has RegionData::kelvin_exterior.
  std::optional<KelvinExterior> kelvin;
  /// What reading the input changed to solve it as its own tool would (e.g. a FEMM B-H table
  /// smoothed as FEMM does), one sentence each, for the user.
  std::vector<std::string> warnings;
};

}  // namespace rheomag::cases
