// A mesh refused as too fine says the smallest requested size, in metres, and its region (issue
// #18: the message said "check units: lengths are in metres" even for a case written in mm,
// whose sizes the case reader had already converted).

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "mesh/mesher.hpp"
#include "pslg_fixtures.hpp"

namespace rheomag::mesh {
namespace {

/// The InputError message of meshing a 30 mm square region 'pot' of mesh size `size` [m], from
/// "tiny.toml"; "no error" if it meshes.
std::string too_fine_message(double size) {
  fixtures::PslgBuilder b;
  b.rectangle(0.0, 0.0, 0.03, 0.03);
  b.region(0.015, 0.015, "pot", size);
  b.pslg.source = "tiny.toml";
  try {
    generate_mesh(b.pslg);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BadInput, MeshTooFineNamesTheSmallestSize) {
  const std::string message = too_fine_message(1e-7);  // "mesh_size = 0.0001" in a case in mm
  EXPECT_EQ(message.rfind("tiny.toml: the requested mesh sizes give about ", 0), 0u) << message;
  EXPECT_NE(message.find("; expected larger mesh sizes (the smallest is 1e-07 m in region "
                         "'pot')"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find("metres"), std::string::npos) << message;
}

// A size off by many orders of magnitude (1e-12 m: "mesh_size = 1e-9" in a case in mm) gives
// more elements than a long holds: the message said "about -9223372036854775808 elements".
// Estimate: 2 x area / (sqrt(3)/4 h^2) = 2 x 9e-4 / (0.4330 x 1e-24) = 4.16e21.
TEST(BadInput, AbsurdlyFineMeshCountIsPrintedAsANumber) {
  const std::string message = too_fine_message(1e-12);
  EXPECT_NE(message.find("tiny.toml: the requested mesh sizes give about 4.16e+21 elements, more "
                         "than the"),
            std::string::npos)
      << message;
}

// The 2D mesher bounds memory as the 3D ones do (issue #36): a mesh whose solve needs more than
// --max-memory is refused before meshing, naming the estimate and the limit. A 30 mm square of
// 0.1 mm elements is about 2 x 9e-4 / (0.433 x 1e-8) = 4.2e5 triangles, 1.5 GB at 3600 B each.
TEST(BadInput, MeshOverTheMemoryLimitIsRefusedNamingIt) {
  fixtures::PslgBuilder b;
  b.rectangle(0.0, 0.0, 0.03, 0.03);
  b.region(0.015, 0.015, "pot", 1e-4);
  b.pslg.source = "big.toml";
  MeshOptions options;
  options.max_memory = 256.0 * 1024 * 1024;  // 256 MiB
  try {
    generate_mesh(b.pslg, options);
    FAIL() << "a 1.5 GB mesh was accepted under a 256 MiB limit";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("about 4.16e+05 elements whose solve would need about 1.5"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("more than the 268 MB allowed (--max-memory"), std::string::npos)
        << message;
  }
  // The same mesh with the default limit (3/4 of this machine's memory) is not refused by it.
  options.max_memory = 1e15;
  options.max_elements = 1000;  // but by the element count, before any meshing
  EXPECT_THROW(generate_mesh(b.pslg, options), InputError);
}

// A boundary's maximum element length orders of magnitude below its length (1e-12 m: a .fem
// segment's MaxSideLength under a unit mistake) cut the segment into 3e10 pieces: the int count
// overflowed and the mesher ran for hours (found by fuzzing a .fem). Refused at once, naming the
// segment; a fine but finite cut counts in the element estimate.
TEST(BadInput, SegmentCutIntoTooManyPiecesIsRefusedNamingIt) {
  fixtures::PslgBuilder b;
  b.rectangle(0.0, 0.0, 0.03, 0.03);
  b.region(0.015, 0.015, "pot", 0.003);
  b.pslg.source = "cut.fem";
  b.pslg.segments[1].max_length = 1e-12;
  try {
    generate_mesh(b.pslg);
    FAIL() << "a segment of 3e10 pieces was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("cut.fem: segment 1 ", 0), 0u) << message;
    EXPECT_NE(message.find("with a maximum element length of 1e-12 m cuts the boundaries into "
                           "more than 5000000 pieces"),
              std::string::npos)
        << message;
  }
  b.pslg.segments[1].max_length = 1e-4;  // 300 pieces: about 600 triangles beside them
  MeshOptions options;
  options.max_elements = 1000;  // the region's own 3 mm elements are about 460
  try {
    generate_mesh(b.pslg, options);
    FAIL() << "the boundary's 600 triangles were not counted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the boundaries' own maximum lengths cut them into about "
                                         "300 pieces"),
              std::string::npos)
        << e.what();
  }
  options.max_elements = 100000;
  EXPECT_NO_THROW(generate_mesh(b.pslg, options));
}

}  // namespace
}  // namespace rheomag::mesh
