// Coil electrical model: wire gauges, resistance, fill, power and time constant; the coil's
// turns from its winding window, wire and fill factor ([geometry] wire + fill_factor).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "case/case_file.hpp"
#include "case/wire_gauge.hpp"
#include "core/error.hpp"
#include "valve/coil.hpp"
#include "valve/valve_chain.hpp"

using namespace rheomag::valve;
using rheomag::cases::awg_diameter;
using rheomag::cases::wire_diameter;

// Reference: ASTM B258 table values: AWG 36 = 0.127 mm (definition), AWG 24 = 0.5106 mm,
// AWG 0000 = 11.684 mm (4 decimals of mm as tabulated).
TEST(Coil, AwgDiameters) {
  EXPECT_NEAR(awg_diameter(36), 0.127e-3, 1e-12);
  EXPECT_NEAR(awg_diameter(24), 0.5106e-3, 0.00005e-3);
  EXPECT_NEAR(awg_diameter(-3), 11.684e-3, 0.0005e-3);
  EXPECT_EQ(wire_diameter("AWG 24"), awg_diameter(24));
  EXPECT_EQ(wire_diameter("24 awg"), awg_diameter(24));
  EXPECT_EQ(wire_diameter("awg0000"), awg_diameter(-3));
  EXPECT_NEAR(wire_diameter("0.5 mm"), 0.5e-3, 1e-15);
  EXPECT_THROW(wire_diameter("AWG 99"), rheomag::InputError);
  EXPECT_THROW(wire_diameter("thick"), rheomag::InputError);
  EXPECT_THROW(wire_diameter("-1 mm"), rheomag::InputError);
  EXPECT_THROW(wire_diameter("AWG 2.5"), rheomag::InputError);
}

// Reference: AWG 24 copper is 84.2 mOhm/m at 20 C (standard wire tables); the paper-000 coil
// (600 turns, mean turn 2 pi 15 mm, cases/annular_valve.toml header) is then ~4.76 Ohm.
// R(T) = R20 (1 + 0.00393 (T - 20)); P = I^2 R; tau = L/R; J = I/(pi d^2/4).
TEST(Coil, ResistancePowerTimeConstant) {
  const double d = awg_diameter(24);
  EXPECT_NEAR(copper_resistivity(20.0) / (std::numbers::pi * d * d / 4.0), 84.2e-3, 0.1e-3);
  CoilSpec spec{600, d, 2.0 * std::numbers::pi * 15e-3, 32e-3 * 7e-3, 20.0};
  const auto cold = coil_properties(spec, 1.0, 0.05);
  EXPECT_NEAR(cold.resistance, 4.76, 0.02);
  EXPECT_NEAR(cold.power, cold.resistance, 1e-12);
  EXPECT_NEAR(cold.time_constant, 0.05 / cold.resistance, 1e-15);
  EXPECT_NEAR(cold.current_density, 1.0 / (std::numbers::pi * d * d / 4.0), 1e-6);
  EXPECT_NEAR(cold.copper_fill, 600 * std::numbers::pi * d * d / 4.0 / (32e-3 * 7e-3), 1e-12);
  spec.temperature = 70.0;
  EXPECT_NEAR(coil_properties(spec, 1.0, 0.05).resistance / cold.resistance, 1.0 + 0.00393 * 50.0,
              1e-12);
  EXPECT_NEAR(coil_properties(spec, 2.0, 0.05).power / coil_properties(spec, 1.0, 0.05).power, 4.0,
              1e-12);
}

TEST(Coil, BadInputThrows) {
  const double d = awg_diameter(24);
  EXPECT_THROW(coil_properties(CoilSpec{0, d, 0.1, 1e-4, 20}, 1.0, 0.01), rheomag::InputError);
  EXPECT_THROW(coil_properties(CoilSpec{600, d, 0.1, 1e-6, 20}, 1.0, 0.01),
               rheomag::InputError);  // does not fit the window
  EXPECT_THROW(coil_properties(CoilSpec{600, d, 0.1, 1e-3, 20}, 1.0, -1.0), rheomag::InputError);
  EXPECT_THROW(copper_resistivity(-300.0), rheomag::InputError);
}

// Issue 36: -250 C was accepted and gave a negative resistivity (R = -0.291 Ohm, exit 0). The
// linear model is positive over its whole domain [-200, 250] C (exactly: 1 + 0.00393 (T - 20) at
// -200 C is 0.1354) and refused outside it, at both ends, with the domain named.
TEST(Coil, TemperatureOutsideTheCopperModelIsRefused) {
  EXPECT_NEAR(copper_resistivity(-200.0), 1.7241e-8 * 0.1354, 1e-15);
  EXPECT_GT(copper_resistivity(kCoilTemperature.lower), 0.0);
  for (const double t : {-250.0, -273.15, -300.0, 250.5, 400.0, std::nan("")}) {
    try {
      copper_resistivity(t);
      ADD_FAILURE() << t << " C accepted";
    } catch (const rheomag::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("expected a number in [-200, 250] (deg C)"),
                std::string::npos)
          << e.what();
    }
  }
}

namespace {

std::string annular_case_with(const std::string& from, const std::string& to) {
  std::ifstream in(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  s = s.substr(0, s.find("\n[valve]"));  // the tests add their own [valve]
  const auto at = s.find(from);
  if (at == std::string::npos) throw std::runtime_error("case text changed: " + from);
  return s.replace(at, from.size(), to);
}

double coil_turns(const rheomag::cases::Case& c) {
  double turns = 0.0;
  for (const auto& region : c.problem.regions)
    if (region.circuit == 0) turns += region.turns;
  return turns;
}

}  // namespace

// Reference, by hand: the annular_valve template's winding window is r 11.5..18.5 mm
// (neck 10.5 + wall 1 .. core 19 - cover 0.5) x z -16..16 mm (coil_length 32 = groove 34 -
// 2 walls) = 7 x 32 = 224 mm^2. 0.5 mm wire (0.19635 mm^2) at copper fill 0.5:
// floor(0.5 x 224 / 0.19635) = floor(570.42) = 570 turns.
TEST(CoilWinding, TurnsFromWindowWireAndFill) {
  using rheomag::cases::parse_case;
  const auto c =
      parse_case(annular_case_with("turns = 600 ", "wire = \"0.5 mm\"\nfill_factor = 0.5 "),
                 "annular_fill.toml");
  EXPECT_EQ(coil_turns(c), 570.0);
  EXPECT_EQ(rheomag::cases::winding_turns(224e-6, 0.5e-3, 0.5), 570.0);
  // The [valve] wire defaults to the [geometry] wire.
  EXPECT_EQ(rheomag::valve::read_valve_options(c).wire, "0.5 mm");
}

// Reference: paper 000 (600 turns AWG 24, bare 0.5106 mm, ASTM B258) in the same 224 mm^2
// window implies a copper fill of 600 x pi 0.5106^2/4 / 224 = 0.5485 (by hand), plausible for
// a layer-wound enamelled coil (orthocyclic packing of ~0.56 mm enamelled AWG 24 allows at most
// 0.9069 (0.5106/0.56)^2 = 0.75). That fill gives back 600 turns.
TEST(CoilWinding, PaperZeroCoilHasAPlausibleFill) {
  const double window = 7e-3 * 32e-3;
  const double d = awg_diameter(24);
  const double fill = 600.0 * std::numbers::pi * d * d / 4.0 / window;
  EXPECT_NEAR(fill, 0.5485, 0.0005);
  EXPECT_EQ(rheomag::cases::winding_turns(window, d, fill), 600.0);
  const auto wound = rheomag::cases::parse_case(
      annular_case_with("turns = 600 ",
                        "wire = \"AWG 24\"\nfill_factor = " + std::to_string(fill) + " "),
      "annular_fill.toml");
  EXPECT_NEAR(coil_turns(wound), 600.0, 1.0);  // fill printed to 6 digits
}

// Bad input: both turns and fill_factor; fill without wire; fill above pi/4; unknown wire;
// [valve] wire different from [geometry] wire.
TEST(CoilWinding, BadInputNamesTheKey) {
  using rheomag::cases::parse_case;
  auto message = [](const std::string& text) -> std::string {
    try {
      rheomag::valve::read_valve_options(parse_case(text, "bad.toml"));
    } catch (const rheomag::InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message(annular_case_with("turns = 600 ",
                                      "turns = 600\nwire = \"AWG 24\"\nfill_factor = 0.5 "))
                .find("fill_factor"),
            std::string::npos);
  EXPECT_NE(message(annular_case_with("turns = 600 ", "fill_factor = 0.5 ")).find("wire"),
            std::string::npos);
  EXPECT_NE(message(annular_case_with("turns = 600 ", "wire = \"AWG 24\"\nfill_factor = 0.9 "))
                .find("pi/4"),
            std::string::npos);
  EXPECT_NE(message(annular_case_with("turns = 600 ", "wire = \"AWG 99\"\nfill_factor = 0.5 "))
                .find("wire"),
            std::string::npos);
  EXPECT_NE(message(annular_case_with("turns = 600 ", "wire = \"AWG 24\"\nfill_factor = 0.5 ") +
                    "\n[valve]\nwire = \"AWG 26\"\n")
                .find("give the wire once"),
            std::string::npos);
}
