// Sweep files: levels of lists and ranges, design ids, Latin hypercube stratification and
// determinism, unknown keys with suggestions, type checks and --shard parsing.

#include <gtest/gtest.h>

#include <set>

#include "case/case_sections.hpp"
#include "core/error.hpp"
#include "sweep/designs.hpp"
#include "sweep/run.hpp"
#include "sweep/spec.hpp"
#include "sweep_fixture.hpp"
// Base cases carry [valve]; in the program the valve layer registers it (valve_chain.hpp), and
// this test, which does not use the valve layer, registers it itself.
const bool kValveSectionRegistered = rheomag::cases::register_case_section("valve");

namespace rheomag::sweep {
namespace {

using testing::sweep_text;

SweepSpec parse(const std::string& sweep_lines, const std::string& axes) {
  return parse_sweep(sweep_text(sweep_lines, axes), "test_sweep.toml");
}

std::string message_of(const std::string& sweep_lines, const std::string& axes) {
  try {
    parse(sweep_lines, axes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SweepSpec, RangeWithCountIncludesBothEnds) {
  // start + i (stop - start)/(count - 1), i = 0..count-1, the last exactly `stop`.
  const SweepSpec spec =
      parse("", "[[axis]]\nkey = \"circuit.current\"\nstart = 0.25\nstop = 1.0\ncount = 4\n");
  ASSERT_EQ(spec.axes.size(), 1u);
  const auto& levels = spec.axes[0].levels;
  ASSERT_EQ(levels.size(), 4u);
  EXPECT_DOUBLE_EQ(std::get<double>(levels[0]), 0.25);
  EXPECT_DOUBLE_EQ(std::get<double>(levels[1]), 0.5);
  EXPECT_DOUBLE_EQ(std::get<double>(levels[2]), 0.75);
  EXPECT_EQ(std::get<double>(levels[3]), 1.0);
}

TEST(SweepSpec, RangeWithStepStopsAtStop) {
  // 0.8, 1.0, 1.2 (1.2 reached within rounding), integer key rounded: turns 100, 300, 500.
  const SweepSpec spec = parse("",
                               "[[axis]]\nkey = \"geometry.gap_width\"\nstart = 0.8\nstop = 1.2\n"
                               "step = 0.2\n[[axis]]\nkey = \"geometry.turns\"\nstart = 100\n"
                               "stop = 599\nstep = 200\n");
  EXPECT_EQ(spec.axes[0].levels.size(), 3u);
  EXPECT_EQ(spec.axes[0].key.type, cases::KeyType::number);
  ASSERT_EQ(spec.axes[1].levels.size(), 3u);
  EXPECT_EQ(spec.axes[1].key.type, cases::KeyType::integer);
  EXPECT_EQ(std::get<long long>(spec.axes[1].levels[2]), 500);
  EXPECT_EQ(design_count(spec), 9);
}

TEST(SweepSpec, FactorialIdsVaryTheLastAxisFastest) {
  const SweepSpec spec = parse("",
                               "[[axis]]\nkey = \"geometry.gap_width\"\nvalues = [0.8, 1.2]\n"
                               "[[axis]]\nkey = \"geometry.core_material\"\n"
                               "values = [\"AISI 1010\", \"AISI 1018\", \"AISI 1010\"]\n");
  const DesignGenerator designs(spec);
  ASSERT_EQ(designs.count(), 6);
  const Design d4 = designs.design(4);  // 4 = 1 * 3 + 1
  EXPECT_EQ(std::get<double>(d4.values[0]), 1.2);
  EXPECT_EQ(std::get<std::string>(d4.values[1]), "AISI 1018");
}

TEST(SweepSpec, LatinHypercubeIsStratifiedAndDeterministic) {
  // Latin hypercube (McKay, Beckman & Conover 1979): with n samples, each axis range split in
  // n equal intervals holds exactly one sample. Same seed -> same designs; other seed -> other.
  const std::string axes =
      "[[axis]]\nkey = \"geometry.gap_width\"\nmin = 0.5\nmax = 1.5\n"
      "[[axis]]\nkey = \"circuit.current\"\nmin = 0.0\nmax = 2.0\n";
  const SweepSpec spec = parse("method = \"latin_hypercube\"\nsamples = 16\nseed = 7", axes);
  const DesignGenerator designs(spec);
  ASSERT_EQ(designs.count(), 16);
  for (std::size_t a = 0; a < 2; ++a) {
    const double lower = a == 0 ? 0.5 : 0.0, upper = a == 0 ? 1.5 : 2.0;
    std::set<int> strata;
    for (long long id = 0; id < 16; ++id) {
      const double x = std::get<double>(designs.design(id).values[a]);
      ASSERT_GE(x, lower);
      ASSERT_LT(x, upper);
      strata.insert(static_cast<int>((x - lower) / (upper - lower) * 16));
    }
    EXPECT_EQ(strata.size(), 16u) << "axis " << a;
  }
  const SweepSpec same = parse("method = \"latin_hypercube\"\nsamples = 16\nseed = 7", axes);
  const SweepSpec other = parse("method = \"latin_hypercube\"\nsamples = 16\nseed = 8", axes);
  const DesignGenerator same_designs(same), other_designs(other);
  int differing = 0;
  for (long long id = 0; id < 16; ++id) {
    EXPECT_EQ(std::get<double>(designs.design(id).values[1]),
              std::get<double>(same_designs.design(id).values[1]));
    differing += std::get<double>(designs.design(id).values[1]) !=
                 std::get<double>(other_designs.design(id).values[1]);
  }
  EXPECT_GT(differing, 0);
}

TEST(SweepSpec, UnknownKeyNamesItAndSuggestsTheClosest) {
  const std::string message =
      message_of("", "[[axis]]\nkey = \"geometry.gap_widht\"\nvalues = [1.0]\n");
  EXPECT_NE(message.find("'geometry.gap_widht'"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean 'geometry.gap_width'"), std::string::npos) << message;
  const std::string circuit =
      message_of("", "[[axis]]\nkey = \"circuit.curent\"\nvalues = [1.0]\n");
  EXPECT_NE(circuit.find("did you mean 'circuit.current'"), std::string::npos) << circuit;
}

TEST(SweepSpec, ArrayIndexForms) {
  for (const char* key : {"circuit.current", "circuit.0.current", "circuit[0].current"}) {
    const SweepSpec spec =
        parse("", std::string("[[axis]]\nkey = \"") + key + "\"\nvalues = [0.5]\n");
    EXPECT_EQ(spec.axes[0].key.path, (std::vector<std::string>{"circuit", "0", "current"})) << key;
  }
  EXPECT_NE(message_of("", "[[axis]]\nkey = \"circuit.1.current\"\nvalues = [0.5]\n")
                .find("item 1 of a list of 1"),
            std::string::npos);
}

TEST(SweepSpec, BadAxesAreInputErrors) {
  // Wrong value types for the key's base type, a table as key, mixed forms, bounds outside a
  // Latin hypercube, a repeated key.
  EXPECT_NE(message_of("", "[[axis]]\nkey = \"geometry.turns\"\nvalues = [100.5]\n")
                .find("expected an integer"),
            std::string::npos);
  EXPECT_NE(message_of("", "[[axis]]\nkey = \"geometry.core_material\"\nvalues = [1.0]\n")
                .find("expected a string"),
            std::string::npos);
  EXPECT_NE(message_of("", "[[axis]]\nkey = \"geometry\"\nvalues = [1.0]\n").find("is a table"),
            std::string::npos);
  EXPECT_NE(message_of("", "[[axis]]\nkey = \"geometry.gap_width\"\nvalues = [1.0]\nstart = 1\n")
                .find("exactly one of"),
            std::string::npos);
  EXPECT_NE(message_of("", "[[axis]]\nkey = \"geometry.gap_width\"\nmin = 1.0\nmax = 2.0\n")
                .find("latin_hypercube"),
            std::string::npos);
  EXPECT_NE(message_of("",
                       "[[axis]]\nkey = \"geometry.gap_width\"\nstart = 1\nstop = 2\n"
                       "step = -1\n")
                .find("goes away from stop"),
            std::string::npos);
  EXPECT_NE(message_of("",
                       "[[axis]]\nkey = \"circuit.current\"\nvalues = [1.0]\n"
                       "[[axis]]\nkey = \"circuit.0.current\"\nvalues = [2.0]\n")
                .find("swept twice"),
            std::string::npos);
  EXPECT_NE(message_of("method = \"random\"",
                       "[[axis]]\nkey = \"circuit.current\"\n"
                       "values = [1.0]\n")
                .find("unknown method"),
            std::string::npos);
}

TEST(SweepSpec, ShippedExampleReads) {
  // cases/sweeps/annular_gap_current.toml: 5 widths x 6 currents; the current range is
  // 0.25 + 0.25 k, and the 6 currents of a width form one mesh-sharing block.
  const SweepSpec spec = read_sweep(std::filesystem::path(RHEOMAG_SOURCE_DIR) /
                                    "cases/sweeps/annular_gap_current.toml");
  EXPECT_EQ(design_count(spec), 30);
  EXPECT_EQ(mesh_sharing_block(spec), 6);
  const DesignGenerator designs(spec);
  EXPECT_DOUBLE_EQ(std::get<double>(designs.design(7).values[1]), 0.5);
}

TEST(SweepSpec, ShardParsing) {
  const Shard s = parse_shard("1/4");
  EXPECT_EQ(s.index, 1);
  EXPECT_EQ(s.count, 4);
  EXPECT_THROW(parse_shard("4/4"), InputError);
  EXPECT_THROW(parse_shard("1-4"), InputError);
  EXPECT_THROW(parse_shard("a/2"), InputError);
  EXPECT_THROW(parse_shard("0/0"), InputError);
}

}  // namespace
}  // namespace rheomag::sweep
