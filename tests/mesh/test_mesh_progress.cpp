// `mesh` of a large case reports its refinement (issue #36: a case with 10^5 regions meshed for
// minutes without a word): the progress callback hears the start and the end with the estimate
// as the total, every 20 000 points in between, and the mesh is the same as without it.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/progress.hpp"
#include "mesh/mesher.hpp"
#include "pslg_fixtures.hpp"

namespace rheomag::mesh {
namespace {

// A 30 mm square of 0.1 mm elements: about 4.2e5 triangles estimated.
TEST(MeshProgress, RefinementIsReportedAndTheMeshUnchanged) {
  fixtures::PslgBuilder b;
  b.rectangle(0.0, 0.0, 0.03, 0.03);
  b.region(0.015, 0.015, "pot", 1e-4);
  MeshOptions quiet;
  quiet.order = 1;
  const Mesh reference = generate_mesh(b.pslg, quiet);
  std::vector<ProgressEvent> events;
  MeshOptions heard = quiet;
  heard.progress = [&events](const ProgressEvent& e) { events.push_back(e); };
  const Mesh reported = generate_mesh(b.pslg, heard);
  EXPECT_EQ(reported.nodes.size(), reference.nodes.size());
  EXPECT_EQ(reported.triangles, reference.triangles);
  // The checked geometry, the lattice of target sizes (every 20 000 points), the refinement's
  // start and end (and every 20 000 points).
  ASSERT_GE(events.size(), 4u);
  EXPECT_EQ(events.front().stage, "geometry checked");
  EXPECT_EQ(events.back().stage, "refined");
  EXPECT_NEAR(events.front().total, 4.16e5, 0.01e5);  // 2 x 9e-4 / (sqrt(3)/4 x 1e-8)
  for (std::size_t k = 1; k < events.size(); ++k) EXPECT_GE(events[k].done, events[k - 1].done);
  // The end's count (twice the vertices) is within 10 % of the triangles made.
  EXPECT_NEAR(events.back().done, static_cast<double>(reference.triangles.size()),
              0.1 * static_cast<double>(reference.triangles.size()));
}

}  // namespace
}  // namespace rheomag::mesh
