// Enum <-> name tables: both directions and the message for an unknown name.

#include <gtest/gtest.h>

#include "core/enum_names.hpp"

namespace {
enum class Colour { red, green, blue };
constexpr auto kColourNames = rheomag::enum_names<Colour>(
    {{Colour::red, "red"}, {Colour::green, "green"}, {Colour::blue, "blue"}});
}  // namespace

TEST(EnumNames, RoundTrip) {
  for (Colour c : {Colour::red, Colour::green, Colour::blue})
    EXPECT_EQ(kColourNames.find(kColourNames.name(c)), c);
  EXPECT_FALSE(kColourNames.find("Red").has_value());
}

TEST(EnumNames, UnknownNameListsTheChoices) {
  try {
    kColourNames.parse("purple", "case.toml:3: colour");
    FAIL() << "expected InputError";
  } catch (const rheomag::InputError& e) {
    EXPECT_STREQ(e.what(),
                 "case.toml:3: colour: expected \"red\", \"green\" or \"blue\", got \"purple\"");
  }
}
