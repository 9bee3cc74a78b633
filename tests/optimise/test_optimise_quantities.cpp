// Quantities of a design beyond the field: thinnest steel wall, steady coil temperature rise and
// the 90 % current rise time with a voltage driver (coarse FE annular valve,
// optimise_fixture.hpp).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "optimise/evaluate.hpp"
#include "optimise/spec.hpp"
#include "optimise_fixture.hpp"

namespace {

using namespace rheomag;
using optimise_fixture::make_case;

std::string optimise_table(const std::string& extra) {
  return "[optimise]\nflow = 6.91e-6\n" + extra +
         "[[optimise.variable]]\nkey = \"geometry.pole_length\"\nlower = 2.0\nupper = 8.0\n";
}

// min_wall of the annular template = min(disk_thickness (5 mm default), pole_length): 3 mm at
// pole_length 3, 5 mm at 7 (exact: template dimensions).
TEST(OptimiseQuantities, MinimumWallIsTheThinnestSteelWall) {
  const auto c = make_case(optimise_table(""));
  optimise::OptimiseEvaluator e(c, optimise::read_optimise_spec(c));
  EXPECT_DOUBLE_EQ(e.evaluate({3.0})[design::Quantity::min_wall], 3e-3);
  EXPECT_DOUBLE_EQ(e.evaluate({7.0})[design::Quantity::min_wall], 5e-3);
}

// temperature_rise = P / (h A), A = 2 pi r_c l_c the coil's outer cylinder: r_c = gap_radius -
// gap_width / 2 - cover_thickness = 18.5 mm, l_c = coil_length = 32 mm (template defaults and
// the case), h = 10 W/(m^2 K) by default; with thermal_resistance: P R_th. Exact up to rounding
// (the mesh has nodes on the coil's corners).
TEST(OptimiseQuantities, TemperatureRiseIsPowerOverSurfaceConductance) {
  const auto c = make_case(optimise_table(""));
  optimise::OptimiseEvaluator e(c, optimise::read_optimise_spec(c));
  const auto q = e.evaluate({5.0});
  const double area = 2.0 * std::numbers::pi * 18.5e-3 * 32e-3;
  EXPECT_NEAR(q[design::Quantity::temperature_rise], q[design::Quantity::power] / (10.0 * area),
              1e-9 * q[design::Quantity::temperature_rise]);
  const auto c2 = make_case(optimise_table("thermal_resistance = 4.0\n"));
  optimise::OptimiseEvaluator e2(c2, optimise::read_optimise_spec(c2));
  const auto q2 = e2.evaluate({5.0});
  EXPECT_NEAR(q2[design::Quantity::temperature_rise], 4.0 * q2[design::Quantity::power], 1e-12);
}

// 90 % rise time after a voltage step V on R and lambda(i). Reference: for a linear inductor
// t90 = ln(10) L / R. At I_f = V / R = 0.05 A the steel is on the linear start of its B-H
// table, so with the secant L at 0.05 A the rise time agrees within 0.5 % (measured: to 5
// digits). At I_f = 3 A the core saturates (L(i) falls),
// so the rise time must be shorter than ln(10) L(0.05 A) / R.
TEST(OptimiseQuantities, RiseTimeMatchesTheLinearRlLimitAndShortensWithSaturation) {
  const auto probe = make_case(optimise_table("current = 0.05\n"));
  optimise::OptimiseEvaluator p(probe, optimise::read_optimise_spec(probe));
  const auto q0 = p.evaluate({5.0});
  const double r = q0[design::Quantity::resistance], l = q0[design::Quantity::inductance];
  auto rise = [&](double final_current) {
    const auto c = make_case(
        optimise_table("current = 0.05\nsupply_voltage = " + std::to_string(final_current * r) +
                       "\n[[optimise.constraint]]\nquantity = \"rise_time\"\nmax = 1.0\n"));
    optimise::OptimiseEvaluator e(c, optimise::read_optimise_spec(c));
    const auto q = e.evaluate({5.0});
    EXPECT_EQ(e.fe_solves(), 5);  // the operating point + 4 lambda(i) samples
    return q[design::Quantity::rise_time];
  };
  const double linear = std::log(10.0) * l / r;
  const double small = rise(0.05), saturated = rise(3.0);
  EXPECT_NEAR(small, linear, 0.005 * linear);
  EXPECT_LT(saturated, linear);
  std::printf("rise time: ln(10) L/R %.5g s; 0.05 A %.5g s; 3 A %.5g s\n", linear, small,
              saturated);
}

using optimise_fixture::input_error;

// rise_time without a driver voltage, and an unknown quantity (named, valid names listed).
TEST(OptimiseQuantities, BadInputNamesTheQuantity) {
  EXPECT_NE(input_error(optimise_table("objective = \"rise_time\"\nsense = \"minimise\"\n"))
                .find("supply_voltage"),
            std::string::npos);
  const std::string unknown = input_error(optimise_table("objective = \"wall_thickness\"\n"));
  EXPECT_NE(unknown.find("\"wall_thickness\""), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("min_wall"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("temperature_rise"), std::string::npos) << unknown;
}

}  // namespace
