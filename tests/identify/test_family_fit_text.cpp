// The text `fit-family` prints: its tables of recordings stay aligned whatever paths the user
// gave (a recording column as wide as the longest path, the same in every table).

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "identify/family_fit_output.hpp"

using namespace rheomag::identify;

namespace {

/// A member with a FIT, no regimes (constant motion) and nothing else.
FamilyMember member(const std::string& path, double fit_percent) {
  FamilyMember m;
  m.csv_path = path;
  m.metrics.fit_percent = fit_percent;
  return m;
}

/// The column at which `token` starts on the line that holds `path`, or npos.
std::size_t column_after(const std::string& text, const std::string& path,
                         const std::string& token) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t at = line.find(path);
    if (at == std::string::npos) continue;
    return line.find(token, at + path.size());
  }
  return std::string::npos;
}

}  // namespace

// Reference: the layout itself. A 70-character path (longer than the 40-character default) and a
// short one, in the training and the predicted tables: the FIT column (87.5, 91.0 and 93.0, printed
// right-aligned in 8 characters after the 8-character field column) starts at the same character
// on every row, and the regime table's first cell ("- (constant motion)") too.
TEST(FamilyFitText, ColumnsStayAlignedWithLongPaths) {
  const std::string long_path(
      "/data/a/lab/with/a/long/folder/name/and/more/tests/0x87V_test10_2.csv");
  ASSERT_GT(long_path.size(), 40u);
  FamilyFit r;
  r.fit.model = "lugre";
  r.training = {member("short.csv", 87.5), member(long_path, 91.0)};
  r.predicted = {member("other.csv", 93.0)};
  std::ostringstream out;
  write_family_fit_text(r, 2, 1, out);
  const std::string text = out.str();
  const std::size_t short_fit = column_after(text, "short.csv", "87.5");
  const std::size_t long_fit = column_after(text, long_path, "91.0");
  const std::size_t other_fit = column_after(text, "other.csv", "93.0");
  ASSERT_NE(short_fit, std::string::npos) << text;
  EXPECT_EQ(short_fit, long_fit) << text;
  EXPECT_EQ(short_fit, other_fit) << text;
  // The regime rows: one per member (the first occurrence of each path is the FIT table's).
  const std::size_t regimes = text.find("residual by regime");
  ASSERT_NE(regimes, std::string::npos) << text;
  const std::string tail = text.substr(regimes);
  const std::size_t short_regime = column_after(tail, "short.csv", "- (constant motion)");
  const std::size_t long_regime = column_after(tail, long_path, "- (constant motion)");
  ASSERT_NE(short_regime, std::string::npos) << tail;
  EXPECT_EQ(short_regime, long_regime) << tail;
}
