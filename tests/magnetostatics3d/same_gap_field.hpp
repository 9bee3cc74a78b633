#pragma once
// Comparing two 3D solutions of one model: every sector of every gap and the flux linkage.

#include <gtest/gtest.h>

#include "magnetostatics3d/results3d.hpp"

namespace rheomag::magnetostatics3d {

/// Expects every 10-degree sector average of every gap and the first circuit's flux linkage of
/// `other` within `tolerance` (relative) of `reference`'s.
inline void expect_same_gap_field(const Results3d& reference, const Results3d& other,
                                  double tolerance) {
  ASSERT_EQ(reference.gaps.size(), other.gaps.size());
  for (std::size_t g = 0; g < reference.gaps.size(); ++g)
    for (int k = 0; k < kThetaSectors; ++k)
      EXPECT_NEAR(other.gaps[g].b_avg_theta[k] / reference.gaps[g].b_avg_theta[k], 1.0, tolerance)
          << reference.gaps[g].name << " sector " << k;
  EXPECT_NEAR(other.circuits.at(0).flux_linkage / reference.circuits.at(0).flux_linkage, 1.0,
              tolerance);
}

}  // namespace rheomag::magnetostatics3d
