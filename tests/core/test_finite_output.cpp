// The non-finite guard of every output: which tokens count, the key path named in a JSON
// document, and the atomic writer refusing text with NaN/inf before touching the old file.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/finite_output.hpp"

namespace fs = std::filesystem;
using rheomag::NonFiniteOutputError;

namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const NonFiniteOutputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(FiniteOutput, NonFiniteSpellingsFound) {
  for (const char* text : {"nan", "-nan", "NaN", "inf", "-inf", "+inf", "Infinity", "-INF",
                           "x = nan(0x8)", "1,2,-nan\n"}) {
    const auto t = rheomag::find_non_finite_token(text);
    EXPECT_TRUE(t.has_value()) << text;
  }
  const auto t = rheomag::find_non_finite_token("a,b\n1,2\n3,-inf\n");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->line, 3u);
  EXPECT_EQ(t->token, "-inf");
  EXPECT_EQ(t->line_text, "3,-inf");
}

TEST(FiniteOutput, WordsContainingNanOrInfAreNotNumbers) {
  for (const char* text : {"information", "isNaN(x)", "inflow", "nanometre", "infinite",
                           "infeasible", "banana", "1e+300", "dp_inf_2", "nan_count"}) {
    EXPECT_FALSE(rheomag::find_non_finite_token(text).has_value()) << text;
  }
}

TEST(FiniteOutput, JsonKeyPathNamed) {
  nlohmann::json j = {{"model", "bingham"}, {"fits", nlohmann::json::array()}};
  j["fits"].push_back({{"fit_percent", 91.0}});
  j["fits"].push_back({{"fit_percent", -std::numeric_limits<double>::infinity()}});
  j["standard_error"] = nullptr;  // null stays allowed: it says "not known"
  EXPECT_EQ(message_of([&] { rheomag::require_finite_json(j, "out.json"); }),
            "out.json: key 'fits[1].fit_percent' is not a finite number; the result was not "
            "written");
  j["fits"][1]["fit_percent"] = 80.0;
  EXPECT_EQ(rheomag::finite_json_text(j, "out.json"), j.dump());
}

TEST(FiniteOutput, AtomicWriterRefusesNonFiniteTextAndKeepsTheOldFile) {
  const fs::path dir = fs::temp_directory_path() / "rheomag_finite_output";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path target = dir / "traces.csv";
  rheomag::write_file_atomically(target, "t,force\n0,1\n");
  EXPECT_EQ(
      message_of([&] { rheomag::write_file_atomically(target, "t,force\n0,1\n1,nan\n"); }),
      target.string() +
          ":3: the result holds a non-finite number ('nan' in \"1,nan\"); it was not written");
  std::ifstream in(target);
  std::stringstream kept;
  kept << in.rdbuf();
  EXPECT_EQ(kept.str(), "t,force\n0,1\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

TEST(FiniteOutput, ValuesIndexNamed) {
  const std::vector<double> v = {1.0, 2.0, -std::numeric_limits<double>::infinity()};
  EXPECT_EQ(
      message_of([&] { rheomag::require_finite_values(v, "out.vtu", "field 'B':"); }),
      "out.vtu: field 'B': value 2 is not a finite number (-inf); the result was not written");
  rheomag::require_finite_values(std::vector<double>{1.0, 0.0}, "out.vtu", "field 'B':");
}
