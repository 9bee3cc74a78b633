// Flux lines of a planar uniform field, end to end: a FEMM planar air rectangle 40 x 20 mm with
// A = 0 on its left side and A = 1 mWb/m on its right (natural top and bottom) has the exact
// solution A = A1 x / W (B uniform, along y; P2 reproduces it to rounding). Its field map with
// 8 flux lines must show, on every pixel row crossed, 8 dark lines at x = (k + 1/2) W / 8
// (levels centred in [0, A1]): straight and parallel (the same x on three rows) and equally
// spaced, each within 1.5 px of the exact place.

#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "case/femm_import.hpp"
#include "figures/field_map.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "tests/magnetostatics/femm_text.hpp"

using namespace rheomag;
namespace fs = std::filesystem;

TEST(FieldMapFluxLines, UniformPlanarFieldGivesStraightParallelEquallySpacedLines) {
  constexpr double W = 0.04, A1 = 1e-3;  // width [m], A on the right side [Wb/m]
  constexpr int kLines = 8;
  rheomag::testing::FemText f;
  f.boundaries = {rheomag::testing::fem_boundary("left", 0, 0.0),
                  rheomag::testing::fem_boundary("right", 0, A1)};
  f.blocks = {rheomag::testing::fem_block("air", 1.0)};
  f.points = {"0 0 0 0", "0.04 0 0 0", "0.04 0.02 0 0", "0 0.02 0 0"};
  // Segment: n0 n1 max-side (-1 auto) boundary (1-based, 0 none) hidden group.
  f.segments = {"0 1 -1 0 0 0", "1 2 -1 2 0 0", "2 3 -1 0 0 0", "3 0 -1 1 0 0"};
  f.labels = {"0.02 0.01 1 0.002 0 0 0 1 0"};
  const magnetostatics::SolveResult s =
      magnetostatics::solve_problem(cases::parse_femm(f.str(), "uniform.fem"));
  figures::FieldMapOptions options;
  options.flux_lines = kLines;
  options.gap_labels = false;
  const figures::FieldMap map = figures::draw_field_map(*s.solver, s.solution, s.results, options);
  const fs::path png =
      fs::temp_directory_path() / ("rheomag_flux_lines_" + std::to_string(::getpid()) + ".png");
  map.figure.write(png, "test");
  cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  auto luminance = [&](int x, int y) {
    const std::uint32_t v = *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x);
    return (((v >> 16) & 0xff) + ((v >> 8) & 0xff) + (v & 0xff)) / (3.0 * 255.0);
  };
  const double px_per_mm = map.axes.to_px(1.0, 0.0)[0] - map.axes.to_px(0.0, 0.0)[0];
  ASSERT_GT(px_per_mm, 5.0);
  const int left = static_cast<int>(map.axes.to_px(0.0, 0.0)[0]) + 3;
  const int right = static_cast<int>(map.axes.to_px(1e3 * W, 0.0)[0]) - 3;
  for (double z_mm : {5.0, 10.0, 15.0}) {
    const int y = static_cast<int>(map.axes.to_px(0.0, z_mm)[1]);
    // Centres of the runs of dark pixels (the uniform field's band is light).
    std::vector<double> centres;
    double sum = 0.0;
    int count = 0;
    for (int x = left; x <= right; ++x) {
      if (luminance(x, y) < 0.35) {
        sum += x, ++count;
      } else if (count > 0) {
        centres.push_back(sum / count);
        sum = 0.0, count = 0;
      }
    }
    if (count > 0) centres.push_back(sum / count);
    ASSERT_EQ(centres.size(), static_cast<std::size_t>(kLines)) << "row at z = " << z_mm << " mm";
    for (int k = 0; k < kLines; ++k) {
      const double exact = map.axes.to_px(1e3 * W * (k + 0.5) / kLines, 0.0)[0];
      EXPECT_NEAR(centres[k], exact, 1.5) << "line " << k << " at z = " << z_mm << " mm";
    }
  }
  cairo_surface_destroy(image);
  fs::remove(png);
}
