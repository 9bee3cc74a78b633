// `rheomag plot`, `solve --plot` and the gap profiles of `solve --json`, run as a user would, on
// the reference valve cases/annular_valve.toml.

#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_run.hpp"

namespace fs = std::filesystem;
using rheomag::cli_test::run_rheomag;

namespace {

const std::string kValve = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";

fs::path fresh_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("rheomag_plot_cli_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Width and height of a PNG file, (-1, -1) when it does not read as one.
std::pair<int, int> png_size(const fs::path& path) {
  cairo_surface_t* image = cairo_image_surface_create_from_png(path.c_str());
  std::pair<int, int> size{-1, -1};
  if (cairo_surface_status(image) == CAIRO_STATUS_SUCCESS)
    size = {cairo_image_surface_get_width(image), cairo_image_surface_get_height(image)};
  cairo_surface_destroy(image);
  return size;
}

}  // namespace

// The mean of each gap's mid-line profile is the mid-line average the same JSON reports (same
// samples: to 1e-12 relative), and close to the gap's area average B_avg: the field hardly varies
// across a thin gap, 2 % allowed (measured 1 % on this valve: 0.699 vs 0.706 T).
TEST(PlotCli, ProfileMeanEqualsReportedAverages) {
  const auto run = run_rheomag("solve '" + kValve + "' --json");
  ASSERT_EQ(run.code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["gaps"].size(), 2u);
  for (const auto& g : j["gaps"]) {
    const auto& p = g["profile"];
    const std::size_t n = p["s"].size();
    ASSERT_EQ(n, g["midline"]["samples"].get<std::size_t>());
    ASSERT_GT(n, 100u);
    ASSERT_EQ(p["B_n"].size(), n);
    ASSERT_EQ(p["B_t"].size(), n);
    double b = 0.0, bn = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      b += std::hypot(p["B_n"][i].get<double>(), p["B_t"][i].get<double>());
      bn += std::abs(p["B_n"][i].get<double>());
      if (i > 0) {
        EXPECT_GT(p["s"][i].get<double>(), p["s"][i - 1].get<double>());
      }
    }
    b /= static_cast<double>(n), bn /= static_cast<double>(n);
    const double midline = g["midline"]["B"]["average"], midline_n = g["midline"]["Bn"]["average"];
    EXPECT_NEAR(b, midline, 1e-12 * midline);
    EXPECT_NEAR(bn, midline_n, 1e-12 * midline_n);
    const double area = g["B_avg"];
    EXPECT_NEAR(b, area, 0.02 * area) << g["name"];
    // Both walls are sampled along the whole gap.
    ASSERT_EQ(p["walls"].size(), 2u);
    for (const auto& wall : p["walls"]) EXPECT_EQ(wall["s"].size(), n);
  }
}

TEST(PlotCli, PlotWritesEveryPictureAtTheRequestedSize) {
  const fs::path dir = fresh_dir("set");
  const auto run = run_rheomag("plot '" + kValve + "' --out '" + (dir / "pictures").string() +
                               "' --width 640 --height 480 --sweep-points 4");
  ASSERT_EQ(run.code, 0) << run.err;
  for (const char* stem : {"field_map", "gap_gap_top", "gap_gap_bottom", "lambda_L"}) {
    for (const char* ext : {".png", ".svg"}) {
      const fs::path file = dir / "pictures" / (std::string(stem) + ext);
      EXPECT_TRUE(fs::exists(file)) << file;
      EXPECT_NE(run.out.find(file.string()), std::string::npos) << run.out;
    }
  }
  EXPECT_EQ(png_size(dir / "pictures" / "field_map.png"), std::make_pair(640, 480));
  EXPECT_EQ(png_size(dir / "pictures" / "gap_gap_top.png"), std::make_pair(900, 560));
  std::ifstream svg(dir / "pictures" / "field_map.svg");
  std::string head(200, '\0');
  svg.read(head.data(), 200);
  EXPECT_NE(head.find("<svg"), std::string::npos);
  // Nothing but the pictures is written, all inside the given folder.
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) files += entry.is_regular_file();
  EXPECT_EQ(files, 8);
  fs::remove_all(dir);
}

TEST(PlotCli, SolvePlotWritesTheFieldMap) {
  const fs::path dir = fresh_dir("solve");
  const auto run =
      run_rheomag("solve '" + kValve + "' --plot '" + (dir / "map.png").string() + "' --json");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(png_size(dir / "map.png"), std::make_pair(1000, 800));
  EXPECT_EQ(nlohmann::json::parse(run.out)["plot"], (dir / "map.png").string());
  fs::remove_all(dir);
}

TEST(PlotCli, BadPictureNameOrSizeExitsTwoNamingTheOption) {
  const fs::path dir = fresh_dir("bad");
  const auto jpg =
      run_rheomag("solve '" + kValve + "' --plot '" + (dir / "map.jpg").string() + "'");
  EXPECT_EQ(jpg.code, 2);
  EXPECT_NE(jpg.err.find("--plot"), std::string::npos) << jpg.err;
  EXPECT_NE(jpg.err.find(".png or .svg"), std::string::npos) << jpg.err;
  EXPECT_FALSE(fs::exists(dir / "map.jpg"));
  const auto tiny = run_rheomag("plot '" + kValve + "' --out '" + dir.string() + "' --width 10");
  EXPECT_EQ(tiny.code, 2);
  EXPECT_NE(tiny.err.find("--width"), std::string::npos) << tiny.err;
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

// `valve --plot` and `transient --plot` write their pictures at the stated size (900 x 800,
// 900 x 1000) and name them in the JSON.
TEST(PlotCli, ValveAndTransientPlotsAreWritten) {
  const fs::path dir = fresh_dir("valve");
  const auto valve = run_rheomag("valve '" + kValve + "' --current 0,1 --flow 1e-5,4e-5 --json " +
                                 "--plot '" + (dir / "dp.svg").string() + "'");
  ASSERT_EQ(valve.code, 0) << valve.err;
  EXPECT_EQ(nlohmann::json::parse(valve.out)["plot"], (dir / "dp.svg").string());
  EXPECT_TRUE(fs::exists(dir / "dp.svg"));
  const auto step = run_rheomag("transient '" + kValve +
                                "' --current 1 --duration 0.02 --steps 4 --quiet --plot '" +
                                (dir / "step.png").string() + "'");
  ASSERT_EQ(step.code, 0) << step.err;
  EXPECT_EQ(png_size(dir / "step.png"), std::make_pair(900, 1000));
  const auto bad =
      run_rheomag("transient '" + kValve + "' --current 1 --duration 0.02 --steps 4 --plot '" +
                  (dir / "step.gif").string() + "'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--plot"), std::string::npos) << bad.err;
  fs::remove_all(dir);
}

// `damper --plot` and `brake --plot`: the picture is written at 900 x 600 and named in the JSON;
// the curves' numbers are those of the same JSON (one run of each).
TEST(PlotCli, DamperAndBrakePlotsAreWritten) {
  const fs::path dir = fresh_dir("devices");
  const std::string cases = std::string(RHEOMAG_SOURCE_DIR) + "/cases/";
  const auto damper =
      run_rheomag("damper '" + cases + "damper_paper004.toml' --current 0,1 " +
                  "--velocity 0.05,0.15 --json --plot '" + (dir / "fv.png").string() + "'");
  ASSERT_EQ(damper.code, 0) << damper.err;
  EXPECT_EQ(nlohmann::json::parse(damper.out)["plot"], (dir / "fv.png").string());
  EXPECT_EQ(png_size(dir / "fv.png"), std::make_pair(900, 600));
  const auto brake = run_rheomag("brake '" + cases + "brake_drum.toml' --current 0,1 " +
                                 "--speed 1,10 --plot '" + (dir / "ts.svg").string() + "'");
  ASSERT_EQ(brake.code, 0) << brake.err;
  EXPECT_TRUE(fs::exists(dir / "ts.svg"));
  EXPECT_NE(brake.out.find("wrote " + (dir / "ts.svg").string()), std::string::npos);
  fs::remove_all(dir);
}

// `solve --3d --plot`: the gaps' B_avg_theta as a polar plot at 800 x 700, named in the JSON.
TEST(PlotCli, Solve3dPlotsTheCircumferentialFluxDensity) {
  const fs::path dir = fresh_dir("3d");
  const auto run = run_rheomag("solve '" + kValve + "' --3d --mesher swept --json --plot '" +
                               (dir / "theta.png").string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(nlohmann::json::parse(run.out)["plot"], (dir / "theta.png").string());
  EXPECT_EQ(png_size(dir / "theta.png"), std::make_pair(800, 700));
  fs::remove_all(dir);
}
