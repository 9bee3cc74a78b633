// The pictures of `rheomag thermal` show the computed temperatures. Temperature map of the
// reference valve (cases/annular_valve.toml, 1 L/min at its circuit current, steady): at the
// centroid of the hottest and of the coldest drawn triangle at least 3 pixels across (the mean of
// its corner temperatures) the PNG pixel read back has the colour of the bin of the colour bar that
// holds that mean, within one bin (a neighbour a pixel away may be drawn there); the hottest is in
// the top two bins and the coldest in the bottom two. Heating curves: drawn only for a transient;
// the command refuses --plot-history without --duration (exit 2 naming the option).

#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "tests/cli_run.hpp"
#include "thermal/thermal_pictures.hpp"
#include "thermal/thermal_report.hpp"

using namespace rheomag;
namespace fs = std::filesystem;

namespace {

const std::string kValve = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";

/// The colour of pixel (x, y) of an ARGB32 image (opaque).
plot::Rgb pixel(cairo_surface_t* image, int x, int y) {
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  const std::uint32_t v = *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x);
  return {((v >> 16) & 0xff) / 255.0, ((v >> 8) & 0xff) / 255.0, (v & 0xff) / 255.0};
}

thermal::ThermalReport valve_report(std::optional<double> duration) {
  const cases::Case c = cases::read_case_file(kValve);
  thermal::ThermalRequest request;
  request.point = {thermal::Motion::flow, c.problem.circuits.front().current, 1.0 / 60000.0, 1.0};
  request.duration = duration;
  request.steps = 20;
  return thermal::run_thermal(c, request);
}

}  // namespace

TEST(ThermalPictures, MapColoursMatchTheComputedTemperature) {
  const thermal::ThermalReport r = valve_report(std::nullopt);
  const thermal::TemperatureMap map = thermal::draw_temperature_map(r, 0);
  const fs::path png =
      fs::temp_directory_path() / ("rheomag_thermal_map_" + std::to_string(::getpid()) + ".png");
  map.figure.write(png, "test");
  cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  // The hottest and the coldest drawn triangle by the mean of their corners, among those whose
  // inscribed circle on the picture is at least 3 pixels wide (so that the centroid's pixel is
  // the triangle's own, clear of the region outlines drawn over edges).
  const auto corner_px = [&](std::size_t e, int i) {
    const mesh::Point& p = r.mesh.nodes[r.mesh.triangles[e][i]];
    return map.axes.to_px(1e3 * p.r, 1e3 * p.z);
  };
  int hottest = -1, coldest = -1;
  std::vector<double> mean(r.mesh.triangles.size(), 0.0);
  for (std::size_t e = 0; e < r.mesh.triangles.size(); ++e) {
    if (!r.regions[r.mesh.region[e]].active) continue;
    const auto a = corner_px(e, 0), b = corner_px(e, 1), c = corner_px(e, 2);
    const double area =
        0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
    const double perimeter = std::hypot(b[0] - a[0], b[1] - a[1]) +
                             std::hypot(c[0] - b[0], c[1] - b[1]) +
                             std::hypot(a[0] - c[0], a[1] - c[1]);
    if (2.0 * area / perimeter < 3.0) continue;
    for (int i = 0; i < 3; ++i) mean[e] += r.field.temperature[r.mesh.triangles[e][i]] / 3.0;
    if (hottest < 0 || mean[e] > mean[hottest]) hottest = static_cast<int>(e);
    if (coldest < 0 || mean[e] < mean[coldest]) coldest = static_cast<int>(e);
  }
  ASSERT_GE(hottest, 0);
  for (const int e : {hottest, coldest}) {
    double r_mm = 0.0, z_mm = 0.0;
    for (int i = 0; i < 3; ++i) {
      r_mm += 1e3 * r.mesh.nodes[r.mesh.triangles[e][i]].r / 3.0;
      z_mm += 1e3 * r.mesh.nodes[r.mesh.triangles[e][i]].z / 3.0;
    }
    const auto px = map.axes.to_px(r_mm, z_mm);
    const int drawn =
        map.colours.nearest_bin(pixel(image, static_cast<int>(px[0]), static_cast<int>(px[1])));
    const int expected = map.colours.bin(mean[e]);
    EXPECT_LE(std::abs(drawn - expected), 1)
        << (e == hottest ? "hottest" : "coldest") << " triangle at " << mean[e] << " deg C";
    if (e == hottest) {
      EXPECT_GE(drawn, map.colours.bins() - 2);
    } else {
      EXPECT_LE(drawn, 1);
    }
  }
  EXPECT_GT(mean[hottest], mean[coldest] + 1.0);  // a field with a visible range
  cairo_surface_destroy(image);
  fs::remove(png);
}

TEST(ThermalPictures, HeatingCurvesNeedATransient) {
  EXPECT_THROW(thermal::draw_heating_curves(valve_report(std::nullopt)), InputError);
  const plot::Figure curves = thermal::draw_heating_curves(valve_report(60.0));
  EXPECT_GT(curves.png().size(), 1000u);
  const auto run = cli_test::run_rheomag("thermal '" + kValve +
                                         "' --flow 1L/min --plot-history /tmp/rheomag_h.png");
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("--plot-history"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--duration"), std::string::npos) << run.err;
}
