// Quantities with units on the command line (core/units.hpp, issue 34): SI when no unit is
// written, each kind's units converted exactly, and a bad unit named with the units accepted.

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "core/units.hpp"

using rheomag::InputError;
using rheomag::parse_quantities;
using rheomag::parse_quantity;
using rheomag::QuantityKind;

TEST(Units, NoUnitIsSi) {
  EXPECT_EQ(parse_quantity("2.5e-5", QuantityKind::flow, "--flow"), 2.5e-5);
  EXPECT_EQ(parse_quantity("-1", QuantityKind::current, "--current"), -1.0);
}

TEST(Units, EachKindConvertsToSi) {
  // Reference: the unit definitions (1 L = 1e-3 m^3, 1 rpm = 2 pi / 60 rad/s, 1 in = 25.4 mm).
  EXPECT_DOUBLE_EQ(parse_quantity("1.5L/min", QuantityKind::flow, "--flow"), 1.5e-3 / 60);
  EXPECT_DOUBLE_EQ(parse_quantity("1.5 l/min", QuantityKind::flow, "--flow"), 1.5e-3 / 60);
  EXPECT_DOUBLE_EQ(parse_quantity("10mm", QuantityKind::length, "--point"), 0.01);
  EXPECT_DOUBLE_EQ(parse_quantity("1in", QuantityKind::length, "--gap"), 0.0254);
  EXPECT_DOUBLE_EQ(parse_quantity("500mA", QuantityKind::current, "--current"), 0.5);
  EXPECT_DOUBLE_EQ(parse_quantity("60rpm", QuantityKind::angular_speed, "--speed"),
                   2.0 * 3.14159265358979323846);
  EXPECT_DOUBLE_EQ(parse_quantity("50ms", QuantityKind::time, "--duration"), 0.05);
  EXPECT_DOUBLE_EQ(parse_quantity("2bar", QuantityKind::pressure, "--tau-y"), 2e5);
  EXPECT_DOUBLE_EQ(parse_quantity("5mm/s", QuantityKind::velocity, "--velocity"), 5e-3);
  const auto list = parse_quantities({"0", "500mA", "1A"}, QuantityKind::current, "--current");
  ASSERT_EQ(list.size(), 3u);
  EXPECT_DOUBLE_EQ(list[1], 0.5);
  EXPECT_DOUBLE_EQ(list[2], 1.0);
}

TEST(Units, BadUnitNamesTheOptionTheUnitAndTheUnitsAccepted) {
  try {
    parse_quantity("2gpm", QuantityKind::flow, "--flow");
    FAIL() << "2gpm read as a flow";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--flow"), std::string::npos) << what;
    EXPECT_NE(what.find("\"gpm\""), std::string::npos) << what;
    EXPECT_NE(what.find("L/min"), std::string::npos) << what;
  }
  // A current is not a length, and a value without a number is refused.
  EXPECT_THROW(parse_quantity("10mm", QuantityKind::current, "--current"), InputError);
  EXPECT_THROW(parse_quantity("mA", QuantityKind::current, "--current"), InputError);
  EXPECT_THROW(parse_quantity("inf", QuantityKind::current, "--current"), InputError);
}
