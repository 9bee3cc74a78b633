// The field map of the reference valve (cases/annular_valve.toml at 1 A) shows the computed |B|:
// at the centre of each gap, at a point in the steel and one in the coil, the PNG pixel read back
// with cairo_image_surface_create_from_png has the colour of the bin of the colour bar that holds
// |B| computed there (flux_density_at), within one bin (the drawn piece's colour is |B| at the
// piece's centre, a fraction of an element away). Flux lines and labels are left off, so that
// they cannot cover the pixels; everything else is drawn as by `rheomag plot`.

#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "figures/field_map.hpp"
#include "magnetostatics/solve_problem.hpp"

const bool kLaterSectionsRegistered = rheomag::cases::register_case_section("valve") &&
                                      rheomag::cases::register_case_section("optimise");

using namespace rheomag;
namespace fs = std::filesystem;

namespace {

/// The colour of pixel (x, y) of an ARGB32 image (opaque).
plot::Rgb pixel(cairo_surface_t* image, int x, int y) {
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  const std::uint32_t v = *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x);
  return {((v >> 16) & 0xff) / 255.0, ((v >> 8) & 0xff) / 255.0, (v & 0xff) / 255.0};
}

/// The first region whose data satisfy `pick`, or -1.
template <class Pick>
int region_where(const cases::Problem& p, Pick pick) {
  for (int r = 0; r < static_cast<int>(p.regions.size()); ++r) {
    if (pick(p.regions[r], p.geometry.regions[r])) return r;
  }
  return -1;
}

}  // namespace

TEST(FieldMap, PixelColoursMatchTheComputedFluxDensity) {
  const cases::Case c =
      cases::read_case_file(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
  const magnetostatics::SolveResult solved = magnetostatics::solve_problem(c.problem);
  figures::FieldMapOptions options;
  options.flux_lines = 0;
  options.gap_labels = false;
  const figures::FieldMap map =
      figures::draw_field_map(*solved.solver, solved.solution, solved.results, options);
  const fs::path png =
      fs::temp_directory_path() / ("rheomag_field_map_" + std::to_string(::getpid()) + ".png");
  map.figure.write(png, "test");
  cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(image), options.width);
  EXPECT_EQ(cairo_image_surface_get_height(image), options.height);

  struct Probe {
    std::string what;
    mesh::Point at;  // [m]
    int region;
  };
  std::vector<Probe> probes;
  for (const magnetostatics::GapResult& g : solved.results.gaps) {
    probes.push_back(
        {"centre of " + g.name,
         {0.5 * (g.line_start.r + g.line_end.r), 0.5 * (g.line_start.z + g.line_end.z)},
         g.region});
  }
  const cases::Problem& p = c.problem;
  const int steel = region_where(p, [&](const cases::RegionData& d, const mesh::RegionSeed& s) {
    return s.gap == mesh::GapKind::none && d.material >= 0 && !p.materials[d.material].bh.empty();
  });
  const int coil = region_where(
      p, [](const cases::RegionData& d, const mesh::RegionSeed&) { return d.circuit >= 0; });
  ASSERT_GE(steel, 0);
  ASSERT_GE(coil, 0);
  probes.push_back(
      {"steel " + p.geometry.regions[steel].name, p.geometry.regions[steel].seed, steel});
  probes.push_back({"coil " + p.geometry.regions[coil].name, p.geometry.regions[coil].seed, coil});
  ASSERT_EQ(probes.size(), 4u);  // two gaps, steel, coil

  int distinct_bins = 0, last_bin = -1;
  for (const Probe& probe : probes) {
    std::array<double, 2> b;
    ASSERT_TRUE(
        magnetostatics::flux_density_at(*solved.solver, solved.solution, probe.at, probe.region, b))
        << probe.what;
    const double magnitude = std::hypot(b[0], b[1]);
    const auto px = map.axes.to_px(1e3 * probe.at.r, 1e3 * probe.at.z);
    const int x = static_cast<int>(px[0]), y = static_cast<int>(px[1]);
    ASSERT_TRUE(x >= 0 && y >= 0 && x < options.width && y < options.height) << probe.what;
    const int drawn = map.colours.nearest_bin(pixel(image, x, y));
    const int expected = map.colours.bin(magnitude);
    RecordProperty(probe.what, std::to_string(magnitude) + " T: bin " + std::to_string(expected) +
                                   ", drawn " + std::to_string(drawn));
    EXPECT_LE(std::abs(drawn - expected), 1)
        << probe.what << ": |B| = " << magnitude << " T is bin " << expected << ", the pixel at ("
        << x << ", " << y << ") has the colour of bin " << drawn;
    if (expected != last_bin) ++distinct_bins, last_bin = expected;
  }
  // The check means something only if the points do not all sit in one bin.
  EXPECT_GE(distinct_bins, 2);
  cairo_surface_destroy(image);
  fs::remove(png);
}
