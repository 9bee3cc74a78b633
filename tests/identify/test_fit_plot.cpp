// What `fit --plot` draws: the figure's text as written. The script of identify/fit_plot.hpp is
// run by gnuplot with its PNG terminal swapped for the text terminal, so the test reads the
// title, key and labels the picture carries.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "identify/fit_plot.hpp"

namespace fs = std::filesystem;
using namespace rheomag::identify;

// Reference: the title and labels given. A recording named 0V_test4_1.csv (UTFPR's file names)
// was drawn as "0Vtest41" with subscripts: gnuplot's enhanced text reads '_' as a subscript.
// The text terminal is asked for enhanced text before the script's own terminal options, so the
// test fails unless the script turns it off.
TEST(FitPlot, NamesWithUnderscoresAreDrawnAsWritten) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot missing";
  const fs::path dir =
      fs::temp_directory_path() / ("rheomag_fit_plot_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string data = (dir / "segment_0.dat").string();
  std::ofstream(data) << "0 1 1.1 -0.1\n1 2 1.9 0.1\n2 1 1.2 -0.2\n";
  const PlotSegment segment{"training_part", {0, 1, 2}, {1, 2, 1}, {1.1, 1.9, 1.2}};
  std::string script = fit_plot_script((dir / "out.png").string(), "damper on 0V_test4_1.csv",
                                       "force_N", {segment}, {data});
  const std::string text = (dir / "out.txt").string();
  script = std::regex_replace(script, std::regex("set terminal pngcairo size [0-9,]+ font '[^']*'"),
                              "set terminal dumb size 140,50 enhanced");
  script = std::regex_replace(script, std::regex("set output '[^']*out\\.png'"),
                              "set output '" + text + "'");
  std::ofstream(dir / "plot.gp") << script;
  ASSERT_EQ(std::system(("gnuplot " + (dir / "plot.gp").string() + " 2>/dev/null").c_str()), 0);
  std::stringstream drawn;
  drawn << std::ifstream(text).rdbuf();
  fs::remove_all(dir);
  EXPECT_NE(drawn.str().find("damper on 0V_test4_1.csv"), std::string::npos) << drawn.str();
  EXPECT_NE(drawn.str().find("model, training_part"), std::string::npos) << drawn.str();
}
