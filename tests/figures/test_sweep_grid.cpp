// Sweep results drawn as a grid: the CSV reader keeps the "ok" rows (quoted fields, empty cells
// as NaN), the grid has one row of panels per output with a number and one column per key, and
// `sweep --plot` writes it.

#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error.hpp"
#include "figures/sweep_grid.hpp"
#include "tests/cli_run.hpp"

namespace fs = std::filesystem;
using namespace rheomag::figures;

namespace {

fs::path temp(const std::string& name) {
  return fs::temp_directory_path() /
         ("rheomag_sweep_grid_" + std::to_string(::getpid()) + "_" + name);
}

}  // namespace

TEST(SweepGrid, ReadsOkRowsAndDrawsOnePanelPerOutputAndKey) {
  const fs::path csv = temp("table.csv");
  std::ofstream(csv) << "design_id,a,b,out.x,\"out,y\",empty,status,error\n"
                        "0,1,10,0.5,2,,ok,\n"
                        "1,2,10,0.7,3,,ok,\n"
                        "2,1,20,,,,error,\"mesh failed, \"\"gap\"\" too thin\"\n"
                        "3,2,20,0.9,4,,ok,\n";
  const SweepTable t = read_sweep_table(csv);
  ASSERT_EQ(t.columns.size(), 8u);
  EXPECT_EQ(t.columns[4], "out,y");
  ASSERT_EQ(t.rows.size(), 3u);  // the error row is left out
  EXPECT_EQ(t.rows[2][3], 0.9);
  EXPECT_TRUE(std::isnan(t.rows[0][5]));
  // Outputs with a number: out.x and out,y (not "empty"); keys a and b: 2 x 2 panels.
  const rheomag::plot::Figure f = sweep_figure(t, {"a", "b"}, 300, 200);
  EXPECT_EQ(f.width(), 600);
  EXPECT_EQ(f.height(), 400);
  EXPECT_THROW(sweep_figure(t, {"c"}, 300, 200), rheomag::InputError);
  fs::remove(csv);
}

TEST(SweepGrid, SweepPlotWritesTheGrid) {
  const fs::path dir = temp("cli");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "s.toml") << "[sweep]\nbase = \"" << RHEOMAG_SOURCE_DIR
                                << "/cases/annular_valve.toml\"\nmethod = \"factorial\"\n"
                                   "[[axis]]\nkey = \"geometry.gap_width\"\nvalues = [0.8, 1.0]\n"
                                   "[[axis]]\nkey = \"circuit.current\"\nvalues = [0.5, 1.0]\n"
                                   "[output]\ncsv = \"r.csv\"\n";
  const auto run = rheomag::cli_test::run_rheomag(
      "sweep '" + (dir / "s.toml").string() + "' --quiet --jobs 1 --out '" +
      (dir / "out").string() + "' --plot '" + (dir / "grid.png").string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  // The expected grid from the results file itself: 2 keys wide, one row per output column.
  const SweepTable t = read_sweep_table(dir / "out" / "r.csv");
  ASSERT_EQ(t.rows.size(), 4u);
  const auto first = std::find(t.columns.begin(), t.columns.end(), "circuit.current") + 1;
  const auto status = std::find(t.columns.begin(), t.columns.end(), "status");
  const int outputs = static_cast<int>(status - first);
  cairo_surface_t* image = cairo_image_surface_create_from_png((dir / "grid.png").c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(image), 2 * 560);
  EXPECT_EQ(cairo_image_surface_get_height(image), outputs * 340);
  cairo_surface_destroy(image);
  fs::remove_all(dir);
}
