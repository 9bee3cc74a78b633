#include "magnetostatics3d/features.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "case/toml_section.hpp"
#include "core/enum_names.hpp"
#include "core/error.hpp"

namespace rheomag::magnetostatics3d {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr auto kFeatureNames =
    enum_names<FeatureKind>({{FeatureKind::lead_slot, "lead_slot"},
                             {FeatureKind::hole, "hole"},
                             {FeatureKind::port, "port"},
                             {FeatureKind::eccentricity, "eccentricity"}});

int find_region(const cases::Problem& closed, const Feature& f) {
  std::string names;
  for (std::size_t r = 0; r < closed.geometry.regions.size(); ++r) {
    if (closed.geometry.regions[r].name == f.region) return static_cast<int>(r);
    names += (names.empty() ? "" : ", ") + closed.geometry.regions[r].name;
  }
  throw InputError(f.label + ": region '" + f.region + "' does not exist (regions: " + names + ")");
}

/// Angle difference wrapped to (-pi, pi].
double angle_difference(double a, double b) {
  double d = std::fmod(a - b, 2 * kPi);
  if (d > kPi) d -= 2 * kPi;
  if (d <= -kPi) d += 2 * kPi;
  return d;
}

/// Half the angular width of a cut about its axis [rad] (0: no walls).
double half_width(const Feature& f, const RegionBox& box) {
  switch (f.kind) {
    case FeatureKind::lead_slot:
      return 0.5 * f.width / box.r1;
    case FeatureKind::hole:
      return std::asin(std::min(1.0, f.radius / f.position));
    default:
      return 0.0;
  }
}

/// True when x lies inside the cut of feature f in region box `box`.
bool inside_cut(const Feature& f, const RegionBox& box, const Eigen::Vector3d& x) {
  const double r = std::hypot(x[0], x[1]);
  const double phi = std::atan2(x[1], x[0]);
  const Eigen::Vector2d axis(std::cos(f.angle), std::sin(f.angle));
  switch (f.kind) {
    case FeatureKind::lead_slot:
      return r >= box.r1 - f.depth &&
             std::abs(angle_difference(phi, f.angle)) * box.r1 <= 0.5 * f.width;
    case FeatureKind::hole:
      return (Eigen::Vector2d(x[0], x[1]) - f.position * axis).norm() <= f.radius;
    case FeatureKind::port: {
      const double along = x[0] * axis[0] + x[1] * axis[1];
      const double across = std::abs(-x[0] * axis[1] + x[1] * axis[0]);
      return along > 0 && std::hypot(across, x[2] - f.z) <= f.radius;
    }
    case FeatureKind::eccentricity:
      break;
  }
  return false;
}

}  // namespace

std::vector<Feature> read_features(const cases::Case& c) {
  std::vector<Feature> features;
  if (c.table.empty()) return features;
  const std::string file = c.source.string();
  const cases::TomlSection top(c.table, "", file);
  const double unit = c.input.length_unit;
  int index = 0;
  for (const cases::TomlSection& s : top.table_array("feature")) {
    ++index;
    Feature f;
    const std::string kind = s.required_string("kind");
    f.kind = kFeatureNames.parse(kind, s.where("kind"));
    f.label = s.where() + " (" + kind + ")";
    f.angle = s.number_or("angle", 0.0) * kPi / 180.0;
    switch (f.kind) {
      case FeatureKind::lead_slot:
        s.allow_only({"kind", "region", "material", "angle", "width", "depth"});
        f.width = s.positive("width") * unit;
        f.depth = s.positive("depth") * unit;
        break;
      case FeatureKind::hole:
        s.allow_only({"kind", "region", "material", "angle", "radius", "position"});
        f.radius = s.positive("radius") * unit;
        f.position = s.positive("position") * unit;
        break;
      case FeatureKind::port:
        s.allow_only({"kind", "region", "material", "angle", "radius", "z"});
        f.radius = s.positive("radius") * unit;
        f.z = s.number_or("z", 0.0) * unit;
        break;
      case FeatureKind::eccentricity:
        s.allow_only({"kind", "gap", "angle", "offset"});
        f.offset = s.positive("offset") * unit;
        break;
    }
    f.region = f.kind == FeatureKind::eccentricity ? s.required_string("gap")
                                                   : s.required_string("region");
    f.material = s.string("material").value_or("");
    features.push_back(f);
  }
  return features;
}

bool features_allow_half_model(const std::vector<Feature>& features) {
  // Every feature is its own mirror image (angle 0 or pi) or has a mirror twin: the same cut at
  // the opposite angle (e.g. a ring of bolt holes).
  auto twins = [](const Feature& a, const Feature& b) {
    return a.kind == b.kind && a.region == b.region && a.material == b.material &&
           a.width == b.width && a.depth == b.depth && a.radius == b.radius &&
           a.position == b.position && a.z == b.z && a.offset == b.offset &&
           std::abs(angle_difference(a.angle, -b.angle)) < 1e-9;
  };
  return std::all_of(features.begin(), features.end(), [&](const Feature& f) {
    return std::any_of(features.begin(), features.end(),
                       [&](const Feature& g) { return twins(f, g); });
  });
}

std::vector<double> feature_cell_sizes(const std::vector<Feature>& features,
                                       const cases::Problem& closed) {
  std::vector<double> size(closed.regions.size(), 0.0);
  for (const Feature& f : features) {
    if (f.kind != FeatureKind::hole && f.kind != FeatureKind::port) continue;
    double& s = size[find_region(closed, f)];
    s = s > 0 ? std::min(s, f.radius / 2.0) : f.radius / 2.0;
  }
  return size;
}

std::vector<double> feature_walls(const std::vector<Feature>& features,
                                  const cases::Problem& closed, const std::vector<RegionBox>& boxes,
                                  double span) {
  std::vector<double> walls;
  for (const Feature& f : features) {
    if (f.kind == FeatureKind::eccentricity) continue;
    const double half = half_width(f, boxes[find_region(closed, f)]);
    if (half <= 0.0) continue;
    for (double a : {f.angle - half, f.angle + half}) {
      const double w = std::fmod(std::fmod(a, 2 * kPi) + 2 * kPi, 2 * kPi);
      if (w > 1e-9 && w < span - 1e-9) walls.push_back(w);
    }
  }
  return walls;
}

std::vector<Eigen::Vector3d> apply_features(const std::vector<Feature>& features,
                                            cases::Problem& closed,
                                            const std::vector<RegionBox>& boxes, double span,
                                            TetMesh& mesh) {
  const std::vector<Eigen::Vector3d> undeformed = mesh.nodes;
  const std::vector<int> original_region = mesh.region;
  std::vector<int> cut_by(mesh.tets.size(), -1);
  for (std::size_t i = 0; i < features.size(); ++i) {
    const Feature& f = features[i];
    const int region = find_region(closed, f);
    const RegionBox& box = boxes[region];
    if (box.empty()) throw InputError(f.label + ": region '" + f.region + "' has no tetrahedra");
    if (f.kind == FeatureKind::eccentricity) {
      if (closed.geometry.regions[region].gap != mesh::GapKind::annular) {
        throw InputError(f.label + ": gap '" + f.region + "' is not an annular fluid gap");
      }
      if (f.offset >= box.r1 - box.r0) {
        throw InputError(f.label + ": offset must be smaller than the gap width");
      }
      for (std::size_t r = 0; r < closed.regions.size(); ++r) {
        if (closed.regions[r].circuit >= 0 && boxes[r].r1 > box.r0)
          throw InputError(f.label + ": coil region '" + closed.geometry.regions[r].name +
                           "' extends beyond the gap's inner radius");
      }
      const Eigen::Vector3d shift(f.offset * std::cos(f.angle), f.offset * std::sin(f.angle), 0.0);
      for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
        const double r = std::hypot(undeformed[n][0], undeformed[n][1]);
        const double s = std::clamp((box.r1 - r) / (box.r1 - box.r0), 0.0, 1.0);
        mesh.nodes[n] = undeformed[n] + s * shift;
      }
      continue;
    }
    int material = f.material.empty() && closed.geometry.default_region >= 0
                       ? closed.regions[closed.geometry.default_region].material
                       : -1;
    std::string names;
    for (std::size_t m = 0; m < closed.materials.size(); ++m) {
      if (closed.materials[m].name == f.material) material = static_cast<int>(m);
      names += (names.empty() ? "\"" : ", \"") + closed.materials[m].name + "\"";
    }
    if (material < 0) {
      throw InputError(f.label + ": material '" + f.material +
                       "' is not one of the case's materials (" + names + ")");
    }
    const bool fits = f.kind == FeatureKind::lead_slot ? f.depth < box.r1 - box.r0
                      : f.kind == FeatureKind::hole
                          ? f.position - f.radius >= box.r0 && f.position + f.radius <= box.r1
                          : f.z - f.radius >= box.z0 && f.z + f.radius <= box.z1;
    if (!fits) {
      throw InputError(f.label + ": the cut lies partly outside region '" + f.region + "'");
    }
    const int new_region = static_cast<int>(closed.regions.size());
    mesh::RegionSeed seed;
    seed.name = "feature " + std::to_string(i + 1) + " (" + f.region + ")";
    closed.geometry.regions.push_back(seed);
    cases::RegionData data;
    data.material = material;
    closed.regions.push_back(data);
    int cut = 0;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      if (original_region[t] != region || !inside_cut(f, box, mesh.centroid(static_cast<int>(t))))
        continue;
      if (cut_by[t] >= 0) {
        throw InputError(f.label + ": overlaps " + features[cut_by[t]].label);
      }
      cut_by[t] = static_cast<int>(i);
      mesh.region[t] = new_region;
      ++cut;
    }
    // A feature of the mirrored half (its twin is cut in the meshed one) cuts nothing here.
    const double meshed = span - 1e-9;
    const double axis = std::fmod(std::fmod(f.angle, 2 * kPi) + 2 * kPi, 2 * kPi);
    if (cut == 0 && axis > meshed && axis < 2 * kPi - 1e-9) continue;
    if (cut == 0) {
      throw InputError(f.label + ": cuts nothing of region '" + f.region +
                       "' (outside the body, or smaller than its tetrahedra)");
    }
  }
  return undeformed;
}

}  // namespace rheomag::magnetostatics3d
