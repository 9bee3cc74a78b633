// Figures come out at the requested size in both formats, a written PNG reads back with the
// colours drawn, and banded colour maps read back bin for bin.

#include <cairo.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "plot/colour_map.hpp"
#include "plot/figure.hpp"
#include "plot/line_plot.hpp"

using namespace rheomag::plot;
namespace fs = std::filesystem;

namespace {

fs::path temp_path(const std::string& name) {
  return fs::temp_directory_path() / ("rheomag_plot_" + std::to_string(::getpid()) + "_" + name);
}

}  // namespace

TEST(Figure, PngAndSvgHaveTheRequestedSize) {
  LinePlot p;
  p.title = "size";
  p.series.push_back({"y = x^2", {0, 1, 2, 3}, {0, 1, 4, 9}, series_colour(0)});
  const Figure figure = line_plot_figure(p, 640, 410);
  const fs::path png = temp_path("size.png"), svg = temp_path("size.svg");
  figure.write(png, "test");
  figure.write(svg, "test");
  cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(image), 640);
  EXPECT_EQ(cairo_image_surface_get_height(image), 410);
  cairo_surface_destroy(image);
  std::ifstream in(svg);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("width=\"640pt\" height=\"410pt\""), std::string::npos)
      << text.substr(0, 300);
  fs::remove(png);
  fs::remove(svg);
}

TEST(Figure, OtherExtensionIsRefusedNamingTheOption) {
  const Figure figure(100, 100);
  try {
    figure.write(temp_path("x.jpg"), "--plot");
    FAIL() << "a .jpg name was accepted";
  } catch (const rheomag::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--plot"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find(".png or .svg"), std::string::npos);
  }
}

TEST(Figure, PngReadsBackTheDrawnColour) {
  const Figure figure(50, 40);
  cairo_set_source_rgb(figure.cr(), 0.2, 0.4, 0.6);
  cairo_rectangle(figure.cr(), 10, 10, 20, 20);
  cairo_fill(figure.cr());
  const fs::path png = temp_path("colour.png");
  figure.write(png, "test");
  cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  // ARGB32, native-endian 32-bit words: blue in the lowest byte on x86.
  const std::uint32_t inside = *reinterpret_cast<const std::uint32_t*>(data + 20 * stride + 4 * 20);
  const std::uint32_t outside = *reinterpret_cast<const std::uint32_t*>(data + 2 * stride + 4 * 2);
  EXPECT_NEAR((inside >> 16) & 0xff, 0.2 * 255, 1.0);
  EXPECT_NEAR((inside >> 8) & 0xff, 0.4 * 255, 1.0);
  EXPECT_NEAR(inside & 0xff, 0.6 * 255, 1.0);
  EXPECT_EQ(outside & 0xffffff, 0xffffffu);
  cairo_surface_destroy(image);
  fs::remove(png);
}

TEST(ColourMap, EveryBinReadsBackFromItsEightBitColour) {
  const ColourMap map(0.0, 2.0, 20);
  for (int i = 0; i < map.bins(); ++i) {
    Rgb c = map.bin_colour(i);
    // What a PNG stores: 8 bits per channel.
    c = {std::round(c.r * 255) / 255, std::round(c.g * 255) / 255, std::round(c.b * 255) / 255};
    EXPECT_EQ(map.nearest_bin(c), i);
  }
  EXPECT_EQ(map.bin(0.05), 0);
  EXPECT_EQ(map.bin(0.15), 1);
  EXPECT_EQ(map.bin(1.99), 19);
  EXPECT_EQ(map.bin(5.0), 19);  // clamped
  EXPECT_EQ(map.bin(-1.0), 0);
}
