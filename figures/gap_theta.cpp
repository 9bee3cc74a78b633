#include "figures/gap_theta.hpp"

#include <cmath>

#include "plot/line_plot.hpp"
#include "plot/polar_plot.hpp"

namespace rheomag::figures {

plot::Figure gap_theta_figure(const magnetostatics3d::Results3d& results, const std::string& name,
                              int width, int height) {
  plot::PolarPlot p;
  p.title = name + ": mean |B| of each gap per 10\u00b0 sector (3D)";
  p.unit = "|B| [T]";
  constexpr int kSectors = magnetostatics3d::kThetaSectors;
  for (std::size_t g = 0; g < results.gaps.size(); ++g) {
    plot::PolarSeries s{results.gaps[g].name, {}, {}, plot::series_colour(static_cast<int>(g))};
    for (int k = 0; k < kSectors; ++k) {
      s.angle.push_back((k + 0.5) * 2.0 * M_PI / kSectors);
      s.radius.push_back(results.gaps[g].b_avg_theta[k]);
    }
    p.series.push_back(std::move(s));
  }
  return plot::polar_plot_figure(p, width, height);
}

}  // namespace rheomag::figures
