// `rheomag report` on the reference valve: one self-contained page (inline SVG only, every id
// unique so that the pictures' glyphs and clips do not borrow each other's), which headless
// Chromium opens without a console message and renders to a screenshot that is not blank
// (skipped when chromium is absent, as the diagnosis report's test).

#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <string>

#include "tests/cli_run.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kValve = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

/// Writes the report of the reference valve into a fresh folder; returns report.html.
fs::path write_report(const std::string& tag) {
  const fs::path dir =
      fs::temp_directory_path() / ("rheomag_report_" + std::to_string(::getpid()) + "_" + tag);
  fs::remove_all(dir);
  const auto run = rheomag::cli_test::run_rheomag("report '" + kValve + "' --out '" + dir.string() +
                                                  "' --sweep-points 4");
  EXPECT_EQ(run.code, 0) << run.err;
  return dir / "report.html";
}

}  // namespace

TEST(ReportCli, PageIsSelfContainedWithUniqueIds) {
  const fs::path html = write_report("ids");
  const std::string text = slurp(html);
  // The only file written.
  const auto files = std::distance(fs::directory_iterator(html.parent_path()), {});
  EXPECT_EQ(files, 1);
  // Field map, two gaps, lambda/L and the valve's dp-Q (its [valve] flow): five inline
  // pictures; nothing fetched from elsewhere.
  std::size_t svgs = 0;
  for (std::size_t at = text.find("<svg"); at != std::string::npos; at = text.find("<svg", at + 1))
    ++svgs;
  EXPECT_EQ(svgs, 5u);
  EXPECT_NE(text.find("<h2>Pressure drop against flow</h2>"), std::string::npos);
  EXPECT_EQ(text.find("<img"), std::string::npos);
  EXPECT_EQ(text.find("<script"), std::string::npos);
  EXPECT_EQ(text.find("<?xml"), std::string::npos);
  EXPECT_NE(text.find("gap_top"), std::string::npos);
  const std::regex id_pattern("id=\"([^\"]+)\"");
  std::set<std::string> ids;
  std::size_t count = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), id_pattern);
       it != std::sregex_iterator(); ++it, ++count)
    EXPECT_TRUE(ids.insert((*it)[1]).second) << "id " << (*it)[1] << " appears twice";
  EXPECT_GT(count, 10u);  // Cairo's glyphs and clips do carry ids
  fs::remove_all(html.parent_path());
}

TEST(ReportCli, OpensInHeadlessChromiumWithoutConsoleMessages) {
  if (std::system("command -v chromium > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "chromium not installed";
  const fs::path html = write_report("chromium");
  const fs::path png = html.parent_path() / "shot.png", log = html.parent_path() / "chromium.log";
  const int rc = std::system(
      ("timeout 120 chromium --headless --no-sandbox --disable-gpu "
       "--disable-background-networking --disable-component-update --no-first-run "
       "--hide-scrollbars --enable-logging=stderr --v=0 --window-size=1000,1400 --screenshot=" +
       png.string() + " file://" + html.string() + " > /dev/null 2> " + log.string())
          .c_str());
  EXPECT_EQ(rc, 0);
  // Chromium logs every console message (errors, warnings, log) as "...:CONSOLE:..." lines;
  // the page has no script, so any of them is a fault of the page.
  const std::string messages = slurp(log);
  EXPECT_EQ(messages.find(":CONSOLE"), std::string::npos) << messages;
  cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS) << "no screenshot";
  const int w = cairo_image_surface_get_width(image), h = cairo_image_surface_get_height(image);
  const int stride = cairo_image_surface_get_stride(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  long coloured = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::uint32_t v = *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x);
      coloured += (v & 0xffffff) != 0xffffff;
    }
  }
  cairo_surface_destroy(image);
  // Not blank: the tables' text and the field map's colour bands cover well over 5 % of the
  // first screen (a blank page: 0 %).
  EXPECT_GT(static_cast<double>(coloured) / (static_cast<double>(w) * h), 0.05);
  fs::remove_all(html.parent_path());
}
