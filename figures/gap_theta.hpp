#pragma once
// A 3D solve's gap flux density around the circumference, as a polar plot.

#include <string>

#include "magnetostatics3d/results3d.hpp"
#include "plot/figure.hpp"

namespace rheomag::figures {

/// Each gap's B_avg_theta (mean |B| of each 10-degree sector, at the sector's centre angle) as a
/// closed curve against phi.
plot::Figure gap_theta_figure(const magnetostatics3d::Results3d& results, const std::string& name,
                              int width, int height);

}  // namespace rheomag::figures
