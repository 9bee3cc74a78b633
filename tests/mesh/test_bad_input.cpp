// Bad geometry and options: one InputError naming the file and the offending item, never a mesh.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/mesher.hpp"
#include "pslg_fixtures.hpp"

namespace rheomag::mesh {
namespace {

using fixtures::PslgBuilder;

/// Message of the InputError thrown by generate_mesh, or "" when none is thrown.
std::string error_of(const Pslg& pslg, const MeshOptions& options = {}) {
  try {
    generate_mesh(pslg, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// A unit square with one region, from file "model.fem".
PslgBuilder square() {
  PslgBuilder b;
  b.rectangle(0.0, 0.0, 1.0, 1.0);
  b.region(0.5, 0.5, "iron");
  b.pslg.source = "model.fem";
  return b;
}

#define EXPECT_ERROR(pslg, ...)                                           \
  do {                                                                    \
    const std::string message = error_of(pslg);                           \
    ASSERT_FALSE(message.empty()) << "no error";                          \
    EXPECT_NE(message.find("model.fem: "), std::string::npos) << message; \
    for (const char* part : {__VA_ARGS__})                                \
      EXPECT_NE(message.find(part), std::string::npos) << message;        \
  } while (false)

TEST(BadGeometry, NonFiniteCoordinates) {
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    PslgBuilder b = square();
    b.pslg.points[2].z = bad;
    EXPECT_ERROR(b.pslg, "point 2", "non-finite");
  }
  PslgBuilder b = square();
  b.pslg.regions[0].seed.r = std::nan("");
  EXPECT_ERROR(b.pslg, "region 0 'iron'", "non-finite seed");
}

TEST(BadGeometry, DuplicatePoints) {
  PslgBuilder b = square();
  b.pslg.points.push_back({1.0, 1.0});  // same as point 2
  EXPECT_ERROR(b.pslg, "points 2 and 4 coincide", "(1, 1)");
}

// A .fem point far from the rest (1e300, a unit typed wrong) makes the extent-relative merge
// tolerance huge: distinct points of the model were said to "coincide" with no hint why.
TEST(BadGeometry, FarPointNamesTheMergeTolerance) {
  PslgBuilder b = square();
  b.pslg.points.push_back({0.5, 1e300});
  EXPECT_ERROR(b.pslg,
               "coincide at (0, 0) (within 1e+291 m, the merge tolerance: 1e-9 of the "
               "geometry's extent; a coordinate far from the rest makes it large)");
}

TEST(BadGeometry, ZeroLengthSegment) {
  PslgBuilder b = square();
  b.pslg.segments.push_back({3, 3, -1, 0.0});
  EXPECT_ERROR(b.pslg, "segment 4 has zero length", "point 3");
}

TEST(BadGeometry, SegmentIndexOutOfRange) {
  PslgBuilder b = square();
  b.pslg.segments[1].b = 17;
  EXPECT_ERROR(b.pslg, "segment 1", "17", "expected indices in [0, 4)");
}

TEST(BadGeometry, SelfIntersectingBoundary) {
  // A bow tie: (0,0) (1,1) (1,0) (0,1) crosses itself at (0.5, 0.5).
  PslgBuilder b;
  b.polygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  b.region(0.9, 0.5, "iron");
  b.pslg.source = "model.fem";
  EXPECT_ERROR(b.pslg, "segments 0 and 2 cross", "(0.5, 0.5)");
}

TEST(BadGeometry, OverlappingRegions) {
  // Two squares overlapping in [0.5, 1] x [0.5, 1]: their sides cross at (1, 0.5), (0.5, 1).
  PslgBuilder b = square();
  b.rectangle(0.5, 0.5, 1.5, 1.5);
  b.region(1.2, 1.2, "copper");
  EXPECT_ERROR(b.pslg, "cross or overlap", "overlapping regions");
}

TEST(BadGeometry, OpenBoundary) {
  PslgBuilder b = square();
  b.pslg.segments.pop_back();                  // the left side is missing
  b.pslg.segments.push_back({0, 2, -1, 0.0});  // a diagonal keeps 3 segments but no closed area
  b.pslg.regions[0].seed = {0.7, 0.3};         // right of the diagonal: enclosed
  b.region(0.2, 0.8, "air");                   // left of it: open
  EXPECT_ERROR(b.pslg, "region 1 'air'", "outside every closed boundary", "(0.2, 0.8)");
}

TEST(BadGeometry, SeedOnASegment) {
  PslgBuilder b = square();
  b.pslg.regions[0].seed = {1.0, 0.25};
  EXPECT_ERROR(b.pslg, "region 0 'iron'", "lies on segment 1");
}

TEST(BadGeometry, TwoSeedsInOneArea) {
  PslgBuilder b = square();
  b.region(0.2, 0.2, "copper");
  EXPECT_ERROR(b.pslg, "region 0 'iron' and region 1 'copper'", "same enclosed area");
}

TEST(BadGeometry, AreaWithoutRegion) {
  PslgBuilder b = square();
  b.rectangle(0.1, 0.1, 0.3, 0.3);  // no seed inside, no default region
  b.pslg.regions[0].seed = {0.6, 0.6};
  EXPECT_ERROR(b.pslg, "no region/material for the area near");
  b.pslg.default_region = 5;
  EXPECT_ERROR(b.pslg, "default region 5 does not exist");
}

TEST(BadGeometry, DuplicateSegmentWithDifferentBoundaryConditions) {
  PslgBuilder b = square();
  b.pslg.segments[0].boundary = 0;
  b.pslg.segments.push_back({1, 0, 1, 0.0});
  EXPECT_ERROR(b.pslg, "segments 0 and 4 overlap", "different boundary conditions");
}

TEST(BadGeometry, NegativeSizes) {
  PslgBuilder b = square();
  b.pslg.regions[0].mesh_size = -1.0;
  EXPECT_ERROR(b.pslg, "region 0 'iron' has mesh size");
  b = square();
  b.pslg.segments[0].max_length = std::nan("");
  EXPECT_ERROR(b.pslg, "segment 0 has maximum edge length");
}

TEST(BadGeometry, EverythingAHole) {
  PslgBuilder b = square();
  b.pslg.regions[0].hole = true;
  EXPECT_ERROR(b.pslg, "every region is a hole");
}

TEST(BadOptions, OrderAngleAndSize) {
  const Pslg pslg = square().pslg;
  MeshOptions options;
  options.order = 3;
  EXPECT_NE(error_of(pslg, options).find("order = 3"), std::string::npos);
  options = {};
  options.min_angle = 40.0;
  EXPECT_NE(error_of(pslg, options).find("min_angle"), std::string::npos);
  options = {};
  options.min_gap_elements = 0;
  EXPECT_NE(error_of(pslg, options).find("min_gap_elements"), std::string::npos);
  options = {};
  options.default_size = 1e-6;  // a unit square at 1 um: ~2e12 elements
  EXPECT_NE(error_of(pslg, options).find("the smallest is 1e-06 m"), std::string::npos);
}

// Accepted on purpose: a segment given twice (shared side of two regions drawn as two closed
// polygons) and a point lying on another segment (FEMM's editor splits the segment there).
TEST(TolerableGeometry, DuplicateSegmentsAndPointsOnSegmentsAreMerged) {
  PslgBuilder b = square();
  b.rectangle(1.0, 0.25, 1.5, 0.75);  // its left side lies inside the square's right side
  b.rectangle(0.0, 1.0, 1.0, 2.0);    // its bottom side duplicates the square's top side
  b.region(1.2, 0.5, "tab");
  b.region(0.5, 1.5, "lid");
  const Mesh mesh = generate_mesh(b.pslg, MeshOptions{});
  double area = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) area += fixtures::signed_area(mesh, t);
  EXPECT_NEAR(area, 1.0 + 0.25 + 1.0, 1e-12);  // exact union area, rounding only
}

}  // namespace
}  // namespace rheomag::mesh
