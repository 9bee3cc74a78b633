#pragma once
// Non-axisymmetric features of a revolved valve: lead-wire slot, axial hole, radial port and an
// eccentric core ([[feature]] tables of a case, docs/case-format.md).

#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "magnetostatics3d/region_box.hpp"
#include "magnetostatics3d/tet_mesh.hpp"

namespace rheomag::magnetostatics3d {

/// [[feature]] tables are read here, not by the case reader.
inline const bool kFeatureSectionRegistered = cases::register_case_section("feature");

/// What a feature is.
enum class FeatureKind {
  lead_slot,     ///< axial slot cut into a region from its outer radius (width, depth, angle)
  hole,          ///< axial cylindrical hole through a region (radius, position, angle)
  port,          ///< radial cylindrical hole through a region (radius, z, angle)
  eccentricity,  ///< everything inside an annular gap shifted sideways (offset, angle)
};

/// One [[feature]] table, lengths in metres and angles in radians.
struct Feature {
  FeatureKind kind = FeatureKind::lead_slot;
  std::string label;      ///< "file:line: feature[i] (kind)" for messages
  std::string region;     ///< region cut (lead_slot, hole, port) or annular gap (eccentricity)
  std::string material;   ///< fill of a cut ("": the background material of the case, air)
  double angle = 0.0;     ///< direction of the feature about z [rad]
  double width = 0.0;     ///< lead_slot: circumferential width at the region's outer radius
  double depth = 0.0;     ///< lead_slot: radial depth from the region's outer radius
  double radius = 0.0;    ///< hole, port: radius
  double position = 0.0;  ///< hole: radial position of its axis
  double z = 0.0;         ///< port: axial position of its axis
  double offset = 0.0;    ///< eccentricity: lateral shift of the inner body
};

/// Reads the case's [[feature]] tables (InputError naming file, line and key).
std::vector<Feature> read_features(const cases::Case& c);

/// True when the set of features is mirror-symmetric about the plane y = 0 (each feature at 0 or
/// 180 degrees or with a twin at minus its angle, e.g. a ring of holes): then the half
/// 0 <= phi <= pi is an exact model.
bool features_allow_half_model(const std::vector<Feature>& features);

/// Element size [m] per region that resolves the round cuts in it (holes, ports): half
/// the smallest radius; 0 for regions without one. (A lead slot's depth is left to the region's
/// own size: a slot is cut into the largest region, the core.)
std::vector<double> feature_cell_sizes(const std::vector<Feature>& features,
                                       const cases::Problem& closed);

/// Angles [rad] in [0, span] where meridian walls make the angular edges of cuts exact.
std::vector<double> feature_walls(const std::vector<Feature>& features,
                                  const cases::Problem& closed, const std::vector<RegionBox>& boxes,
                                  double span);

/// Applies the cuts to the mesh of the part 0 <= phi <= span: tetrahedra of the cut region whose
/// centroid lies inside a cut get a new region (appended to closed, named after the feature,
/// material = fill). Radial and axial extents are resolved by the region's tetrahedra (angular
/// edges are exact walls). Applies an eccentricity by moving the nodes: r <= inner gap radius shift
/// by the offset, linearly less across the gap, none outside it. Returns the undeformed node
/// positions. InputError naming the feature for unknown regions or materials, features outside
/// their region (or cutting nothing although their axis is in the meshed part), overlapping
/// features, or coils the eccentricity would cut through.
std::vector<Eigen::Vector3d> apply_features(const std::vector<Feature>& features,
                                            cases::Problem& closed,
                                            const std::vector<RegionBox>& boxes, double span,
                                            TetMesh& mesh);

}  // namespace rheomag::magnetostatics3d
