#pragma once
// The pictures of `rheomag thermal`: the temperature map of the thermal model (banded colours,
// isotherms, region outlines) and a transient's heating curves with the limit.

#include "plot/axes.hpp"
#include "plot/colour_map.hpp"
#include "plot/figure.hpp"
#include "thermal/thermal_report.hpp"

namespace rheomag::thermal {

/// A drawn temperature map and how it maps the model (mm) and the temperature onto its pixels.
struct TemperatureMap {
  plot::Figure figure;
  plot::Axes axes;          ///< data in mm: (r, z) or (x, y)
  plot::ColourMap colours;  ///< temperature [deg C]
};

/// The temperature of the report's state over the thermal model's triangles (each coloured by the
/// mean of its corner temperatures, `bins` bands), `isotherms` contour lines of the field linear
/// on the corners, the region outlines and a colour bar in deg C; r-z (or x-y) in mm at true
/// aspect ratio.
TemperatureMap draw_temperature_map(const ThermalReport& report, int isotherms = 12, int bins = 16,
                                    int width = 1000, int height = 800);

/// A transient's coil and fluid temperatures (mean and hottest point) against time, with the
/// limit and the time it was reached. InputError when the report holds no transient.
plot::Figure draw_heating_curves(const ThermalReport& report, int width = 900, int height = 560);

}  // namespace rheomag::thermal
