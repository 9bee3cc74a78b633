// Two ways a FEMM model went wrong without a word (issue #36): a driven circuit that winds no
// region gave lambda = 0 with exit 0, and `export` wrote a .fem that does not read back when a
// name holds a line break or a double quote.

#include <gtest/gtest.h>

#include <string>

#include "case/case_file.hpp"
#include "case/femm_export.hpp"
#include "core/error.hpp"
#include "magnetostatics/domain.hpp"
#include "magnetostatics/solve_problem.hpp"

using namespace rheomag;

namespace {

const std::string kValve = std::string(RHEOMAG_SOURCE_DIR) + "/tests/data/pot_core_equivalent.toml";

}  // namespace

// A second circuit at 1 A that no region names: its lambda is 0 and the result says why; the
// coil's own circuit carries no warning.
TEST(UnwoundCircuit, DrivenCircuitWithoutWindingIsWarnedAbout) {
  cases::Case c = cases::load_case(kValve);
  ASSERT_FALSE(c.problem.circuits.empty());
  cases::Circuit spare = c.problem.circuits.front();
  spare.name = "spare";
  spare.current = 1.0;
  c.problem.circuits.push_back(spare);
  const magnetostatics::SolveResult solved = magnetostatics::solve_problem(c.problem);
  ASSERT_EQ(solved.results.circuits.size(), 2u);
  EXPECT_EQ(solved.results.circuits[0].warning, "");
  EXPECT_EQ(solved.results.circuits[1].flux_linkage, 0.0);
  EXPECT_NE(solved.results.circuits[1].warning.find("circuit 'spare' carries a current but winds "
                                                    "no region"),
            std::string::npos)
      << solved.results.circuits[1].warning;
}

// A material name with a line break, a circuit name with a double quote: refused naming the
// kind of name and showing the line break as \n; the model's ordinary names export.
TEST(FemmNames, NameFemmCannotHoldIsRefusedOnExport) {
  cases::Case c = cases::load_case(kValve);
  const cases::Problem closed = magnetostatics::close_domain(c.problem);
  EXPECT_NO_THROW(cases::write_femm(closed, {}));
  cases::Problem broken = closed;
  broken.materials.front().name = "steel\n1010";
  try {
    cases::write_femm(broken, {});
    FAIL() << "a material name with a line break was written";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("material name 'steel\\n1010' cannot be written to a "
                                         ".fem"),
              std::string::npos)
        << e.what();
  }
  broken = closed;
  broken.circuits.front().name = "coil \"A\"";
  EXPECT_THROW(cases::write_femm(broken, {}), InputError);
}
