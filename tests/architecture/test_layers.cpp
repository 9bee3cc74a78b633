// The layer order is enforced, not only written down: the real tree is checked against the layer
// table of docs/architecture.md, and the check is shown to fail on planted violations.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "tests/architecture/layer_rules.hpp"

namespace {

namespace fs = std::filesystem;
using namespace rheomag::architecture;

const fs::path kRoot = RHEOMAG_SOURCE_DIR;
const std::set<std::string> kUnlayered = {"tests", "bench"};

/// Every violation, one per line, for a failure message.
std::string listed(const std::vector<Violation>& violations) {
  std::string text;
  for (const auto& v : violations)
    text += v.file + ":" + std::to_string(v.line) + ": " + v.text + "\n";
  return text;
}

/// A fresh empty folder under the system's temporary folder, removed at the end of the test.
class ScratchTree : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ =
        fs::temp_directory_path() / ("rheomag_layers_" + std::to_string(std::random_device{}()));
    fs::create_directories(root_ / "docs");
  }
  void TearDown() override { fs::remove_all(root_); }
  /// Writes `text` to `relative` under the scratch root (folders created).
  void write(const std::string& relative, const std::string& text) {
    fs::create_directories((root_ / relative).parent_path());
    std::ofstream(root_ / relative) << text;
  }
  fs::path root_;
};

const char* kTwoLayers =
    "# Architecture\n\n| layer | depends on | owns |\n|---|---|---|\n"
    "| `low` | nothing of rheomag | a |\n| `high` | low, Eigen | b |\n";

TEST(Layers, RealTreeFollowsTheLayerTable) {
  const LayerTable table = read_layer_table(kRoot / "docs/architecture.md");
  ASSERT_TRUE(table.count("core") && table.count("app")) << "the table lost its ends";
  const auto violations = check_tree(kRoot, table, kUnlayered);
  EXPECT_TRUE(violations.empty()) << listed(violations);
}

TEST(Layers, EveryLayerOfTheTableIsAFolderWithABuildAndARowInTheReadme) {
  const LayerTable table = read_layer_table(kRoot / "docs/architecture.md");
  std::ifstream in(kRoot / "README.md");
  const std::string readme((std::istreambuf_iterator<char>(in)), {});
  for (const auto& [layer, deps] : table) {
    EXPECT_TRUE(fs::exists(kRoot / layer / "CMakeLists.txt")) << layer << " has no folder";
    EXPECT_NE(readme.find("| `" + layer + "/` |"), std::string::npos)
        << layer << " has no row in the README's layout table";
  }
}

TEST_F(ScratchTree, UpwardIncludeIsReportedWithItsFileAndLine) {
  write("docs/architecture.md", kTwoLayers);
  write("low/a.hpp", "#pragma once\n#include <vector>\n#include \"high/b.hpp\"\n");
  write("high/b.hpp", "#pragma once\n#include \"low/a.hpp\"\n#include <Eigen/Dense>\n");
  const auto violations =
      check_tree(root_, read_layer_table(root_ / "docs/architecture.md"), kUnlayered);
  ASSERT_EQ(violations.size(), 1u) << listed(violations);
  EXPECT_EQ(violations[0].file, "low/a.hpp");
  EXPECT_EQ(violations[0].line, 3);
  EXPECT_NE(violations[0].text.find("low includes high/b.hpp"), std::string::npos);
}

TEST_F(ScratchTree, PlantedUpwardIncludeInACopyOfTheRealCoreIsReported) {
  fs::copy(kRoot / "docs/architecture.md", root_ / "docs/architecture.md");
  fs::copy(kRoot / "core", root_ / "core", fs::copy_options::recursive);
  const LayerTable table = read_layer_table(root_ / "docs/architecture.md");
  EXPECT_TRUE(check_tree(root_, table, kUnlayered).empty()) << "the copy alone must pass";
  std::ofstream(root_ / "core/error.hpp", std::ios::app) << "#include \"app/command.hpp\"\n";
  const auto violations = check_tree(root_, table, kUnlayered);
  ASSERT_EQ(violations.size(), 1u) << listed(violations);
  EXPECT_EQ(violations[0].file, "core/error.hpp");
}

TEST_F(ScratchTree, UpwardLinkInACMakeListsIsReported) {
  write("docs/architecture.md", kTwoLayers);
  write("low/CMakeLists.txt",
        "add_library(rheomag_low a.cpp)  # not rheomag_high\n"
        "target_link_libraries(rheomag_low PUBLIC rheomag_high)\n");
  const auto violations =
      check_tree(root_, read_layer_table(root_ / "docs/architecture.md"), kUnlayered);
  ASSERT_EQ(violations.size(), 1u) << listed(violations);
  EXPECT_EQ(violations[0].file, "low/CMakeLists.txt");
  EXPECT_EQ(violations[0].line, 2);
}

TEST_F(ScratchTree, FolderWithoutARowIsReported) {
  write("docs/architecture.md", kTwoLayers);
  write("extra/CMakeLists.txt", "add_library(rheomag_extra x.cpp)\n");
  write("tests/CMakeLists.txt", "\n");
  const auto violations =
      check_tree(root_, read_layer_table(root_ / "docs/architecture.md"), kUnlayered);
  ASSERT_EQ(violations.size(), 1u) << listed(violations);
  EXPECT_EQ(violations[0].file, "extra/CMakeLists.txt");
}

TEST_F(ScratchTree, CircleInTheTableIsRefused) {
  write("docs/architecture.md",
        "| layer | depends on |\n|---|---|\n| `a` | b |\n| `b` | c |\n| `c` | a |\n");
  try {
    read_layer_table(root_ / "docs/architecture.md");
    FAIL() << "a circle was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("circle"), std::string::npos) << e.what();
  }
}

TEST_F(ScratchTree, TransitiveDependenciesAreAllowed) {
  write("docs/architecture.md",
        "| layer | depends on |\n|---|---|\n| `a` | nothing |\n| `b` | a |\n| `c` | b |\n"
        "| `app` | all |\n");
  const LayerTable table = read_layer_table(root_ / "docs/architecture.md");
  EXPECT_EQ(allowed_layers(table, "c"), (std::set<std::string>{"a", "b", "c"}));
  EXPECT_EQ(allowed_layers(table, "a"), (std::set<std::string>{"a"}));
  EXPECT_EQ(allowed_layers(table, "app").size(), 4u);
}

}  // namespace

// Issue 36: `sweep -j -1` said "Value -1 not in range 0.000000 to 1797693134862315…" (309 digits):
// CLI11's range validators print an open end as the largest double. Every numeric option of app/
// checks its range with app::in_domain (the readers' wording); this scan fails on a CLI11 one.
TEST(AppOptions, NoCli11RangeValidatorPrintsTheLargestDouble) {
  std::string found;
  for (const auto& entry : fs::directory_iterator(kRoot / "app")) {
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      for (const char* v : {"CLI::Range", "CLI::Bound", "CLI::PositiveNumber",
                            "CLI::NonNegativeNumber", "CLI::Number"})
        if (line.find(v) != std::string::npos && line.find("//") == std::string::npos)
          found += entry.path().filename().string() + ":" + std::to_string(n) + ": " + line + "\n";
  }
  EXPECT_EQ(found, "") << "use rheomag::app::in_domain (app/command.hpp)";
}
