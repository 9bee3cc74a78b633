// format_text: the text printf would print, however long.

#include <gtest/gtest.h>

#include <string>

#include "core/format_text.hpp"

TEST(FormatText, FormatsLikePrintf) {
  EXPECT_EQ(rheomag::format_text("%8.4g|%s|%d\n", 1.5, "ab", 7), "     1.5|ab|7\n");
  EXPECT_EQ(rheomag::format_text("%s", ""), "");
}

TEST(FormatText, LongerThanAnyFixedBuffer) {
  const std::string long_text(5000, 'x');
  EXPECT_EQ(rheomag::format_text("<%s>", long_text.c_str()), "<" + long_text + ">");
}
